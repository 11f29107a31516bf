# The workbench's Tcl console: a text widget with a "% " prompt that
# evaluates commands at global level, with history, Tab completion of
# commands, sandflow verbs and options, and the output of puts (stdout and
# stderr, captured by channel transforms) shown above the prompt.
#
#   ::sf::gui::console::create W ?text option value ...?   -> W
#   ::sf::gui::console::write W text ?tag?     tag: output error warning echo
#                                              (also result hint)
#   ::sf::gui::console::echo W command         show a GUI action as typed
#   ::sf::gui::console::eval W script          -> {code result}, as if typed
#   ::sf::gui::console::history                the commands, oldest first
#   ::sf::gui::console::beforeEval             hook, called before each one
#   ::sf::gui::console::afterEval code result  hook, called after each one
#
# Layout of the text: the log, then the prompt, then the input:
#   ...log...<out>% <limit>input typed by the user<end>
# Both marks have left gravity and are moved explicitly. Everything before
# "limit" is read-only: the widget command is replaced by a proxy that
# refuses edits there (typing while the cursor is in the log goes to the
# input). While a typed command runs there is no prompt (out == limit) and
# what the user types waits for it.

package require Tk 8.6

namespace eval ::sf::gui::console {
    variable History {}      ;# typed and echoed commands, oldest first
    variable HistoryMax 500
    variable MaxLines 5000   ;# older log lines are dropped
    variable Consoles {}     ;# the consoles that show captured output
    variable S               ;# array: per-console state, keys "$W,name"
    array set S {}

    # Tags and their colours, on a light background.
    variable Colours {
        prompt  #1a3a8a
        input   #1a3a8a
        echo    #1a3a8a
        result  #000000
        output  #333333
        error   #b3261e
        warning #b35c00
        hint    #8a8a8a
        trace   #707070
        link    #6a7aa0
    }
}

# Default hooks; the GUI redefines them (its status bar, its view).
if {[info commands ::sf::gui::console::beforeEval] eq ""} {
    proc ::sf::gui::console::beforeEval {} {}
}
if {[info commands ::sf::gui::console::afterEval] eq ""} {
    proc ::sf::gui::console::afterEval {code result} {}
}

# Tab completion and the capture of stdout/stderr live in their own files.
source [file join [file dirname [file normalize [info script]]] console_complete.tcl]
source [file join [file dirname [file normalize [info script]]] console_capture.tcl]

# ---------------------------------------------------------------- creation

proc ::sf::gui::console::create {W args} {
    variable S
    ttk::frame $W
    set t $W.text
    text $t -font TkFixedFont -wrap char -undo 0 -width 80 -height 12 \
        -background #fbfbf8 -foreground #202020 -borderwidth 0 \
        -highlightthickness 0 -relief flat -padx 8 -pady 6 -spacing1 1 \
        -insertbackground #1a3a8a -insertwidth 2 \
        -selectbackground #c8daf4 -selectforeground #000000 \
        -inactiveselectbackground #dde6f2 \
        -yscrollcommand [list $W.sb set] {*}$args
    ttk::scrollbar $W.sb -orient vertical -command [list $t yview]
    grid $t $W.sb -sticky nsew
    grid columnconfigure $W 0 -weight 1
    grid rowconfigure $W 0 -weight 1
    ConfigureTags $t
    $t mark set out 1.0
    $t mark set limit 1.0
    $t mark gravity out left
    $t mark gravity limit left
    array set S [list $W,busy 0 $W,prompted 0 $W,soft 0 $W,walk {} \
                     $W,draft {} $W,traces 0 $W,follow 0]
    # The proxy: the widget's own command gets another name.
    rename $t [Real $W]
    interp alias {} $t {} ::sf::gui::console::Proxy $W
    Bindings $W
    bind $t <Destroy> [list ::sf::gui::console::Forget $W]
    InstallCapture
    variable Consoles
    lappend Consoles $W
    Prompt $W
    return $W
}

proc ::sf::gui::console::Real {W} {
    return ::sf::gui::console::real$W.text
}

proc ::sf::gui::console::ConfigureTags {t} {
    variable Colours
    foreach {tag colour} $Colours {
        $t tag configure $tag -foreground $colour
    }
    # Continuation lines of a command line up under its first character.
    set indent [font measure TkFixedFont "% "]
    foreach tag {prompt input echo} {
        $t tag configure $tag -lmargin2 $indent
    }
    foreach tag {input echo} {
        $t tag configure $tag -lmargin1 $indent
    }
    # Messages and printed lines wrap at words (typed code wraps anywhere).
    foreach tag {hint error warning output} {
        $t tag configure $tag -wrap word
    }
    $t tag configure trace -lmargin1 $indent -lmargin2 $indent
    $t tag configure link -underline 1
    $t tag bind link <Enter> [list $t configure -cursor hand2]
    $t tag bind link <Leave> [list $t configure -cursor xterm]
    # The selection stays visible over coloured text.
    $t tag raise sel
}

proc ::sf::gui::console::Forget {W} {
    variable S
    variable Consoles
    catch {interp alias {} $W.text {}}
    array unset S $W,*
    set Consoles [lsearch -all -inline -exact -not $Consoles $W]
}

# ---------------------------------------------------------------- the proxy

# True when word is "full" or an abbreviation of it (Tk accepts those).
proc ::sf::gui::console::Is {word full min} {
    expr {[string length $word] >= $min && [string first $word $full] == 0}
}

proc ::sf::gui::console::Proxy {W cmd args} {
    set r [Real $W]
    if {[Is $cmd insert 3]} {
        return [UserInsert $r {*}$args]
    }
    if {[Is $cmd delete 3]} {
        return [UserDelete $r {*}$args]
    }
    if {[Is $cmd replace 3]} {
        return [UserReplace $r {*}$args]
    }
    return [$r $cmd {*}$args]
}

# Text typed or pasted into the log goes to the end of the input instead.
proc ::sf::gui::console::UserInsert {r index args} {
    set i [$r index $index]
    if {[$r compare $i < limit]} {
        set i [$r index end-1c]
        $r mark set insert $i
    }
    set text ""
    foreach {chars tags} $args {
        append text $chars
    }
    $r insert $i $text input
}

# Only the input may be deleted: ranges are cut at the limit.
proc ::sf::gui::console::UserDelete {r args} {
    set idx {}
    foreach i $args {
        lappend idx [$r index $i]
    }
    if {[llength $idx] % 2} {
        lappend idx [$r index "[lindex $idx end] + 1c"]
    }
    set keep {}
    foreach {a b} $idx {
        if {[$r compare $b <= limit]} continue
        if {[$r compare $a < limit]} {
            set a [$r index limit]
        }
        lappend keep $a $b
    }
    if {[llength $keep]} {
        $r delete {*}$keep
    }
}

proc ::sf::gui::console::UserReplace {r a b args} {
    if {[$r compare $b <= limit]} {
        return [UserInsert $r end {*}$args]
    }
    if {[$r compare $a < limit]} {
        set a limit
    }
    set text ""
    foreach {chars tags} $args {
        append text $chars
    }
    $r replace $a $b $text input
}

# ---------------------------------------------------------------- the log

proc ::sf::gui::console::write {W text {tag output}} {
    if {[winfo exists $W.text]} {
        Put $W $text $tag
    }
}

# Appends text/tags pairs to the log above the prompt, leaving the input,
# and the cursor in it, alone. A text that ends mid-line gets a "soft"
# newline so the prompt stays on a line of its own; the next write
# continues the line.
proc ::sf::gui::console::Put {W args} {
    variable S
    set r [Real $W]
    set follow [expr {$S($W,follow) || ![winfo ismapped $W.text]
                      || [lindex [$r yview] 1] >= 1.0}]
    set prompt [$r count -chars out limit]
    if {$S($W,soft)} {
        $r delete out-1c out
        set S($W,soft) 0
    }
    # A right-gravity mark follows the inserted text; out stays before it.
    $r mark set put out
    $r mark gravity put right
    set last ""
    foreach {text tags} $args {
        $r insert put $text $tags
        if {$text ne ""} {
            set last $text
        }
    }
    if {$last ne "" && [string index $last end] ne "\n"} {
        $r insert put \n
        set S($W,soft) 1
    }
    $r mark set out put
    $r mark set limit "out + $prompt chars"
    $r mark unset put
    Trim $W
    if {$follow} {
        Follow $W
    }
}

# Scrolls to the end once the burst of output is over: "see" costs a
# layout, too much to pay for every line of a chatty run.
proc ::sf::gui::console::Follow {W} {
    variable S
    if {!$S($W,follow)} {
        set S($W,follow) 1
        after idle [list ::sf::gui::console::SeeEnd $W]
    }
}

proc ::sf::gui::console::SeeEnd {W} {
    variable S
    if {[info exists S($W,follow)]} {
        set S($W,follow) 0
        [Real $W] see end
    }
}

proc ::sf::gui::console::Trim {W} {
    variable MaxLines
    set r [Real $W]
    set lines [lindex [split [$r index out] .] 0]
    # Trim in batches: deleting from the top is not free.
    if {$lines > $MaxLines + 100} {
        $r delete 1.0 [expr {$lines - $MaxLines}].0
    }
}

proc ::sf::gui::console::Prompt {W} {
    variable S
    set r [Real $W]
    set p [$r index out]
    $r insert out "% " prompt
    $r mark set out $p
    $r mark set limit "$p + 2 chars"
    set S($W,prompted) 1
    $r see end
}

proc ::sf::gui::console::Clear {W} {
    variable S
    set r [Real $W]
    $r delete 1.0 out
    set S($W,soft) 0
    array unset S $W,trace,*
    foreach tag [lsearch -all -inline -glob [$r tag names] link#*] {
        $r tag delete $tag
    }
    $r see insert
}

# ---------------------------------------------------------------- evaluation

proc ::sf::gui::console::echo {W command} {
    AddHistory $command
    if {[winfo exists $W.text]} {
        Put $W "% " prompt $command\n echo
    }
}

proc ::sf::gui::console::eval {W script} {
    echo $W $script
    return [Run $W $script]
}

# Return: evaluate a complete input, else continue it on a new line.
proc ::sf::gui::console::Return {W} {
    variable S
    set r [Real $W]
    set cmd [$r get limit end-1c]
    # As tclsh reads it: a line ends with a newline (so "a \" continues).
    if {![info complete $cmd\n]} {
        Newline $W
        return
    }
    if {[string trim $cmd] eq "" && $S($W,busy)} {
        return
    }
    Submit $W $cmd
}

proc ::sf::gui::console::Newline {W} {
    set r [Real $W]
    if {[$r compare insert < limit]} {
        $r mark set insert end-1c
    }
    $r insert insert \n input
    $r see insert
}

# The input joins the log and the prompt goes until the command returns.
proc ::sf::gui::console::Submit {W cmd} {
    variable S
    set r [Real $W]
    # Typed while another command ran: it goes to the log as if prompted.
    if {!$S($W,prompted)} {
        $r insert limit "% " prompt
    }
    # Trailing empty lines (Shift-Return) are not worth a place in the log.
    while {[$r compare end-1c > limit] && [$r get end-2c] eq "\n"} {
        $r delete end-2c
    }
    $r insert end-1c \n input
    $r mark set out end-1c
    $r mark set limit end-1c
    $r mark set insert end-1c
    set S($W,prompted) 0
    set S($W,soft) 0
    set S($W,walk) {}
    $r see end
    if {[string trim $cmd] eq ""} {
        Prompt $W
        return
    }
    AddHistory $cmd
    Run $W $cmd
}

# Evaluates at global level; nested calls (a command that serves events
# while the user types another) each show their own result, and the prompt
# comes back when the outermost returns.
proc ::sf::gui::console::Run {W script} {
    variable S
    if {[info exists S($W,busy)]} {
        incr S($W,busy)
    }
    if {[catch beforeEval msg]} {
        Put $W "beforeEval: $msg\n" warning
    }
    set code [catch {uplevel #0 $script} result opts]
    if {[info exists S($W,busy)]} {
        incr S($W,busy) -1
        Show $W $code $result $opts
    }
    if {[catch {afterEval $code $result} msg]} {
        if {[info exists S($W,busy)]} {
            Put $W "afterEval: $msg\n" warning
        }
    }
    if {[info exists S($W,busy)] && $S($W,busy) == 0 && !$S($W,prompted)} {
        Prompt $W
    }
    return [list $code $result]
}

proc ::sf::gui::console::Show {W code result opts} {
    switch -- $code {
        0 - 2 {
            if {$result ne ""} {
                Put $W $result\n result
            }
        }
        1 {
            ShowError $W $result [dict get $opts -errorinfo] [dict get $opts -errorcode]
        }
        3 {
            ShowError $W {invoked "break" outside of a loop} {}
        }
        4 {
            ShowError $W {invoked "continue" outside of a loop} {}
        }
        default {
            ShowError $W "command returned bad code: $code" {}
        }
    }
}

# The message in red; behind a "(details)" link, its error code (what a
# script can catch) and the stack trace.
proc ::sf::gui::console::ShowError {W message info {code {}}} {
    variable S
    if {![winfo exists $W.text]} return
    set trace [Trace $message $info]
    if {$code ni {{} NONE}} {
        set trace "error code: $code\n$trace"
    }
    set trace [string trimright $trace]
    if {$trace eq ""} {
        Put $W $message\n error
        return
    }
    set n [incr S($W,traces)]
    set S($W,trace,$n) $trace
    set link link#$n
    Put $W $message error "  " error (details) [list hint link $link] \n error
    [Real $W] tag bind $link <ButtonRelease-1> \
        [list ::sf::gui::console::Details $W $n]
}

# The frames of errorInfo below the message (the command typed itself is
# one: a user who typed several lines sees which failed).
proc ::sf::gui::console::Trace {message info} {
    # Our own "uplevel" frame ends every trace: drop it.
    set cut [string last "\n    (\"uplevel\" body line" $info]
    if {$cut >= 0} {
        set info [string range $info 0 $cut-1]
    }
    if {[string first $message $info] == 0} {
        set info [string range $info [string length $message] end]
    }
    return [string trimleft $info \n]
}

proc ::sf::gui::console::Details {W n} {
    variable S
    set r [Real $W]
    set range [$r tag ranges link#$n]
    if {$range eq "" || ![info exists S($W,trace,$n)]} return
    lassign $range a b
    $r delete $a $b
    $r insert $a \n$S($W,trace,$n) trace
    $r tag delete link#$n
    unset S($W,trace,$n)
    $r configure -cursor xterm
}

# ---------------------------------------------------------------- history

proc ::sf::gui::console::history {} {
    variable History
    return $History
}

proc ::sf::gui::console::AddHistory {cmd} {
    variable History
    variable HistoryMax
    set cmd [string trimright $cmd]
    if {[string trim $cmd] eq "" || $cmd eq [lindex $History end]} return
    lappend History $cmd
    if {[llength $History] > $HistoryMax} {
        set History [lrange $History end-[expr {$HistoryMax - 1}] end]
    }
}

# Up on the first line of the input (Down on its last) walks the history;
# elsewhere the keys move the cursor as usual. Returns 1 when handled.
proc ::sf::gui::console::Up {W} {
    variable S
    variable History
    set r [Real $W]
    if {[$r compare insert < limit]
        || [$r compare "insert linestart" > "limit linestart"]} {
        return 0
    }
    if {$S($W,walk) eq ""} {
        set S($W,draft) [$r get limit end-1c]
        set S($W,walk) [llength $History]
    }
    if {$S($W,walk) == 0} {
        bell
        return 1
    }
    incr S($W,walk) -1
    # The cursor on the first line, so that Up again goes on at once.
    SetInput $W [lindex $History $S($W,walk)] "limit lineend"
    return 1
}

proc ::sf::gui::console::Down {W} {
    variable S
    variable History
    set r [Real $W]
    if {[$r compare insert < limit]
        || [$r compare "insert lineend" < end-1c]} {
        return 0
    }
    if {$S($W,walk) eq ""} {
        return 1
    }
    incr S($W,walk)
    if {$S($W,walk) >= [llength $History]} {
        set S($W,walk) {}
        SetInput $W $S($W,draft) end-1c
    } else {
        SetInput $W [lindex $History $S($W,walk)] end-1c
    }
    return 1
}

proc ::sf::gui::console::SetInput {W text cursor} {
    set r [Real $W]
    $r delete limit end-1c
    $r insert limit $text input
    $r mark set insert $cursor
    $r tag remove sel 1.0 end
    $r see insert
}

# ---------------------------------------------------------------- keys

proc ::sf::gui::console::Bindings {W} {
    set t $W.text
    set ns ::sf::gui::console
    foreach key {<Return> <KP_Enter>} {
        bind $t $key "[list ${ns}::Return $W]; break"
    }
    foreach key {<Shift-Return> <Control-Return> <Shift-KP_Enter>} {
        bind $t $key "[list ${ns}::Newline $W]; break"
    }
    bind $t <Up> "if {\[[list ${ns}::Up $W]\]} break"
    bind $t <Down> "if {\[[list ${ns}::Down $W]\]} break"
    bind $t <Tab> "[list ${ns}::Complete $W]; break"
    foreach key {<Home> <Control-a>} {
        bind $t $key "[list ${ns}::Home $W]; break"
    }
    bind $t <Control-l> "[list ${ns}::Clear $W]; break"
    foreach key {<Control-c> <<Copy>>} {
        bind $t $key "[list tk_textCopy $t]; break"
    }
    foreach key {<Control-v> <<Paste>>} {
        bind $t $key "[list ${ns}::Paste $W]; break"
    }
}

proc ::sf::gui::console::Home {W} {
    set r [Real $W]
    if {[$r compare insert < limit]
        || [$r compare "insert linestart" <= "limit linestart"]} {
        set to limit
    } else {
        set to "insert linestart"
    }
    $r mark set insert $to
    $r tag remove sel 1.0 end
    $r see insert
}

proc ::sf::gui::console::Paste {W} {
    set t $W.text
    if {[catch {::tk::GetSelection $t CLIPBOARD} text]} return
    set r [Real $W]
    if {[$r compare insert < limit]} {
        $r mark set insert end-1c
    }
    $t insert insert $text
    $r see insert
}
