# The dense coupled scene of issue 36 through the command language (the
# scene of coupled_bench.cpp's --dense, after Yade's 2D coupling example): a
# closed 250 x 180 box of fluid (h = dt = 1), 70 discs 8 to 12 cells in radius
# covering about half the cells, settling under gravity. Each round times
# `run steps` on the bare lattice, then on the coupled scene (after 200 steps
# of settling), so that any sandflow binary, old or new, runs the same scene:
#
#   sandflow scripts/benchmarks/dense_scene.tcl ?threads? ?steps? ?reps?
#
# Prints the best MLUPS of each and the median of the rounds' ratios.
set threads [expr {[llength $argv] > 0 ? [lindex $argv 0] : 1}]
set steps [expr {[llength $argv] > 1 ? [lindex $argv 1] : 1000}]
set reps [expr {[llength $argv] > 2 ? [lindex $argv 2] : 3}]

proc scene {discs} {
    reset
    sim configure -threads $::threads
    lattice create -size {250 180} -cells 250 -tau 0.8 -viscosity 0.1 \
        -walls {left noslip right noslip bottom noslip top noslip}
    if {!$discs} return
    material create grain -density 3 -kn 20 -ks 20 -friction 0.3
    sim configure -gravity {0 -2e-5}
    expr {srand(7)}
    set pitchY [expr {180.0 / 7}]
    for {set k 0} {$k < 70} {incr k} {
        set r [expr {8 + 4 * rand()}]
        set room [expr {max(0.0, 0.5 * $pitchY - $r - 0.5)}]
        set x [expr {($k % 10 + 0.5) * 25 + $room * (2 * rand() - 1)}]
        set y [expr {($k / 10 + 0.5) * $pitchY + $room * (2 * rand() - 1)}]
        disc create -center [list $x $y] -radius $r -material grain
    }
    run 200
}

proc timed {} {
    set t0 [clock microseconds]
    run $::steps
    expr {250 * 180 * double($::steps) / ([clock microseconds] - $t0)}
}

set best(bare) 0
set best(coupled) 0
set ratios {}
for {set r 0} {$r < $reps} {incr r} {
    scene 0
    set bare [timed]
    scene 1
    set coupled [timed]
    foreach k {bare coupled} { set best($k) [expr {max($best($k), [set $k])}] }
    lappend ratios [expr {$coupled / $bare}]
    puts [format "round %d: bare %.1f MLUPS, coupled %.1f MLUPS (%.3f), covered %d" $r $bare \
              $coupled [expr {$coupled / $bare}] [dict get [sim info] covered]]
}
set ratios [lsort -real $ratios]
puts [format "dense scene, %d thread(s), %d steps: bare %.1f MLUPS, coupled %.1f MLUPS (best); \
median ratio %.3f" $threads $steps $best(bare) $best(coupled) \
          [lindex $ratios [expr {[llength $ratios] / 2}]]]
