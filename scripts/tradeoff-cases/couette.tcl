# scripts/tradeoff case: cylindrical Couette flow (docs/validation.md case B;
# tests/validation/couette_case.hpp): inner cylinder r1 = 0.1 at rest, outer
# r2 = 0.3 turning at 0.1, nu = 4.166e-2, a 1 x 1 periodic lattice, both
# cylinders circular walls of the lattice. After -time (1.5: 16 decay times
# of the slowest mode, the error within 1e-6 of its steady value) the error
# is the relative L2 velocity error over the fluid nodes between the walls
# against u(r) = A r + B / r; error2 the torque's relative error. The inner
# cylinder is 0.2 across: cells per diameter = 0.2 x cells.
#
#   sandflow scripts/tradeoff-cases/couette.tcl ?-cells N? ?-tau tau? ?-time T?
#            ?-collision bgk|trt? ?-magic L? ?-solidratio exact|1|2|4|8? ?-out FILE? ...
source [file join [file dirname [info script]] common.tcl]
set options [tradeoff::options {
    {cells.arg      40    "lattice cells across the unit square"}
    {tau.arg        1.0   "relaxation time (the viscosity is fixed: the timestep follows)"}
    {time.arg       1.5   "how long to run"}
    {collision.arg  bgk   "collision: bgk or trt"}
    {magic.arg      0.1875 "TRT's magic parameter Lambda"}
    {solidratio.arg exact "solid ratio: exact, or 1, 2, 4, 8 subcells a side"}
}]
dict with options {}
set r1 0.1; set r2 0.3; set w2 0.1; set nu 4.166e-2

tradeoff::start
tradeoff::try lattice create -size {1 1} -cells ${-cells} -viscosity $nu -tau ${-tau} -periodic {1 1} \
    -collision ${-collision} -magic ${-magic}
tradeoff::try sim configure -solidratio ${-solidratio}
set inner [lattice obstacle circle [list 0.5 0.5 $r1]]
lattice obstacle circle [list 0.5 0.5 $r2] -outside 1 -velocity [list 0 0 $w2]
set steps [expr {int(round(${-time} / [dict get [lattice info] timestep]))}]
tradeoff::run $steps
tradeoff::stop

set A [expr {$w2 * $r2**2 / ($r2**2 - $r1**2)}]
set B [expr {-$w2 * $r1**2 * $r2**2 / ($r2**2 - $r1**2)}]
set exact [expr {4 * acos(-1) * $nu * $w2 * $r1**2 * $r2**2 / ($r2**2 - $r1**2)}]
set err 0.0; set norm 0.0
set h [expr {1.0 / ${-cells}}]
for {set j 0} {$j < ${-cells}} {incr j} {
    for {set i 0} {$i < ${-cells}} {incr i} {
        set x [expr {($i + 0.5) * $h - 0.5}]
        set y [expr {($j + 0.5) * $h - 0.5}]
        set r [expr {hypot($x, $y)}]
        if {$r <= $r1 || $r >= $r2} continue
        set p [lattice probe [list [expr {$x + 0.5}] [expr {$y + 0.5}]]]
        if {[dict get $p solid] > 0} continue
        set u [expr {$A * $r + $B / $r}]
        lassign [dict get $p velocity] ux uy
        set err [expr {$err + ($ux + $u * $y / $r) ** 2 + ($uy - $u * $x / $r) ** 2}]
        set norm [expr {$norm + $u * $u}]
    }
}
set T [dict get [lattice obstacle info $inner] torque]
tradeoff::finish ok [expr {sqrt($err / $norm)}] [expr {abs($T - $exact) / $exact}] $T
