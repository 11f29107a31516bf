# snapshot_bench.tcl -- time of one headless picture of a lattice scene.
#   sandflow snapshot_bench.tcl ?-offscreen osmesa|egl? ?-reps N? ?-cells N? ?-size {W H}?
# A cells x cells lattice with a few held discs after some steps of flow,
# pictured with the speed field and arrows; prints one line per case:
#   cells <N> size <WxH> offscreen <name> case <name> best_ms <t> mean_ms <t>
# The first picture of a process (font and context set-up) is timed apart.
set options [dict merge {-offscreen auto -reps 5 -cells 1024 -size {800 600}} $argv]
set reps [dict get $options -reps]
set n [dict get $options -cells]
view configure -offscreen [dict get $options -offscreen]
sim configure -threads 2
lattice create -size {1 1} -cells $n -viscosity 0.001 -periodic {1 0} -forcing {1e-4 0}
material create grain
foreach {x y} {0.25 0.5 0.5 0.3 0.75 0.6} {
    disc create -center [list $x $y] -radius 0.05 -material grain -fix {x y rot}
}
run 20
set file [file join [expr {[info exists env(TMPDIR)] ? $env(TMPDIR) : "/tmp"}] sandflow-bench-[pid].png]
set size [dict get $options -size]
set first [lindex [time {snapshot $file -size $size}] 0]
puts [format "cells %d size %s offscreen %s case first best_ms %.1f mean_ms %.1f" \
    $n [join $size x] [view cget -offscreen] [expr {$first / 1e3}] [expr {$first / 1e3}]]
foreach {case args} {
    speed {-field velocity}
    speed+arrows {-field velocity -vectors 1}
    vorticity+streamlines {-field vorticity -streamlines 1}
    no-field {-field none}
} {
    set times {}
    for {set k 0} {$k < $reps} {incr k} {
        lappend times [lindex [time {snapshot $file -size $size {*}$args}] 0]
    }
    set best [tcl::mathfunc::min {*}$times]
    set mean [expr "([join $times +]) / double([llength $times])"]
    puts [format "cells %d size %s offscreen %s case %s best_ms %.1f mean_ms %.1f" \
        $n [join $size x] [view cget -offscreen] $case [expr {$best / 1e3}] [expr {$mean / 1e3}]]
}
file delete $file
