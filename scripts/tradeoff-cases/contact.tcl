# scripts/tradeoff case: an ellipse (semi-axes 1 and 0.5, density 1, kn = 1e4,
# linear law) pressed into a wall by an overlap of 0.01 at seven angles
# (0 to 90 degrees, and 37), each drawn as an N-sided polygon (ellipse
# create -sides N) or as a superquadric with exponents 2 2 sampled at N
# points (superquadric create -sides N: sandflow has no other sample-count
# option). The contact force after one step against the exact ellipse's under
# the same law: a polygon's wall contact pushes with kn x (area behind the
# wall) / (chord), so its exact value is that of the ellipse's segment; a
# superquadric's pushes with kn x (its deepest sample's depth), exact: kn x
# 0.01. error: the RMS relative error over the angles, error2 the largest.
# The wall time is that of 2000 steps of the pressed contact at each angle
# (a step of 1e-6: the ellipse barely moves), the cost of the contact.
#
#   sandflow scripts/tradeoff-cases/contact.tcl ?-shape polygon|superquadric?
#            ?-sides N? ?-out FILE? ...
source [file join [file dirname [info script]] common.tcl]
set options [tradeoff::options {
    {shape.arg polygon "polygon (ellipse create) or superquadric"}
    {sides.arg 32      "the polygon's sides, or the superquadric's samples"}
}]
dict with options {}
set a 1.0; set b 0.5; set delta 0.01; set kn 1e4
set threads [sim cget -threads]
set pi [expr {acos(-1)}]
set errs {}
set steps 2000
set wall 0.0
set cpu0 [tradeoff::cpuNow]
foreach deg {0 15 30 37 45 60 75 90} {
    reset
    sim configure -threads $threads
    set th [expr {$deg * $pi / 180}]
    # The lowest point of the ellipse turned by th lies R below its centre.
    set A [expr {$a * sin($th)}]; set B [expr {$b * cos($th)}]
    set R [expr {hypot($A, $B)}]
    set yc [expr {$R - $delta}]
    material create m -density 1 -kn $kn -ks $kn -friction 0 -restitution 0.5
    wall create -from {-5 0} -to {5 0} -material m
    if {${-shape} eq "polygon"} {
        set e [tradeoff::try ellipse create -center [list 0 $yc] -axes [list $a $b] -angle $th \
                   -sides ${-sides} -material m]
        # The segment of the exact ellipse below y = 0: the image of a circular
        # segment of the unit disc at distance yc / R, of half-angle al.
        set al [expr {acos($yc / $R)}]
        set area [expr {$a * $b * ($al - sin($al) * cos($al))}]
        set phi [expr {atan2($B, $A)}]
        set pts {}
        foreach t [list [expr {$phi + $pi - $al}] [expr {$phi + $pi + $al}]] {
            lappend pts [expr {$a * cos($t) * cos($th) - $b * sin($t) * sin($th)}]
        }
        set chord [expr {abs([lindex $pts 1] - [lindex $pts 0])}]
        set exact [expr {$kn * $area / $chord}]
    } else {
        set e [tradeoff::try superquadric create -center [list 0 $yc] -axes [list $a $b] -angle $th \
                   -exponents {2 2} -sides ${-sides} -material m]
        set exact [expr {$kn * $delta}]
    }
    sim configure -timestep 1e-6
    set t0 [clock microseconds]
    tradeoff::run 1
    set f [lindex [dict get [element info $e] contactforce] 1]
    tradeoff::run [expr {$steps - 1}]
    set wall [expr {$wall + ([clock microseconds] - $t0) * 1e-6}]
    lappend errs [expr {($f - $exact) / $exact}]
}
set tradeoff::wall $wall
set tradeoff::cpu [format %.2f [expr {[tradeoff::cpuNow] - $cpu0}]]
set sq 0.0; set worst 0.0
foreach x $errs { set sq [expr {$sq + $x * $x}]; set worst [expr {max($worst, abs($x))}] }
tradeoff::finish ok [expr {sqrt($sq / [llength $errs])}] $worst {} \
    "errors by angle [lmap x $errs {format %.3g $x}]"
