# A disc settling in a narrow vertical channel (thesis case D, §5.3; Feng, Hu &
# Joseph 1994): channel width L = 1.5 d, the disc started 0.15 d off the
# centreline and 10 d below the top, density ratio 2. Consistent units with
# d = 1 and fluid density 1. Prints the settling speed, the Reynolds number
# u d / nu and the lateral position x/L as it falls; with -csv writes them.
#
#   sandflow examples/sediment-disc.tcl ?-cells N? ?-ratio r? ?-nu nu? ?-g g?
#            ?-fall D? ?-every K? ?-integrator central|euler|verlet?
#            ?-coupling explicit|implicit? ?-csv FILE?
#
# -cells: lattice cells across the channel (the thesis: 180, the disc then
# 120 cells across); -fall: how far to let it fall, in diameters.
# The thesis's reference material does not give Feng et al.'s gravity or
# viscosity; the default g = 1.2 with nu = 0.02 settles at Re near 6.

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {cells.arg      60        "lattice cells across the channel (the thesis: 180, the disc then 120 across)"}
    {ratio.arg      2.0       "the disc's density over the fluid's"}
    {nu.arg         0.02      "kinematic viscosity"}
    {g.arg          1.2       "gravity"}
    {fall.arg       8         "how far to let the disc fall, in diameters"}
    {every.arg      500       "steps between printed lines"}
    {integrator.arg central   "integrator: central, euler or verlet"}
    {coupling.arg   explicit  "fluid coupling: explicit or implicit"}
    {csv.arg        {}        "CSV file for the history"}
}]
dict with options {}
set d 1.0
set L [expr {1.5 * $d}]
set H [expr {22.5 * $d}]
set h [expr {$L / ${-cells}}]

lattice create -size [list $L $H] -cells ${-cells} -viscosity ${-nu} -tau 0.8 \
    -walls {left noslip right noslip bottom noslip top noslip}
sim configure -gravity [list 0 [expr {-${-g}}]] -integrator ${-integrator} -coupling ${-coupling}
# Contacts (only if it reaches a wall) stiff enough, and soft enough that the
# critical step is five fluid steps.
set dt [dict get [lattice info] timestep]
set k [expr {${-ratio} * acos(-1) * 0.25 * $d * $d * 4 / (25 * $dt * $dt)}]
material create grain -density ${-ratio} -kn $k -ks $k -friction 0.1
# Walls for contacts, on the lattice's no-slip sides.
foreach {from to} [list {0 0} [list 0 $H] [list $L 0] [list $L $H] {0 0} [list $L 0]] {
    wall create -from $from -to $to -material grain
}
set x0 [expr {0.5 * $L + 0.15 * $d}]
set y0 [expr {$H - 10 * $d}]
set disc [disc create -center [list $x0 $y0] -radius [expr {0.5 * $d}] -material grain]

set info [lattice info]
puts [format "lattice %d x %d, h = %g, dt = %g, tau %g; disc %g cells across, density ratio %g" \
    [dict get $info nx] [dict get $info ny] $h [dict get $info timestep] [dict get $info tau] \
    [expr {$d / $h}] ${-ratio}]
set csv {}
if {${-csv} ne {}} {
    set csv [open ${-csv} w]
    puts $csv "t,x_over_L,y,vx,vy,Re"
}
proc report {} {
    global disc d L csv options
    set e [element info $disc]
    lassign [dict get $e position] x y
    lassign [dict get $e velocity] vx vy
    set t [dict get [sim info] time]
    set re [expr {abs($vy) * $d / [dict get $options -nu]}]
    puts [format "t %8.3f  y %7.3f  x/L %.4f  v %9.5f  Re %.3f" $t $y [expr {$x / $L}] $vy $re]
    if {$csv ne {}} { puts $csv [join [list $t [expr {$x / $L}] $y $vx $vy $re] ,] }
    return $y
}
# Stop after the fall, or a diameter above the floor, whichever comes first.
set stop [expr {max($y0 - ${-fall} * $d, 1.5 * $d)}]
while {[report] > $stop} {
    run ${-every}
}
if {$csv ne {}} { close $csv }
