# helpers.tcl -- procedures shared by the command tests (sourced by each
# *.test file; not a test file itself).
#
# The test files run in the sandflow application, where the commands are
# global. Run in a plain tclsh instead, they load the package and import it.

if {[info commands ::lattice] eq ""} {
    if {[info exists ::env(SANDFLOW_PKGDIR)] && $::env(SANDFLOW_PKGDIR) ne ""} {
        lappend ::auto_path $::env(SANDFLOW_PKGDIR)
    }
    package require sandflow
    namespace import ::sf::*
}

# The step's threads: one keeps these tiny lattices fast on a busy machine
# (and under AddressSanitizer); "reset" keeps the thread count.
sim configure -threads 1

# The application under test and a plain tclsh (set by all.tcl; defaults for
# a test file run on its own).
proc sfApp {} {
    if {[info exists ::env(SANDFLOW_APP)] && $::env(SANDFLOW_APP) ne ""} {
        return $::env(SANDFLOW_APP)
    }
    return [info nameofexecutable]
}

# An empty scene with the usual 10 x 10 lattice on the unit square
# (spacing 0.1, tau 1, so the timestep is 1/6) and any extra options.
proc newLattice {args} {
    reset
    lattice create -size {1 1} -cells 10 -viscosity 0.01 {*}$args
}

# The errorCode / errorInfo of a script that must fail.
proc errorCodeOf {script} {
    if {![catch {uplevel 1 $script} message options]} {
        return "no error (result \"$message\")"
    }
    return [dict get $options -errorcode]
}
proc errorInfoOf {script} {
    if {![catch {uplevel 1 $script} message options]} {
        return "no error (result \"$message\")"
    }
    return [dict get $options -errorinfo]
}

# 1 when two numbers (or two lists of numbers) agree to a relative tolerance.
proc near {a b {tolerance 1e-12}} {
    if {[llength $a] != [llength $b]} {return 0}
    foreach x $a y $b {
        if {abs($x - $y) > $tolerance * max(1.0, abs($x), abs($y))} {return 0}
    }
    return 1
}

# Warnings go to ::sf::warn; collect them instead of printing them.
proc collectWarnings {} {
    set ::warnings {}
    proc ::sf::warn {message} {lappend ::warnings $message}
}

# Everything a user can read back about the scene, to show that a refused
# command changed nothing.
proc sceneState {} {
    set state [list sim [sim configure] simInfo [simState]]
    if {![catch {lattice configure} options]} {
        lappend state lattice $options \
                latticeInfo [dict remove [lattice info] threads memory bytespernode] \
                obstacles [lattice obstacles]
    }
    return $state
}

# sim info less the figures of the last step's work (speed, threads,
# profile, cells measured again), which a load or reset clears.
proc simState {} {
    dict remove [sim info] mlups threads passes remeasured
}

# Reads a whole file (binary, so that the appended data does not trip an
# encoding).
proc readFile {path} {
    set f [open $path rb]
    set data [read $f]
    close $f
    return $data
}

# Runs the application with the given arguments (and standard input) and
# returns {status stdout stderr}; stdout and stderr without the final newline.
proc runApp {arguments {input ""}} {
    set dir [temporaryDirectory]
    set out [file join $dir app-[pid].out]
    set err [file join $dir app-[pid].err]
    set in [file join $dir app-[pid].in]
    set f [open $in w]
    puts -nonewline $f $input
    close $f
    set status 0
    if {[catch {exec [sfApp] {*}$arguments < $in > $out 2> $err} message options]} {
        set code [dict get $options -errorcode]
        if {[lindex $code 0] ne "CHILDSTATUS"} {
            file delete -- $in $out $err
            return -options $options $message
        }
        set status [lindex $code 2]
    }
    set result [list $status [string trimright [readFile $out] \n] [string trimright [readFile $err] \n]]
    file delete -- $in $out $err
    return $result
}

# Writes a script file in the scratch folder and returns its path.
proc scriptFile {name body} {
    set path [file join [temporaryDirectory] $name]
    set f [open $path w]
    puts -nonewline $f $body
    close $f
    return $path
}

# -match approx: the values a test returns, compared with the expected ones
# word by word, so that a failure prints both. An expected number matches a
# number within a relative tolerance (near's: 1e-12, or TOL where the
# expected list, or a list inside it, ends with "within TOL"; "by TOL" makes
# it an absolute one, as for the levels of a colour); a bound (>X,
# <X, >=X, <=X, or two of them as in >0.25<0.42) matches a number inside it;
# "same" matches a pair {value reference} of numbers (or of lists of them)
# that agree within the tolerance, for a reference known only at run time;
# {= VALUE} matches VALUE itself only (a string compared exactly, as
# tcltest's exact matching would); any other word matches a word that equals
# it or that it matches as a glob pattern; lists are compared word by word,
# nested lists too.
proc approxMatch {expected actual} {
    return [approxWord $expected $actual {within 1e-12}]
}
proc approxWord {expected actual tolerance} {
    if {![catch {llength $expected} n] && $n >= 2 && [lindex $expected end-1] in {within by}} {
        set tolerance [lrange $expected end-1 end]
        set expected [expr {$n == 3 ? [lindex $expected 0] : [lrange $expected 0 end-2]}]
    }
    if {![catch {llength $expected} n] && $n == 2 && [lindex $expected 0] eq "="} {
        return [expr {[lindex $expected 1] eq $actual}]
    }
    if {$expected eq "same"} {
        return [expr {![catch {llength $actual} m] && $m == 2
                      && [nearWords [lindex $actual 0] [lindex $actual 1] $tolerance]}]
    }
    if {$expected eq $actual} {return 1}
    set number {[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?}
    if {[string is double -strict $expected]} {
        return [nearWords $actual $expected $tolerance]
    }
    if {[regexp "^(>=|<=|>|<)($number)(?:(>=|<=|>|<)($number))?\$" $expected \
             -> op1 bound1 op2 bound2]} {
        if {![string is double -strict $actual]
                || [catch {expr "\$actual $op1 \$bound1"} ok] || !$ok} {return 0}
        return [expr {$op2 eq "" || (![catch {expr "\$actual $op2 \$bound2"} ok] && $ok)}]
    }
    # (a list of one word is unwrapped too, where that changes it)
    if {![catch {llength $expected} n] && ($n > 1 || ($n == 1 && [lindex $expected 0] ne $expected))
            && ![catch {llength $actual} m] && $m == $n} {
        set all 1
        foreach e $expected a $actual {
            if {![approxWord $e $a $tolerance]} {set all 0; break}
        }
        if {$all} {return 1}
    }
    return [string match $expected $actual]
}
# 1 when two words are equal, or numbers within the tolerance ({within
# RELATIVE} or {by ABSOLUTE}), or lists of the same length whose words are.
proc nearWords {a b tolerance} {
    if {$a eq $b} {return 1}
    if {[string is double -strict $a] && [string is double -strict $b]} {
        lassign $tolerance kind t
        set scale [expr {$kind eq "by" ? 1.0 : "max(1.0, abs(\$a), abs(\$b))"}]
        # (a NaN is a word that matches no number)
        return [expr {![catch {expr "abs(\$a - \$b) <= \$t * $scale"} ok] && $ok}]
    }
    if {[catch {llength $a} na] || [catch {llength $b} nb] || $na != $nb || $na < 2} {return 0}
    foreach x $a y $b {
        if {![nearWords $x $y $tolerance]} {return 0}
    }
    return 1
}
customMatch approx approxMatch

# Where two values differ: {} when they are equal, else {path first second}
# for each differing word, the path made of list indices (or keys, where both
# are key-value lists with the same keys). A test that shows that something
# changed nothing returns this, expecting {}: a failure names what changed.
proc diffValues {a b {path {}}} {
    if {$a eq $b} {return {}}
    if {[catch {llength $a} na] || [catch {llength $b} nb] || $na != $nb || $na < 2} {
        return [list [list $path $a $b]]
    }
    set keyed [expr {$na % 2 == 0}]
    if {$keyed} {
        foreach {ka -} $a {kb -} $b {
            if {$ka ne $kb} {set keyed 0; break}
        }
    }
    set out {}
    if {$keyed} {
        foreach {key va} $a {- vb} $b {
            lappend out {*}[diffValues $va $vb [concat $path [list $key]]]
        }
    } else {
        for {set i 0} {$i < $na} {incr i} {
            lappend out {*}[diffValues [lindex $a $i] [lindex $b $i] [concat $path $i]]
        }
    }
    return $out
}

# "identical" when two byte strings are, else where they first differ.
proc compareBytes {a b} {
    if {$a eq $b} {return identical}
    set n [expr {min([string length $a], [string length $b])}]
    for {set i 0} {$i < $n && [string index $a $i] eq [string index $b $i]} {incr i} {}
    return "differ from byte $i (lengths [string length $a] and [string length $b])"
}
