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
    set state [list sim [sim configure] \
            simInfo [dict remove [sim info] mlups threads passes]]
    if {![catch {lattice configure} options]} {
        lappend state lattice $options \
                latticeInfo [dict remove [lattice info] threads memory bytespernode] \
                obstacles [lattice obstacles]
    }
    return $state
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
