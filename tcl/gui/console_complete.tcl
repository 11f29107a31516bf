# Tab completion for the workbench's Tcl console (console.tcl sources it):
# the candidates for the word before the cursor, commands, variables, file
# names, the verbs of ensembles, and the options parsed from help texts.

# Tab: the word before the cursor is completed; with several candidates
# their common prefix is, and the candidates are listed above the prompt.
proc ::sf::gui::console::Complete {W} {
    set r [Real $W]
    if {[$r compare insert < limit]} {
        $r mark set insert end-1c
    }
    # The command being typed: after the last newline, ";" or "[".
    regexp {[^\n;\[]*$} [$r get limit insert] cmd
    regexp {\S*$} $cmd partial
    set head [string range $cmd 0 end-[string length $partial]]
    set matches [Candidates [Words $head] $partial]
    if {![llength $matches]} {
        bell
        return
    }
    if {[llength $matches] == 1} {
        set word [lindex $matches 0]
        # A finished word gets its space, a namespace or folder does not.
        if {![string match *:: $word] && ![string match */ $word]
            && [$r get insert] ni {" " "\t"}} {
            append word " "
        }
    } else {
        set word [CommonPrefix $matches]
        ShowCandidates $W $matches
    }
    $r delete "insert - [string length $partial] chars" insert
    $r insert insert $word input
    $r see insert
}

proc ::sf::gui::console::ShowCandidates {W matches} {
    set shown [lrange $matches 0 99]
    if {[llength $matches] > 100} {
        lappend shown "... ([expr {[llength $matches] - 100}] more)"
    }
    Put $W "[join $shown {  }]\n" hint
}

proc ::sf::gui::console::Words {text} {
    if {[string is list $text]} {
        return $text
    }
    return [regexp -all -inline {\S+} $text]
}

proc ::sf::gui::console::CommonPrefix {words} {
    set p [lindex $words 0]
    foreach w $words {
        while {![string equal -length [string length $p] $p $w]} {
            set p [string range $p 0 end-1]
        }
    }
    return $p
}

# The completions of partial after the words before it: a command, a
# variable, an ensemble's verb, an option from the "help" text, a value of
# an option whose help lists its choices (a|b|c), else a file name.
proc ::sf::gui::console::Candidates {words partial} {
    if {[string index $partial 0] eq "\$"} {
        return [Variables [string range $partial 1 end]]
    }
    if {![llength $words]} {
        # Not every command at once.
        if {$partial eq ""} {
            return {}
        }
        return [Commands $partial]
    }
    set matches {}
    foreach word [Arguments $words $partial] {
        if {[string equal -length [string length $partial] $partial $word]} {
            lappend matches $word
        }
    }
    if {![llength $matches] && [string index $partial 0] ne "-"} {
        return [Files $partial]
    }
    return [lsort -dictionary -unique $matches]
}

# What may follow the words typed, from the ensembles and help texts.
proc ::sf::gui::console::Arguments {words partial} {
    set top [Origin [lindex $words 0]]
    if {$top eq ""} {
        return {}
    }
    # Follow the verbs typed through nested ensembles (lattice obstacle ...).
    set cmd $top
    set verbs {}
    set i 1
    while {$i < [llength $words] && [namespace ensemble exists $cmd]} {
        set next [Verb $cmd [lindex $words $i]]
        if {$next eq ""} break
        lassign $next verb cmd
        lappend verbs $verb
        incr i
    }
    if {[string index $partial 0] eq "-"} {
        return [dict keys [Options $top $verbs]]
    }
    if {$i == [llength $words] && [namespace ensemble exists $cmd]} {
        return [Subcommands $cmd]
    }
    set option [lindex $words end]
    if {[string match -* $option]} {
        set options [Options $top $verbs]
        if {[dict exists $options $option]
            && [regexp {^[\w.+-]+(\|[\w.+-]+)+$} [dict get $options $option]]} {
            return [split [dict get $options $option] |]
        }
    }
    return {}
}

proc ::sf::gui::console::Files {partial} {
    set found {}
    foreach f [glob -nocomplain -- [Glob $partial]] {
        if {[file isdirectory $f]} {
            append f /
        }
        lappend found $f
    }
    return [lsort -dictionary $found]
}

proc ::sf::gui::console::Glob {text} {
    return [string map {* \\* ? \\? [ \\[ ] \\] \\ \\\\ \{ \\\{ \} \\\}} $text]*
}

proc ::sf::gui::console::Commands {partial} {
    lsort -dictionary -unique \
        [namespace eval :: [list info commands [Glob $partial]]]
}

proc ::sf::gui::console::Variables {partial} {
    lmap v [uplevel #0 [list info vars [Glob $partial]]] {string cat \$ $v}
}

# The command a global name refers to, fully qualified, or "".
proc ::sf::gui::console::Origin {name} {
    if {[catch {namespace eval :: [list namespace origin $name]} origin]} {
        return ""
    }
    return $origin
}

proc ::sf::gui::console::Subcommands {ens} {
    set subs [namespace ensemble configure $ens -subcommands]
    if {![llength $subs]} {
        set subs [dict keys [namespace ensemble configure $ens -map]]
    }
    if {![llength $subs]} {
        # Neither given: the namespace's exported commands.
        set ns [namespace ensemble configure $ens -namespace]
        foreach pattern [namespace eval $ns {namespace export}] {
            foreach c [info commands ${ns}::$pattern] {
                lappend subs [namespace tail $c]
            }
        }
    }
    return [lsort -dictionary -unique $subs]
}

# {verb command} for a (possibly abbreviated) verb of an ensemble, or "".
proc ::sf::gui::console::Verb {ens word} {
    set subs [Subcommands $ens]
    if {$word ni $subs} {
        set found [lsearch -all -inline -glob $subs [Glob $word]]
        if {[llength $found] != 1
            || ![namespace ensemble configure $ens -prefixes]} {
            return ""
        }
        set word [lindex $found 0]
    }
    set map [namespace ensemble configure $ens -map]
    if {[dict exists $map $word]} {
        set target [lindex [dict get $map $word] 0]
    } else {
        set target [namespace ensemble configure $ens -namespace]::$word
    }
    set origin [Origin $target]
    if {$origin eq ""} {
        set origin $target
    }
    return [list $word $origin]
}

# The help text that lists a command's options. An ensemble answers
# "NAME help"; snapshot answers "snapshot help"; other sandflow commands
# have a line in "help". Nothing else is called: a command might act.
proc ::sf::gui::console::HelpText {cmd} {
    if {[namespace ensemble exists $cmd]} {
        if {"help" ni [Subcommands $cmd]
            || [catch {uplevel #0 [list $cmd help]} text]} {
            return ""
        }
        return $text
    }
    if {$cmd eq "::sf::snapshot"} {
        if {[catch {uplevel #0 [list $cmd help]} text]} {
            return ""
        }
        return $text
    }
    if {![string match ::sf::* $cmd] || [info commands ::sf::help] eq ""
        || [catch {uplevel #0 ::sf::help} text]} {
        return ""
    }
    set name [namespace tail $cmd]
    foreach line [split $text \n] {
        if {[lindex [Words $line] 0] eq $name} {
            return [string trim $line]
        }
    }
    return ""
}

# A dict option -> synopsis (e.g. -collision -> bgk|trt) for the verbs
# typed: the options on their usage lines, and the "options:" section
# when a usage line says "-option" (or refers to the view options).
proc ::sf::gui::console::Options {cmd verbs} {
    set usage {}
    set section {}
    set inSection 0
    foreach line [split [HelpText $cmd] \n] {
        if {[regexp {^options\M} $line]} {
            set inSection 1
        } elseif {$inSection} {
            if {[regexp {^\s+(-[A-Za-z]\w*)\s*(\S*)} $line -> o syn]} {
                dict set section $o $syn
            }
        } else {
            lappend usage $line
        }
    }
    set lines [VerbLines $usage $verbs]
    set options {}
    set all 0
    set views 0
    foreach line $lines {
        foreach {-> o syn} [regexp -all -inline \
                                {(?:^|[\s?(\[|])(-[A-Za-z]\w*)(?:\s+([^\s?]*))?} $line] {
            if {$o eq "-option"} {
                set all 1
            } elseif {![dict exists $options $o] || [dict get $options $o] eq ""} {
                dict set options $o $syn
            }
        }
        if {[string match "*view options*" $line]} {
            set views 1
        }
    }
    if {$all || ![llength $lines]} {
        set options [dict merge $section $options]
    }
    # "output movie ... ?view options?": those are view's.
    if {$views && $cmd ne "::sf::view" && [namespace ensemble exists ::sf::view]} {
        set options [dict merge [Options ::sf::view configure] $options]
    }
    return $options
}

# The usage lines of the verbs typed ("lattice obstacle circle ..."); when
# no line has all of them, those of fewer.
proc ::sf::gui::console::VerbLines {usage verbs} {
    for {set n [llength $verbs]} {$n >= 0} {incr n -1} {
        set lines {}
        foreach line $usage {
            set words [regexp -all -inline {\S+} $line]
            if {[llength $words] && [lrange $words 1 $n] eq [lrange $verbs 0 $n-1]} {
                lappend lines $line
            }
        }
        if {[llength $lines]} {
            return $lines
        }
    }
    return {}
}
