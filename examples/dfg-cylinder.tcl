# The DFG benchmark "flow around a cylinder" of Schaefer & Turek (1996), cases
# 2D-1 (steady, Re 20) and 2D-2 (periodic, Re 100): a channel 2.2 x 0.41, a
# cylinder of diameter 0.1 centred at (0.2, 0.2), nu = 0.001, rho = 1, a
# parabolic inflow on the left, an outflow side on the right, no-slip walls.
# The cylinder is a lattice circle obstacle (Noble-Torczynski cells); its
# force gives c_D and c_L, probes give the pressure difference between its
# front and back points, the lift's period the Strouhal number. Prints a
# progress line now and then and, last, one summary line (scripts/validate
# reads it).
#
#   sandflow examples/dfg-cylinder.tcl ?-case 1|2? ?-cells D? ?-collision bgk|trt?
#            ?-solidratio exact|1|2|4|8? ?-ulattice U? ?-time T? ?-tolerance TOL?
#            ?-outlet outflow|pressure? ?-threads N?

set options [::sf::scriptOptions {
    {case.arg       1     "1: 2D-1, steady, U_max 0.3 (Re 20); 2: 2D-2, periodic, U_max 1.5 (Re 100)"}
    {cells.arg      20    "cells across the cylinder's diameter D"}
    {collision.arg  trt   "bgk or trt"}
    {solidratio.arg exact "the circle's solid ratio: exact, or N x N subcells"}
    {ulattice.arg   0.1   "U_max in lattice units (h / dt): the Mach number's knob"}
    {time.arg       0     "end time (0: 2D-1 30 s or steady, 2D-2 10 s)"}
    {tolerance.arg  1e-6  "2D-1: steady when c_D moves less than this in 0.5 s (0: run to -time)"}
    {outlet.arg     outflow "the right side: outflow, or pressure (Zou-He, the reference pressure)"}
    {threads.arg    1     "threads"}
}]
dict with options {}

set case ${-case}
if {$case ni {1 2}} { error "-case must be 1 or 2, got \"$case\"" }
set D 0.1
set Umax [expr {$case == 1 ? 0.3 : 1.5}]
set Umean [expr {2.0 / 3.0 * $Umax}]
set nu 0.001
set h [expr {$D / ${-cells}}]
# U_max is ${-ulattice} lattice units: dt = u h / U_max, and tau follows from nu.
set dt [expr {${-ulattice} * $h / $Umax}]
set tau [expr {0.5 + 3.0 * $nu * $dt / ($h * $h)}]
set endTime [expr {${-time} > 0 ? ${-time} : ($case == 1 ? 30.0 : 10.0)}]

sim configure -threads ${-threads} -solidratio ${-solidratio}
# 2D-1 is steady: the inflow rises over 1 s (no start-up shock); 2D-2 starts
# at once, as the benchmark does.
set inflow [list velocity [list $Umax 0] -profile parabolic]
if {$case == 1} { lappend inflow -ramp 1.0 }
lattice create -origin {0 0} -size {2.2 0.41} -spacing $h -viscosity $nu -tau $tau \
    -collision ${-collision} -walls [list left $inflow right outflow bottom noslip top noslip]
if {${-outlet} eq "pressure"} {
    lattice configure -walls [list right [list pressure [expr {[dict get [lattice info] cs] ** 2}]]]
}
set cylinder [lattice obstacle circle {0.2 0.2 0.05}]
set info [lattice info]
puts [format "DFG 2D-%d: D = %d cells, %d x %d, tau %.4f, dt %.4g, %s, solid ratio %s" \
    $case ${-cells} [dict get $info nx] [dict get $info ny] $tau $dt ${-collision} ${-solidratio}]

proc coefficients {} {
    global cylinder Umean D
    lassign [dict get [lattice obstacle info $cylinder] force] fx fy
    set q [expr {0.5 * $Umean * $Umean * $D}]
    list [expr {$fx / $q}] [expr {$fy / $q}]
}

# Pressure at a point of the cylinder's surface on y = 0.2, from the fluid
# outside it: along x from the point in direction `dir` (-1 front, +1 back),
# the first two node columns the solid does not cover, each interpolated
# linearly in y, extrapolated linearly back to the point.
proc surfacePressure {x dir} {
    global h
    set y 0.2
    set j0 [expr {int(floor($y / $h - 0.5))}]
    set y0 [expr {($j0 + 0.5) * $h}]
    set wy [expr {($y - $y0) / $h}]
    set i [expr {int(floor($x / $h))}]
    set columns {}
    while {[llength $columns] < 4} {
        set xc [expr {($i + 0.5) * $h}]
        set below [lattice probe [list $xc $y0]]
        set above [lattice probe [list $xc [expr {$y0 + $h}]]]
        if {[dict get $below solid] == 0 && [dict get $above solid] == 0 &&
            ($dir < 0 ? $xc < $x : $xc > $x)} {
            lappend columns $xc [expr {(1 - $wy) * [dict get $below pressure] +
                                       $wy * [dict get $above pressure]}]
        }
        incr i $dir
    }
    lassign $columns xa pa xb pb
    expr {$pa + ($pa - $pb) * ($x - $xa) / ($xa - $xb)}
}

proc pressureDifference {} {
    expr {[surfacePressure 0.15 -1] - [surfacePressure 0.25 1]}
}

set started [clock milliseconds]
set stepsPerHalf [expr {max(1, int(round(0.5 / $dt)))}]
set endSteps [expr {int(round($endTime / $dt))}]
if {$case == 1} {
    # Steady: stop once c_D moves less than -tolerance over 0.5 s, after the ramp.
    set last {}
    set steps 0
    while {$steps < $endSteps} {
        run $stepsPerHalf
        incr steps $stepsPerHalf
        lassign [coefficients] cD cL
        set t [dict get [sim info] time]
        puts [format "t %6.2f  c_D %.6f  c_L %.6f  dp %.6f" $t $cD $cL [pressureDifference]]
        if {$last ne {} && $t > 2.0 && ${-tolerance} > 0 &&
            abs($cD - $last) < ${-tolerance}} break
        set last $cD
    }
    set seconds [expr {([clock milliseconds] - $started) / 1000.0}]
    lassign [coefficients] cD cL
    set dp [pressureDifference]
    set t [dict get [sim info] time]
    set steps [dict get [sim info] step]
    set mlups [expr {$steps * double([dict get $info nodes]) / $seconds / 1e6}]
    puts [format "summary case 1 D %d collision %s solidratio %s cD %.6f cL %.6f dp %.6f St - t %.3f steps %d seconds %.1f mlups %.1f" \
        ${-cells} ${-collision} ${-solidratio} $cD $cL $dp $t $steps $seconds $mlups]
} else {
    # Periodic: run to the end, the last 3 s (about 9 periods) sampled every step.
    set window [expr {min(3.0, $endTime / 2)}]
    set quiet [expr {$endSteps - int(round($window / $dt))}]
    set every [expr {max(1, int(round(0.5 / $dt)))}]
    for {set done 0} {$done < $quiet} {incr done $n} {
        set n [expr {min($every, $quiet - $done)}]
        run $n
        lassign [coefficients] cD cL
        puts [format "t %6.2f  c_D %.5f  c_L %+.5f" [dict get [sim info] time] $cD $cL]
    }
    set cDmax -Inf
    set cLmax -Inf
    set crossings {}
    set previous {}
    run [expr {$endSteps - $quiet}] -every 1 {
        lassign [coefficients] cD cL
        set t [dict get [sim info] time]
        set cDmax [expr {max($cDmax, $cD)}]
        set cLmax [expr {max($cLmax, $cL)}]
        if {$previous ne {}} {
            lassign $previous t0 cL0
            if {$cL0 < 0 && $cL >= 0} {  # an upward zero crossing, interpolated
                lappend crossings [expr {$t0 + ($t - $t0) * (-$cL0) / ($cL - $cL0)}]
            }
        }
        set previous [list $t $cL]
    }
    set seconds [expr {([clock milliseconds] - $started) / 1000.0}]
    set St nan
    if {[llength $crossings] >= 2} {
        set period [expr {([lindex $crossings end] - [lindex $crossings 0]) /
                          ([llength $crossings] - 1)}]
        set St [expr {$D / ($period * $Umean)}]
    }
    set dp [pressureDifference]
    set t [dict get [sim info] time]
    set steps [dict get [sim info] step]
    set mlups [expr {$steps * double([dict get $info nodes]) / $seconds / 1e6}]
    puts [format "summary case 2 D %d collision %s solidratio %s cD %.6f cL %.6f dp %.6f St %s t %.3f steps %d seconds %.1f mlups %.1f periods %d" \
        ${-cells} ${-collision} ${-solidratio} $cDmax $cLmax $dp \
        [expr {$St eq "nan" ? "nan" : [format %.5f $St]}] $t $steps $seconds $mlups \
        [expr {max(0, [llength $crossings] - 1)}]]
}
