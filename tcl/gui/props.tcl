# The property panel: the options of the selected element, or of the lattice,
# `sim`, the view or a material, as `configure` reports them, each editable.
# An edit is the `configure` command a user could type, with the same
# validation; a refused value leaves the scene unchanged and the message
# stands beside the field until the next command succeeds.
#
# Numbers show as typed, else to 6 significant digits; a field applied with
# some of its numbers untouched sends those at full precision.

namespace eval ::sf::gui::props {
    variable f ""
    variable target sim         ;# what is shown: sim, lattice, view, element ID, material NAME
    variable chosen sim         ;# the last target chosen that is not an element
    variable values             ;# option -> value in the entry
    variable shown              ;# option -> value the field showed for the scene
    variable full               ;# option -> the scene's value, every digit
    variable typed              ;# option -> {text value}: text typed that gave the value
    variable errors             ;# option -> {refused message N}: the last refused edit, N
                                ;# the commands started by then (::sf::gui::started)
    variable flags              ;# option,choice -> 1 where a flags option holds the choice
    variable choicesOf          ;# flags option -> its choices, in order
    array set values {}
    array set flags {}
    array set choicesOf {}
    array set shown {}
    array set full {}
    array set typed {}
    array set errors {}
}

proc ::sf::gui::props::create {path} {
    variable f
    ttk::frame $path -padding 4
    ttk::label $path.title -text Properties -style Heading.TLabel
    ttk::combobox $path.target -textvariable ::sf::gui::props::target -state readonly -width 18 \
        -postcommand ::sf::gui::props::targets
    ::bind $path.target <<ComboboxSelected>> ::sf::gui::props::chosen
    ttk::frame $path.rows
    ttk::label $path.info -justify left -foreground #444444 -wraplength 260
    grid $path.title -sticky w
    grid $path.target -sticky ew -pady {2 6}
    grid $path.rows -sticky nsew
    grid $path.info -sticky ew -pady {6 0}
    grid columnconfigure $path 0 -weight 1
    # Messages wrap to the panel's width, whatever the pane gives it.
    ::bind $path <Configure> {::sf::gui::props::wrap %w}
    set f $path
    # A run (from a script, the console or Run) shows the settings it runs
    # with, and what it ends with.
    trace add execution ::sf::run enter ::sf::gui::props::runTraced
    trace add execution ::sf::run leave ::sf::gui::props::runTraced
    show
    return $path
}

proc ::sf::gui::props::wrap {width} {
    variable f
    set length [expr {max(100, $width - 12)}]
    $f.info configure -wraplength $length
    foreach w [winfo children $f.rows] {
        if {[string match $f.rows.x* $w]} { $w configure -wraplength $length }
    }
}

proc ::sf::gui::props::runTraced {args} {
    if {![::sf::gui::running]} refresh
}

# A target picked from the list.
proc ::sf::gui::props::chosen {} {
    variable target
    variable chosen
    if {[lindex $target 0] ne "element"} { set chosen $target }
    show
}

proc ::sf::gui::props::targets {} {
    variable f
    set list {sim view}
    if {![catch {lattice info}]} { lappend list lattice }
    foreach m [material names] { lappend list "material $m" }
    foreach id $::sf::gui::selection { lappend list "element $id" }
    $f.target configure -values $list
}

# The selection decides what is shown: one element; of several, one of
# them; with none, what was last chosen from the list (sim at first).
proc ::sf::gui::props::refresh {} {
    variable target
    variable chosen
    variable f
    if {$f eq ""} return
    set selection $::sf::gui::selection
    if {[lindex $target 0] eq "element" && [lindex $target 1] in $selection &&
            [llength $selection] > 1} {
        # one of several, picked from the list: kept
    } elseif {[llength $selection]} {
        set target "element [lindex $selection 0]"
    } elseif {[lindex $target 0] eq "element"} {
        set target $chosen
    }
    if {$target eq "lattice" && [catch {lattice cget -spacing}]} { set target sim }
    if {[lindex $target 0] eq "material" && [lindex $target 1] ni [material names]} {
        set target sim
    }
    show
}

# The configure/cget command prefix of the target.
proc ::sf::gui::props::prefix {} {
    variable target
    switch [lindex $target 0] {
        element { return [list element configure [lindex $target 1]] }
        material { return [list material configure [lindex $target 1]] }
        default { return [list $target configure] }
    }
}

proc ::sf::gui::props::show {} {
    variable f
    variable values
    variable shown
    variable full
    variable typed
    variable errors
    variable flags
    variable choicesOf
    variable lastTarget
    variable target
    set rows $f.rows
    # A refused edit, and what was typed, belong to what they were typed for.
    if {![info exists lastTarget] || $lastTarget ne $target} {
        foreach opt [array names errors] { clearError $opt }
        array unset typed
        set lastTarget $target
    }
    if {[catch {uplevel #0 [prefix]} options]} {
        set options {}
    }
    # A refusal lasts until a command started after it succeeds; then its
    # field shows the scene's value, even while it has the focus.
    set answered {}
    foreach opt [array names errors] {
        if {[lindex $errors($opt) 2] < $::sf::gui::settled} {
            clearError $opt
            lappend answered $opt
        }
    }
    # An element's table lists only the options that apply to its shape.
    set table [table]
    set keep {}
    foreach {opt value} $options {
        if {[lindex $target 0] eq "element" && [dict size $table] && ![dict exists $table $opt]} {
            continue
        }
        lappend keep $opt $value
    }
    # Rebuild the rows only when the set of options changes (typing is kept).
    set names [dict keys $keep]
    if {[winfo children $rows] eq {} || [lsort [array names shown]] ne [lsort $names]} {
        foreach child [winfo children $rows] { destroy $child }
        array unset values
        array unset shown
        array unset full
        array unset typed
        array unset errors
        array unset flags
        array unset choicesOf
        set r 0
        foreach opt $names {
            set key [string range $opt 1 end]
            ttk::label $rows.l$key -text $opt
            # The option table, where the noun has one, picks the field.
            set row [expr {[dict exists $table $opt] ? [dict get $table $opt] : {}}]
            set type [expr {$row ne {} ? [dict get $row type] : "text"}]
            if {$type eq "choice"} {
                ttk::combobox $rows.e$key -textvariable ::sf::gui::props::values($opt) -width 14 \
                    -values [choices $row] -state readonly
                ::bind $rows.e$key <<ComboboxSelected>> [list ::sf::gui::props::apply $opt]
            } elseif {$type eq "boolean"} {
                ttk::checkbutton $rows.e$key -variable ::sf::gui::props::values($opt) \
                    -onvalue 1 -offvalue 0 -command [list ::sf::gui::props::apply $opt]
            } elseif {$type eq "flags"} {
                # One checkbutton per choice ({x y rot} of -fix), side by side.
                ttk::frame $rows.e$key
                set choicesOf($opt) [dict get $row choices]
                foreach c $choicesOf($opt) {
                    ttk::checkbutton $rows.e$key.$c -text $c \
                        -variable ::sf::gui::props::flags($opt,$c) \
                        -command [list ::sf::gui::props::applyFlags $opt]
                    pack $rows.e$key.$c -side left -padx {0 8}
                    if {$row ne {}} { ::sf::gui::tip $rows.e$key.$c [describe $row] }
                }
            } else {
                # Short numbers: the column, not the entry, sets the width.
                ttk::entry $rows.e$key -textvariable ::sf::gui::props::values($opt) -width 8
            }
            if {$row ne {}} {
                ::sf::gui::tip $rows.l$key [describe $row]
                ::sf::gui::tip $rows.e$key [describe $row]
            }
            ttk::label $rows.x$key -foreground #c92a2a -justify left \
                -wraplength [expr {max(100, [winfo width $f] - 12)}]
            # Each option takes two rows: the field, and its refusal beneath.
            grid $rows.l$key -row [expr {2 * $r}] -column 0 -sticky ew -pady 2 -padx {0 8}
            grid $rows.e$key -row [expr {2 * $r}] -column 1 -sticky ew -pady 2 -padx {0 2}
            grid $rows.x$key -row [expr {2 * $r + 1}] -column 0 -columnspan 2 -sticky w
            grid remove $rows.x$key
            ::bind $rows.e$key <Return> [list ::sf::gui::props::apply $opt]
            ::bind $rows.e$key <KP_Enter> [list ::sf::gui::props::apply $opt]
            ::bind $rows.e$key <FocusOut> [list ::sf::gui::props::apply $opt]
            ::bind $rows.e$key <Escape> [list ::sf::gui::props::revert $opt]
            incr r
        }
        grid columnconfigure $rows 1 -weight 1
    }
    foreach {opt value} $keep {
        set key [string range $opt 1 end]
        set row [expr {[dict exists $table $opt] ? [dict get $table $opt] : {}}]
        # What was typed while the scene holds what it gave, else a short form.
        if {[info exists typed($opt)] && [lindex $typed($opt) 1] eq $value} {
            set text [lindex $typed($opt) 0]
        } else {
            unset -nocomplain typed($opt)
            set text [fieldOf $row $value]
        }
        set full($opt) $value
        set value $text
        if {[info exists errors($opt)]} {
            # A refused value stays in its field, its reason beneath it.
            lassign $errors($opt) refused message
            set values($opt) $refused
            $rows.x$key configure -text $message
            grid $rows.x$key
            $rows.e$key state invalid
        } elseif {![info exists shown($opt)] || $values($opt) eq $shown($opt) ||
                  [focus] ne "$rows.e$key" || $opt in $answered} {
            # A field being edited keeps what is typed in it.
            set values($opt) $value
        }
        set shown($opt) $value
        syncFlags $opt
        # Choices that change (an element's -material: the materials there are).
        if {[dict exists $table $opt] && [dict get $table $opt type] eq "choice"} {
            $rows.e$key configure -values [choices [dict get $table $opt]]
        }
    }
    $f.info configure -text [summary]
}

# Read-only facts under the options: what `info` says that is not an option.
proc ::sf::gui::props::summary {} {
    variable target
    switch [lindex $target 0] {
        element {
            set info [element info [lindex $target 1]]
            set lines [list "[dict get $info type] [dict get $info id]"]
            set n [llength $::sf::gui::selection]
            if {$n > 1} {
                lset lines 0 "[lindex $lines 0] (one of $n selected: choose another above)"
            }
            foreach key {mass area velocity contacts fluidforce} {
                set v [dict get $info $key]
                if {[llength $v] > 1} { set v [lmap x $v {format %.4g $x}] } else { set v [format %.4g $v] }
                lappend lines "$key  $v"
            }
            return [join $lines \n]
        }
        lattice {
            set info [lattice info]
            return [format "%d x %d nodes, h %.4g, dt %.4g, tau %.4g" [dict get $info nx] \
                        [dict get $info ny] [dict get $info spacing] [dict get $info timestep] \
                        [dict get $info tau]]
        }
        default { return "" }
    }
}

# The target's option table by name ({} for a noun without one): `NOUN options`,
# for an element those that apply to its shape.
proc ::sf::gui::props::table {} {
    variable target
    set table {}
    set cmd [list [lindex [prefix] 0] options]
    if {[lindex $target 0] eq "element"} { lappend cmd [lindex $target 1] }
    if {![catch {uplevel #0 $cmd} rows]} {
        foreach row $rows { dict set table [dict get $row name] $row }
    }
    return $table
}

# A row's tooltip: its help, unit, range and default.
proc ::sf::gui::props::describe {row} {
    set text [dict get $row help]
    if {[dict get $row unit] ne {}} { append text "\nunit: [dict get $row unit]" }
    set lo [dict get $row min]
    set hi [dict get $row max]
    if {$lo ne {} || $hi ne {}} {
        set range {}
        if {$lo ne {}} { lappend range "[expr {[dict get $row minopen] ? ">" : ">="}] $lo" }
        if {$hi ne {}} { lappend range "[expr {[dict get $row maxopen] ? "<" : "<="}] $hi" }
        append text "\nrange: [join $range { and }]"
    }
    if {[dict get $row choices] ne {}} {
        set which [expr {[dict get $row type] eq "flags" ? "any" : "one"}]
        append text "\n$which of: [join [dict get $row choices] {, }]"
    }
    set default [dict get $row default]
    if {[hasAuto $row]} {
        append text "\ndefault: auto (none set: chosen for you)"
    } else {
        append text "\ndefault: [expr {$default eq {} ? "none" : [tidy $default]}]"
    }
    return $text
}

# A value as the panel shows it: each number in it to 6 significant digits
# (a wall's -from reads 0.1, not 0.09999999999999998; a lattice's timestep
# 0.0166667); words that are not numbers, and lists within the list, as they
# are.
proc ::sf::gui::props::tidy {value} {
    if {[catch {llength $value}]} { return $value }
    set out {}
    foreach word $value {
        if {[string is double -strict $word] && ![string is entier -strict $word]} {
            set word [format %.6g $word]
            if {[string is entier -strict $word]} { append word .0 }
        }
        lappend out $word
    }
    return $out
}

# A field's words sent back: those left as the field showed them at full
# precision (0.0166667 untouched is 0.016666666666666666 again).
proc ::sf::gui::props::precise {opt text} {
    variable shown
    variable full
    if {![info exists full($opt)] || [catch {llength $text}] ||
            [catch {llength $shown($opt)}] || [catch {llength $full($opt)}] ||
            [llength $text] != [llength $full($opt)] ||
            [llength $shown($opt)] != [llength $full($opt)]} {
        return $text
    }
    lmap word $text was $shown($opt) exact $full($opt) {
        expr {$word eq $was ? $exact : $word}
    }
}

# A default that means "none set, chosen for you" shows as "auto": a choice
# whose default is empty (the view's -field: velocity with a lattice, else
# none), and a number whose default lies outside its range (sim's -timestep
# 0.0: the lattice's, or the elements'). The field "auto" looks like no
# value at all less than a blank or a 0.0 would.
proc ::sf::gui::props::hasAuto {row} {
    if {$row eq {}} { return 0 }
    set default [dict get $row default]
    if {[dict get $row type] eq "choice"} { return [expr {$default eq {}}] }
    if {![string is double -strict $default]} { return 0 }
    set lo [dict get $row min]
    set hi [dict get $row max]
    expr {($lo ne {} && ($default < $lo || ($default == $lo && [dict get $row minopen]))) ||
          ($hi ne {} && ($default > $hi || ($default == $hi && [dict get $row maxopen])))}
}
proc ::sf::gui::props::choices {row} {
    set choices [dict get $row choices]
    if {[hasAuto $row]} { set choices [linsert $choices 0 auto] }
    return $choices
}
# (if, not expr's ?: which would turn a value such as 1.50 into 1.5)
proc ::sf::gui::props::fieldOf {row value} {
    if {[hasAuto $row] && $value eq [dict get $row default]} { return auto }
    return [tidy $value]
}
proc ::sf::gui::props::valueOf {opt field} {
    set table [table]
    if {$field eq "auto" && [dict exists $table $opt] && [hasAuto [dict get $table $opt]]} {
        return [dict get $table $opt default]
    }
    return [precise $opt $field]
}

# Applies one edited field: the configure command, through ::sf::gui::do.
# The value last refused is not sent again (leaving its field, Return
# again): it stays, red, until it is changed or another command succeeds.
proc ::sf::gui::props::apply {opt} {
    variable values
    variable shown
    variable full
    variable typed
    variable errors
    variable f
    if {![info exists shown($opt)] || $values($opt) eq $shown($opt)} {
        clearError $opt
        return
    }
    if {[info exists errors($opt)] && $values($opt) eq [lindex $errors($opt) 0]} return
    set text $values($opt)
    set cmd [list {*}[prefix] $opt [valueOf $opt $text]]
    set undo [list {*}[prefix] $opt $full($opt)]
    if {[catch {::sf::gui::do $cmd $undo "[lindex [prefix] 0] $opt"} err]} {
        set errors($opt) [list $text $err $::sf::gui::started]
        show
        return
    }
    clearError $opt
    # What was typed shows while the scene holds what it gave.
    set cget [lreplace [prefix] 1 1 cget]
    if {![catch {uplevel #0 [list {*}$cget $opt]} now]} { set typed($opt) [list $text $now] }
    show
}

# A flags option's checkbutton changed: the list of the choices ticked.
proc ::sf::gui::props::applyFlags {opt} {
    variable values
    variable flags
    variable choicesOf
    set values($opt) [lmap c $choicesOf($opt) {
        if {!$flags($opt,$c)} continue
        set c
    }]
    apply $opt
}

proc ::sf::gui::props::revert {opt} {
    variable values
    variable shown
    clearError $opt
    if {![info exists shown($opt)]} return
    set values($opt) $shown($opt)
    syncFlags $opt
}

# A flags option's checkbuttons from its value.
proc ::sf::gui::props::syncFlags {opt} {
    variable values
    variable flags
    variable choicesOf
    if {![info exists choicesOf($opt)]} return
    foreach c $choicesOf($opt) { set flags($opt,$c) [expr {$c in $values($opt)}] }
}

proc ::sf::gui::props::clearError {opt} {
    variable errors
    variable f
    unset -nocomplain errors($opt)
    set key [string range $opt 1 end]
    if {[winfo exists $f.rows.x$key]} {
        grid remove $f.rows.x$key
        $f.rows.e$key state !invalid
    }
}
