# Drives the workbench as a user does, for tests that run inside `sandflow
# -gui FILE` under Xvfb: mouse gestures on the view (`event generate`, in
# world units or the view's pixels), the wheel, keys, typing into entries and
# the console, menus invoked through their entries, the dialogs that open
# answered by clicking their buttons, screenshots of the window. It also
# records what a user must never meet: background errors (bgerror) and error
# dialogs (tk_messageBox). Sourced by tests/gui/newuser.test.

namespace eval ::driver {
    namespace export px pressAt moveAt releaseAt dragAt drag clickAt click middleDragAt wheel \
        viewKey tool drawNow typeInto typeCommand invokeEntry menuEntries answer waitFor \
        newConsoleErrors shot
    variable shots ""       ;# folder of the screenshots; "" takes none
    variable shotCount 0
    variable bgerrors {}    ;# messages given to bgerror
    variable dialogs {}     ;# {icon message} of every tk_messageBox shown
    variable answers {}     ;# queued {pattern action args} for dialogs to come
    variable answered {}    ;# what the answerer did, and what it could not do
}

set ::driver::v $::sf::gui::W(view)

# ---- what must not happen ------------------------------------------------------

proc ::bgerror {message} {
    lappend ::driver::bgerrors $message
    puts stderr "bgerror: $message\n$::errorInfo"
}
auto_load tk_messageBox
rename ::tk_messageBox ::driver::realMessageBox
proc ::tk_messageBox {args} {
    set icon [expr {[dict exists $args -icon] ? [dict get $args -icon] : "info"}]
    set message [expr {[dict exists $args -message] ? [dict get $args -message] : ""}]
    lappend ::driver::dialogs [list $icon $message]
    ::driver::realMessageBox {*}$args
}

# ---- the view ------------------------------------------------------------------

# World point -> the view's pixel, rounded.
proc ::driver::px {x y} { lmap c [::sf::gui::view::toPixel $x $y] {expr {round($c)}} }

proc ::driver::pressAt {X Y {state 0}} {
    event generate $::driver::v <Motion> -x $X -y $Y
    event generate $::driver::v <ButtonPress-1> -x $X -y $Y -state $state
    update
}
proc ::driver::moveAt {X Y {button 1}} {
    event generate $::driver::v <Motion> -x $X -y $Y -state [expr {128 << $button}]
    update
}
proc ::driver::releaseAt {X Y {button 1}} {
    event generate $::driver::v <ButtonRelease-$button> -x $X -y $Y -state [expr {128 << $button}]
    update
}
# A drag in the view's pixels, through `steps` motions (a hand moves in many).
proc ::driver::dragAt {X0 Y0 X1 Y1 {steps 4}} {
    pressAt $X0 $Y0
    for {set k 1} {$k <= $steps} {incr k} {
        moveAt [expr {round($X0 + ($X1 - $X0) * $k / double($steps))}] \
            [expr {round($Y0 + ($Y1 - $Y0) * $k / double($steps))}]
    }
    releaseAt $X1 $Y1
}
proc ::driver::drag {x0 y0 x1 y1} { dragAt {*}[px $x0 $y0] {*}[px $x1 $y1] }
proc ::driver::clickAt {X Y} { pressAt $X $Y; releaseAt $X $Y }
proc ::driver::click {x y} { clickAt {*}[px $x $y] }
# A drag with the middle button (pan, whatever the tool).
proc ::driver::middleDragAt {X0 Y0 X1 Y1} {
    event generate $::driver::v <ButtonPress-2> -x $X0 -y $Y0
    update
    moveAt [expr {($X0 + $X1) / 2}] [expr {($Y0 + $Y1) / 2}] 2
    moveAt $X1 $Y1 2
    releaseAt $X1 $Y1 2
}
# The wheel: n notches in (n > 0) or out, the pointer at (X, Y).
proc ::driver::wheel {X Y n} {
    set button [expr {$n > 0 ? 4 : 5}]
    for {set k 0} {$k < abs($n)} {incr k} {
        event generate $::driver::v <ButtonPress-$button> -x $X -y $Y
        event generate $::driver::v <ButtonRelease-$button> -x $X -y $Y
    }
    update
}
# A key pressed with the pointer over the view (it takes the focus then).
proc ::driver::viewKey {keysym} {
    event generate $::driver::v <Enter> -x 10 -y 10
    focus -force $::driver::v
    update
    event generate $::driver::v <KeyPress-$keysym>
    event generate $::driver::v <KeyRelease-$keysym>
    update
}
# The tool chosen by its button in the palette.
proc ::driver::tool {name} {
    .main.tools.c.in.$name invoke
    update
}
# One frame drawn, now.
proc ::driver::drawNow {} {
    ::sf::gui::view::draw
    update
}

# ---- typing ------------------------------------------------------------------------

# Text typed into a widget key by key (its class bindings insert it), then a
# key to end it (Return, Tab, ...; "" for none).
proc ::driver::typeInto {w text {end Return}} {
    focus -force $w
    update
    event generate $w <Control-a>
    if {[winfo class $w] in {TEntry Entry TSpinbox Spinbox TCombobox}} { $w delete 0 end }
    foreach char [split $text ""] {
        set keysym [keysymOf $char]
        event generate $w <KeyPress> -keysym $keysym
        event generate $w <KeyRelease> -keysym $keysym
    }
    if {$end ne ""} { event generate $w <KeyPress-$end>; event generate $w <KeyRelease-$end> }
    update
}
proc ::driver::keysymOf {char} {
    set names {" " space "{" braceleft "}" braceright "-" minus "." period "/" slash
        "_" underscore "\[" bracketleft "\]" bracketright "\$" dollar "\"" quotedbl
        "=" equal "+" plus "*" asterisk "," comma ":" colon ";" semicolon "(" parenleft
        ")" parenright "<" less ">" greater "#" numbersign "'" apostrophe "!" exclam
        "?" question "&" ampersand "%" percent "|" bar "@" at "^" asciicircum "~" asciitilde
        "\\" backslash}
    if {[dict exists $names $char]} { return [dict get $names $char] }
    return $char
}
# A command typed at the console's prompt and entered (Return; "" leaves it
# typed). It runs as the Return key's binding: this returns when it has.
proc ::driver::typeCommand {text {end Return}} {
    set W $::sf::gui::W(console)
    set t $W.text
    set r [::sf::gui::console::Real $W]
    $r mark set insert end-1c
    typeInto $t $text $end
}

# ---- menus and dialogs ---------------------------------------------------------------

# A menu's entry invoked, found by its label (an error if there is none).
proc ::driver::invokeEntry {menu label} {
    set index [entryIndex $menu $label]
    $menu invoke $index
    update
}
proc ::driver::entryIndex {menu label} {
    set last [$menu index end]
    for {set i 0} {$i <= $last} {incr i} {
        if {[$menu type $i] in {separator tearoff}} continue
        if {[$menu entrycget $i -label] eq $label} { return $i }
    }
    error "$menu has no entry \"$label\""
}
# Every entry of a menu and its cascades: {menu label type} each.
proc ::driver::menuEntries {menu} {
    set found {}
    set last [$menu index end]
    for {set i 0} {$i <= $last} {incr i} {
        set type [$menu type $i]
        if {$type in {separator tearoff}} continue
        if {$type eq "cascade"} {
            lappend found {*}[menuEntries [$menu entrycget $i -menu]]
        } else {
            lappend found [list $menu [$menu entrycget $i -label] $type]
        }
    }
    return $found
}

# Answers the next dialog to open, as a user would, once it shows: its
# toplevel's path matches `pattern`; action is one of
#   button LABEL       click the button labelled LABEL
#   file PATH          type PATH into a file chooser and click its Open/Save
#   text TEXT          type TEXT into the dialog's entry and click OK
#   close              close its window (the window manager's close)
# Dialogs run their own event loop, so the answer is given from a poll.
proc ::driver::answer {pattern action args} {
    variable answers
    lappend answers [list $pattern $action {*}$args]
    if {[llength $answers] == 1} { after 50 ::driver::poll }
}
proc ::driver::poll {} {
    variable answers
    variable answered
    if {![llength $answers]} return
    set args [lassign [lindex $answers 0] pattern action]
    set shown {}
    foreach w [wm stackorder .] {
        if {[string match $pattern $w] && [winfo ismapped $w]} { set shown $w }
    }
    if {$shown eq ""} {
        foreach w [winfo children .] {
            if {[winfo toplevel $w] eq $w && [string match $pattern $w] && [winfo ismapped $w]} {
                set shown $w
            }
        }
    }
    if {$shown eq ""} { after 50 ::driver::poll; return }
    set answers [lrange $answers 1 end]
    update
    if {[catch {act $shown $action {*}$args} err]} {
        lappend answered "$shown: $action $args failed: $err"
    } else {
        lappend answered "$shown: $action $args"
    }
    if {[llength $answers]} { after 50 ::driver::poll }
}
proc ::driver::act {w action args} {
    switch $action {
        button {
            set b [buttonLabelled $w [lindex $args 0]]
            if {$b eq ""} { error "no button \"[lindex $args 0]\" in $w" }
            $b invoke
        }
        file {
            # Tk's own file chooser: its entry and its Open/Save button.
            set e $w.contents.f2.ent
            typeInto $e [lindex $args 0] ""
            $w.contents.f2.ok invoke
        }
        text {
            set e [lindex [descendants $w {*Entry}] 0]
            typeInto $e [lindex $args 0] ""
            [buttonLabelled $w OK] invoke
        }
        close {
            set protocol [wm protocol $w WM_DELETE_WINDOW]
            if {$protocol ne ""} { uplevel #0 $protocol } else { destroy $w }
        }
    }
}
proc ::driver::descendants {w classPattern} {
    set found {}
    foreach child [winfo children $w] {
        if {[string match $classPattern [winfo class $child]]} { lappend found $child }
        lappend found {*}[descendants $child $classPattern]
    }
    return $found
}
proc ::driver::buttonLabelled {w label} {
    foreach b [descendants $w {*Button}] {
        if {[string map {& ""} [$b cget -text]] eq $label} { return $b }
    }
    return ""
}
# Waits, serving events, until a condition (a Tcl expression at global level)
# holds, or `seconds` pass -> whether it holds.
proc ::driver::waitFor {condition {seconds 120}} {
    set end [expr {[clock milliseconds] + 1000 * $seconds}]
    while {![uplevel #0 [list expr $condition]]} {
        if {[clock milliseconds] > $end} { return 0 }
        after 20 {set ::driver::tick 1}
        vwait ::driver::tick
    }
    return 1
}

# ---- the console's log ---------------------------------------------------------------

# The errors (red) and warnings written to the console since the last call:
# one string each.
proc ::driver::newConsoleErrors {} {
    set r [::sf::gui::console::Real $::sf::gui::W(console)]
    if {"driverSeen" ni [$r mark names]} { $r mark set driverSeen 1.0; $r mark gravity driverSeen left }
    set found {}
    foreach tag {error warning} {
        foreach {a b} [$r tag ranges $tag] {
            if {[$r compare $b <= driverSeen]} continue
            if {[$r compare $a < driverSeen]} { set a driverSeen }
            set text [string trim [$r get $a $b]]
            if {$text ne "" && $text ne "(details)"} { lappend found $text }
        }
    }
    $r mark set driverSeen out
    return $found
}

# ---- screenshots -----------------------------------------------------------------------

# The whole window (menus included) as the screen shows it, as NN-name.png in
# the shots folder -> the file.
proc ::driver::shot {name} {
    variable shots
    variable shotCount
    if {$shots eq ""} return
    drawNow
    after idle {set ::driver::tick 1}
    vwait ::driver::tick
    set file [file join $shots [format %02d-%s.png [incr shotCount] $name]]
    # The menu bar sits above ".", inside its wrapper: the wrapper's top is
    # where the window's geometry puts it.
    regexp {\+(-?[0-9]+)\+(-?[0-9]+)$} [wm geometry .] -> x y
    set w [winfo width .]
    set h [expr {[winfo rooty .] - $y + [winfo height .]}]
    exec import -window root -crop ${w}x${h}+${x}+${y} +repage $file
    return $file
}
