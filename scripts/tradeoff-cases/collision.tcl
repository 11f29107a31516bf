# scripts/tradeoff case: two equal discs (radius 1, density 1, kn = ks = 1e4,
# no friction, restitution set to -e) meet head-on at 1 each, with no fluid.
# The step is fixed at -dtfraction times the critical step 2 sqrt(m/k) (it
# stands for a fluid step the elements must follow); -substeps runs that many
# element steps in it. An impact's rebound depends on where in a step the
# contact begins, so the impact is run at 20 entry phases (the first step in
# contact begins at (k + 1/2)/20 of one step's closing travel): value is the
# mean restitution, error |mean / e - 1|, error2 the largest |e_k / e - 1|.
#
#   sandflow scripts/tradeoff-cases/collision.tcl ?-integrator central|euler|verlet?
#            ?-substeps n? ?-dtfraction f? ?-e e? ?-out FILE? ...
source [file join [file dirname [info script]] common.tcl]
set options [tradeoff::options {
    {integrator.arg central "element integrator: central, euler or verlet"}
    {substeps.arg   1       "element steps per (fluid) step"}
    {dtfraction.arg 0.5     "the step over the critical step 2 sqrt(m/k)"}
    {e.arg          0.5     "the restitution set on the material"}
}]
dict with options {}
set threads [sim cget -threads]
set rs {}
set total 0
tradeoff::start
set phases 20
for {set k 0} {$k < $phases} {incr k} {
    reset
    sim configure -threads $threads
    tradeoff::try material create m -density 1 -kn 1e4 -ks 1e4 -restitution ${-e} -friction 0
    set a [disc create -center {0 0} -radius 1 -material m -velocity {1 0 0}]
    set b [disc create -center {5 0} -radius 1 -material m -velocity {-1 0 0}]
    set crit [dict get [sim info] critical]
    set dt [expr {${-dtfraction} * $crit}]
    tradeoff::try sim configure -integrator ${-integrator} -timestep $dt -substeps ${-substeps}
    # The gap the discs close in the steps before contact: the first step in
    # contact ends at an overlap of (k + 1/2)/20 of one step's closing travel 2 dt.
    set gap [expr {(1.0 - ($k + 0.5) / $phases) * 2 * $dt}]
    element configure $b -center [list [expr {2 + $gap}] 0]
    tradeoff::run [expr {int(ceil(8.0 * $crit / $dt)) + 1}]
    incr total [dict get [sim info] step]
    set va [lindex [dict get [element info $a] velocity] 0]
    set vb [lindex [dict get [element info $b] velocity] 0]
    lappend rs [expr {($vb - $va) / 2.0}]
}
tradeoff::stop
set mean [expr {[tcl::mathop::+ {*}$rs] / double($phases)}]
set worst 0.0
foreach r $rs { set worst [expr {max($worst, abs($r / ${-e} - 1))}] }
tradeoff::finish ok [expr {abs($mean / ${-e} - 1)}] $worst $mean "restitution [format %.4f [tcl::mathfunc::min {*}$rs]] to [format %.4f [tcl::mathfunc::max {*}$rs]]"
