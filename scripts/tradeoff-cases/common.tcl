# Shared by the scripts/tradeoff cases (docs/accuracy.md): the options every
# case takes, the run that turns a stop into an "unstable" result, and the
# one-row CSV each job writes.
#
#   source [file join [file dirname [info script]] common.tcl]
#   set options [tradeoff::options {{cells.arg 40 "..."} ...}]
#   tradeoff::start                    ;# the clock starts (scene setup counts)
#   if {![tradeoff::run N ?-every K script?]} { tradeoff::finish ... }
#   tradeoff::stop                     ;# the clock stops (measuring does not count)
#   tradeoff::finish ok ERROR ?ERROR2? ?VALUE? ?MESSAGE?
#
# The row (after a header): problem,knob,setting,resolution,status,error,
# error2,value,wall_s,cpu_s,steps,nodes,message. wall_s and cpu_s: the run's
# wall-clock and CPU seconds (the process's, from /proc/self/stat, in 10 ms
# ticks; empty where there is no /proc): on a shared machine the CPU time is
# the cost, the wall time what a user waits. status: ok, unstable (the run
# stopped with a SANDFLOW UNSTABLE error: no number), refused (a command
# refused the setting). error and error2 are relative errors against the
# case's exact value, or empty where scripts/tradeoff's summary takes the
# reference from another run (value is then what it compares).

namespace eval tradeoff {
    variable t0 {}
    variable wall {}
    variable cpu0 {}
    variable cpu {}
    variable o {}
}

proc tradeoff::options {rows} {
    variable o
    # -help makes scriptOptions print and end its caller: here the lambda,
    # so that this script ends too.
    set o [apply {{spec} {::sf::scriptOptions $spec}} [concat $rows {
        {problem.arg    {}  "problem name written in the row"}
        {knob.arg       {}  "knob name written in the row"}
        {setting.arg    {}  "setting label written in the row"}
        {resolution.arg {}  "resolution written in the row (cells per diameter, or across)"}
        {threads.arg    1   "threads of the step"}
        {out.arg        {}  "the one-row CSV file (default: standard output)"}
    }]]
    if {"-help" in $::argv || "-?" in $::argv} { exit 0 }
    sim configure -threads [dict get $o -threads]
    return $o
}

# CPU seconds of this process so far (user + system, all its threads).
proc tradeoff::cpuNow {} {
    if {[catch {
        set f [open /proc/self/stat]
        set stat [read $f]
        close $f
    }]} { return {} }
    set fields [string range $stat [expr {[string last ")" $stat] + 2}] end]
    return [expr {([lindex $fields 11] + [lindex $fields 12]) / 100.0}]
}
proc tradeoff::start {} {
    variable t0 [clock microseconds]
    variable cpu0 [cpuNow]
}
proc tradeoff::stop {} {
    variable t0
    variable wall
    variable cpu0
    variable cpu
    if {$wall eq {}} {
        set wall [expr {([clock microseconds] - $t0) * 1e-6}]
        set now [cpuNow]
        if {$now ne {} && $cpu0 ne {}} { set cpu [format %.2f [expr {$now - $cpu0}]] }
    }
}

# Runs N steps (extra arguments go to run). Returns 1, or 0 when the run
# stopped (the row is then written as unstable and the script ends).
proc tradeoff::run {n args} {
    if {[catch {uplevel #0 [list run $n {*}$args]} message opts]} {
        set code [dict get $opts -errorcode]
        stop
        if {[lindex $code 1] eq "UNSTABLE"} {
            finish unstable {} {} {} $message
        }
        finish error {} {} {} $message
    }
    return 1
}

# A setup command that may be refused (the row says so, the script ends).
proc tradeoff::try {args} {
    if {[catch {uplevel 1 $args} result]} {
        stop
        finish refused {} {} {} "[lrange $args 0 1]: $result"
    }
    return $result
}

proc tradeoff::csvField {s} {
    if {[string match {*[,\"]*} $s] || [string first "\n" $s] >= 0} {
        return "\"[string map {\" \"\"} [string map {"\n" " "} $s]]\""
    }
    return $s
}

proc tradeoff::fmt {x} {
    if {$x eq {}} { return {} }
    return [format %.6g $x]
}

# Writes the row and ends the script.
proc tradeoff::finish {status {error {}} {error2 {}} {value {}} {message {}}} {
    variable o
    variable wall
    variable cpu
    stop
    set steps [dict get [sim info] step]
    set nodes [expr {[catch {lattice info} li] ? 0 : [dict get $li nodes]}]
    set row [list [dict get $o -problem] [dict get $o -knob] [dict get $o -setting] \
                 [dict get $o -resolution] $status [fmt $error] [fmt $error2] [fmt $value] \
                 [format %.6f $wall] $cpu $steps $nodes $message]
    set line [join [lmap f $row {csvField $f}] ,]
    set header problem,knob,setting,resolution,status,error,error2,value,wall_s,cpu_s,steps,nodes,message
    if {[dict get $o -out] eq {}} {
        puts $header
        puts $line
    } else {
        set tmp [dict get $o -out].tmp
        set f [open $tmp w]
        puts $f $header
        puts $f $line
        close $f
        file rename -force $tmp [dict get $o -out]
    }
    exit 0
}
