# Hydraulic fracturing and borehole breakout in a bonded disc specimen (thesis
# case H, Cook 2001 §2.5): pure DEM, no lattice.
#
# The specimen is built as the thesis built it. Rings of source discs at the
# centre shoot clones outward, largest first, so that each ring packs an
# annulus inside the last: a radially graded assembly of about 2000 discs,
# 5-40 cm across (coarse at the plates, fine about the hole), in a 4 m x 4 m
# box of four plates. The clones' push is then switched off and the four
# plates, servo-controlled (`element configure -stress`), consolidate it to the
# test's mean confining stress; the discs within 1 m of the centre are
# bonded (`bond auto`), after an anisotropic stress has been servoed on
# (at friction 0.5); then the hole is loaded:
#   -mode fracture   hole 20 cm across; "fluid" source discs (radius 0.5 cm,
#                    friction 0.1) in it are pushed outward with 50 N each
#                    and pressurize it; bonds 1e6 N/m, 500 N; confining
#                    stress 187.5 kPa (neutral) or 250 kPa across x and
#                    125 kPa across y (anisotropic); dt 5e-6 s, 0.1 s.
#   -mode breakout   the discs of a hole 50 cm across are removed; bonds
#                    3e6 N/m, 1000 N; confining 1.375 MPa (neutral) or
#                    2.25 MPa across x, 0.5 MPa across y; dt 1e-5 s, 0.05 s.
# Discs: density 2650 kg/m^3, kn = ks = 1e7 N/m, friction 0.5.
# Broken bonds (`bond broken`) are counted in 60 sectors of 6 degrees by the
# angle of the bond's middle about the hole centre: the rose plot. Its
# non-uniformity is given as max sector / mean sector and, from the second
# angular moment of the breaks (axial, so a fracture through the hole counts
# once), the dominant axis (0 = x, the axis of the larger stress, 90 = y)
# and its strength (0 uniform, 1 all on one line).
#
# The plates servo only while the specimen is consolidated and hold their
# place during the loading (their servo's gain is per step, and at the
# loading's short steps it drives them to and fro).
#
#   sandflow examples/thesis-fracture.tcl ?-mode fracture|breakout?
#            ?-stress neutral|anisotropic? ?-seed N? ?-out DIR? ?-discs N?
#            ?-time T? ?-every K? ?-stressscale F? ?-movie 0|1?
#
# -discs: about how many discs the specimen has (the thesis: about 2000; a
# smaller number keeps the 4 m box and the grading and scales the sizes up);
# -time: the loading time in s (default the thesis's: 0.1 fracture, 0.05
# breakout); -every: steps between progress lines (default a twentieth of
# the loading); -seed: turns the source rings and jitters the disc sizes by
# +-10% (the packing, and so the failure, changes with it); -stressscale:
# multiplies the confining stresses (default 1, the thesis's).
# -out DIR: rose.csv (breaks per sector: sector,angle,count,x,y with x, y
# the count times cos, sin of the sector's angle), rose.png (drawn from it
# with `plot`), breaks.csv (every break: time since the loading began,
# x, y, the bond's direction, the angle about the hole), series.csv (broken
# and intact bonds and fluid discs against time), start.png, end.png
# (broken bonds red) and, with ffmpeg and -movie 1, loading.mp4.
# The last line: "summary: mode M stress S seed N discs D coordination C
# bonds B broken K at 0.01/0.04/0.07 s a/b/c peak/mean P axis A deg axial X
# threefold Y chi2 Z time T s".
#
# Size and time here (2 cores, one thread, shared): about 1930 discs, 30,000
# steps to build and consolidate the specimen (about 40 s of CPU), then
# 20,000 steps of fracturing or 5,000 of breakout; 80-180 s (fracturing) or
# 45-75 s (breakout) of wall-clock time on the shared machine.

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {mode.arg        fracture "fracture (a pressurized hole) or breakout (an empty one)"}
    {stress.arg      neutral  "confining stress: neutral or anisotropic"}
    {seed.arg        1        "seed: turns the source rings, jitters the disc sizes"}
    {out.arg         {}       "folder for the rose, CSV files, pictures and the movie"}
    {discs.arg       2000     "about how many discs (the thesis: about 2000)"}
    {time.arg        {}       "loading time in s (default 0.1 fracture, 0.05 breakout)"}
    {every.arg       {}       "steps between progress lines (default a twentieth of the loading)"}
    {stressscale.arg 1.0      "factor on the confining stresses"}
    {movie.arg       1        "1: loading.mp4 with -out, when ffmpeg is installed"}
}]
dict with options {}
if {${-mode} ni {fracture breakout}} { error "bad -mode \"${-mode}\": must be fracture or breakout" }
if {${-stress} ni {neutral anisotropic}} {
    error "bad -stress \"${-stress}\": must be neutral or anisotropic"
}
if {![string is integer -strict ${-seed}]} { error "bad -seed \"${-seed}\": must be an integer" }
if {![string is integer -strict ${-discs}] || ${-discs} < 100} {
    error "bad -discs \"${-discs}\": must be an integer >= 100"
}
set pi [expr {acos(-1)}]
expr {srand(${-seed})}
set started [clock milliseconds]
proc elapsed {} { expr {([clock milliseconds] - $::started) / 1000.0} }

# ---- the test's parameters (thesis §2.5) ------------------------------------
if {${-mode} eq "fracture"} {
    set sigma [expr {${-stress} eq "neutral" ? {187.5e3 187.5e3} : {250e3 125e3}}]
    set holeRadius 0.10
    set bondStiffness 1e6
    set bondStrength 500.0
    set loadDt 5e-6
    set loadTime [expr {${-time} eq {} ? 0.1 : ${-time}}]
} else {
    set sigma [expr {${-stress} eq "neutral" ? {1.375e6 1.375e6} : {2.25e6 0.5e6}}]
    set holeRadius 0.25
    set bondStiffness 3e6
    set bondStrength 1e3
    set loadDt 1e-5
    set loadTime [expr {${-time} eq {} ? 0.05 : ${-time}}]
}
lassign $sigma sigmaX sigmaY
set sigmaX [expr {$sigmaX * ${-stressscale}}]
set sigmaY [expr {$sigmaY * ${-stressscale}}]
if {${-mode} eq "breakout"} {
    # At the breakout's confining stresses (sigma / kn = 0.05 to 0.23) the
    # contacts overlap by up to about half a radius, and grains falling into
    # the emptied hole deeper for a moment: let the run go on (the default
    # stops at 0.5 of the smaller radius).
    sim configure -maxoverlap 0.9
}
set half 2.0             ;# the specimen is 2 half x 2 half
set bondRadius 1.0       ;# discs within this of the centre are bonded

material create rock -density 2650 -kn 1e7 -ks 1e7 -friction 0.5 -restitution 0.3 \
    -bondstiffness $bondStiffness -bondstrength $bondStrength
material create fluid -density 2650 -kn 1e7 -ks 1e7 -friction 0.1 -restitution 0.3

# ---- the plates: four walls, longer than the specimen so the corners stay shut
# (1 m under anisotropic stress, where the specimen deforms more)
set over [expr {${-stress} eq "neutral" ? 0.3 : 1.0}]
set L [expr {$half + $over}]
set plates [list \
    [wall create -from [list [expr {-$L}] [expr {-$half}]] -to [list $L [expr {-$half}]] -material rock] \
    [wall create -from [list $half [expr {-$L}]] -to [list $half $L] -material rock] \
    [wall create -from [list $L $half] -to [list [expr {-$L}] $half] -material rock] \
    [wall create -from [list [expr {-$half}] $L] -to [list [expr {-$half}] [expr {-$L}]] -material rock]]
lassign $plates bottom right top left

# ---- the source rings: a radially graded specimen ---------------------------
# Disc radii by stage, largest first, and the inner edge of the annulus each
# fills (the radius grows with the distance from the hole about as
# ((rho - 0.12 m) / 2.14 m)^3, from 2.5 cm to 20 cm). -discs scales the radii
# by sqrt(2000 / discs).
set scale [expr {sqrt(2000.0 / ${-discs})}]
set stages {0.20 2.12 0.14 1.86 0.10 1.61 0.07 1.36 0.05 1.10 0.035 0.76 0.025 0.12}
proc makeStage {r inner outer accel} {
    # Rings of sources 4 radii apart across the annulus inner..outer, inside
    # the box; each source clones until the packing reaches it.
    global pi half
    set ids {}
    set first [expr {max(min($inner + 1.2 * $r, $outer - $r), 2.5 * $r)}]
    for {set ring $first} {$ring < $outer} \
            {set ring [expr {$ring + 4 * $r}]} {
        set n [expr {max(3, int(2 * $pi * $ring / (2.4 * $r)))}]
        set offset [expr {2 * $pi * rand()}]
        for {set k 0} {$k < $n} {incr k} {
            set theta [expr {$offset + 2 * $pi * $k / $n}]
            set radius [expr {$r * (0.9 + 0.2 * rand())}]
            set x [expr {$ring * cos($theta)}]
            set y [expr {$ring * sin($theta)}]
            if {max(abs($x), abs($y)) > $half - 1.5 * $r} continue
            set id [disc create -material rock -radius $radius -center [list $x $y]]
            source create $id -acceleration [list [expr {$accel * cos($theta)}] \
                                                 [expr {$accel * sin($theta)}]]
            lappend ids $id
        }
    }
    return $ids
}
sim configure -threads 1
# The packing and the consolidation run with friction 0.1, which packs denser
# (the coordination number nearer the thesis's 4.5); 0.5 from the bonding on.
material configure rock -friction 0.1
set accel 20.0
set outer [expr {2 * $half / sqrt($pi)}]   ;# the circle of the box's area
foreach {r inner} $stages {
    set r [expr {$r * $scale}]
    set sources [makeStage $r $inner $outer $accel]
    set outer $inner
    # Run until no source has cloned for three clone times.
    set tb [expr {2 * sqrt($r / $accel)}]
    set check [expr {int(ceil(10 * $tb / [dict get [sim info] critical]))}]
    set last -1
    set still 0
    set made 0
    while {[llength $sources] && $still < 3} {
        run $check
        set made 0
        foreach s $sources { incr made [dict get [source info $s] made] }
        if {$made == $last} { incr still } else { set still 0 }
        set last $made
    }
    foreach s $sources { source delete $s; element delete $s }
    puts [format "stage r %.3f m: %d discs, annulus to %.2f m, t = %.2f s, step %d, %d discs (%.0f s)" \
        $r $made $outer [dict get [sim info] time] [dict get [sim info] step] \
        [llength [element ids -type disc]] [elapsed]]
}
set discs [element ids -type disc]
set prepSteps [dict get [sim info] step]

# ---- consolidation: the push off, the plates servo to the confining stress ---
foreach id $discs { element configure $id -acceleration {0 0} -velocity {0 0 0} }
# A plate's servo holds its load at stress x its length; the specimen's face
# is 2 half long, so the stress asked of a plate is scaled by face / length.
set ratio [expr {$half / $L}]
proc inward {plate} {
    set a [element cget $plate -angle]
    list [expr {-sin($a)}] [expr {cos($a)}]
}
proc plateLoad {plate} {
    lassign [dict get [element info $plate] contactforce] fx fy
    lassign [inward $plate] nx ny
    expr {-($fx * $nx + $fy * $ny)}
}
proc plateAt {plate} {
    lassign [dict get [element info $plate] position] x y
    lassign [inward $plate] nx ny
    expr {-($x * $nx + $y * $ny)}   ;# the distance of the plate from the centre
}
# Servo the plates to stress sx on the x faces and sy on the y faces until
# their loads are within 2% of it and they stand still (< 0.2 mm in 500
# steps), at most `tries` times 500 steps; sets ::worst (the largest load
# error) and ::now (the plates' distances from the centre).
proc servo {sx sy tries} {
    global plates ratio half worst now
    foreach plate $plates sigma [list $sy $sx $sy $sx] {
        element configure $plate -stress [expr {$sigma * $ratio}]
        dict set target $plate [expr {$sigma * 2 * $half}]
    }
    set before {}
    for {set k 0} {$k < $tries} {incr k} {
        run 500
        set worst 0
        set moved 0
        set now {}
        foreach plate $plates {
            set err [expr {abs([plateLoad $plate] / [dict get $target $plate] - 1)}]
            set worst [expr {max($worst, $err)}]
            lappend now [plateAt $plate]
        }
        if {$before ne {}} {
            foreach a $now b $before { set moved [expr {max($moved, abs($a - $b))}] }
            if {$worst < 0.02 && $moved < 2e-4} break
        }
        set before $now
    }
}
# Consolidated under the mean stress at friction 0.1; an anisotropic stress
# comes at friction 0.5 (at 0.1 the specimen flows under it), before the
# bonding (a bonded specimen loses half its bonds to the change of shape).
set mean [expr {0.5 * ($sigmaX + $sigmaY)}]
servo $mean $mean 200
lassign $now yb xr yt xl
set width [expr {$xr + $xl}]
set height [expr {$yb + $yt}]
set consolidated [dict get [sim info] step]
# Coordination: contacts between discs per disc (plates left out).
set wallContacts 0
foreach plate $plates { incr wallContacts [dict get [element info $plate] contacts] }
set coordination [expr {2.0 * ([dict get [sim info] contacts] - $wallContacts) / [llength $discs]}]
set maxOverlap 0
puts [format "consolidated: %d discs, %.3f x %.3f m, coordination %.2f, plate loads within %.1f%%, step %d (%.0f s)" \
    [llength $discs] $width $height $coordination [expr {100 * $worst}] $consolidated [elapsed]]

# ---- bonding the centre region ---------------------------------------------
material configure rock -friction 0.5
if {$sigmaX != $sigmaY} {
    # The anisotropic stress, servoed as before at friction 0.5, for at most
    # 30,000 steps. At the breakout's stress ratio, 4.5, the unbonded
    # specimen cannot carry it and flows, faster and faster (it lengthens
    # along y): the breakout's servo stops after 6000 steps, the specimen
    # still moving.
    servo $sigmaX $sigmaY [expr {${-mode} eq "fracture" ? 60 : 12}]
    lassign $now yb xr yt xl
    puts [format "anisotropic stress: %.3f x %.3f m, plate loads within %.1f%%, kinetic %.3g J/m, step %d (%.0f s)" \
        [expr {$xr + $xl}] [expr {$yb + $yt}] [expr {100 * $worst}] \
        [dict get [sim info] kinetic] [dict get [sim info] step] [elapsed]]
}
set centre {}
foreach id $discs {
    lassign [dict get [element info $id] position] x y
    if {hypot($x, $y) < $bondRadius} { lappend centre $id }
}
set bonds [bond auto -elements $centre -gap 1e-3]
puts [format "bonded: %d bonds among %d discs within %.1f m (%.2f a disc)" $bonds [llength $centre] \
    $bondRadius [expr {2.0 * $bonds / [llength $centre]}]]

# ---- the hole and its loading -------------------------------------------------
set removed 0
foreach id $discs {
    lassign [dict get [element info $id] position] x y
    if {hypot($x, $y) < $holeRadius} { element delete $id; incr removed }
}
sim configure -timestep $loadDt
# The plates hold their place while the hole is loaded: their servo's gain is
# per step, and at the loading's short steps it would drive them to and fro.
foreach plate $plates { element configure $plate -stress {} -velocity {0 0 0} }
set fluidSources {}
if {${-mode} eq "fracture"} {
    # Rings of "fluid" sources in the hole, each clone pushed outward with 50 N.
    set rf 0.005
    set force 50.0
    for {set ring [expr {2 * $rf}]} {$ring < $holeRadius - 3 * $rf} {set ring [expr {$ring + 3 * $rf}]} {
        set n [expr {int(2 * $pi * $ring / (2.4 * $rf))}]
        for {set k 0} {$k < $n} {incr k} {
            set theta [expr {2 * $pi * ($k + 0.5 * ($ring / $rf)) / $n}]
            set id [disc create -material fluid -radius $rf \
                        -center [list [expr {$ring * cos($theta)}] [expr {$ring * sin($theta)}]] \
                        -force [list [expr {$force * cos($theta)}] [expr {$force * sin($theta)}] 0]]
            source create $id
            lappend fluidSources $id
        }
    }
    puts [format "hole %.0f cm across: %d discs removed, %d fluid sources pushing 50 N each" \
        [expr {200 * $holeRadius}] $removed [llength $fluidSources]]
} else {
    puts [format "hole %.0f cm across: %d discs removed" [expr {200 * $holeRadius}] $removed]
}
set t0 [dict get [sim info] time]
set preBroken [llength [bond broken]]   ;# broken before the loading: not counted
set steps [expr {int(round($loadTime / $loadDt))}]
set every [expr {${-every} eq {} ? max(1, $steps / 20) : ${-every}}]
set out ${-out}
if {$out ne {}} {
    file mkdir $out
    view configure -size {800 800} -region [list -2.3 -2.3 2.3 2.3]
    snapshot [file join $out start.png] -bonds 1
    set series [open [file join $out series.csv] w]
    puts $series "time,broken,bonds,fluid"
    if {${-movie} && [auto_execok ffmpeg] ne {}} {
        output movie [file join $out loading.mp4] -every $every -fps 10 -bonds 1
    }
}
proc progress {} {
    global t0 series out fluidSources preBroken
    set s [sim info]
    dict set s broken [expr {[dict get $s broken] - $preBroken}]
    set fluid 0
    foreach id $fluidSources { incr fluid [dict get [source info $id] made] }
    set t [expr {[dict get $s time] - $t0}]
    if {$out ne {}} {
        puts $series [format "%.6g,%d,%d,%d" $t [dict get $s broken] [dict get $s bonds] $fluid]
        flush $series
    }
    puts [format "t = %.4f s  broken bonds %d  intact %d  fluid discs %d  kinetic %.3g J/m (%.0f s)" \
        $t [dict get $s broken] [dict get $s bonds] $fluid [dict get $s kinetic] [elapsed]]
}
progress
run $steps -every $every progress

# ---- the rose: broken bonds per 6-degree sector about the hole ----------------
set sectors 60
set counts [lrepeat $sectors 0]
set c2 0.0
set s2 0.0
set c3 0.0
set s3 0.0
set breaks [bond broken -since [expr {$t0 + 0.5 * $loadDt}]]
foreach b $breaks {
    lassign $b t x y
    set phi [expr {atan2($y, $x)}]
    if {$phi < 0} { set phi [expr {$phi + 2 * $pi}] }
    set k [expr {int($phi / (2 * $pi) * $sectors) % $sectors}]
    lset counts $k [expr {[lindex $counts $k] + 1}]
    set c2 [expr {$c2 + cos(2 * $phi)}]
    set s2 [expr {$s2 + sin(2 * $phi)}]
    set c3 [expr {$c3 + cos(3 * $phi)}]
    set s3 [expr {$s3 + sin(3 * $phi)}]
}
set n [llength $breaks]
set peak [tcl::mathfunc::max {*}$counts]
set nonuniform [expr {$n ? $peak * $sectors / double($n) : 0}]
set axial [expr {$n ? hypot($c2, $s2) / $n : 0}]
set axis [expr {$n ? fmod(90.0 / $pi * atan2($s2, $c2) + 180.0, 180.0) : 0}]
set threefold [expr {$n ? hypot($c3, $s3) / $n : 0}]
# Chi-square of the counts in 12 sectors of 30 degrees against a uniform rose
# (11 degrees of freedom: above 19.7 for 5%, 31.3 for 0.1% chance).
set chi2 0.0
for {set k 0} {$k < 12} {incr k} {
    set c 0
    foreach j [lrange $counts [expr {5 * $k}] [expr {5 * $k + 4}]] { incr c $j }
    if {$n} { set chi2 [expr {$chi2 + ($c - $n / 12.0) ** 2 / ($n / 12.0)}] }
}
# Breaks by the thesis's sampling times.
set at {}
foreach tt {0.01 0.04 0.07} {
    set k 0
    foreach b $breaks { if {[lindex $b 0] - $t0 <= $tt + 0.5 * $loadDt} { incr k } }
    lappend at $k
}
if {$out ne {}} {
    close $series
    set f [open [file join $out rose.csv] w]
    puts $f "sector,angle,count,x,y"
    for {set k 0} {$k <= $sectors} {incr k} {
        set c [lindex $counts [expr {$k % $sectors}]]
        set a [expr {($k % $sectors + 0.5) * 2 * $pi / $sectors}]
        puts $f [format "%d,%.1f,%d,%.4g,%.4g" [expr {$k % $sectors}] [expr {$a * 180 / $pi}] $c \
            [expr {$c * cos($a)}] [expr {$c * sin($a)}]]
    }
    close $f
    set f [open [file join $out breaks.csv] w]
    puts $f "time,x,y,angle,about_hole"
    foreach b $breaks {
        lassign $b t x y a
        puts $f [format "%.6g,%.5g,%.5g,%.4g,%.2f" [expr {$t - $t0}] $x $y $a \
            [expr {fmod(atan2($y, $x) * 180 / $pi + 360, 360)}]]
    }
    close $f
    output close
    snapshot [file join $out end.png] -bonds 1 -size {700 700} -region {-1.2 -1.2 1.2 1.2}
    set lim [expr {max(1, $peak)}]
    plot [file join $out rose.png] [file join $out rose.csv] -x x -y y -style lines -key off \
        -size {600 600} -xrange [list -$lim $lim] -yrange [list -$lim $lim] \
        -title "${-mode}, ${-stress} stress, seed ${-seed}: broken bonds per 6-degree sector" \
        -xlabel "count cos(angle)" -ylabel "count sin(angle)"
}
puts [format "summary: mode %s stress %s seed %d discs %d coordination %.2f bonds %d broken %d at 0.01/0.04/0.07 s %s peak/mean %.2f axis %.0f deg axial %.2f threefold %.2f chi2 %.1f time %.0f s" \
    ${-mode} ${-stress} ${-seed} [llength $discs] $coordination $bonds $n [join $at /] \
    $nonuniform $axis $axial $threefold $chi2 [elapsed]]
