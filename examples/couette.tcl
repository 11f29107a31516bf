# Cylindrical Couette flow (thesis case B, §5.1): an inner cylinder of radius
# 0.1 at rest inside an outer one of radius 0.3 turning at 0.1 rad per unit
# time, started impulsively, in a 1 x 1 periodic lattice (nu = 4.166e-2,
# rho = 1). Both cylinders are circular walls of the lattice. At the end it
# compares the velocity and the torque on the inner cylinder with the exact
# steady solution u(r) = A r + B / r.
#
#   sandflow examples/couette.tcl ?-cells N? ?-tau tau? ?-time T? ?-omega1 w1?
#            ?-omega2 w2? ?-translate {vx vy}? ?-solidratio exact|1|2|4|8?

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {cells.arg      40     "lattice cells across the unit square"}
    {tau.arg        1.0    "relaxation time"}
    {time.arg       2.5    "how long to run"}
    {omega1.arg     0.0    "the inner cylinder's angular velocity"}
    {omega2.arg     0.1    "the outer cylinder's angular velocity"}
    {translate.arg  {0 0}  "velocity {vx vy} added to both cylinders"}
    {solidratio.arg exact  "solid ratio: exact, or 1, 2, 4, 8 subcells a side"}
}]
dict with options {}
set r1 0.1
set r2 0.3
set nu 4.166e-2
lassign ${-translate} vx vy

lattice create -size {1 1} -cells ${-cells} -viscosity $nu -tau ${-tau} -periodic {1 1}
sim configure -solidratio ${-solidratio}
set inner [lattice obstacle circle [list 0.5 0.5 $r1] -velocity [list $vx $vy ${-omega1}]]
set outer [lattice obstacle circle [list 0.5 0.5 $r2] -outside 1 -velocity [list $vx $vy ${-omega2}]]
set dt [dict get [lattice info] timestep]
set steps [expr {int(round(${-time} / $dt))}]
puts [format "%d x %d lattice, h = %g, dt = %g, tau %g: %d steps" ${-cells} ${-cells} \
    [expr {1.0 / ${-cells}}] $dt ${-tau} $steps]
run $steps -every [expr {max(1, $steps / 5)}] {
    puts [format "t %.3f  torque on the inner cylinder %.6e" [dict get [sim info] time] \
        [dict get [lattice obstacle info $inner] torque]]
}

# The exact steady solution, and the error over the fluid nodes between the walls.
set A [expr {(${-omega2} * $r2**2 - ${-omega1} * $r1**2) / ($r2**2 - $r1**2)}]
set B [expr {(${-omega1} - ${-omega2}) * $r1**2 * $r2**2 / ($r2**2 - $r1**2)}]
set torque [expr {4 * acos(-1) * $nu * (${-omega2} - ${-omega1}) * $r1**2 * $r2**2 / ($r2**2 - $r1**2)}]
lassign [lindex [dict get [lattice obstacle info $inner] circle]] cx cy
set err 0.0
set norm 0.0
set h [expr {1.0 / ${-cells}}]
for {set j 0} {$j < ${-cells}} {incr j} {
    for {set i 0} {$i < ${-cells}} {incr i} {
        set x [expr {($i + 0.5) * $h}]
        set y [expr {($j + 0.5) * $h}]
        set p [lattice probe [list $x $y]]
        if {[dict get $p solid] > 0} continue
        set dx [expr {$x - $cx - round($x - $cx)}]
        set dy [expr {$y - $cy - round($y - $cy)}]
        set r [expr {hypot($dx, $dy)}]
        if {$r <= $r1 || $r >= $r2} continue
        set u [expr {$A * $r + $B / $r}]
        lassign [dict get $p velocity] ux uy
        set ex [expr {$ux - ($vx - $u * $dy / $r)}]
        set ey [expr {$uy - ($vy + $u * $dx / $r)}]
        set err [expr {$err + $ex * $ex + $ey * $ey}]
        set norm [expr {$norm + $u * $u}]
    }
}
set T [dict get [lattice obstacle info $inner] torque]
puts [format "velocity L2 error %.3e; torque %.6e (exact %.6e, error %.3e)" \
    [expr {sqrt($err / $norm)}] $T $torque [expr {abs($T - $torque) / abs($torque)}]]
