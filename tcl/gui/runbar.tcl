# Run controls and the status bar. A run is the `run` command, whoever started
# it (the Run button, the console, a script): the workbench hooks a tick into
# it (::sf::gui::runtick) that serves Tk's events at least every 50 ms, redraws
# the view at the chosen frame rate and updates the status bar, and that breaks
# the run when Pause was pressed (run then returns the step it reached).

namespace eval ::sf::gui::runbar {
    variable steps 1000        ;# Run: steps a press advances (TIMESTEPS)
    variable fps 20            ;# target frame rate of the view during a run
    variable stepsPerFrame 0   ;# > 0: redraw every this many steps instead (GRAPHICSFRAMES)
    variable lastFrameStep -1
    variable period 50.0       ;# milliseconds between frames, as last worked out
    variable run -1            ;# the run the tick last served
    variable pause 0           ;# Pause pressed: the tick breaks the run
    variable nextFrame 0       ;# clock milliseconds when the next redraw is due
    variable budget 0.09       ;# the view's own share of a run's time: its frames sample the
                               ;# view's pixels, not the lattice, and hardly slow the steps after
                               ;# them; the tick's other work (under 1%) comes on top
    variable longest 1000.0    ;# milliseconds: frames are never further apart, whatever they cost
    variable frameCost {}      ;# milliseconds each redraw took (the last 50)
    variable progress 0
    variable text ""           ;# status line
    variable pauseClicked 0    ;# clock microseconds of the Pause click (latency)
    variable latency {}        ;# microseconds from Pause click to the run's end
}

proc ::sf::gui::runbar::create {f} {
    ttk::frame $f -padding {4 2}
    ttk::button $f.run -text "\u25b6 Run" -command ::sf::gui::runbar::runPressed -width 8
    ttk::button $f.pause -text "\u275a\u275a Pause" -command ::sf::gui::runbar::pausePressed -width 8
    ttk::button $f.step -text "Step" -command ::sf::gui::runbar::stepPressed -width 6
    ttk::button $f.reset -text "Reset" -command ::sf::gui::runbar::resetPressed -width 6
    ttk::label $f.lsteps -text "steps"
    ttk::spinbox $f.steps -from 1 -to 100000000 -increment 100 -width 8 \
        -textvariable ::sf::gui::runbar::steps
    ttk::label $f.lfps -text "frames/s"
    ttk::spinbox $f.fps -from 1 -to 60 -width 4 -textvariable ::sf::gui::runbar::fps
    ttk::label $f.lspf -text "or every"
    ttk::spinbox $f.spf -from 0 -to 1000000 -width 6 -textvariable ::sf::gui::runbar::stepsPerFrame
    ttk::label $f.lspf2 -text "steps" 
    ttk::progressbar $f.progress -length 100 -variable ::sf::gui::runbar::progress -maximum 1.0
    pack $f.run $f.pause $f.step $f.reset -side left -padx 2
    pack $f.lsteps $f.steps $f.lfps $f.fps $f.lspf $f.spf $f.lspf2 -side left -padx {8 2}
    pack $f.progress -side right -padx 4
    ::sf::gui::tip $f.run "Run the set number of steps (F5)"
    ::sf::gui::tip $f.pause "Pause a run, whoever started it (Esc / F6)"
    ::sf::gui::tip $f.step "One step (F7)"
    ::sf::gui::tip $f.reset "Empty the scene: reset"
    ::sf::gui::tip $f.fps "How often the view redraws while a run goes on (frames are spaced out where drawing would take more than 9% of the run, but come at least once a second)"
    ::sf::gui::tip $f.spf "Redraw every this many steps instead (0: by the frame rate)"
    $f.pause state disabled
    ::sf::gui::runtick ::sf::gui::runbar::tick 50
    return $f
}

proc ::sf::gui::runbar::statusBar {f} {
    ttk::frame $f -padding {6 2}
    ttk::label $f.text -textvariable ::sf::gui::runbar::text -anchor w
    ttk::label $f.pointer -textvariable ::sf::gui::pointer -width 26 -anchor e
    ttk::label $f.message -textvariable ::sf::gui::message -anchor w -foreground #555555
    pack $f.text -side left
    pack $f.pointer -side right
    pack $f.message -side left -fill x -expand 1 -padx 12
    return $f
}

# Run: `run N` through the console path, so that it is echoed like a typed one.
proc ::sf::gui::runbar::runPressed {} {
    variable steps
    if {[::sf::gui::running]} return
    if {![string is integer -strict $steps] || $steps < 1} {
        ::sf::gui::status "steps must be a whole number >= 1" error
        return
    }
    catch {::sf::gui::do [list run $steps]}
}

proc ::sf::gui::runbar::pausePressed {} {
    variable pause
    variable pauseClicked
    if {![::sf::gui::running]} return
    set pause 1
    set pauseClicked [clock microseconds]
}

proc ::sf::gui::runbar::stepPressed {} {
    if {[::sf::gui::running]} return
    catch {::sf::gui::do step}
}

proc ::sf::gui::runbar::resetPressed {} {
    if {[::sf::gui::running]} {
        ::sf::gui::status "pause the run first" error
        return
    }
    if {[llength [element ids]] || ![catch {lattice info}]} {
        set answer [tk_messageBox -parent . -icon question -type okcancel -title Reset \
                        -message "Empty the scene?" -detail "This cannot be undone."]
        if {$answer ne "ok"} return
    }
    ::sf::gui::forgetHistory
    catch {::sf::gui::do reset}
    ::sf::gui::view::fit
}

# Called from inside `run` at most every 50 ms.
proc ::sf::gui::runbar::tick {} {
    variable pause
    variable fps
    variable nextFrame
    variable budget
    variable longest
    variable frameCost
    variable stepsPerFrame
    variable lastFrameStep
    variable period
    variable run
    variable progress
    variable latency
    variable pauseClicked
    running 1
    # The pause is taken before serving events, so a click served now is seen
    # at the next tick, at most one tick (50 ms) later.
    if {$pause} {
        set pause 0
        lappend latency [expr {[clock microseconds] - $pauseClicked}]
        running 0
        return -code break
    }
    set now [clock milliseconds]
    lassign [::sf::gui::progress] done total serial
    # A new run starts from the picture the view already shows: its first
    # frame comes a period (or K steps) in, not at once.
    if {$serial != $run} {
        set run $serial
        set lastFrameStep 0
        set nextFrame [expr {$now + round($period)}]
    }
    # Every K steps when asked (each frame shown, whatever it costs), else by
    # the frame rate within the budget.
    if {[string is integer -strict $stepsPerFrame] && $stepsPerFrame > 0} {
        set due [expr {$done - $lastFrameStep >= $stepsPerFrame}]
    } else {
        set due [expr {$now >= $nextFrame}]
    }
    if {$due} {
        set lastFrameStep $done
        set t0 [clock microseconds]
        set progress [expr {$total > 0 ? double($done) / $total : 0.0}]
        ::sf::gui::view::draw
        # Not `sim info`, whose Mach number scans the lattice (as long as the
        # frame on a large one): the last step's.
        set info [::sf::gui::statusinfo]
        ::sf::gui::runbar::update $info
        # The frame rate asked for, unless frames cost more than the budget's
        # share of the run: then they are spaced out, but never more than
        # `longest` apart (a run always shows it goes on). The cost is the
        # median of the last five frames', so that one frame slowed by another
        # process does not hold the next ones back. The next frame is timed
        # from this one's end, also across runs.
        set end [clock microseconds]
        set cost [expr {($end - $t0) / 1000.0}]
        set frameCost [lrange [lappend frameCost $cost] end-49 end]
        set recent [lsort -real [lrange $frameCost end-4 end]]
        # (The lower median: a run's first, cold frame alone does not space
        # out the second.)
        set typical [lindex $recent [expr {([llength $recent] - 1) / 2}]]
        # A frame rate being typed (not a number yet) counts as the default.
        set rate [expr {[string is double -strict $fps] ? max(1, min(60, $fps)) : 20}]
        set period [expr {min($longest,
                              max(1000.0 / $rate, $typical * (1 - $budget) / $budget))}]
        set nextFrame [expr {$end / 1000 + round($period)}]
    }
    # Serve the window: clicks, keys, typing at the console, `after` scripts.
    if {[catch {::update} err]} { ::sf::gui::status "event: $err" error }
    if {$pause} {
        set pause 0
        lappend latency [expr {[clock microseconds] - $pauseClicked}]
        running 0
        return -code break
    }
}

# The buttons' states follow whether a run is going.
proc ::sf::gui::runbar::running {on} {
    set f $::sf::gui::W(runbar)
    if {$on} {
        $f.run state disabled
        $f.step state disabled
        $f.reset state disabled
        $f.pause state !disabled
    } else {
        $f.run state !disabled
        $f.step state !disabled
        $f.reset state !disabled
        $f.pause state disabled
    }
}

# Element steps per second between two updates of a run without a lattice.
proc ::sf::gui::runbar::particleRate {info} {
    variable lastRate
    set now [clock microseconds]
    set step [dict get $info step]
    set text ""
    if {[info exists lastRate]} {
        lassign $lastRate t0 s0 text0
        set dt [expr {($now - $t0) / 1e6}]
        if {$step > $s0 && $dt > 0} {
            set text [format "%.3g particle-steps/s" \
                          [expr {($step - $s0) * [dict get $info elements] / $dt}]]
        } else {
            set text $text0
        }
    }
    set lastRate [list $now $step $text]
    return $text
}

# "1 element", "3 elements".
proc ::sf::gui::runbar::counted {n noun} {
    return "$n $noun[expr {$n == 1 ? {} : {s}}]"
}

# Step, time, speed, Mach and warnings in the status bar.
proc ::sf::gui::runbar::update {{info {}}} {
    variable text
    variable progress
    running [::sf::gui::running]
    if {![::sf::gui::running]} { set progress 0 }
    if {$info eq {} && [catch {sim info} info]} return
    set parts [list "step [dict get $info step]" [format "t %.5g" [dict get $info time]]]
    if {[dict get $info nodes] > 0} {
        lappend parts [format "%.1f MLUPS" [dict get $info mlups]]
        lappend parts [format "Mach %.3f" [dict get $info mach]]
    } elseif {[set rate [particleRate $info]] ne ""} {
        lappend parts $rate
    }
    lappend parts [counted [dict get $info elements] element]
    set nw [llength [dict get $info warnings]]
    if {$nw} { lappend parts [counted $nw warning] }
    set text [join $parts "   \u00b7   "]
}
