# Channel flow around a fixed disc (thesis case A, §4.2.2, the GUI example):
# a lattice over [0,2] x [0,1], 200 cells across x, a fixed disc of radius
# 0.051 at (0.5, 0.5), viscosity 0.001, forcing 0.0025 in x, timestep 0.005;
# periodic in x, no-slip top and bottom. Prints the drag and lift on the disc
# and the Reynolds number as the flow accelerates; with -out writes ParaView
# files at the end.
#
#   sandflow examples/channel-disc.tcl ?-cells N? ?-steps N? ?-every K? ?-nu nu?
#            ?-forcing F? ?-timestep dt|auto? ?-out DIR?
#
# -timestep auto lets tau = 1 set the timestep (for refinement studies).

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {cells.arg    200     "lattice cells across x"}
    {steps.arg    10000   "steps to run"}
    {every.arg    1000    "steps between printed lines"}
    {nu.arg       0.001   "kinematic viscosity"}
    {forcing.arg  0.0025  "forcing in x"}
    {timestep.arg 0.005   "timestep, or auto: tau = 1 sets it (for refinement studies)"}
    {out.arg      {}      "folder for ParaView files at the end"}
}]
dict with options {}

if {${-timestep} ne "auto"} { sim configure -timestep ${-timestep} }
lattice create -size {2 1} -cells ${-cells} -viscosity ${-nu} -forcing [list ${-forcing} 0]
set r 0.051
set disc [disc create -center {0.5 0.5} -radius $r -fix {x y rot}]
set info [lattice info]
puts [format "lattice %d x %d, h = %g, dt = %g, tau %.4g; disc %.1f cells across" \
    [dict get $info nx] [dict get $info ny] [dict get $info spacing] [dict get $info timestep] \
    [dict get $info tau] [expr {2 * $r / [dict get $info spacing]}]]
run ${-steps} -every ${-every} {
    set f [dict get [element info $disc] fluidforce]
    set u [lindex [dict get [lattice probe {1.5 0.5}] velocity] 0]
    puts [format "t %8.2f  drag %.6e  lift %+.3e  u(1.5, 0.5) %.4f  Re %.1f  Mach %.3f" \
        [dict get [sim info] time] [lindex $f 0] [lindex $f 1] $u \
        [expr {$u * 2 * $r / ${-nu}}] [dict get [sim info] mach]]
}
if {${-out} ne {}} {
    file mkdir ${-out}
    output vtk [file join ${-out} channel-disc]
    puts "wrote [file join ${-out} channel-disc].vti and .vtp"
}
