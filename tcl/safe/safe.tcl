# Safe mode (docs/robustness.md): `sandflow -safe ?-outdir DIR? script.tcl`
# runs an untrusted script in a safe interpreter made by Tcl's safe base. It
# has the sandflow commands and the thesis layer; its files -- sandflow's
# outputs, `open`, `file mkdir` and the like -- stay inside DIR. No `exec`,
# no `cd`, no `load` or `source` beyond Tcl's own library, tcllib's cmdline
# and the thesis layer. This file runs in the trusted interpreter.

namespace eval ::sf::safe {
    # The file commands the script may use, each confined to the folder.
    variable fileVerbs {exists isdirectory isfile size mkdir delete}
}

# Runs SCRIPT with ARGUMENTS as argv in a new safe interpreter whose files stay
# in OUTDIR (made if missing; it becomes the current folder, so that plain
# names land there). COMPAT is the thesis layer's folder. Returns 0, or 1
# when the script failed, after printing its error.
proc ::sf::safe::run {outdir compat script arguments} {
    set script [file normalize $script]
    set chan [open $script]
    fconfigure $chan -encoding utf-8
    set text [read $chan]
    close $chan
    file mkdir $outdir
    cd $outdir
    set outdir [pwd]

    set access [list $::tcl_library $compat]
    if {![catch {package require cmdline}]} {
        lappend access [file dirname [lindex [package ifneeded cmdline [package present cmdline]] end]]
    }
    set slave [::safe::interpCreate -accessPath $access]
    interp share {} stdout $slave
    interp share {} stderr $slave
    load {} sandflow $slave
    interp alias $slave open {} ::sf::safe::openFile $slave $outdir
    interp alias $slave exit {} ::sf::safe::exitProgram
    variable fileVerbs
    set map [interp eval $slave {namespace ensemble configure ::file -map}]
    foreach verb $fileVerbs {
        interp eval $slave {namespace eval ::sf::safe {}}
        interp alias $slave ::sf::safe::file_$verb {} ::sf::safe::fileVerb $verb $outdir
        dict set map $verb ::sf::safe::file_$verb
    }
    interp eval $slave [list namespace ensemble configure ::file -map $map]
    interp eval $slave {namespace import ::sf::*; ::sf::shareSource}
    # The thesis layer, read through the safe base's own `source`.
    set token [::safe::interpFindInAccessPath $slave $compat]
    interp eval $slave [list namespace eval ::sf::thesis [list variable library $token]]
    interp eval $slave [list source [file join $token thesis.tcl]]
    interp eval $slave [list set argv $arguments]
    interp eval $slave [list set argc [llength $arguments]]
    interp eval $slave [list set argv0 [file tail $script]]

    # Caught inside, so that the trace and the line are the script's own.
    interp eval $slave {namespace eval ::sf::safe {}}
    set code [interp eval $slave [list ::catch $text ::sf::safe::result ::sf::safe::options]]
    if {$code == 1} {
        set options [interp eval $slave {::set ::sf::safe::options}]
        puts stderr "[dict get $options -errorinfo]\n    (file \"$script\" line [dict get $options -errorline])"
        return 1
    }
    return 0
}

# A path inside OUTDIR, normalised; an error otherwise. With orSelf, OUTDIR
# itself will do too (to ask whether it exists, or make it).
proc ::sf::safe::inside {outdir path {orSelf 0}} {
    if {[string index $path 0] eq "|"} {
        return -code error -errorcode {SANDFLOW SAFE PIPE} "safe mode starts no programs: \"$path\""
    }
    # (normalize resolves every link but the last component's)
    set full [file normalize [file join $outdir $path]]
    set ok [expr {[string first $outdir/ $full] == 0 || ($orSelf && $full eq $outdir)}]
    if {!$ok || ([::file exists $full] && [::file type $full] eq "link")} {
        return -code error -errorcode {SANDFLOW SAFE PATH} \
            "safe mode reads and writes files only in \"$outdir\": \"$path\" is outside it"
    }
    return $full
}

# `open` for the script: a file inside the folder, moved into its interpreter.
proc ::sf::safe::openFile {slave outdir path {access r} {permissions 0666}} {
    set chan [::open [inside $outdir $path] $access $permissions]
    interp transfer {} $chan $slave
    return $chan
}

# `file VERB PATH ...` for the script, each path inside the folder.
proc ::sf::safe::fileVerb {verb outdir args} {
    set paths {}
    foreach path $args {
        if {$verb eq "delete" && $path in {-force --}} {
            lappend paths $path
        } else {
            lappend paths [inside $outdir $path [expr {$verb in {exists isdirectory mkdir}}]]
        }
    }
    tailcall ::file $verb {*}$paths
}

# `exit ?code?` for the script: the program ends, its recordings finished.
proc ::sf::safe::exitProgram {{code 0}} {
    if {![string is integer -strict $code]} {
        return -code error "expected integer but got \"$code\""
    }
    ::exit $code
}
