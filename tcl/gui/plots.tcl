# Live plots: every series sampled on the run's own clock and the chosen one
# drawn with tklib's Plotchart. "Save PNG" writes the samples as CSV and draws
# them with the `plot` command (gnuplot), as a script would.
#
# A run is sampled at its start, after every K-th of its steps (K: perRun
# points a run, or more to give one every `interval` seconds, with sampling
# kept within `budget` of the run's time) and at its last step, however it
# ends; `step` adds a sample too. Whatever
# starts them (the Run button, the console, a script), `run` and `step` are
# followed by execution traces, and the steps in between by the run's sample
# hook (::sf::gui::runsample), not by the view's frames. A new scene (reset, a
# new lattice, a checkpoint loaded, the clock going back) starts a new history.

namespace eval ::sf::gui::plots {
    variable f ""
    variable series kinetic
    # The samples, one row each: the columns below, every series at once, so
    # that choosing another series shows its history.
    variable columns {step time kinetic mach broken contacts fluidfx fluidfy}
    variable samples {}
    variable maxSamples 4000     ;# then every other is dropped (the last kept)
    variable perRun 200          ;# points a run gives at most, unless
    variable interval 0.1        ;# a point every this many seconds of the run, at least
    variable stepTime 0          ;# microseconds a step took, as last measured
    variable budget 0.05         ;# sampling's share of a run's time, at most
    variable costs {}            ;# the last samples' costs, in steps' time
    variable every 0             ;# K of the run in progress (0: none)
    variable lastWall 0          ;# clock microseconds and step of the last sample
    variable lastStep 0
    variable lastDraw 0
    variable lastPanel 0
    variable stepsSince 0        ;# steps (the command) since the last sample
    # name label: what can be plotted
    variable choices {
        kinetic   "kinetic energy"
        mach      "Mach number"
        broken    "broken bonds"
        contacts  "contacts"
        fluidfx   "fluid force x on the selection"
        fluidfy   "fluid force y on the selection"
    }
}

proc ::sf::gui::plots::create {path} {
    variable f
    variable choices
    package require Plotchart
    ttk::frame $path -padding 4
    ttk::frame $path.bar
    ttk::label $path.bar.l -text Plot
    ttk::combobox $path.bar.series -state readonly -values [dict values $choices] -width 10
    $path.bar.series set [dict get $choices kinetic]
    ::bind $path.bar.series <<ComboboxSelected>> ::sf::gui::plots::choose
    # Buttons as wide as their words, packed first: the list gives up room.
    ttk::button $path.bar.clear -text Clear -width -5 -command ::sf::gui::plots::clear
    ttk::button $path.bar.save -text "Save PNG\u2026" -width -9 -command ::sf::gui::plots::saveDialog
    pack $path.bar.save $path.bar.clear -side right -padx 2
    pack $path.bar.l -side left -padx 2
    pack $path.bar.series -side left -padx 2 -fill x -expand 1
    canvas $path.c -background white -highlightthickness 0 -width 300 -height 160
    pack $path.bar -fill x
    pack $path.c -fill both -expand 1
    ::bind $path.c <Configure> ::sf::gui::plots::draw
    set f $path
    follow
    return $path
}

# The traces that follow runs, steps and new scenes.
proc ::sf::gui::plots::follow {} {
    set ns ::sf::gui::plots
    trace add execution ::sf::run enter [list ${ns}::safely runStarts]
    trace add execution ::sf::run leave [list ${ns}::safely runEnds]
    trace add execution ::sf::step leave [list ${ns}::safely stepped]
    foreach cmd {::sf::reset ::sf::lattice ::sf::checkpoint} {
        trace add execution $cmd leave [list ${ns}::safely sceneChanged]
    }
}

# A trace's error would be the traced command's: the plot's own is only told.
proc ::sf::gui::plots::safely {handler args} {
    if {[catch {$handler {*}$args} err]} {
        catch {::sf::gui::console::write $::sf::gui::W(console) "live plot: $err\n" warning}
    }
}

proc ::sf::gui::plots::choose {} {
    variable f
    variable choices
    variable series
    set label [$f.bar.series get]
    dict for {name l} $choices { if {$l eq $label} { set series $name } }
    draw
}

# Clear: a new history from the state now.
proc ::sf::gui::plots::clear {} {
    variable samples {}
    sample
    draw
}

# A new scene starts a new history: after reset, a new lattice, a loaded
# checkpoint.
proc ::sf::gui::plots::sceneChanged {cmd code result op} {
    if {$code != 0} return
    set words [split [string trim $cmd]]
    set verb [lindex $words 1]
    if {[string match *reset [lindex $words 0]] || $verb in {create load}} {
        variable stepTime 0   ;# another scene: its steps and samples are timed afresh
        variable costs {}
        variable samples {}
        sample
        drawSoon
    }
}

# The steps a `run` command asks for: its count, else TIMESTEPS; 0 if unknown.
proc ::sf::gui::plots::stepsOf {cmd} {
    if {[catch {lrange $cmd 1 end} words]} { return 0 }
    set n [lindex $words 0]
    if {[string is wideinteger -strict $n]} { return $n }
    if {[info exists ::TIMESTEPS] && [string is wideinteger -strict $::TIMESTEPS]} {
        return $::TIMESTEPS
    }
    return 0
}

# A run starts (not one refused while another goes on): the step hook every
# K steps. Its first point is the last one taken (every command that
# changes the step count is followed), or, in a new history, taken now.
proc ::sf::gui::plots::runStarts {cmd op} {
    variable samples
    variable every
    variable perRun
    variable lastWall
    variable lastStep
    if {[::sf::gui::running]} return
    set lastStep [expr {[llength $samples] ? [lindex $samples end 0] : [sample]}]
    variable steps [stepsOf $cmd]
    set every [wanted $steps]
    set lastWall [clock microseconds]
    ::sf::gui::runsample {::sf::gui::plots::safely runSample} $every
}

# K for a run of n steps: up to perRun points a run (n / perRun steps apart),
# or as many as give a point every `interval` seconds (a run paused long
# before its end has its points too), unless sampling would cost more than
# its budget. Before a step has been timed, every step: K adapts from there.
proc ::sf::gui::plots::wanted {n} {
    variable perRun
    variable interval
    variable stepTime
    set k [expr {max(1, ($n + $perRun - 1) / $perRun)}]
    if {$stepTime > 0} {
        set k [expr {min($k, max(1, int($interval * 1e6 / $stepTime)))}]
    } else {
        set k 1
    }
    expr {max($k, [budgetEvery])}
}

# The run ended (completed, paused or failed): its last step is a point.
proc ::sf::gui::plots::runEnds {cmd code result op} {
    variable every
    if {[::sf::gui::running]} return
    ::sf::gui::runsample {} 0
    set every 0
    sample
    drawSoon
}

# A step typed or clicked is a point; steps in a loop, one as often as the
# budget allows (the run's last point is its last step).
proc ::sf::gui::plots::stepped {cmd code result op} {
    variable stepsSince
    if {$code != 0 || [::sf::gui::running]} return
    if {[incr stepsSince] >= [budgetEvery]} {
        sample
        drawSoon
    }
}

# The plot redrawn once the window is served (a script's many runs and
# steps draw it once).
proc ::sf::gui::plots::drawSoon {} {
    after cancel ::sf::gui::plots::draw
    after idle ::sf::gui::plots::draw
}

# The fewest steps between samples that keep their cost within the budget,
# from the median of the last few samples' costs (one slow sample, the
# machine busy elsewhere, does not thin the plot).
proc ::sf::gui::plots::budgetEvery {} {
    variable costs
    variable budget
    if {![llength $costs]} { return 1 }
    set median [lindex [lsort -real $costs] [expr {[llength $costs] / 2}]]
    return [expr {max(1, int(ceil($median / $budget)))}]
}

# After every K-th step of a run: a point, and K widened (at most doubled
# at a time) while sampling costs more than its budget. The plot and the
# property panel follow about once a second, a cost of their own apart from
# the samples'.
proc ::sf::gui::plots::runSample {} {
    variable every
    variable steps
    variable stepTime
    variable costs
    variable lastWall
    variable lastStep
    variable lastDraw
    variable lastPanel
    set t0 [clock microseconds]
    set step [sample]
    set t1 [clock microseconds]
    # This sample's cost in steps: its time over a step's (the time since
    # the last sample, less that one's own work, over the steps between).
    set taken [expr {$step - $lastStep}]
    if {$taken > 0 && $t0 > $lastWall} {
        set stepTime [expr {($t0 - $lastWall) / double($taken)}]
        set costs [lrange [lappend costs [expr {($t1 - $t0) / $stepTime}]] end-4 end]
    }
    # At most doubled at a time: one slow sample does not thin the plot.
    set k [expr {min([wanted $steps], 2 * $every)}]
    if {$k != $every} {
        set every $k
        ::sf::gui::runsample {::sf::gui::plots::safely runSample} $every
    }
    if {$t1 - $lastDraw > 1000000} {
        set lastDraw $t1
        draw
    }
    if {$t1 - $lastPanel > 1000000} {
        set lastPanel $t1
        catch {::sf::gui::props::refresh}
    }
    set lastWall [clock microseconds]
    set lastStep $step
}

# Takes one sample of the state now (once per step) -> the step.
proc ::sf::gui::plots::sample {} {
    variable samples
    variable maxSamples
    variable stepsSince 0
    if {[catch {::sf::sim info} info]} { return 0 }
    set step [dict get $info step]
    set last [lindex $samples end 0]
    if {$last ne {} && $step < $last} { set samples {} }   ;# the clock went back
    if {$last ne {} && $step == $last} { return $step }
    set force {0.0 0.0}
    foreach id $::sf::gui::selection {
        if {[catch {dict get [::sf::element info $id] fluidforce} f]} continue
        set force [list [expr {[lindex $force 0] + [lindex $f 0]}] \
                       [expr {[lindex $force 1] + [lindex $f 1]}]]
    }
    lappend samples [list $step [dict get $info time] [dict get $info kinetic] \
                         [dict get $info mach] [dict get $info broken] \
                         [dict get $info contacts] {*}$force]
    # Keep the plot light: every other sample once there are too many, the
    # last always.
    if {[llength $samples] > $maxSamples} {
        set kept [lmap {a b} [lrange $samples 0 end-1] {set a}]
        set samples [lappend kept [lindex $samples end]]
    }
    return $step
}

# The chosen series as {time value} pairs.
proc ::sf::gui::plots::points {} {
    variable samples
    variable series
    variable columns
    set k [lsearch -exact $columns $series]
    lmap s $samples { list [lindex $s 1] [lindex $s $k] }
}

# A scale {min max step} over lo..hi with at most `n` round steps (1, 2 or 5
# times a power of ten), so that the labels fit the plot's size.
proc ::sf::gui::plots::scale {lo hi n} {
    if {$hi <= $lo} {
        set pad [expr {max(1e-12, abs($lo) * 0.1)}]
        set lo [expr {$lo - $pad}]
        set hi [expr {$hi + $pad}]
    }
    set raw [expr {($hi - $lo) / max(1, $n)}]
    set mag [expr {10.0 ** floor(log10($raw))}]
    foreach m {1 2 5 10} {
        set step [expr {$m * $mag}]
        if {$step >= $raw * (1 - 1e-9)} break
    }
    set min [expr {floor($lo / $step) * $step}]
    set max [expr {ceil($hi / $step) * $step}]
    if {$max <= $min} { set max [expr {$min + $step}] }
    list $min $max $step
}

proc ::sf::gui::plots::draw {} {
    variable f
    variable series
    variable choices
    if {$f eq "" || ![winfo exists $f.c]} return
    set c $f.c
    $c delete all
    set width [winfo width $c]
    set height [winfo height $c]
    set points [points]
    if {[llength $points] < 2} {
        $c create text [expr {$width / 2}] [expr {$height / 2}] \
            -text "[dict get $choices $series]:\nrun to plot" -fill #868e96 -justify center
        return
    }
    set ts [lmap p $points {lindex $p 0}]
    set vs [lmap p $points {lindex $p 1}]
    # About one label per 90 pixels across and 35 up.
    set xs [scale [tcl::mathfunc::min {*}$ts] [tcl::mathfunc::max {*}$ts] \
                [expr {max(2, $width / 90)}]]
    set ys [scale [tcl::mathfunc::min {*}$vs] [tcl::mathfunc::max {*}$vs] \
                [expr {max(2, $height / 35)}]]
    # The labels a little off the axes, the lowest y label clear of the
    # first x label (Plotchart spaces both axes' labels by the left axis's
    # offset); the x axis is time (the saved picture says so; here it needs
    # the room).
    ::Plotchart::plotconfig xyplot background outercolor white
    ::Plotchart::plotconfig xyplot leftaxis labeloffset 7
    ::Plotchart::plotconfig xyplot bottomaxis format %.4g
    ::Plotchart::plotconfig xyplot leftaxis format %.3g
    set p [::Plotchart::createXYPlot $c $xs $ys]
    $p dataconfig s -colour #1f6feb -width 2
    $p title [dict get $choices $series]
    foreach t $ts v $vs { $p plot s $t $v }
}

proc ::sf::gui::plots::saveDialog {} {
    set file [tk_getSaveFile -parent . -title "Save plot as PNG" -defaultextension .png \
                  -filetypes {{{PNG pictures} {.png}}}]
    if {$file eq ""} return
    if {[catch {save $file} err]} { ::sf::gui::showError $err }
}

# The samples as CSV beside the picture, drawn by `plot`.
proc ::sf::gui::plots::save {file} {
    variable series
    variable choices
    set points [points]
    if {[llength $points] < 2} { error "nothing to plot yet: run first" }
    set csv [file rootname $file].csv
    set ch [open $csv w]
    puts $ch "time,$series"
    foreach p $points { puts $ch [join $p ,] }
    close $ch
    ::sf::gui::do [list plot $file $csv -y $series -title [dict get $choices $series] \
                       -size {800 450}]
}
