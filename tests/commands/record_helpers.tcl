# record_helpers.tcl -- what the record_*.test files share: a scratch
# folder, CSV rows and headers, small scenes, usage messages and the
# constraints; sourced after helpers.tcl, not a test file itself.

# Root may write into a read-only folder; those tests need an ordinary user.
testConstraint notRoot [expr {$::tcl_platform(user) ne "root"}]
testConstraint gnuplot [expr {[auto_execok gnuplot] ne ""}]

# A fresh, empty scratch folder for each test.
proc scratch {} {
    set dir [file join [temporaryDirectory] record-scratch]
    file delete -force -- $dir
    file mkdir $dir
    return $dir
}
proc cleanScratch {} {
    catch {output close}
    set dir [file join [temporaryDirectory] record-scratch]
    foreach d [list $dir [file join $dir ro]] {catch {file attributes $d -permissions 0755}}
    file delete -force -- $dir
}
# Every name in a folder, hidden ones (a left-over temporary file) included.
proc filesIn {dir} {
    set names [glob -nocomplain -directory $dir -tails *]
    foreach name [glob -nocomplain -directory $dir -tails .*] {
        if {$name ni {. ..}} {lappend names $name}
    }
    lsort $names
}
# A CSV file as a list of lines, each a list of fields.
proc csvLines {path} {
    set lines {}
    foreach line [split [string trimright [readFile $path] \n] \n] {
        lappend lines [split $line ,]
    }
    return $lines
}
proc writeText {path text} {
    set f [open $path w]
    puts -nonewline $f $text
    close $f
}

# A disc falling under gravity, nothing to touch (fixed timestep 1e-3).
proc fallingDisc {} {
    reset
    sim configure -gravity {0 -9.81} -timestep 1e-3
    disc create -center {0.25 0.5} -radius 0.05
}
# What output csv must write for one element now, from sim info and element info.
proc elementRow {id} {
    set s [sim info]
    set e [element info $id]
    lassign [dict get $e position] x y
    lassign [dict get $e velocity] vx vy w
    lassign [dict get $e force] fx fy
    lassign [dict get $e fluidforce] ffx ffy
    list [dict get $s step] [dict get $s time] $x $y [dict get $e angle] $vx $vy $w $fx $fy \
        [dict get $e torque] $ffx $ffy [dict get $e fluidtorque]
}
# 1 when two lists of numbers are equal, number by number (== on doubles:
# the file's shortest round-trip form reads back the very same double).
proc sameNumbers {a b} {
    if {[llength $a] != [llength $b]} {return 0}
    foreach x $a y $b {
        if {!($x == $y)} {return 0}
    }
    return 1
}
set elementColumns {x y angle vx vy w fx fy torque fluidfx fluidfy fluidtorque}
proc elementHeader {args} {
    set h {step time}
    foreach id $args {
        foreach c $::elementColumns {lappend h ${c}_$id}
    }
    return $h
}

# A 1 x 1 periodic box (h = 0.05) with a soft, dense disc of radius 0.2 in a
# fluid pushed along x: elements, contacts-free, with a fluid force.
proc coupledScene {} {
    reset
    lattice create -size {1 1} -cells 20 -viscosity 0.01 -walls {left periodic bottom periodic} \
        -forcing {1e-4 0}
    material create soft -density 4 -kn 1e-3 -ks 1e-3
    disc create -center {0.5 0.5} -radius 0.2 -material soft
}

# The width and height of a PNG file (its signature checked), or an error.
proc pngSize {path} {
    set data [readFile $path]
    binary scan $data a8Ia4II signature length chunk width height
    if {$signature ne "\x89PNG\r\n\x1a\n"} {return "not a PNG"}
    if {$chunk ne "IHDR"} {return "no IHDR"}
    list $width $height
}
# A small CSV file to plot.
proc sampleCsv {dir} {
    set path [file join $dir data.csv]
    writeText $path "step,time,a,b\n0,0,1,2\n1,0.5,2,3\n2,1,4,5\n"
    return $path
}

set csvUsage {wrong # args: should be "output csv FILE -elements IDS ?-every K?"}
set recordUsage {wrong # args: should be "record FILE ?-every K? ?-quantities LIST?"}
set plotUsage {wrong # args: should be "plot OUT.png CSVFILE ?-option value ...?"}
