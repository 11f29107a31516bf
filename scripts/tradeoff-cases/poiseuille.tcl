# scripts/tradeoff case: plane Poiseuille flow, a channel of height 1 between
# no-slip walls (halfway bounce-back), periodic along x, driven by a body
# force F for a centreline speed of 0.05 (nu = 0.05, so F = 8 nu 0.05 / H^2):
# started from rest and run -time H^2/nu (2: the slowest mode decayed to 3e-9).
# The error: the relative L2 error of u_x over the nodes of one column against
# the exact parabola u = F/(2 nu) y (1 - y).
#
#   sandflow scripts/tradeoff-cases/poiseuille.tcl ?-cells N? ?-tau tau?
#            ?-collision bgk|trt? ?-forcescheme nodal|guo? ?-magic L? ?-time T?
#            ?-out FILE? ...
source [file join [file dirname [info script]] common.tcl]
set options [tradeoff::options {
    {cells.arg       16     "cells across the channel"}
    {tau.arg         0.8    "relaxation time (the viscosity is fixed: the timestep follows)"}
    {collision.arg   bgk    "collision: bgk or trt"}
    {forcescheme.arg nodal  "forcing: nodal or guo"}
    {magic.arg       0.1875 "TRT's magic parameter Lambda (3/16: walls exact for this flow)"}
    {time.arg        2      "how long to run, in diffusive times H^2 / nu"}
}]
dict with options {}
set nu 0.05; set H 1.0
set F [expr {8 * $nu * 0.05 / ($H * $H)}]
set h [expr {$H / ${-cells}}]

tradeoff::start
tradeoff::try lattice create -size [list [expr {4 * $h}] $H] -cells 4 -viscosity $nu -tau ${-tau} \
    -forcing [list $F 0] -collision ${-collision} -forcescheme ${-forcescheme} -magic ${-magic}
set steps [expr {int(round(${-time} * $H * $H / $nu / [dict get [lattice info] timestep]))}]
tradeoff::run $steps
tradeoff::stop

set num 0.0; set den 0.0
for {set j 0} {$j < ${-cells}} {incr j} {
    set y [expr {($j + 0.5) * $h}]
    set u [lindex [dict get [lattice probe [list [expr {2.5 * $h}] $y]] velocity] 0]
    set ue [expr {$F / (2 * $nu) * $y * ($H - $y)}]
    set num [expr {$num + ($u - $ue) ** 2}]
    set den [expr {$den + $ue ** 2}]
}
set uc [lindex [dict get [lattice probe [list [expr {2.5 * $h}] [expr {0.5 * $H}]]] velocity] 0]
tradeoff::finish ok [expr {sqrt($num / $den)}] {} $uc
