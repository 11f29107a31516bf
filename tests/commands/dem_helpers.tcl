# dem_helpers.tcl -- procedures shared by the tests of the discrete-element
# commands (material, element, bond, source, sim for elements); sourced after
# helpers.tcl, not a test file itself.

# Everything a user can read back about the elements, materials, bonds and
# sources, to show that a refused command changed nothing.
proc demState {} {
    set state [list ids [element ids] next [catch {element next} next] $next]
    foreach name [material names] {
        lappend state material $name [material configure $name]
    }
    foreach id [element ids] {
        lappend state element $id [element configure $id] [element info $id]
    }
    foreach id [bond ids] {
        lappend state bond $id [bond info $id]
    }
    lappend state broken [bond broken]
    foreach id [::sf::source ids] {
        lappend state source $id [::sf::source info $id]
    }
    lappend state sim [sim configure] simInfo [simState]
    return $state
}

# Runs each command of `commands` (a list of scripts) that must fail; returns
# the ones that were accepted ("accepted: ..."), that failed without a
# refusal's errorCode ("bad errorCode: ...") or that changed the scene. A
# refusal sets errorCode to SANDFLOW <CLASS> <DETAIL> (docs/commands.md,
# Conventions), or Tcl's own code for wrong arguments (TCL WRONGARGS), a bad
# option or subcommand (TCL LOOKUP ...), a bad value (TCL VALUE ...) or an
# integer out of range (ARITH IOVERFLOW, which Tcl_GetIntFromObj sets and
# src/tcl/args.cpp's getInt repeats for what an int cannot hold: the one code
# of Tcl's own outside TCL). An error that leaves errorCode NONE
# or unset is a script error (a typo in the test, a missing command) or a
# product bug, not a refusal, so it does not count as one.
proc refusedChangeNothing {commands} {
    set problems {}
    foreach command $commands {
        set before [demState]
        if {![catch {uplevel 1 $command} message options]} {
            lappend problems "accepted: $command"
            continue
        }
        set code [expr {[dict exists $options -errorcode]
                        ? [dict get $options -errorcode] : ""}]
        # Tcl's codes for an unknown command or an unset variable are the
        # test's own errors, not a refusal.
        if {([lindex $code 0] ni {SANDFLOW TCL} && [lrange $code 0 1] ne {ARITH IOVERFLOW})
                || [llength $code] < 2
                || [lrange $code 0 2] in {{TCL LOOKUP COMMAND} {TCL LOOKUP VARNAME}}} {
            lappend problems "bad errorCode \"$code\": $command ($message)"
        }
        if {[demState] ne $before} {
            lappend problems "changed the scene: $command ($message)"
        }
    }
    return $problems
}

# The result of a script that must fail, with its errorCode.
proc failure {script} {
    if {![catch {uplevel 1 $script} message options]} {
        return "no error (result \"$message\")"
    }
    return [list $message [dict get $options -errorcode]]
}

# The keys of `dict` that are missing from it, of those in `keys`.
proc missingKeys {dict keys} {
    set missing {}
    foreach key $keys {
        if {![dict exists $dict $key]} {lappend missing $key}
    }
    return $missing
}

# The words of `words` that do not occur in `text`.
proc missingWords {text words} {
    set missing {}
    foreach word $words {
        if {[string first $word $text] < 0} {lappend missing $word}
    }
    return $missing
}

set pi [expr {acos(-1)}]

# A value just outside the range of a row of `NOUN options` ({} for a row
# without one): the end itself where it is open, one beyond it where closed.
proc outOfRange {row} {
    set min [dict get $row min]
    set max [dict get $row max]
    set bad {}
    if {$min ne {}} {
        set bad [expr {[dict get $row minopen] ? $min : $min - 1}]
    } elseif {$max ne {}} {
        set bad [expr {[dict get $row maxopen] ? $max : $max + 1}]
    }
    if {$bad ne {} && [dict get $row type] eq "integer"} { set bad [expr {int($bad)}] }
    return $bad
}

# "SANDFLOW VALUE RADIUS" for the row of -radius.
proc valueCodeOf {row} {
    list SANDFLOW VALUE [string toupper [string range [dict get $row name] 1 end]]
}

# For each row of `rows` with a range, `NOUN configure ...` with a value out
# of it: the problems (see refusedChangeNothing), and each errorCode that is
# not SANDFLOW VALUE <OPTION>.
proc refusedOutOfRange {prefix rows} {
    set problems {}
    foreach row $rows {
        set bad [outOfRange $row]
        if {$bad eq {}} continue
        set command [list {*}$prefix [dict get $row name] $bad]
        lappend problems {*}[uplevel 1 [list refusedChangeNothing [list $command]]]
        set code [lindex [uplevel 1 [list failure $command]] 1]
        if {$code ne [valueCodeOf $row]} { lappend problems "errorCode \"$code\": $command" }
    }
    return $problems
}

# Each option of `rows` set, through `configure`, to what `cget` gives: the
# options whose `cget` then differs.
proc cgetRoundTrip {noun name rows} {
    set differ {}
    foreach row $rows {
        set opt [dict get $row name]
        set before [$noun cget $name $opt]
        if {[catch {$noun configure $name $opt $before} message]} {
            lappend differ "$opt {$before}: $message"
        } elseif {[$noun cget $name $opt] ne $before} {
            lappend differ "$opt {$before} -> {[$noun cget $name $opt]}"
        }
    }
    return $differ
}
