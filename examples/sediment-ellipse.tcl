# A sedimenting ellipse in a vertical channel (thesis case C, Cook 2001 §5.2;
# Huang, Hu & Joseph 1998): an ellipse, made as a 200-sided polygon, a by
# 0.75 a (the thesis: 20 by 15 cells), starts centred across a channel 5 a
# wide with its major axis at 45 degrees and settles. Consistent units with
# the major axis a = 1 and fluid density 1. The thesis: density ratio 1.0015
# gives Re = u a / nu near 0.30 and the ellipse turns its major axis to the
# vertical and oscillates about it and about the centreline; ratio 1.005
# gives Re near 0.80 and it turns broadside (horizontal), slowly. Here
# (build/notes/validation-c.md): the first as in the thesis; at 1.005 (Re
# 1.03) it turns back toward the vertical, off-centre; broadside from about
# Re 1.4 (ratio 1.0075).
#
#   sandflow examples/sediment-ellipse.tcl ?-ratio r? ?-cells N? ?-height H?
#            ?-start S? ?-time T? ?-nu nu? ?-g g? ?-tau tau? ?-sides N?
#            ?-every K? ?-report K? ?-frames N? ?-out DIR? ?-csv FILE?
#
# -ratio: the ellipse's density over the fluid's; -cells: lattice cells
# across the channel (the thesis: 100, the ellipse then 20 cells long);
# -height: the channel's height in a (the thesis: 150, 3000 cells); -start:
# how far below the top the ellipse starts, in a (the thesis: 20, 400 nodes);
# -time: how long to run (0: until the ellipse's centre is 5 a above the
# floor); -every: steps between samples; -report: samples between printed
# lines. The reference material gives neither gravity nor viscosity: with
# nu = 0.1 and tau = 1 the default g = 48 gives Re 0.33 at ratio 1.0015.
# The ellipse is nearly as light as the fluid, so the coupling is implicit
# (the explicit one is unstable below a density ratio of about 2:
# docs/coupling.md).
#
# Prints a line every -report samples and, last, a summary line
#   "summary: ratio R Re RE angle A0 -> A1 deg (from vertical D1 deg), x/W ...";
# with -csv FILE (or -out DIR: DIR/ellipse.csv) the history
#   t, fall (a), y, x_over_W, angle (deg, major axis from the horizontal,
#   unwrapped: 90 is vertical, 0 and 180 broadside), vx, vy, w, Re;
# with -out DIR pictures ellipse-start.png, ellipse-end.png and -frames
# between (a window 2 W tall that follows the ellipse, speed and vectors),
# and ellipse.mp4 from them when ffmpeg is installed.
#
# Size and time on this 2-core machine (one thread, the cores shared with
# other work): the default, 60 x 720 cells (43,200 nodes), the ellipse 12 x 9
# cells, a fall of 45 a in 120,000 steps, 216 s (ratio 1.0015; 1.005: 77 s).
# The thesis's 100 x 3000 lattice is -cells 100 -height 150 -start 20 (about
# two hours here, estimated from the node updates per second); the
# shorter channel gives the same history (build/notes/validation-c.md).

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {ratio.arg  1.0015 "the ellipse's density over the fluid's (the thesis: 1.0015, 1.005)"}
    {cells.arg  60     "lattice cells across the channel (the thesis: 100, the ellipse then 20 long)"}
    {height.arg 60     "the channel's height in a (the thesis: 150)"}
    {start.arg  10     "how far below the top the ellipse starts, in a (the thesis: 20)"}
    {time.arg   0      "how long to run (0: until the centre is 5 a above the floor)"}
    {nu.arg     0.1    "kinematic viscosity"}
    {g.arg      48     "gravity"}
    {tau.arg    1.0    "relaxation time"}
    {sides.arg  200    "the ellipse polygon's sides"}
    {every.arg  500    "steps between samples"}
    {report.arg 20     "samples between printed lines"}
    {frames.arg 8      "pictures between the start and the end (with -out)"}
    {out.arg    {}     "folder for pictures, the movie and ellipse.csv"}
    {csv.arg    {}     "CSV file for the history"}
}]
dict with options {}
set a 1.0
set W [expr {5.0 * $a}]
set H [expr {double(${-height}) * $a}]
set pi [expr {acos(-1)}]
set out ${-out}
if {$out ne {}} { file mkdir $out }
if {${-csv} eq {} && $out ne {}} { set -csv [file join $out ellipse.csv] }

lattice create -size [list $W $H] -cells ${-cells} -viscosity ${-nu} -tau ${-tau} \
    -walls {left noslip right noslip bottom noslip top noslip}
sim configure -gravity [list 0 [expr {-${-g}}]] -coupling implicit
set dt [dict get [lattice info] timestep]
# Contacts (only if it reaches a wall) stiff enough, and soft enough that the
# critical step is five fluid steps.
set area [expr {$pi * 0.5 * $a * 0.375 * $a}]
set k [expr {${-ratio} * $area * 4 / (25 * $dt * $dt)}]
material create grain -density ${-ratio} -kn $k -ks $k -friction 0.1
foreach {from to} [list {0 0} [list 0 $H] [list $W 0] [list $W $H] {0 0} [list $W 0]] {
    wall create -from $from -to $to -material grain
}
set y0 [expr {$H - ${-start} * $a}]
set body [ellipse create -center [list [expr {0.5 * $W}] $y0] -axes [list [expr {0.5 * $a}] [expr {0.375 * $a}]] \
              -sides ${-sides} -angle [expr {$pi / 4}] -material grain]

set info [lattice info]
set h [expr {$W / ${-cells}}]
puts [format "lattice %d x %d (%d nodes), h = %g, dt = %g, tau %g; ellipse %g x %g cells, %d sides, density ratio %g" \
    [dict get $info nx] [dict get $info ny] [dict get $info nodes] $h $dt [dict get $info tau] \
    [expr {$a / $h}] [expr {0.75 * $a / $h}] ${-sides} ${-ratio}]
set csv {}
if {${-csv} ne {}} {
    set csv [open ${-csv} w]
    puts $csv "t,fall,y,x_over_W,angle,vx,vy,w,Re"
}

# Pictures: a window two channel widths tall, following the ellipse.
set frame 0
proc picture {name args} {
    global out body W
    if {$out eq {}} return
    set y [lindex [dict get [element info $body] position] 1]
    set lo [expr {max(0.0, $y - $W)}]
    set hi [expr {min([lindex [dict get [lattice info] size] 1], $lo + 2 * $W)}]
    set lo [expr {$hi - 2 * $W}]
    snapshot [file join $out $name] -field velocity -vectors 1 -region [list 0 $lo $W $hi] -size {320 640} {*}$args
}

set samples 0
set reSum 0.0
set reCount 0
proc sample {} {
    global body csv a W y0 pi options samples reSum reCount
    set e [element info $body]
    lassign [dict get $e position] x y
    lassign [dict get $e velocity] vx vy w
    set t [dict get [sim info] time]
    set angle [expr {[dict get $e angle] * 180 / $pi}]
    set re [expr {-$vy * $a / [dict get $options -nu]}]
    set fall [expr {($y0 - $y) / $a}]
    # Terminal Re: the mean after the first 5 a of fall.
    if {$fall > 5} { set reSum [expr {$reSum + $re}]; incr reCount }
    if {$csv ne {}} { puts $csv [join [list $t $fall $y [expr {$x / $W}] $angle $vx $vy $w $re] ,] }
    if {$samples % [dict get $options -report] == 0} {
        puts [format "t %9.2f  fall %6.2f a  x/W %.4f  angle %7.2f deg  Re %.3f" \
                  $t $fall [expr {$x / $W}] $angle $re]
    }
    incr samples
    return [list $t $y $angle [expr {$x / $W}] $re]
}

# (At the start the fluid is at rest: the ellipse alone.)
picture ellipse-start.png -field none -vectors 0
lassign [sample] t y angle0
set floor [expr {5 * $a}]
# The whole fall, for the frames: estimated from the first pass of the loop.
set frames ${-frames}
set frameAt {}
set history {}
while {1} {
    run ${-every}
    lassign [sample] t y angle xw re
    lappend history [list $t $y $angle $xw $re]
    if {${-time} > 0 && $t >= ${-time}} break
    if {$y < $floor} break
    # Frames at equal fractions of the fall to the floor (or of the time).
    if {$out ne {} && $frames > 0} {
        set progress [expr {${-time} > 0 ? $t / ${-time} : ($y0 - $y) / ($y0 - $floor)}]
        if {$progress >= ($frame + 1.0) / ($frames + 1)} {
            incr frame
            picture [format "ellipse-%02d.png" $frame]
        }
    }
}
picture ellipse-end.png
if {$csv ne {}} { close $csv }
if {$out ne {} && [auto_execok ffmpeg] ne {}} {
    set pngs [list ellipse-start.png]
    for {set i 1} {$i <= $frame} {incr i} { lappend pngs [format "ellipse-%02d.png" $i] }
    lappend pngs ellipse-end.png
    set list [file join $out frames.txt]
    set f [open $list w]
    foreach p $pngs { puts $f "file '[file normalize [file join $out $p]]'\nduration 0.5" }
    puts $f "file '[file normalize [file join $out ellipse-end.png]]'"
    close $f
    catch {exec ffmpeg -y -loglevel error -f concat -safe 0 -i $list -pix_fmt yuv420p \
               -vf "scale=trunc(iw/2)*2:trunc(ih/2)*2" [file join $out ellipse.mp4] 2>@1}
    file delete $list
}

# Summary: the terminal Re (mean after 5 a of fall), the angle at the start
# and end, its distance from the vertical (folded into 0..90), the range of
# the angle and of x/W over the last third of the fall.
set n [llength $history]
set last [lrange $history [expr {2 * $n / 3}] end]
set amin 1e9; set amax -1e9; set xmin 1e9; set xmax -1e9
foreach s $last {
    lassign $s t y ang xw
    set amin [expr {min($amin, $ang)}]; set amax [expr {max($amax, $ang)}]
    set xmin [expr {min($xmin, $xw)}]; set xmax [expr {max($xmax, $xw)}]
}
set folded [expr {fmod(fmod($angle, 180.0) + 180.0, 180.0)}]
set fromVertical [expr {abs($folded - 90.0)}]
set re [expr {$reCount > 0 ? $reSum / $reCount : 0.0}]
puts [format "summary: ratio %g Re %.3f angle %.1f -> %.1f deg (from vertical %.1f deg), last third angle %.1f..%.1f x/W %.3f..%.3f, fall %.1f a in t %.1f" \
    ${-ratio} $re $angle0 $angle $fromVertical $amin $amax $xmin $xmax [expr {($y0 - $y) / $a}] $t]
