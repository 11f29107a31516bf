# all.tcl -- runs the command tests (tcltest) of sandflow.
#
#   tclsh all.tcl -app /path/to/sandflow ?-pkgdir /path/to/build/lib? ?tcltest options?
#
# This driver runs in a plain tclsh. Each *.test file runs in its own process
# of the application (tcltest::interpreter is the sandflow executable, as
# design.md asks: a Tk-loaded interpreter would lose the exit code), and the
# parent adds up the "Total N Passed N Skipped N Failed N" line that every
# child prints. The last line of output is "N passed, N failed"; the exit
# status is non-zero when a test failed or a test file could not run.
#
# -pkgdir names the folder that holds the loadable package (build/lib, the
# parent of lib/sandflow/pkgIndex.tcl); package.test loads it into a plain
# tclsh. Other options (-verbose, -match, -file, -skip, -constraints ...) go
# to tcltest::configure and on to every child.

package require Tcl 8.6
package require tcltest 2.5

proc usage {message} {
    puts stderr "all.tcl: $message"
    puts stderr "usage: tclsh all.tcl -app SANDFLOW ?-pkgdir DIR? ?tcltest options?"
    exit 2
}

# Our own options first; the rest is tcltest's.
set app ""
set pkgdir ""
set rest {}
for {set i 0} {$i < [llength $argv]} {incr i} {
    set word [lindex $argv $i]
    switch -- $word {
        -app - -pkgdir {
            if {$i + 1 >= [llength $argv]} {usage "value for \"$word\" missing"}
            set [string range $word 1 end] [lindex $argv [incr i]]
        }
        default {lappend rest $word}
    }
}
if {$app eq ""} {usage "-app is required"}
set app [file normalize $app]
if {![file executable $app]} {usage "\"$app\" is not an executable"}
if {$pkgdir ne ""} {set pkgdir [file normalize $pkgdir]}

# The children learn about the programs through the environment (tcltest
# passes only its own options on to them).
set env(SANDFLOW_APP) $app
set env(SANDFLOW_PKGDIR) $pkgdir
set env(SANDFLOW_TCLSH) [info nameofexecutable]

# Scratch files go to a folder of our own, removed at the end.
set tmpRoot /tmp
foreach var {TMPDIR TEMP TMP} {
    if {[info exists env($var)] && [file isdirectory $env($var)]} {
        set tmpRoot $env($var)
        break
    }
}
set tmpdir [file join $tmpRoot sandflow-commands-[pid]-[clock milliseconds]]
file mkdir $tmpdir

set here [file dirname [file normalize [info script]]]
tcltest::configure -testdir $here -tmpdir $tmpdir -singleproc 0 {*}$rest
tcltest::interpreter $app

# Children that reported their totals: each child's totals line adds to
# numTests(Failed), so count those writes. A child that dies before it
# reports (a crash, an error at file level) is a file that could not run.
set reported 0
trace add variable ::tcltest::numTests(Failed) write {apply {args {incr ::reported}}}

# "Test file error: ..." is what runAllTests prints when a child exits with
# a non-zero status (also after its totals, e.g. a sanitizer's report at
# exit); watch the output for it with a transform on stdout.
set fileErrors 0
namespace eval watch {
    variable partial ""
    proc handler {cmd chan args} {
        variable partial
        switch -- $cmd {
            initialize {return {initialize finalize write flush}}
            finalize {return}
            flush {return}
            write {
                set data [lindex $args 0]
                append partial $data
                while {[set nl [string first \n $partial]] >= 0} {
                    if {[string match "Test file error:*" [string range $partial 0 $nl]]} {
                        incr ::fileErrors
                    }
                    set partial [string range $partial [expr {$nl + 1}] end]
                }
                return $data
            }
        }
    }
}
chan push stdout ::watch::handler

set totals {}
proc tcltest::cleanupTestsHook {} {
    variable numTests
    variable numTestFiles
    # (cleanupTests resets numTests after this hook: take the count now)
    set ::totals [list total $numTests(Total) passed $numTests(Passed) \
            skipped $numTests(Skipped) failed $numTests(Failed) \
            files $numTestFiles reported $::reported]
}

tcltest::runAllTests
flush stdout
chan pop stdout

catch {file delete -force -- $tmpdir}

if {$totals eq ""} {
    set totals {total 0 passed 0 skipped 0 failed 0 files 0 reported 0}
}
set reported [dict get $totals reported]
set passed [dict get $totals passed]
set failed [dict get $totals failed]
set files [dict get $totals files]
set problems {}
if {$files == 0} {
    lappend problems "no test files found in $here"
}
if {$reported < $files} {
    lappend problems "[expr {$files - $reported}] of $files test files reported no totals"
}
if {$fileErrors > 0} {
    lappend problems "$fileErrors test files exited with an error"
}
foreach p $problems {
    puts "all.tcl: $p"
}
puts "$passed passed, $failed failed"
flush stdout
exit [expr {$failed > 0 || [llength $problems] > 0}]
