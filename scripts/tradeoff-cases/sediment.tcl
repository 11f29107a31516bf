# scripts/tradeoff case: a disc settling on the centreline of a channel 1.5 d
# wide (docs/validation.md case D; examples/sediment-disc.tcl), d = 1, fluid
# density 1, nu = 0.02, tau 0.8. The disc is driven by a constant applied
# force equal to case D's submerged weight, (ratio - 1) g A with g = 1.2 and
# ratio 2 (A = pi d^2/4), with no gravity: the steady settling speed is then
# the same at every density ratio (drag = that force), and -ratio changes
# only the disc's inertia, which is what the coupling's stability depends on.
# It starts at rest 2.5 d below the top of a channel 12 d tall and falls 6 d;
# the settling speed U is 1 d over the time the last diameter of the fall
# took (Re = U d / nu about 6.4). value: U; the error is left to
# scripts/tradeoff's summary (against the finest run). error2: the RMS
# fluctuation of the vertical fluid force over the last diameter, relative to
# the driving force (the solid ratio's noise). -forcecsv writes t, fluid
# force and velocity every step of the last diameter.
#
#   sandflow scripts/tradeoff-cases/sediment.tcl ?-cpd N? ?-ratio r?
#            ?-coupling explicit|implicit? ?-integrator central|euler|verlet?
#            ?-substeps n? ?-solidratio exact|1|2|4|8? ?-interior equilibrium|collide?
#            ?-tau tau? ?-collision bgk|trt?
#            ?-forcescheme nodal|guo? ?-fall D? ?-forcecsv FILE? ...
source [file join [file dirname [info script]] common.tcl]
set options [tradeoff::options {
    {cpd.arg        16       "lattice cells per disc diameter"}
    {ratio.arg      2.0      "the disc's density over the fluid's"}
    {coupling.arg   explicit "fluid coupling: explicit or implicit"}
    {integrator.arg central  "element integrator: central, euler or verlet"}
    {substeps.arg   1        "element steps per fluid step"}
    {solidratio.arg exact    "solid ratio: exact, or 1, 2, 4, 8 subcells a side"}
    {interior.arg   equilibrium "cells deep inside the disc: equilibrium or collide"}
    {tau.arg        0.8      "relaxation time"}
    {collision.arg  bgk      "collision: bgk or trt"}
    {forcescheme.arg nodal   "forcing: nodal or guo"}
    {fall.arg       6        "how far it falls, in diameters"}
    {forcecsv.arg   {}       "CSV of the fluid force over the last diameter"}
}]
dict with options {}
set d 1.0; set L 1.5; set H 12.0; set nu 0.02
set W [expr {1.2 * acos(-1) / 4}]      ;# case D's submerged weight, (2 - 1) 1.2 pi/4
set h [expr {$d / ${-cpd}}]
set cells [expr {int(round($L / $h))}]

tradeoff::start
tradeoff::try lattice create -size [list $L $H] -cells $cells -viscosity $nu -tau ${-tau} \
    -walls {left noslip right noslip bottom noslip top noslip} -periodic {0 0} \
    -collision ${-collision} -forcescheme ${-forcescheme}
tradeoff::try sim configure -integrator ${-integrator} -coupling ${-coupling} \
    -solidratio ${-solidratio} -interior ${-interior}
set dt [dict get [lattice info] timestep]
# Contacts (only at a wall) soft enough that the critical step is five fluid steps.
set k [expr {${-ratio} * acos(-1) * 0.25 * $d * $d * 4 / (25 * $dt * $dt)}]
material create grain -density ${-ratio} -kn $k -ks $k -friction 0.1
foreach {from to} [list {0 0} [list 0 $H] [list $L 0] [list $L $H]] {
    wall create -from $from -to $to -material grain
}
set y0 [expr {$H - 2.5 * $d}]
set disc [disc create -center [list [expr {$L / 2}] $y0] -radius [expr {$d / 2}] -material grain \
              -force [list 0 [expr {-$W}] 0]]
tradeoff::try sim configure -substeps ${-substeps}

# Sample every step of about 1/100 d of fall at U = 0.13; the crossing times
# of y0 - fall + 1 and y0 - fall by linear interpolation.
set every [expr {max(1, int(round(0.01 / (0.13 * $dt))))}]
set ya [expr {$y0 - ${-fall} + 1}]
set yb [expr {$y0 - ${-fall}}]
set tmax [expr {3.0 * ${-fall} / 0.13}]
set ta {}; set tb {}
set last [list 0.0 $y0]
set forces {}
set fcsv {}
proc sample {} {
    global disc last ta tb ya yb forces fcsv
    set t [dict get [sim info] time]
    set e [element info $disc]
    set y [lindex [dict get $e position] 1]
    lassign $last t1 y1
    if {$ta eq {} && $y <= $ya} { set ta [expr {$t1 + ($t - $t1) * ($y1 - $ya) / ($y1 - $y)}] }
    if {$tb eq {} && $y <= $yb} { set tb [expr {$t1 + ($t - $t1) * ($y1 - $yb) / ($y1 - $y)}] }
    if {$ta ne {} && $tb eq {}} {
        set fy [lindex [dict get $e fluidforce] 1]
        lappend forces $fy
        if {$fcsv ne {}} {
            puts $fcsv [join [list $t $y $fy [lindex [dict get $e velocity] 1]] ,]
        }
    }
    set last [list $t $y]
}
while {$tb eq {}} {
    if {[dict get [sim info] time] > $tmax} {
        tradeoff::finish error {} {} {} "no fall of ${-fall} d by t = $tmax"
    }
    # In the last diameter, every step (the force's noise).
    if {$ta ne {}} {
        if {$fcsv eq {} && ${-forcecsv} ne {}} {
            set fcsv [open ${-forcecsv} w]
            puts $fcsv "t,y,fluidfy,vy"
        }
        tradeoff::run 1
    } else {
        tradeoff::run $every
    }
    sample
}
tradeoff::stop
if {$fcsv ne {}} { close $fcsv }
set U [expr {$d / ($tb - $ta)}]
set n [llength $forces]
set mean [expr {[tcl::mathop::+ {*}$forces] / $n}]
set var 0.0
foreach f $forces { set var [expr {$var + ($f - $mean) ** 2}] }
tradeoff::finish ok {} [expr {sqrt($var / $n) / $W}] $U "Re [format %.3f [expr {$U * $d / $nu}]]"
