# The DEM bed of shared/reference/dem-bed.md through the command language:
# N discs, radii uniform in [0.5, 1] mm (Tcl's rand, seeded: not the very bed
# of dem_bed.cpp, the same kind), settled under gravity in a box open at the
# top (on the first thread count: two threads crawl when another process
# takes a core), kept in a checkpoint, then `run 2000` timed from it at each thread
# count in turn, repetitions alternating the counts (both meet the same
# machine). Prints particle-steps per second, best and worst, per count.
#
#   sandflow scripts/benchmarks/dem_bed_run.tcl ?N? ?settle? ?reps? ?threads? ?checkpoint?
#
# A checkpoint file that exists is loaded instead of settling again.
set n [lindex $argv 0]; if {$n eq ""} { set n 10000 }
set settle [expr {[llength $argv] > 1 ? [lindex $argv 1] : 100000}]
set reps [expr {[llength $argv] > 2 ? [lindex $argv 2] : 3}]
set threads [expr {[llength $argv] > 3 ? [lindex $argv 3] : {1 2}}]
set chk [expr {[llength $argv] > 4 ? [lindex $argv 4] : "/tmp/sandflow-dem-bed-run.chk"}]

if {[file exists $chk]} {
    checkpoint load $chk
} else {
    expr {srand(12345)}
    material create glass -density 2650 -kn 1e5 -ks 1e5 -restitution 0.5 -friction 0.5
    set pitch 2.05e-3
    set cols [expr {($n + 127) / 128}]
    set rows [expr {($n + $cols - 1) / $cols}]
    set W [expr {($cols + 0.25) * $pitch}]
    set H [expr {1.05e-3 + $rows * $pitch + 0.01}]
    wall create -from {0 0} -to [list $W 0] -material glass -thickness 1e-3
    wall create -from {0 0} -to [list 0 $H] -material glass -thickness 1e-3
    wall create -from [list $W 0] -to [list $W $H] -material glass -thickness 1e-3
    for {set i 0} {$i < $n} {incr i} {
        set row [expr {$i / $cols}]
        set x [expr {($i % $cols + 0.5 + 0.25 * ($row % 2)) * $pitch + (rand() - 0.5) * 0.04e-3}]
        set y [expr {1.05e-3 + $row * $pitch}]
        disc create -center [list $x $y] -radius [expr {0.5e-3 + 0.5e-3 * rand()}] -material glass
    }
    set mMin [expr {2650 * acos(-1) * 0.25e-6}]
    sim configure -timestep [expr {2 * sqrt($mMin / 1e5) / 20}] -gravity {0 -9.81} \
        -maxoverlap 1.0 -threads [lindex $threads 0]
    set t0 [clock milliseconds]
    run $settle
    puts [format "settled %d steps in %.1f s" $settle [expr {([clock milliseconds] - $t0) / 1e3}]]
    checkpoint save $chk
}

foreach t $threads { set best($t) 1e300; set worst($t) 0 }
for {set r 0} {$r < $reps} {incr r} {
    foreach t $threads {
        checkpoint load $chk
        sim configure -threads $t
        set t0 [clock microseconds]
        run 2000
        set s [expr {([clock microseconds] - $t0) / 1e6}]
        set best($t) [expr {min($best($t), $s)}]
        set worst($t) [expr {max($worst($t), $s)}]
    }
}
foreach t $threads {
    puts [format "run N=%d threads=%d psps=%.4g psps_min=%.4g" $n $t \
              [expr {$n * 2000 / $best($t)}] [expr {$n * 2000 / $worst($t)}]]
}
