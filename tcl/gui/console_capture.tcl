# The capture of stdout and stderr for the workbench's Tcl console
# (console.tcl sources it): channel transforms that show what puts writes
# in every console and pass it on unchanged.

namespace eval ::sf::gui::console {
    variable Capturing 0     ;# guards the capture against writing to itself
    variable Pending         ;# array: bytes of a split UTF-8 character, by channel
    variable Installed       ;# array: channel -> 1 once its transform is pushed
    array set Pending {stdout {} stderr {}}
    array set Installed {}
}

# Transforms on stdout and stderr show what is written in every console and
# pass it on unchanged, so the real streams (logs) still get it. They stay
# pushed for the life of the interpreter: popping could remove a transform
# someone pushed later; without consoles they only pass data through.
proc ::sf::gui::console::InstallCapture {} {
    variable Installed
    foreach {chan tag} {stdout output stderr warning} {
        # ("chan names" misses a std channel that has a transform already.)
        if {[info exists Installed($chan)]
            || [catch {chan push $chan [list ::sf::gui::console::Capture $chan $tag]}]} {
            continue
        }
        set Installed($chan) 1
        # Each puts reaches the console at once, not when a buffer fills.
        chan configure $chan -buffering none
    }
}

proc ::sf::gui::console::Capture {chan tag cmd args} {
    variable Consoles
    variable Capturing
    switch -- $cmd {
        initialize {
            return {initialize finalize write}
        }
        finalize {
            return
        }
        write {
            set data [lindex $args 1]
            if {[llength $Consoles] && !$Capturing} {
                set Capturing 1
                catch {
                    set text [Decode $chan $data]
                    foreach W $Consoles {
                        if {$text ne "" && [winfo exists $W.text]} {
                            Put $W $text $tag
                        }
                    }
                }
                set Capturing 0
            }
            return $data
        }
    }
}

# The transform sees encoded bytes; a UTF-8 character split between two
# writes waits for its end.
proc ::sf::gui::console::Decode {chan bytes} {
    variable Pending
    set bytes $Pending($chan)$bytes
    set Pending($chan) ""
    set encoding [chan configure $chan -encoding]
    if {$encoding eq "utf-8"
        && [regexp {[\xC0-\xF7][\x80-\xBF]*$} $bytes tail]} {
        set lead [scan [string index $tail 0] %c]
        set need [expr {$lead >= 0xF0 ? 4 : $lead >= 0xE0 ? 3 : 2}]
        if {[string length $tail] < $need} {
            set Pending($chan) $tail
            set bytes [string range $bytes 0 end-[string length $tail]]
        }
    }
    if {$encoding eq "binary"} {
        set encoding iso8859-1
    }
    return [encoding convertfrom $encoding $bytes]
}
