# Six discs settling together (thesis §6.1, the six-disc version of case E):
# the channel and discs of examples/dkt.tcl (8 d wide, density ratio 2,
# nu = 0.02, g = 0.08, tau 0.7), with three discs on each side of the
# centreline, 2 d off it, 2 d apart vertically, the right-hand column 1 d
# lower than the left-hand one (a mirror-symmetric start would stay
# symmetric and could not mix). Consistent units with d = 1 and fluid
# density 1. Shows hindered settling (the group settles slower than one
# disc alone or case E's pair: its centroid at 0.84 of one disc's speed
# here) and mixing across the channel (all six cross the centreline and
# change places, 28 crossings in the fall). -count 1 or 2 runs the same scene
# with one disc (the left column's top disc) or with case E's pair, for the
# comparison.
#
#   sandflow examples/dkt-six.tcl ?-count 1|2|6? ?-cells N? ?-height H?
#            ?-time T? ?-stagger s? ?-nu nu? ?-g g? ?-every K? ?-report K?
#            ?-frames N? ?-out DIR? ?-csv FILE?
#
# -cells: lattice cells across the channel (the thesis: 120, the discs then
# 15 across); -height: the channel's height in d (the thesis: 100); -time:
# how long to run, in units of d / U, U the mean settling speed so far
# (case E's measure); the run also ends when the lowest disc is 2 d above
# the floor. -stagger: how much lower the right-hand column starts, in d.
#
# Prints a line every -report samples and, last, a summary line
#   "summary: discs N U u Re r centroid speed v spread s0 -> s1 d (max m)
#    crossed c of N crossings k closest q d, t T (t U/d x)"
# (U: the mean over the samples of the discs' mean settling speed, as
# dkt.tcl; the centroid speed: the discs' mean height's fall rate between
# 3 d of fall and the end; spread: the standard deviation of the discs'
# x; crossed: discs that have crossed the centreline at least once;
# crossings: all crossings; closest: the smallest centre distance, in d).
# With -csv FILE (or -out DIR: DIR/dkt-six.csv) the history
#   t, tU (t U/d), centroid (mean y), speed (mean settling speed now),
#   spread, crossed, x1, y1, ... xN, yN;
# with -out DIR pictures six-start.png, six-end.png and -frames between (a
# window 3 channel widths tall that follows the discs), and six.mp4 from
# them when ffmpeg is installed.
#
# Size and time on this 2-core machine (one thread, the cores shared with
# other work): 120 x 1500 cells (180,000 nodes), about 36,000 steps: 126 s
# for the six discs, 118 s for one disc or the pair.

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {count.arg   6     "discs: 6, or 1 (one disc) or 2 (case E's pair) for comparison"}
    {cells.arg   120   "lattice cells across the channel (the thesis: 120, the discs then 15 across)"}
    {height.arg  100   "the channel's height in d (the thesis: 100)"}
    {time.arg    100   "how long to run, in d / U (U the mean settling speed so far)"}
    {stagger.arg 1.0   "how much lower the right-hand column starts, in d"}
    {nu.arg      0.02  "kinematic viscosity"}
    {g.arg       0.08  "gravity"}
    {every.arg   200   "steps between samples"}
    {report.arg  25    "samples between printed lines"}
    {frames.arg  8     "pictures between the start and the end (with -out)"}
    {out.arg     {}    "folder for pictures, the movie and dkt-six.csv"}
    {csv.arg     {}    "CSV file for the history"}
}]
dict with options {}
if {${-count} ni {1 2 6}} { error "bad -count \"${-count}\": must be 1, 2 or 6" }
set d 1.0
set L [expr {8.0 * $d}]
set H [expr {double(${-height}) * $d}]
set out ${-out}
if {$out ne {}} { file mkdir $out }
if {${-csv} eq {} && $out ne {}} { set -csv [file join $out dkt-six.csv] }

lattice create -size [list $L $H] -cells ${-cells} -viscosity ${-nu} -tau 0.7 \
    -walls {left noslip right noslip bottom noslip top noslip}
sim configure -gravity [list 0 [expr {-${-g}}]]
# Contacts stiff enough, and soft enough that the critical step is five
# fluid steps (as dkt.tcl).
set dt [dict get [lattice info] timestep]
set k [expr {2.0 * acos(-1) * 0.25 * 4 / (25 * $dt * $dt)}]
material create grain -density 2.0 -kn $k -ks $k -friction 0.1 -restitution 0.5
foreach {from to} [list {0 0} [list 0 $H] [list $L 0] [list $L $H] {0 0} [list $L 0]] {
    wall create -from $from -to $to -material grain
}
set xl [expr {0.5 * $L - 2 * $d}]
set xr [expr {0.5 * $L + 2 * $d}]
switch -- ${-count} {
    1 { set centres [list [list $xl [expr {$H - 10 * $d}]]] }
    2 { set centres [list [list $xl [expr {$H - 12 * $d}]] [list $xl [expr {$H - 10 * $d}]]] }
    6 {
        set centres {}
        foreach k {0 1 2} {
            lappend centres [list $xl [expr {$H - (10 + 2 * $k) * $d}]]
            lappend centres [list $xr [expr {$H - (10 + 2 * $k + ${-stagger}) * $d}]]
        }
    }
}
set discs {}
foreach c $centres {
    lappend discs [disc create -center $c -radius [expr {0.5 * $d}] -material grain]
}
set n [llength $discs]
# The side of the centreline each disc is on (-1 left, 1 right), and its crossings.
foreach id $discs {
    set side($id) [expr {[lindex [dict get [element info $id] position] 0] < 0.5 * $L ? -1 : 1}]
    set crossings($id) 0
}

set info [lattice info]
puts [format "lattice %d x %d (%d nodes), h = %g, dt = %g, tau %g; %d discs %g cells across" \
    [dict get $info nx] [dict get $info ny] [dict get $info nodes] [expr {$L / ${-cells}}] \
    [dict get $info timestep] [dict get $info tau] $n [expr {${-cells} / 8.0}]]
set csv {}
if {${-csv} ne {}} {
    set csv [open ${-csv} w]
    set head {t tU centroid speed spread crossed}
    for {set k 1} {$k <= $n} {incr k} { lappend head x$k y$k }
    puts $csv [join $head ,]
}

# Pictures: a window three channel widths tall around the discs' mean height.
set frame 0
proc picture {name} {
    global out discs L H
    if {$out eq {}} return
    set ys [lmap id $discs {lindex [dict get [element info $id] position] 1}]
    set yc [expr {[tcl::mathop::+ {*}$ys] / [llength $ys]}]
    set lo [expr {max(0.0, min($H - 3 * $L, $yc - 1.5 * $L))}]
    snapshot [file join $out $name] -field vorticity -region [list 0 $lo $L [expr {$lo + 3 * $L}]] \
        -size {280 840}
}

set speeds {}
set closest 1e9
set maxSpread 0.0
set samples 0
set centroid0 {}
set t3 {}
set yc3 {}
proc sample {} {
    global discs n L d csv speeds closest maxSpread samples side crossings options \
        centroid0 t3 yc3
    set t [dict get [sim info] time]
    set xs {}; set ys {}; set vs 0.0
    foreach id $discs {
        set e [element info $id]
        lassign [dict get $e position] x y
        lappend xs $x; lappend ys $y
        set vs [expr {$vs - [lindex [dict get $e velocity] 1]}]
        set s [expr {$x < 0.5 * $L ? -1 : 1}]
        if {$s != $side($id)} { incr crossings($id); set side($id) $s }
    }
    set speed [expr {$vs / $n}]
    lappend speeds $speed
    set yc [expr {[tcl::mathop::+ {*}$ys] / $n}]
    set xc [expr {[tcl::mathop::+ {*}$xs] / $n}]
    set spread [expr {sqrt([tcl::mathop::+ 0.0 {*}[lmap x $xs {expr {($x - $xc) ** 2}}]] / $n)}]
    if {$spread > $maxSpread} { set maxSpread $spread }
    if {$centroid0 eq {}} { set centroid0 $yc }
    if {$t3 eq {} && $centroid0 - $yc >= 3 * $d} { set t3 $t; set yc3 $yc }
    for {set i 0} {$i < $n} {incr i} {
        for {set j [expr {$i + 1}]} {$j < $n} {incr j} {
            set r [expr {hypot([lindex $xs $i] - [lindex $xs $j], [lindex $ys $i] - [lindex $ys $j])}]
            if {$r < $closest} { set closest $r }
        }
    }
    set crossed 0
    foreach id $discs { if {$crossings($id) > 0} { incr crossed } }
    set u [expr {max(1e-12, [tcl::mathop::+ {*}$speeds] / [llength $speeds])}]
    set tU [expr {$t * $u / $d}]
    if {$csv ne {}} {
        set row [list $t $tU $yc $speed $spread $crossed]
        foreach x $xs y $ys { lappend row $x $y }
        puts $csv [join $row ,]
    }
    if {$samples % [dict get $options -report] == 0} {
        puts [format "t %8.2f  (t U/d %5.1f)  mean height %7.3f  speed %.4f  spread %.3f d  crossed %d of %d" \
                  $t $tU $yc $speed [expr {$spread / $d}] $crossed $n]
    }
    incr samples
    return [list $t $tU [tcl::mathfunc::min {*}$ys] $yc $spread]
}

picture six-start.png
lassign [sample] t tU ymin yc spread0
set y0 $ymin
while {1} {
    run ${-every}
    lassign [sample] t tU ymin yc spread
    if {$tU >= ${-time} || $ymin < 2 * $d} break
    if {$out ne {} && ${-frames} > 0} {
        set progress [expr {max($tU / ${-time}, ($y0 - $ymin) / ($y0 - 2 * $d))}]
        if {$progress >= ($frame + 1.0) / (${-frames} + 1)} {
            incr frame
            picture [format "six-%02d.png" $frame]
        }
    }
}
picture six-end.png
if {$csv ne {}} { close $csv }
if {$out ne {} && [auto_execok ffmpeg] ne {}} {
    set list [file join $out frames.txt]
    set f [open $list w]
    set pngs [list six-start.png]
    for {set i 1} {$i <= $frame} {incr i} { lappend pngs [format "six-%02d.png" $i] }
    lappend pngs six-end.png six-end.png
    foreach p $pngs { puts $f "file '[file normalize [file join $out $p]]'\nduration 0.5" }
    close $f
    catch {exec ffmpeg -y -loglevel error -f concat -safe 0 -i $list -pix_fmt yuv420p \
               -vf "scale=trunc(iw/2)*2:trunc(ih/2)*2" [file join $out six.mp4] 2>@1}
    file delete $list
}

set u [expr {[tcl::mathop::+ {*}$speeds] / [llength $speeds]}]
set vc [expr {$t3 ne {} && $t > $t3 ? ($yc3 - $yc) / ($t - $t3) : 0.0}]
set crossed 0
set total 0
foreach id $discs {
    if {$crossings($id) > 0} { incr crossed }
    incr total $crossings($id)
}
puts [format "summary: discs %d U %.4f Re %.2f centroid speed %.4f spread %.3f -> %.3f d (max %.3f) crossed %d of %d crossings %d closest %s d, t %.1f (t U/d %.1f)" \
    $n $u [expr {$u * $d / ${-nu}}] $vc [expr {$spread0 / $d}] [expr {$spread / $d}] [expr {$maxSpread / $d}] \
    $crossed $n $total [if {$n > 1} {format %.3f [expr {$closest / $d}]} else {string cat -}] $t $tU]
