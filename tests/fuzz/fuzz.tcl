# fuzz.tcl -- the command fuzzer (docs/robustness.md). Run by the sandflow
# application, best built with AddressSanitizer and UBSan:
#
#   sandflow tests/fuzz/fuzz.tcl ?-count N? ?-seed S? ?-dir DIR? ?-slow SECONDS? ?-quiet 0|1?
#
# It grows real scenes (lattices with walls and obstacles, elements of every
# shape, bonds, sources, short runs, recordings, snapshots, checkpoints saved
# and loaded, reset) from command lines whose arguments are mostly valid and
# sometimes boundary, wrong-type, huge, negative, NaN/Inf, empty or unicode
# values; it also loads mutated checkpoints and sources mutated scripts. After
# every command line:
#   - refused: the scene's `sim hash` is what it was before (a refused command
#     changes nothing; `run`, `step` and `source` excepted, which keep the
#     steps or commands done before their error), and the message is not empty;
#   - accepted: `sim check` is empty (no NaN, ids at their slots, finite masses,
#     ordered contacts, ...).
# A crash or a sanitizer report ends the process; a hang is caught by the
# caller's timeout (ctest, scripts/fuzz). DIR/fuzz.log holds every command line
# tried, each wrapped in `catch`, so `sandflow -c "source DIR/fuzz.log"`
# replays a run up to its crash. The last line printed is the summary:
#   fuzz: seed S, N command lines (A accepted, R refused), ... 0 failures
# Exit status 1 when any check failed. With -quiet 0 it also tallies accepted
# and refused lines per command; FUZZ_SHOW=PATTERN (an environment variable,
# a glob on the command's first words, e.g. "run") prints the refusals of the
# matching commands, to see why scenes stop growing.

set options [dict create -count 2000 -seed 1 -dir {} -slow 60 -quiet 1]
if {[llength $argv] % 2} { error "usage: fuzz.tcl ?-count N? ?-seed S? ?-dir DIR? ?-slow S? ?-quiet 0|1?" }
foreach {key value} $argv {
    if {![dict exists $options $key]} {
        error "bad option \"$key\": must be [join [dict keys $options] {, }]"
    }
    dict set options $key $value
}
dict with options {}
if {${-dir} eq {}} {
    set -dir [file join [expr {[info exists env(TMPDIR)] ? $env(TMPDIR) : "/tmp"}] \
                  sandflow-fuzz-[pid]]
}
file mkdir ${-dir}
set dir [file normalize ${-dir}]
# A mutated line may name an output file by a bare word: it lands here, not
# wherever the fuzzer was started.
cd $dir
# A run depends on the files of this run only: those of an earlier one go.
set mutants 0
foreach pattern {ck*.sfck mutant* vtk* series* e*.csv r*.csv shot*.png plot.png fuzz.log nosuchdir} {
    file delete -force {*}[glob -nocomplain -directory $dir $pattern]
}
expr {srand(${-seed})}
# Warnings are counted, not printed: thousands would drown the report.
set warnings 0
proc ::sf::warn {message} { incr ::warnings }

# ---- random choices ------------------------------------------------------------
proc chance {p} { expr {rand() < $p} }
proc pick {items} { lindex $items [expr {int(rand() * [llength $items])}] }
proc uniform {lo hi} { expr {$lo + ($hi - $lo) * rand()} }
proc between {lo hi} { expr {$lo + int(($hi - $lo + 1) * rand())} }
# A weighted choice: {weight value weight value ...}.
proc weighted {pairs} {
    set total 0.0
    foreach {w v} $pairs { set total [expr {$total + $w}] }
    set r [expr {rand() * $total}]
    foreach {w v} $pairs {
        if {[set r [expr {$r - $w}]] < 0} { return $v }
    }
    return [lindex $pairs end]
}

# Like weighted, over scripts: evaluates the one chosen in the caller.
proc choose {pairs} { uplevel 1 [weighted $pairs] }

# Values no option should take quietly, by class.
set bad [dict create \
    boundary {0 -0 0.5 1 -1 1e-300 4.9e-324 2147483647 -2147483648} \
    wrongtype {abc true yes {1 2} {1 2 3} {{}} {a b} 1e 0x 1..2 -- - end {#ff0000}} \
    huge {1e300 -1e300 1e18 9223372036854775807 9223372036854775808 2147483648 99999999999999999999999 1e308} \
    negative {-1 -0.5 -1e-9 -1000 -2147483649} \
    nonfinite {NaN nan -NaN Inf -Inf inf infinity 1e999 -1e999} \
    empty {{} { } {  }} \
    unicode "\u00e9 \u221e \u03bb\u03bb \u0000 a\u0000b \u4e2d\u6587 \U0001F600 \ufeff1"]
# Mostly the value given; sometimes a bad one (probability p).
proc maybe {value {p 0.05}} {
    if {![chance $p]} { return $value }
    set class [pick [dict keys $::bad]]
    return [pick [dict get $::bad $class]]
}
proc vec2 {x y} {
    if {[chance 0.04]} { return [pick {{} 1 {1 2 3} {a b} {NaN 0} {0 Inf} {1e300 1e300} {{1 2} 3}}] }
    list [maybe $x 0.03] [maybe $y 0.03]
}
proc point {} { vec2 [format %.4g [uniform 0.02 0.98]] [format %.4g [uniform 0.02 0.98]] }

# Option pairs: each included with probability p, from {name generator ...}.
proc options {p spec} {
    set words {}
    foreach {name script} $spec {
        if {[chance $p]} { lappend words $name [uplevel 1 $script] }
    }
    if {[chance 0.02]} { lappend words [pick {-bogus -id -center -x}] [maybe 1 0.5] }
    if {[chance 0.01]} { lappend words [pick {-radius -material -every}] }   ;# an option without its value
    return $words
}

# ---- the scene as it stands (queried, so that mutated loads are followed) ------
proc elementIds {} { if {[catch {element ids} ids]} { return {} }; return $ids }
proc anyElement {} {
    set ids [elementIds]
    if {[llength $ids] && [chance 0.9]} { return [pick $ids] }
    return [pick {-1 0 1 7 999999 2147483647 2147483648 abc {} 1.5}]
}
proc anyBond {} {
    if {![catch {bond ids} ids] && [llength $ids] && [chance 0.85]} { return [pick $ids] }
    return [pick {-1 0 3 99999 x {}}]
}
proc anyMaterial {} {
    if {[chance 0.05]} { return [pick {nosuch {} "\u00e9" {two words}}] }
    pick [material names]
}
proc anyObstacle {} {
    if {![catch {lattice obstacles} ids] && [llength $ids] && [chance 0.85]} { return [pick $ids] }
    return [pick {-1 0 5 99999 x}]
}

# ---- generators: each returns one command line (a list) ----------------------
proc gen_lattice_create {} {
    set size [pick {{1 1} {1 1} {1 0.5} {2 1} {0.5 1}}]
    set cells [weighted {6 16 6 24 3 32 1 48 0.3 2 0.2 1 0.2 100000 0.1 0}]
    set walls [weighted {
        3 {}
        2 {bottom noslip top noslip}
        1 {left noslip right noslip bottom noslip top noslip}
        1 {bottom noslip top slip}
        1 {left {velocity {0.01 0}} right {pressure 0.3333} bottom noslip top noslip}
        0.5 {top {noslip {0.02 0}} bottom noslip left noslip right noslip}
        0.3 {left noslip right periodic}
        0.3 {left {velocity {5 0}} bottom {pressure 0.3}}
    }]
    set periodic [expr {[string match *left* $walls] ? {0 0} : {1 0}}]
    concat [list lattice create -size [vec2 {*}$size] -cells [maybe $cells]] \
        [options 0.8 {-viscosity {maybe [pick {0.05 0.1 0.1 0.02}]}}] \
        [options 0.3 {-tau {maybe [pick {0.6 0.8 1 1.5 0.51}]}}] \
        [options 0.6 {-walls {maybe $walls 0.03}}] \
        [options 0.6 {-periodic {maybe $periodic 0.03}}] \
        [options 0.3 {-forcing {vec2 [pick {0 1e-4 1e-3}] 0}}] \
        [options 0.2 {-collision {maybe [pick {bgk trt}]}}] \
        [options 0.2 {-forcescheme {maybe [pick {nodal guo}]}}] \
        [options 0.1 {-origin {vec2 0 0}}] \
        [options 0.1 {-density {maybe 1}}] \
        [options 0.05 {-magic {maybe 0.1875}}]
}
proc gen_lattice {} {
    choose { \
        4 {list lattice info} \
        2 {list lattice probe [point]} \
        3 {concat {lattice configure} [options 0.5 {
                -viscosity {maybe [pick {0.02 0.05 0.1}]} -tau {maybe [pick {0.6 0.9 1.2}]}
                -forcing {vec2 [pick {0 1e-4 -1e-4}] [pick {0 1e-5}]}
                -collision {maybe [pick {bgk trt}]} -forcescheme {maybe [pick {nodal guo}]}
                -magic {maybe 0.25} -size {vec2 1 1} -cells {maybe 20}}]} \
        2 {list lattice cget [pick {-viscosity -tau -forcing -walls -periodic -size -cells -magic -nope}]} \
        3 {concat [list lattice obstacle rect [maybe [list [uniform 0 0.5] [uniform 0 0.5] [uniform 0.5 1] [uniform 0.5 1]] 0.05]] \
               [options 0.3 {-slip {maybe [pick {0 1}]}}]} \
        3 {concat [list lattice obstacle circle [maybe [list [uniform 0.2 0.8] [uniform 0.2 0.8] [uniform 0.03 0.2]] 0.05]] \
               [options 0.3 {-outside {maybe [pick {0 0 1}]}}] \
               [options 0.3 {-velocity {maybe [list [uniform -0.01 0.01] 0 [uniform -0.1 0.1]]}}]} \
        2 {list lattice obstacle info [anyObstacle]} \
        1 {list lattice obstacle delete [anyObstacle]} \
        1 {list lattice obstacles} \
        0.4 {list lattice delete} \
        0.3 {list lattice help}}
}
proc gen_material {} {
    set name [pick {grain sand rock default light}]
    set spec {
        -density {maybe [pick {1.5 2 2.65 0.8 1}]} -kn {maybe [pick {10 50 100 1000}]}
        -ks {maybe [pick {10 50 100}]} -friction {maybe [pick {0 0.3 0.5 1}]}
        -restitution {maybe [pick {0 0.5 0.9 1}]} -damping {maybe [pick {0.01 0.1 {}}]}
        -bondstiffness {maybe [pick {10 100}]} -bondstrength {maybe [pick {0.01 0.1 1}]}
        -law {maybe [pick {linear linear hertz}]} -youngs {maybe [pick {1e3 1e4}]}
        -poisson {maybe [pick {0.2 0.3 0.49}]}
    }
    choose { \
        3 {concat [list material create [maybe $name 0.03]] [options 0.4 $spec]} \
        2 {concat [list material configure [anyMaterial]] [options 0.4 $spec]} \
        1 {list material cget [anyMaterial] [pick {-density -kn -friction -damping -law -nope}]} \
        0.5 {list material names}}
}
proc common {} {
    options 0.2 {
        -material {anyMaterial} -angle {maybe [uniform -3 3]}
        -velocity {maybe [list [uniform -0.02 0.02] [uniform -0.02 0.02] [uniform -0.5 0.5]]}
        -fix {maybe [pick {{} {} x {x y} {x y rot} rot z}]}
        -force {maybe [list 0 [uniform -1e-3 0] 0]} -acceleration {vec2 0 [uniform -1 0]}
        -id {maybe [pick {1000 1001 5 0 0 1 2 2147483647}] 0.1}
    }
}
# Where new elements go: the centres of a 9 x 9 grid, one element a cell, so
# that most scenes can run (elements created overlapping stop a run).
set occupied [dict create]
proc freeSpot {} {
    for {set try 0} {$try < 20} {incr try} {
        set i [between 0 8]
        set j [between 0 8]
        if {![dict exists $::occupied $i,$j]} break
    }
    dict set ::occupied $i,$j 1
    list [format %.4g [expr {0.1 + 0.1 * $i + [uniform -0.01 0.01]}]] \
         [format %.4g [expr {0.1 + 0.1 * $j + [uniform -0.01 0.01]}]]
}
proc forgetSpots {} {
    set ::occupied [dict create]
    foreach id [elementIds] {
        lassign [dict get [element info $id] position] x y
        # (only the grid's spots: an element may lie anywhere, x = 1e300 too)
        if {abs($x) > 2 || abs($y) > 2} continue
        dict set ::occupied [expr {round($x * 10) - 1}],[expr {round($y * 10) - 1}] 1
    }
}
proc gen_element_create {} {
    # Most elements are of a soft material, so that a lattice's timestep suits them.
    if {"soft" ni [material names]} {
        return [list material create soft -density [maybe 2] -kn [maybe 10] -ks 10 -friction 0.4 \
                    -bondstiffness 20 -bondstrength 0.05]
    }
    set r [format %.3g [uniform 0.015 0.045]]
    lassign [expr {[chance 0.9] ? [freeSpot] : [list [uniform 0 1] [uniform 0 1]]}] x y
    set material [expr {[chance 0.95] ? {-material soft} : {}}]
    switch [weighted {5 disc 2 polygon 2 ellipse 2 superquadric 1 wall}] {
        disc {
            concat [list disc create -center [vec2 $x $y] -radius [maybe $r]] $material [common]
        }
        polygon {
            set n [between 3 8]
            set vertices {}
            set turn [expr {[chance 0.95] ? 1 : -1}]
            for {set i 0} {$i < $n} {incr i} {
                set a [expr {$turn * 2 * acos(-1) * $i / $n + 0.3}]
                lappend vertices [format %.5g [expr {$x + $r * cos($a)}]] [format %.5g [expr {$y + $r * sin($a)}]]
            }
            if {[chance 0.1]} { lappend vertices {*}[lrange $vertices 0 1] }   ;# repeated vertex
            if {[chance 0.05]} { set vertices [lreverse $vertices] }             ;# x/y swapped pairs
            if {[chance 0.05]} { set vertices [lrange $vertices 0 end-1] }       ;# odd count
            concat [list polygon create -vertices [maybe $vertices 0.03]] $material [common]
        }
        ellipse {
            concat [list ellipse create -center [vec2 $x $y] -axes [vec2 $r [expr {$r * 0.6}]]] \
                [options 0.4 {-sides {maybe [pick {3 8 16 64 200}]}}] $material [common]
        }
        superquadric {
            concat [list superquadric create -center [vec2 $x $y] -axes [vec2 $r [expr {$r * 0.7}]] \
                        -exponents [vec2 [pick {1 2 4 8}] [pick {2 3 100}]]] \
                [options 0.4 {-sides {maybe [pick {8 16 32}]}}] $material [common]
        }
        wall {
            # Along the box's sides mostly: walls across the grid would overlap elements.
            set ends [pick {{{0.01 0.01} {0.99 0.01}} {{0.99 0.99} {0.01 0.99}} {{0.01 0.99} {0.01 0.01}}
                            {{0.99 0.01} {0.99 0.99}}}]
            if {[chance 0.2]} { set ends [list [list [uniform 0 1] [uniform 0 1]] [list [uniform 0 1] [uniform 0 1]]] }
            concat [list wall create -from [vec2 {*}[lindex $ends 0]] -to [vec2 {*}[lindex $ends 1]]] \
                [options 0.2 {-thickness {maybe 0.02}}] [options 0.15 {-stress {maybe [pick {0.01 1}]}}] \
                $material [common]
        }
    }
}
proc gen_element {} {
    choose { \
        3 {list element info [anyElement]} \
        1 {list element ids {*}[options 0.3 {-type {maybe [pick {disc polygon superquadric wall}]}}]} \
        1 {list element next} \
        1 {list element delete [anyElement]} \
        1 {list element cget [anyElement] [pick {-center -radius -angle -velocity -fix -material -stress -from}]} \
        4 {concat [list element configure [anyElement]] [options 0.3 {
                -center {point} -radius {maybe [uniform 0.02 0.08]} -angle {maybe 0.3}
                -velocity {maybe {0 0 0}} -fix {maybe [pick {{} x {x y rot}}]}
                -force {maybe {0 0 0}} -acceleration {vec2 0 0} -material {anyMaterial}
                -stress {maybe [pick {{} 0.1}]} -from {point} -to {point}}]}}
}
proc gen_bond {} {
    choose { \
        3 {concat [list bond create [anyElement] [anyElement]] \
               [options 0.3 {-stiffness {maybe 50} -strength {maybe 0.05} -shearstrength {maybe 0.05}}]} \
        2 {concat {bond auto} [options 0.5 {-gap {maybe [pick {0 0.001 0.01 0.1}]}
                                            -elements {maybe [lrange [elementIds] 0 5]}}]} \
        1 {list bond ids} \
        2 {list bond info [anyBond]} \
        1 {list bond delete [anyBond]} \
        1 {concat {bond broken} [options 0.3 {-since {maybe 0}}]}}
}
proc gen_source {} {
    choose { \
        3 {concat [list source create [anyElement]] [options 0.5 {
                -acceleration {vec2 0 -1} -interval {maybe [pick {0 0.01 0.1}]} -limit {maybe [pick {-1 3 10}]}}]} \
        1 {list source ids} \
        1 {list source info [anyElement]} \
        1 {list source delete [anyElement]}}
}
proc gen_sim {} {
    choose { \
        4 {concat {sim configure} [options 0.35 {
                -timestep {maybe [pick {0.001 0.002 0.005 {}}]} -threads {maybe [pick {1 2 3}]}
                -gravity {vec2 0 [pick {0 -1 -9.81}]} -integrator {maybe [pick {central euler verlet}]}
                -maxoverlap {maybe [pick {0.1 0.5 1 1}]} -solidratio {maybe [pick {exact 1 2 4 8}]}
                -substeps {maybe [pick {1 2 4}]} -buoyancy {maybe [pick {0 1}]}
                -share {maybe [pick {coverage equal}]} -interior {maybe [pick {equilibrium collide}]}
                -coupling {maybe [pick {explicit implicit}]}}]} \
        2 {list sim cget [pick {-timestep -threads -gravity -integrator -solidratio -substeps -coupling -x}]} \
        2 {list sim info}}
}
proc gen_run {} {
    choose { \
        6 {list run [if {[chance 0.03]} {pick {0 -1 abc {} 1.5 NaN \u221e}} else {between 1 6}]} \
        2 {list step} \
        1 {list run [between 2 6] -every [maybe [between 1 3]] \
               [pick {{sim info} break {error "stopped by the fuzzer"} {element ids} {incr ::everyCount}}]}}
}
proc gen_output {} {
    global dir
    set n [between 0 3]
    choose { \
        2 {list output vtk [file join $dir vtk$n]} \
        1 {list output vtk [file join $dir series$n] -every [maybe [between 1 4]]} \
        2 {concat [list output csv [file join $dir e$n.csv] -elements [maybe [lrange [elementIds] 0 2]]] \
               [options 0.5 {-every {maybe [between 1 3]}}]} \
        2 {concat [list record [file join $dir r$n.csv]] [options 0.5 {-every {maybe 2}
                -quantities {maybe [pick {{kinetic contacts} {mach} {nosuch} {}}]}}]} \
        1 {list output list} \
        1 {concat {output close} [expr {[chance 0.7] ? [list [file join $dir [pick [list e$n.csv r$n.csv series$n.pvd]]]] : {}}]} \
        0.3 {list output vtk [file join $dir nosuchdir x]} \
        0.3 {list output csv /proc/forbidden.csv -elements [lrange [elementIds] 0 0]}}
}
proc gen_view {} {
    global dir
    set spec {
        -field {maybe [pick {none nodes solid density pressure velocity vorticity}]}
        -vectors {maybe [pick {0 1}]} -streamlines {maybe [pick {0 1}]} -range {maybe [pick {{} {0 1} {1 0}}]}
        -colorby {maybe [pick {none speed mass bond}]} -fill {maybe [pick {0 1}]}
        -bonds {maybe [pick {0 1}]} -forces {maybe [pick {0 1}]} -label {maybe [pick {0 1}]}
        -size {vec2 [pick {40 64 100}] [pick {30 64 80}]} -region {maybe [pick {{} {0 0 1 1} {0.2 0.2 0.6 0.5} {1 1 0 0}}]}
        -materialcolors {maybe [pick {{grain #e69f00} {grain red} {x}}]}
    }
    choose { \
        3 {concat [list snapshot [file join $dir shot[between 0 2].png] -size [vec2 [pick {32 64 96}] [pick {32 48 64}]]] \
               [options 0.3 $spec]} \
        2 {concat {view configure} [options 0.3 $spec]} \
        1 {list view cget [pick {-field -size -region -colorby -nope}]} \
        1 {list view pixel [point] {*}[options 0.3 {-size {vec2 100 80}}]}}
}
proc gen_checkpoint {} {
    global dir
    set n [between 0 2]
    choose { \
        3 {list checkpoint save [file join $dir ck$n.sfck]} \
        3 {concat [list checkpoint load [file join $dir ck$n.sfck]] [options 0.3 {-recordings {maybe [pick {0 1}]}}]} \
        4 {list checkpoint load [mutantCheckpoint]} \
        0.3 {list checkpoint save [file join $dir nosuchdir ck.sfck]}}
}
proc gen_plot {} {
    global dir
    list plot [file join $dir plot.png] [file join $dir [pick {r0.csv e0.csv r1.csv nosuch.csv}]] \
        {*}[options 0.3 {-size {vec2 200 150} -logy {maybe [pick {0 1}]} -y {maybe [pick {kinetic contacts nosuch}]}}]
}
proc gen_misc {} {
    choose { \
        1 {list help} \
        1 {list [pick {lattice material element bond source sim output view checkpoint}] help} \
        1.5 {list reset} \
        2 {list source [mutantScript]} \
        2 {garbage}}
}
# A random word salad on a real command.
proc garbage {} {
    set words [list [pick {lattice material disc polygon ellipse superquadric wall element bond source
                           sim run step checkpoint output snapshot view record plot}]]
    for {set i [between 0 5]} {$i > 0} {incr i -1} {
        set class [pick [dict keys $::bad]]
        lappend words [pick [concat [dict get $::bad $class] {create info configure cget delete ids auto
                                     save load vtk csv -center -radius -size -every}]]
    }
    return $words
}

# ---- mutated files ---------------------------------------------------------------
# A checkpoint saved by this run, broken one of several ways; some keep a valid
# checksum over a changed scene, so the reader's own checks are what refuse it.
proc mutantCheckpoint {} {
    global dir
    incr ::counts(mutantCheckpoints)
    set saved [lsort [glob -nocomplain -directory $dir ck*.sfck]]
    # A file of its own for each, kept: fuzz.log then replays the run.
    set out [file join $dir mutant[incr ::mutants].sfck]
    if {![llength $saved] || [chance 0.1]} {
        set data [weighted [list 1 {} 1 "\x89SFCKP\r\n" 1 [string repeat \x00 40] 1 "plain text\n" \
                      1 [binary format a8iuiuwiu "\x89SFCKP\r\n" 1 0x01020304 0 0]]]
    } else {
        set f [open [pick $saved] rb]
        set data [read $f]
        close $f
        set n [string length $data]
        switch [weighted {2 truncate 2 flip 6 payload 1 version 1 size 1 append 1 crc}] {
            truncate { set data [string range $data 0 [expr {int(rand() * $n) - 1}]] }
            flip {
                for {set i [between 1 8]} {$i > 0} {incr i -1} {
                    set k [expr {int(rand() * $n)}]
                    set data [string replace $data $k $k [format %c [expr {int(rand() * 256)}]]]
                }
            }
            payload {
                # Overwrite 1 to 8 bytes of the scene with a value chosen to hurt,
                # then make the checksum right again.
                if {$n > 28} {
                    set k [expr {28 + int(rand() * ($n - 28))}]
                    set value [pick [list [binary format q NaN] [binary format q Inf] [binary format q -1e308] \
                        [binary format q 0] [binary format q -1] [binary format iu 0xffffffff] \
                        [binary format i -1] [binary format wu 0xffffffffffff] [binary format i 0] \
                        [binary format c 0xff] [binary format c 0] [binary format c 2]]]
                    set data [string replace $data $k [expr {$k + [string length $value] - 1}] $value]
                    set data [string range $data 0 [expr {$n - 1}]]
                    set payload [string range $data 28 end]
                    set data [string replace $data 24 27 [binary format iu [zlib crc32 $payload]]]
                }
            }
            version { set data [string replace $data 8 11 [binary format iu [pick {0 2 99 0xffffffff}]]] }
            size { set data [string replace $data 16 23 [binary format wu [pick {0 1 0xffffffffffff 28}]]] }
            append { append data [string repeat \x55 [between 1 64]] }
            crc { set data [string replace $data 24 27 [binary format iu [expr {int(rand() * 4e9)}]]] }
        }
    }
    set f [open $out wb]
    puts -nonewline $f $data
    close $f
    return $out
}
# A script of generated command lines with its text damaged.
proc mutantScript {} {
    global dir
    incr ::counts(mutantScripts)
    set lines {}
    for {set i [between 1 8]} {$i > 0} {incr i -1} {
        lappend lines [generate [pick {gen_element_create gen_material gen_bond gen_sim gen_element gen_lattice}]]
    }
    set text [join $lines \n]
    for {set i [between 0 3]} {$i > 0} {incr i -1} {
        set n [string length $text]
        set k [expr {int(rand() * ($n + 1))}]
        switch [pick {delete insert truncate duplicate}] {
            delete { set text [string replace $text $k [expr {$k + [between 0 6]}] {}] }
            insert { set text [string range $text 0 [expr {$k - 1}]][pick {\{ \} \" \[ \] \\ { } \n ; "\u00e9" $}][string range $text $k end] }
            truncate { set text [string range $text 0 [expr {$k - 1}]] }
            duplicate { append text \n[pick $lines] }
        }
    }
    set out [file join $dir mutant[incr ::mutants].tcl]
    set f [open $out w]
    fconfigure $f -encoding utf-8
    puts $f $text
    close $f
    return $out
}

# ---- the loop ----------------------------------------------------------------------
set generators {
    10 gen_element_create 6 gen_element 5 gen_run 4 gen_lattice 2 gen_lattice_create
    3 gen_material 3 gen_bond 2 gen_source 3 gen_sim 2 gen_output 2 gen_view 2 gen_checkpoint
    0.3 gen_plot 2 gen_misc
}
# Generating may itself ask the scene (ids); a generator's own error is a bug here.
proc generate {name} { $name }

proc fail {index command message} {
    incr ::failures
    puts "FUZZ FAILURE at command $index: $message\n  command: $command"
    if {$::failures >= 20} { summary; exit 1 }
}
# Commands whose error may keep part of what they did.
proc partial {command} {
    expr {[lindex $command 0] in {run step} || ([lindex $command 0] eq "source" &&
          [lindex $command 1] ni {create delete ids info help})}
}
array set counts {accepted 0 refused 0 scenes 0 runs 0 steps 0 mutantCheckpoints 0 mutantScripts 0
                  checkpointsLoaded 0 checkpointsSaved 0 elements 0 maxElements 0 bonds 0 resets 0}
set failures 0
set slowest {0 {}}
set everyCount 0
proc summary {} {
    global counts
    puts [format "fuzz: seed %s, %d command lines (%d accepted, %d refused), %d scenes built, %d runs (%d steps), %d elements created (at most %d at once), %d bonds, %d checkpoints saved, %d loaded, %d mutated checkpoints, %d mutated scripts, %d resets, %d warnings; slowest %.2f s (%s); %d failures" \
        $::seed $::total $counts(accepted) $counts(refused) $counts(scenes) $counts(runs) $counts(steps) \
        $counts(elements) $counts(maxElements) $counts(bonds) $counts(checkpointsSaved) $counts(checkpointsLoaded) \
        $counts(mutantCheckpoints) $counts(mutantScripts) $counts(resets) $::warnings \
        [lindex $::slowest 0] [string range [lindex $::slowest 1] 0 60] $::failures]
}
set seed ${-seed}
set total 0
set log [open [file join $dir fuzz.log] w]
fconfigure $log -encoding utf-8
puts $log "# sandflow fuzz, seed $seed: each line one command tried\nproc ::sf::warn {m} {}\ncd [list $dir]"
set built 0   ;# whether the scene since the last reset/load holds anything
for {set i 1} {$i <= ${-count}} {incr i} {
    set command [generate [weighted $generators]]
    puts $log [list catch $command]
    flush $log
    set before [sim hash]
    set stepBefore [dict get [sim info] step]
    set start [clock microseconds]
    set code [catch {uplevel #0 $command} result options]
    set seconds [expr {([clock microseconds] - $start) * 1e-6}]
    incr total
    if {$seconds > [lindex $slowest 0]} { set slowest [list $seconds $command] }
    if {$seconds > ${-slow}} { fail $i $command "took [format %.1f $seconds] s (more than ${-slow})" }
    set verb [lrange $command 0 [expr {[lindex $command 0] in {run step reset help snapshot record plot} ? 0 : 1}]]
    incr tally([list $verb [expr {$code == 1 ? "refused" : "accepted"}]])
    if {$code == 1} {
        incr counts(refused)
        if {[info exists ::env(FUZZ_SHOW)] && [string match $::env(FUZZ_SHOW) $verb]} { puts "REFUSED: $command -> [string range $result 0 150]" }
        if {[string trim $result] eq {}} { fail $i $command "refused with an empty message" }
        if {![partial $command] && [sim hash] ne $before} {
            fail $i $command "refused (\"$result\") but the scene changed"
        }
    } elseif {$code == 0 || $code == 3 || $code == 4} {
        incr counts(accepted)
        switch -- [lindex $command 0] {
            reset { incr counts(resets); set built 0 }
            checkpoint { incr counts([expr {[lindex $command 1] eq "save" ? "checkpointsSaved" : "checkpointsLoaded"}]) }
            disc - polygon - ellipse - superquadric - wall { incr counts(elements) }
            bond { if {[lindex $command 1] eq "create"} { incr counts(bonds) } elseif {[lindex $command 1] eq "auto"} { incr counts(bonds) $result } }
            run - step { incr counts(runs) }
        }
    } else {
        incr counts(accepted)
    }
    # Steps that ran: only a run or step line advances the clock by stepping
    # (a loaded checkpoint, even one sourced, sets it to anything).
    if {[lindex $command 0] in {run step}} {
        incr counts(steps) [expr {max(0, [dict get [sim info] step] - $stepBefore)}]
    }
    set problems [sim check]
    if {[llength $problems]} {
        fail $i $command "after it ([expr {$code == 1 ? "refused: $result" : "accepted"}]) sim check reports: [join $problems {; }]"
    }
    # A scene is built once it holds a lattice or elements (a loaded one counts).
    if {[lindex $command 0] eq "checkpoint" && [lindex $command 1] eq "load" && $code == 0} { set built 0 }
    if {[lindex $command 0] in {reset checkpoint source}} { forgetSpots }
    if {!$built && ([llength [elementIds]] || ![catch {lattice info}])} { set built 1; incr counts(scenes) }
    set n [llength [elementIds]]
    if {$n > $counts(maxElements)} { set counts(maxElements) $n }
    # Keep a scene small enough to stay quick: start again past 150 elements.
    if {$n > 150} { puts $log {catch reset}; reset; set built 0; incr counts(resets); forgetSpots }
    if {!${-quiet} && $i % 1000 == 0} { puts "  $i command lines"; flush stdout }
}
close $log
if {!${-quiet}} {
    foreach key [lsort [array names tally]] { puts [format "  %-28s %-9s %6d" {*}$key $tally($key)] }
}
summary
exit [expr {$failures > 0}]
