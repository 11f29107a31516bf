# Drafting, kissing and tumbling of two settling discs (thesis case E, §5.4;
# Qi 1999): a channel 8 d wide, two discs of density ratio 2, one 2 d above
# the other, both 2 d off the centreline and about 10 d below the top.
# Consistent units with d = 1 and fluid density 1. Prints the positions, the
# centre distance and the stage; with -csv writes the history.
#
#   sandflow examples/dkt.tcl ?-cells N? ?-nu nu? ?-g g? ?-height H? ?-time T? ?-every K?
#            ?-coupling explicit|implicit? ?-csv FILE?
#
# -cells: lattice cells across the channel (the thesis: 120, the discs then 15
# cells across); -height: the channel's height in d (the thesis: 100); -time:
# how long to run, in units of d / (mean settling speed) estimated from the
# leading disc's speed.

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {cells.arg    120       "lattice cells across the channel (the thesis: 120, the discs then 15 across)"}
    {nu.arg       0.02      "kinematic viscosity"}
    {g.arg        0.08      "gravity"}
    {height.arg   100       "the channel's height in d (the thesis: 100)"}
    {time.arg     100       "how long to run, in d / (mean settling speed of the leading disc)"}
    {every.arg    200       "steps between samples"}
    {coupling.arg explicit  "fluid coupling: explicit or implicit"}
    {csv.arg      {}        "CSV file for the history"}
}]
dict with options {}
set d 1.0
set L [expr {8.0 * $d}]
set H [expr {double(${-height}) * $d}]

lattice create -size [list $L $H] -cells ${-cells} -viscosity ${-nu} -tau 0.7 \
    -walls {left noslip right noslip bottom noslip top noslip}
sim configure -gravity [list 0 [expr {-${-g}}]] -coupling ${-coupling}
# Contacts stiff enough, and soft enough that the critical step is five fluid steps.
set dt [dict get [lattice info] timestep]
set k [expr {2.0 * acos(-1) * 0.25 * 4 / (25 * $dt * $dt)}]
material create grain -density 2.0 -kn $k -ks $k -friction 0.1 -restitution 0.5
foreach {from to} [list {0 0} [list 0 $H] [list $L 0] [list $L $H] {0 0} [list $L 0]] {
    wall create -from $from -to $to -material grain
}
set x0 [expr {0.5 * $L - 2 * $d}]
set lead [disc create -center [list $x0 [expr {$H - 12 * $d}]] -radius 0.5 -material grain]
set trail [disc create -center [list $x0 [expr {$H - 10 * $d}]] -radius 0.5 -material grain]

set info [lattice info]
puts [format "lattice %d x %d, h = %g, dt = %g, tau %g; discs %g cells across" \
    [dict get $info nx] [dict get $info ny] [expr {$L / ${-cells}}] [dict get $info timestep] \
    [dict get $info tau] [expr {${-cells} / 8.0}]]
set csv {}
if {${-csv} ne {}} {
    set csv [open ${-csv} w]
    puts $csv "t,x_lead,y_lead,x_trail,y_trail,distance"
}
# Stages: drafting (the gap closes), kissing (the closest approach), tumbling
# (the trailing disc passes the leading one).
set closest 1e9
set kissAt -1
set tumbleAt -1
set speeds {}
proc sample {} {
    global lead trail csv closest kissAt tumbleAt speeds
    lassign [dict get [element info $lead] position] xl yl
    lassign [dict get [element info $trail] position] xt yt
    lappend speeds [expr {-[lindex [dict get [element info $lead] velocity] 1]}]
    set t [dict get [sim info] time]
    set dist [expr {hypot($xt - $xl, $yt - $yl)}]
    if {$dist < $closest} { set closest $dist; set kissAt $t }
    if {$tumbleAt < 0 && $yt < $yl} { set tumbleAt $t }
    if {$csv ne {}} { puts $csv [join [list $t $xl $yl $xt $yt $dist] ,] }
    return [format "t %8.2f  lead {%.3f %.3f}  trail {%.3f %.3f}  distance %.3f" \
                $t $xl $yl $xt $yt $dist]
}
puts [sample]
set steps 0
set dt [sim cget -timestep]
while {1} {
    run ${-every}
    set line [sample]
    set u [expr {max(1e-12, [tcl::mathop::+ {*}$speeds] / [llength $speeds])}]
    set t [dict get [sim info] time]
    if {[incr steps] % 10 == 0} { puts "$line  (t U/d = [format %.1f [expr {$t * $u / $d}]])" }
    if {$t * $u / $d >= ${-time}} break
    if {[lindex [dict get [element info $lead] position] 1] < 2 * $d} break
}
set u [expr {[tcl::mathop::+ {*}$speeds] / [llength $speeds]}]
puts [format "mean settling speed %.4f, Re %.2f; closest approach %.3f d at t %.1f; tumbling %s" \
    $u [expr {$u * $d / ${-nu}}] [expr {$closest / $d}] $kissAt \
    [expr {$tumbleAt < 0 ? "not seen" : "at t [format %.1f $tumbleAt]"}]]
if {$csv ne {}} { close $csv }
