# gui_bench.tcl -- what the workbench's live view costs a run, how often it
# draws, and how soon Pause stops a run. Runs inside the workbench:
#   sandflow -gui scripts/benchmarks/gui_bench.tcl ?-cells N? ?-steps K? ?-reps R? ?-minfps M?
# A cells^2 lattice (default 1024) with moving discs covering about 10% of
# its cells. First one frame alone (build and draw, median of 9) and the
# status bar's figures (`sim info`, which scans the lattice, and the tick's
# ::sf::gui::statusinfo); then runs of K steps alternate without the view's
# tick (bare) and with it at the default frame rate. Prints one line per run,
# then the verdict:
#   frame_ms F sim_info_ms S statusinfo_ms T
#   run bare|view steps K ms_per_step T frames F fps P
#   overhead <%> (target <= 10%) fps <median> (lowest <L>, target >= M)  pause_ms <median> (max <X>) frame_ms <period> ...
set options [dict merge {-cells 1024 -steps 400 -reps 3 -minfps 5} $argv]
set n [dict get $options -cells]
set steps [dict get $options -steps]
set reps [dict get $options -reps]
set minfps [dict get $options -minfps]
# An error ends the program (the workbench would otherwise keep its window).
proc bgerror {message} { puts stderr $message; exit 1 }
if {[catch {

lattice create -size {1 1} -cells $n -viscosity 0.0005 -periodic {1 0} -forcing {2e-4 0}
# Soft enough for the fluid's timestep (2 sqrt(m/k) above it).
material create grain -density 2 -kn 100 -ks 100
# Discs 16 cells across on a grid, moving: about 10% of the cells covered at 1024^2.
set r [expr {min(8.0 / $n, 0.4 / 22)}]
expr {srand(7)}
set count 0
for {set i 0} {$i < 22} {incr i} {
    for {set j 0} {$j < 22} {incr j} {
        set x [expr {($i + 0.5) / 22.0}]
        set y [expr {0.04 + ($j + 0.5) / 22.0 * 0.92}]
        disc create -center [list $x $y] -radius $r -material grain \
            -velocity [list [expr {0.002 * (rand() - 0.5)}] [expr {0.002 * (rand() - 0.5)}] 0]
        incr count
    }
}
run 10
set covered [dict get [sim info] covered]
puts [format "scene %d^2 lattice, %d discs, %d covered cells (%.1f%%), %d threads, view %s" \
    $n $count $covered [expr {100.0 * $covered / ($n * $n)}] [sim cget -threads] \
    [::sf::gui::view::describe]]

# One frame alone, and the status bar's figures, each the median of 9.
proc medianOf {script} {
    set times {}
    for {set k 0} {$k < 9} {incr k} {
        set t0 [clock microseconds]
        uplevel #0 $script
        lappend times [expr {([clock microseconds] - $t0) / 1000.0}]
    }
    lindex [lsort -real $times] 4
}
update
puts [format "frame_ms %.1f sim_info_ms %.1f statusinfo_ms %.2f  (view %dx%d, load %s)" \
    [medianOf {::sf::gui::view::draw 0}] [medianOf {sim info}] \
    [medianOf {::sf::gui::statusinfo}] [winfo width $::sf::gui::view::w] \
    [winfo height $::sf::gui::view::w] [lrange [exec cat /proc/loadavg] 0 2]]

set tick [::sf::gui::runtick]
proc timed {kind} {
    global steps tick
    if {$kind eq "bare"} { ::sf::gui::runtick {} } else { ::sf::gui::runtick {*}$tick }
    set f0 $::sf::gui::view::frames
    set ::sf::gui::runbar::frameCost {}
    set t0 [clock microseconds]
    run $steps
    set us [expr {[clock microseconds] - $t0}]
    set frames [expr {$::sf::gui::view::frames - $f0}]
    ::sf::gui::runtick {*}$tick
    set ms [expr {$us / 1000.0 / $steps}]
    set fps [expr {$frames / ($us / 1e6)}]
    # What the tick's frames cost in the run (drawing, status bar), median.
    set costs $::sf::gui::runbar::frameCost
    set cost [expr {[llength $costs] ? [median $costs] : 0}]
    puts [format "run %-4s steps %d ms_per_step %.2f frames %d fps %.1f frame_ms %.1f" \
              $kind $steps $ms $frames $fps $cost]
    list $ms $fps
}
proc median {values} {
    set s [lsort -real $values]
    set k [llength $s]
    expr {$k % 2 ? [lindex $s [expr {$k / 2}]] : ([lindex $s [expr {$k / 2 - 1}]] + [lindex $s [expr {$k / 2}]]) / 2.0}
}

set ratios {}
set rates {}
for {set k 0} {$k < $reps} {incr k} {
    lassign [timed bare] bare
    lassign [timed view] view fps
    lappend ratios [expr {$view / $bare - 1}]
    lappend rates $fps
}

# Pause: clicked at a random moment of a long run; the time until run returns.
set pauses {}
for {set k 0} {$k < 5} {incr k} {
    after [expr {300 + int(rand() * 400)}] {
        set ::clicked [clock microseconds]
        ::sf::gui::runbar::pausePressed
    }
    run 1000000000
    lappend pauses [expr {([clock microseconds] - $::clicked) / 1000.0}]
}
set frame [expr {1000.0 / $::sf::gui::runbar::fps}]
puts [format "overhead %.1f%% (target <= 10%%) fps %.1f (lowest %.1f, target >= %s)  pause_ms %.1f (max %.1f) frame_ms %.1f (target: pause <= one frame)  load %s" \
    [expr {100 * [median $ratios]}] [median $rates] [tcl::mathfunc::min {*}$rates] $minfps \
    [median $pauses] [tcl::mathfunc::max {*}$pauses] $frame [lrange [exec cat /proc/loadavg] 0 2]]
} err]} {
    puts stderr $::errorInfo
    exit 1
}
exit 0
