# What the workbench does to the scene: every action is a command a user could
# type, run at global level, echoed in the console, and paired with the command
# that reverses it for undo and redo. The selection lives here too.

namespace eval ::sf::gui {
    variable undoStack {}   ;# {label do undo} entries, newest last
    variable redoStack {}
    variable selection {}   ;# element ids
    variable highlight #1f6feb
    # Commands (actions and typed ones) numbered as they start; `settled` is
    # the number of the latest that succeeded. A message, or a refused
    # property, from before it has had its answer.
    variable started 0
    variable settled 0
}

# A command starts -> its number.
proc ::sf::gui::begin {} {
    variable started
    incr started
}

# The command numbered `serial` succeeded: the status bar's older message goes.
proc ::sf::gui::succeeded {serial} {
    variable settled
    variable messageAt
    if {$serial > $settled} { set settled $serial }
    if {[info exists messageAt] && $messageAt < $serial} { status "" }
}

# Runs `cmd` as typed: echoed, evaluated at global level, its result shown
# as a typed one's is. On success the pair (cmd, undo) joins the undo history
# (an empty undo: not undoable) and the result is returned; on failure the
# error is shown and raised, and nothing is recorded (the command itself left
# the scene unchanged).
proc ::sf::gui::do {cmd {undo ""} {label ""}} {
    variable undoStack
    variable redoStack
    echo $cmd
    set serial [begin]
    set code [catch {uplevel #0 $cmd} result options]
    if {$code == 1} {
        showError $result $options
        changed
        return -options $options $result
    }
    if {$undo ne ""} {
        if {$label eq ""} { set label [lrange $cmd 0 1] }
        lappend undoStack [list $label $cmd $undo]
        set redoStack {}
    }
    succeeded $serial
    if {$result ne "" && [info exists ::sf::gui::W(console)]} {
        console::write $::sf::gui::W(console) $result\n result
    }
    changed
    return $result
}

# Several commands as one undoable action (a bond of a selection, a delete of
# several elements). `pairs` is a list of {do undo}; undo runs in reverse.
proc ::sf::gui::doAll {label pairs} {
    variable undoStack
    variable redoStack
    set done {}
    set serial [begin]
    foreach pair $pairs {
        lassign $pair cmd undo
        echo $cmd
        if {[catch {uplevel #0 $cmd} result options]} {
            showError $result $options
            # What ran so far is taken back: the action is all or nothing.
            foreach d [lreverse $done] { catch {uplevel #0 [lindex $d 1]} }
            changed
            return -code error $result
        }
        lappend done [list $cmd $undo]
    }
    if {[llength $done]} {
        lappend undoStack [list $label [join [lmap d $done {lindex $d 0}] \n] \
                               [join [lreverse [lmap d $done {lindex $d 1}]] \n]]
        set redoStack {}
    }
    succeeded $serial
    changed
}

proc ::sf::gui::undo {} { replay undoStack redoStack 2 undone }
proc ::sf::gui::redo {} { replay redoStack undoStack 1 redone }

# Moves the newest entry of one history to the other, running its undo
# (field 2) or its command (field 1). A step that fails stays where it was.
proc ::sf::gui::replay {fromName toName field verb} {
    upvar #0 ::sf::gui::$fromName from ::sf::gui::$toName to
    if {![llength $from]} { status "nothing to [string range $verb 0 end-2]"; return }
    set entry [lindex $from end]
    set label [lindex $entry 0]
    set script [lindex $entry $field]
    echo $script
    set serial [begin]
    if {[catch {uplevel #0 $script} result]} {
        showError "[string range $verb 0 end-2] $label: $result"
        changed
        return
    }
    succeeded $serial
    set from [lrange $from 0 end-1]
    lappend to $entry
    status "$verb: $label"
    changed
}

# A new scene (File > New, reset) starts a new history.
proc ::sf::gui::forgetHistory {} {
    variable undoStack {}
    variable redoStack {}
    variable selection {}
}

proc ::sf::gui::echo {cmd} {
    if {[namespace exists console] && [info exists ::sf::gui::W(console)]} {
        console::echo $::sf::gui::W(console) $cmd
    }
}

# An error in the console (with its details, as a typed one's) and the
# status bar.
proc ::sf::gui::showError {message {options {}}} {
    if {[info exists ::sf::gui::W(console)]} {
        set info [expr {[dict exists $options -errorinfo] ? [dict get $options -errorinfo] : ""}]
        set code [expr {[dict exists $options -errorcode] ? [dict get $options -errorcode] : ""}]
        console::ShowError $::sf::gui::W(console) $message $info $code
    }
    status $message error
}

# After anything that may have changed the scene: the selection drops ids
# that are gone, and the view, the property panel and the status bar follow.
proc ::sf::gui::changed {} {
    variable selection
    set ids [element ids]
    set selection [lmap id $selection {expr {$id in $ids ? $id : [continue]}}]
    view::redraw
    if {[llength [info commands ::sf::gui::props::refresh]]} { props::refresh }
    if {[llength [info commands ::sf::gui::runbar::update]]} { runbar::update }
}

# ---- the selection ----------------------------------------------------------

# Outlines of the selected elements for the view's overlay.
proc ::sf::gui::selectionOverlay {} {
    variable selection
    variable highlight
    if {![llength $selection]} { return {} }
    set items {}
    foreach {id type x y reach} [::sf::gui::elements] {
        if {$id ni $selection} continue
        if {$type eq "wall"} {
            set info [element info $id]
            lappend items [list line $highlight {*}[dict get $info from] {*}[dict get $info to]]
        } else {
            set pad [expr {3 * [view::pixelSize]}]
            lappend items [list circle $highlight $x $y [expr {$reach + $pad}]]
        }
    }
    return $items
}

proc ::sf::gui::select {ids {add 0}} {
    variable selection
    if {$add} {
        foreach id $ids {
            if {$id in $selection} {
                set selection [lsearch -all -inline -not -exact $selection $id]
            } else {
                lappend selection $id
            }
        }
    } else {
        set selection $ids
    }
    view::redraw 1
    if {[llength [info commands ::sf::gui::props::refresh]]} { props::refresh }
}

proc ::sf::gui::selectAll {} {
    select [element ids]
}

# The element under a world point: the nearest centre among those whose
# outline (bounding circle, or a wall's segment) lies within `tol`.
proc ::sf::gui::pick {x y tol} {
    set best ""
    set bestD Inf
    foreach {id type cx cy reach} [::sf::gui::elements] {
        if {$type eq "wall"} {
            set info [element info $id]
            set d [segmentDistance $x $y {*}[dict get $info from] {*}[dict get $info to]]
            # A wall is a line: a little more slack than for a body with area.
            if {$d > 3 * $tol} continue
        } else {
            set d [expr {hypot($x - $cx, $y - $cy)}]
            if {$d > $reach + $tol} continue
        }
        if {$d < $bestD} {
            set bestD $d
            set best $id
        }
    }
    return $best
}

proc ::sf::gui::segmentDistance {x y ax ay bx by} {
    set dx [expr {$bx - $ax}]
    set dy [expr {$by - $ay}]
    set len2 [expr {$dx * $dx + $dy * $dy}]
    set t [expr {$len2 > 0 ? (($x - $ax) * $dx + ($y - $ay) * $dy) / $len2 : 0.0}]
    set t [expr {max(0.0, min(1.0, $t))}]
    expr {hypot($x - ($ax + $t * $dx), $y - ($ay + $t * $dy))}
}

# Elements whose centres lie in a world box (rubber-band selection).
proc ::sf::gui::within {x0 y0 x1 y1} {
    set ids {}
    foreach {id type cx cy reach} [::sf::gui::elements] {
        if {$cx >= $x0 && $cx <= $x1 && $cy >= $y0 && $cy <= $y1} { lappend ids $id }
    }
    return $ids
}

# ---- actions on the selection -----------------------------------------------

# The commands that recreate an element as it is now, with its bonds and its
# source settings (undo of a delete).
proc ::sf::gui::recreateScript {id} {
    set lines [list [elementScript $id]]
    foreach b [bond ids] {
        set info [bond info $b]
        if {$id in [dict get $info elements]} {
            lassign [dict get $info elements] a c
            lappend lines [list bond create $a $c -stiffness [dict get $info stiffness] \
                               -strength [dict get $info strength] \
                               -shearstrength [dict get $info shearstrength]]
        }
    }
    if {$id in [source ids]} {
        set info [source info $id]
        lappend lines [list source create $id -acceleration [dict get $info acceleration] \
                           -interval [dict get $info interval] -limit [dict get $info limit]]
    }
    join $lines \n
}

# An element's create command from its current state, when the scene saver
# (scene_script.tcl) does not provide one.
if {![llength [info commands ::sf::gui::elementScript]]} {
    proc ::sf::gui::elementScript {id} {
        set info [element info $id]
        set common [list -id $id -material [dict get $info material] \
                        -velocity [dict get $info velocity] -fix [dict get $info fix] \
                        -force [dict get $info applied] \
                        -acceleration [dict get $info acceleration]]
        switch [dict get $info type] {
            disc {
                list disc create -center [dict get $info position] \
                    -radius [dict get $info radius] -angle [dict get $info angle] {*}$common
            }
            polygon {
                list polygon create -vertices [dict get $info vertices] {*}$common
            }
            superquadric {
                list superquadric create -center [dict get $info position] \
                    -axes [dict get $info axes] -exponents [dict get $info exponents] \
                    -sides [dict get $info sides] -angle [dict get $info angle] {*}$common
            }
            wall {
                set stress [element cget $id -stress]
                set extra [expr {$stress eq {} ? {} : [list -stress $stress]}]
                list wall create -from [dict get $info from] -to [dict get $info to] \
                    {*}$extra {*}$common
            }
        }
    }
}

proc ::sf::gui::deleteSelection {} {
    variable selection
    if {![llength $selection]} { status "nothing selected"; return }
    set pairs [lmap id $selection {
        list [list element delete $id] [recreateScript $id]
    }]
    doAll "delete [llength $pairs]" $pairs
}

# Moves the selection by a world offset: one configure per element, its
# numbers at the gesture's precision (0.5, not 0.49989999999999996).
proc ::sf::gui::moveSelection {dx dy} {
    variable selection
    set pairs {}
    foreach id $selection {
        set info [element info $id]
        if {[dict get $info type] eq "wall"} {
            lassign [dict get $info from] ax ay
            lassign [dict get $info to] bx by
            set to [lmap c [list [expr {$ax + $dx}] [expr {$ay + $dy}] [expr {$bx + $dx}] [expr {$by + $dy}]] {
                tools::tidy $c
            }]
            lappend pairs [list \
                [list element configure $id -from [lrange $to 0 1] -to [lrange $to 2 3]] \
                [list element configure $id -from [dict get $info from] -to [dict get $info to]]]
        } else {
            lassign [dict get $info position] x y
            lappend pairs [list \
                [list element configure $id -center [list [tools::tidy [expr {$x + $dx}]] [tools::tidy [expr {$y + $dy}]]]] \
                [list element configure $id -center [dict get $info position]]]
        }
    }
    if {[llength $pairs]} { doAll "move" $pairs }
}

# Turns each selected element by `da` radians about its own centre.
proc ::sf::gui::rotateSelection {da} {
    variable selection
    set pairs {}
    foreach id $selection {
        set a [element cget $id -angle]
        if {$a eq {}} continue
        lappend pairs [list [list element configure $id -angle [expr {$a + $da}]] \
                           [list element configure $id -angle $a]]
    }
    if {[llength $pairs]} { doAll "rotate" $pairs }
}

# Sets one option on every selected element (fix, velocity, force).
proc ::sf::gui::configureSelection {option value} {
    variable selection
    if {![llength $selection]} { status "nothing selected"; return }
    set pairs [lmap id $selection {
        list [list element configure $id $option $value] \
            [list element configure $id $option [element cget $id $option]]
    }]
    doAll "configure $option" $pairs
}

# Bonds every touching pair of the selection. Undo deletes the bonds by their
# pairs of elements (a redo makes new bond ids).
proc ::sf::gui::bondSelection {} {
    variable selection
    variable undoStack
    if {[llength $selection] < 2} { status "select two or more elements to bond"; return }
    set before [bond ids]
    set cmd [list bond auto -elements $selection]
    set n [do $cmd]
    set pairs [lmap b [bond ids] {
        expr {$b in $before ? [continue] : [dict get [bond info $b] elements]}
    }]
    if {[llength $pairs]} {
        lappend undoStack [list "bond $n" $cmd [list ::sf::gui::unbond $pairs]]
    }
    status "[runbar::counted $n bond] made"
}

# Deletes the bonds between the given pairs of elements.
proc ::sf::gui::unbond {pairs} {
    foreach b [bond ids] {
        set e [dict get [bond info $b] elements]
        if {$e in $pairs || [lreverse $e] in $pairs} { bond delete $b }
    }
}

proc ::sf::gui::sourceSelection {} {
    variable selection
    if {[llength $selection] != 1} { status "select one element to make a source"; return }
    set id [lindex $selection 0]
    do [list source create $id] [list source delete $id] "source $id"
}
