# Bed erosion and saltation (thesis case G, Cook 2001 §6.2.2): a bed of
# elliptical superquadric grains, consolidated under gravity from a line of
# sources, lies on the floor of a periodic channel with a slip lid; at t = 0 a
# horizontal forcing starts to drive the fluid over it. With gravity the grains
# that the flow lifts fall back and hop along the bed (saltation); without it
# they are carried off and the bed erodes in mass. Prints the first grain to
# move and when, the number moving, the mass flux and how high the moving
# grains go; with -out writes CSV series, pictures and (with ffmpeg) a movie.
#
#   sandflow examples/bed-erosion.tcl ?-g G? ?-forcing F? ?-length L? ?-height H?
#            ?-spacing h? ?-layers N? ?-time T? ?-every K? ?-seed S? ?-bed FILE?
#            ?-out DIR? ?-threads N? ?-start D? ?-moving V?
#            ?-coupling implicit|explicit? ?-solidratio exact|1|2|4|8?
#
# The thesis's scene (the defaults): a 300 x 32 channel at spacing 0.4 (751 x
# 81 nodes there; ours 750 x 80 cells, nodes at cell centres: 60,000),
# dt = 0.01, tau = 0.6875 (nu = 1), fluid density 1; periodic left/right,
# no-slip floor, slip lid. Grains: 16-sided superquadrics 3 long and 2 high
# (exponents 2: ellipses), density 2.65, kn = ks = 1e4, friction 0.5, and
# restitution 0.3 (the thesis gives none). -length / 4 sources (75), -layers
# clones each (7): 525 grains (the thesis: over 500). The grains touching the
# ends and the floor are held. The fluid is at rest when the forcing starts;
# -time 500 is the thesis's 50,000 steps; -g 0 and -g 0.5 its two runs.
#
# Not the thesis's (it does not give them, or they fail here):
# - the forcing, 0.04 (a pressure gradient; with it motion starts at
#   g = 0.5 near the thesis's t = 130). The lid's speed passes Mach 0.1 of
#   the lattice speed (40) at t ~ 110 and approaches 9.5 (Mach 0.24) in
#   steady flow, so sandflow warns once about compressibility.
# - -coupling implicit: with the thesis's explicit coupling the packed bed of
#   grains 2.65 times as dense as the fluid rattles as soon as the fluid is
#   there (323 of 411 free grains faster than 0.05 after one time unit) and
#   the run stops at step 118 (a grain's surface at Mach 0.31);
#   -solidratio 2: the thesis's 2 x 2 subcells (the exact areas of
#   superquadrics cost 2.6 times as much per step here).
# - "motion starts": a grain has started when it is -start (1.0, half its
#   height) from where it lay when the forcing began (grains deep in the bed
#   jiggle in the pore flow by a few tenths); it moves at a sample when its
#   speed exceeds -moving (0.2). The mass flux is sum(m vx) / L over the
#   free grains; heights are of the moving grains' centres above the bed's
#   surface at t = 0 (the mean over columns 3 wide of the highest grain top).
#   The most exposed grain is the free one whose top is highest. Grains whose
#   centre passes the right end are taken out (the grains' contacts do not
#   wrap round the periodic ends) and counted as carried out.
#
# The consolidation (pure DEM, no fluid, the grains' weight under water at
# g = 0.5) runs once: -bed FILE keeps it as a checkpoint and later runs with
# the same FILE start from it, so that both values of g start from the same
# bed. -seed sets the sources' small random offsets and angles.
#
# Time here (2 cores shared with other work, one thread): the consolidation
# 20-25 s; the default run (t = 500, 50,000 steps) 500 s with g = 0 and
# 625 s with g = 0.5 (355 and 400 s of CPU); t = 200 (scripts/validate's)
# 350-395 s.

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {g.arg          0.5       "gravity on the grains (the thesis's two runs: 0 and 0.5)"}
    {forcing.arg    0.04      "horizontal forcing on the fluid from t = 0 (a pressure gradient)"}
    {length.arg     300       "the channel's length (-length / 4 sources)"}
    {height.arg     32        "the channel's height"}
    {spacing.arg    0.4       "lattice node spacing"}
    {layers.arg     7         "clones per source, the bed's layers"}
    {time.arg       500       "how long to run after the forcing starts (500: the thesis's 50,000 steps)"}
    {every.arg      100       "steps between samples"}
    {seed.arg       1         "seed of the sources' random offsets and angles"}
    {bed.arg        {}        "checkpoint of the consolidated bed: saved, or loaded when it exists"}
    {out.arg        {}        "folder for CSV series, pictures and the movie"}
    {threads.arg    1         "threads of the step"}
    {start.arg      1.0       "distance from where it lay at which a grain has started"}
    {moving.arg     0.2       "speed above which a grain is moving"}
    {coupling.arg   implicit  "fluid coupling: implicit or explicit"}
    {solidratio.arg 2         "solid ratio: exact, or 1, 2, 4, 8 subcells a side"}
}]
dict with options {}
set Lx [expr {double(${-length})}]
set Ly [expr {double(${-height})}]
set dt 0.01
set a 1.5    ;# semi-axes of a grain: 3 long, 2 high
set b 1.0
sim configure -threads ${-threads}
if {${-out} ne {}} { file mkdir ${-out} }

# ---- the bed: a line of sources, consolidated under gravity ------------------
proc consolidate {} {
    global Lx Ly dt a b options
    expr {srand([dict get $options -seed])}
    # The grains' weight under water at g = 0.5 (no fluid yet, so no buoyancy):
    # the bed of the run with g = 0.5 then starts in equilibrium.
    sim configure -timestep $dt -gravity [list 0 [expr {-0.5 * (1 - 1 / 2.65)}]]
    material create grain -density 2.65 -kn 1e4 -ks 1e4 -friction 0.5 -restitution 0.3
    wall create -from {0 0} -to [list $Lx 0] -material grain
    wall create -from [list 0 [expr {$Ly + 10}]] -to {0 0} -material grain
    wall create -from [list $Lx 0] -to [list $Lx [expr {$Ly + 10}]] -material grain
    set n [expr {max(1, int(round($Lx / 4.0)))}]
    set spacing [expr {$Lx / $n}]
    set yTop [expr {max(3 * $b, $Ly - 2 * $b)}]
    for {set i 0} {$i < $n} {incr i} {
        set id [element next]
        superquadric create -id $id -material grain -axes [list $a $b] -exponents {2 2} -sides 16 \
            -center [list [expr {($i + 0.5) * $spacing + 0.4 * (rand() - 0.5)}] \
                          [expr {$yTop + 2.0 * rand()}]] \
            -angle [expr {rand() - 0.5}]
        source create $id -limit [dict get $options -layers]
    }
    # Until every source has made its clones and the bed is still.
    set steps 0
    while {1} {
        run 500
        incr steps 500
        set made 0
        foreach s [source ids] { incr made [dict get [source info $s] made] }
        set s [sim info]
        set grains [expr {[llength [element ids -type superquadric]] - [llength [source ids]]}]
        if {$made == [llength [source ids]] * [dict get $options -layers]
                && [dict get $s kinetic] < 1e-3 * $grains} break
        if {$steps >= 30000} break
    }
    foreach s [source ids] { source delete $s; element delete $s }
    # Kinetic damping: the grains are stopped every 100 steps for 3000 steps,
    # so that the bed comes to rest rather than rocking (an ellipse rocks on
    # its neighbours with little to damp it).
    for {set k 0} {$k < 30} {incr k} {
        foreach id [element ids -type superquadric] { element configure $id -velocity {0 0 0} }
        run 100
        incr steps 100
    }
    # The grains touching the ends or the floor are held; the end walls go
    # (the flow carries grains across the periodic ends).
    foreach id [element ids -type superquadric] {
        lassign [extent $id] x0 y0 x1 y1
        if {$x0 < 0.3 || $x1 > $Lx - 0.3 || $y0 < 0.3} {
            element configure $id -fix {x y rot} -velocity {0 0 0}
        } else {
            element configure $id -velocity {0 0 0}
        }
    }
    foreach w [element ids -type wall] {
        if {[lindex [dict get [element info $w] from] 1] != 0 || [lindex [dict get [element info $w] to] 1] != 0} {
            element delete $w
        }
    }
    sim configure -gravity {0 0}
    # One step after the deletions: a checkpoint saved right after "element
    # delete" (before a step) is refused by checkpoint load (its contact list
    # still names the deleted slots).
    step
    return $steps
}

# Bounding box of a grain (an ellipse turned by its angle).
proc extent {id} {
    global a b
    set i [element info $id]
    lassign [dict get $i position] x y
    set t [dict get $i angle]
    set hx [expr {sqrt(($a * cos($t)) ** 2 + ($b * sin($t)) ** 2)}]
    set hy [expr {sqrt(($a * sin($t)) ** 2 + ($b * cos($t)) ** 2)}]
    list [expr {$x - $hx}] [expr {$y - $hy}] [expr {$x + $hx}] [expr {$y + $hy}]
}

set clock0 [clock milliseconds]
if {${-bed} ne {} && [file exists ${-bed}]} {
    checkpoint load ${-bed} -recordings 0
    set made "loaded from ${-bed}"
} else {
    set made "consolidated in [consolidate] steps"
    if {${-bed} ne {}} { checkpoint save ${-bed} }
}
set free {}
set held {}
foreach id [element ids -type superquadric] {
    if {[dict get [element info $id] fix] eq {}} { lappend free $id } else { lappend held $id }
}
set consolidateSeconds [expr {([clock milliseconds] - $clock0) / 1000.0}]
puts [format "bed: %d grains (%d held), %s (%.0f s)" \
    [expr {[llength $free] + [llength $held]}] [llength $held] $made $consolidateSeconds]

# ---- the bed's surface and its most exposed grain ------------------------------
# The surface: the mean over columns 3 wide (a grain's length) of the highest
# grain top in each. The most exposed grain: the free grain whose top stands
# highest (grains are ranked by it; the flow is uniform along the periodic bed).
set nb [expr {max(1, int($Lx / 3.0))}]
set bw [expr {$Lx / $nb}]
for {set k 0} {$k < $nb} {incr k} { set surf($k) 0.0 }
set tops {}
foreach id [concat $free $held] {
    lassign [extent $id] x0 y0 x1 y1
    set p0($id) [dict get [element info $id] position]
    set k [expr {min($nb - 1, max(0, int(([lindex $p0($id) 0]) / $bw)))}]
    if {$y1 > $surf($k)} { set surf($k) $y1 }
    if {$id in $free} { lappend tops [list $id $y1] }
}
set sum 0.0
for {set k 0} {$k < $nb} {incr k} { set sum [expr {$sum + $surf($k)}] }
set ySurface [expr {$sum / $nb}]
set ranking {}
foreach pair [lsort -real -decreasing -index 1 $tops] { lappend ranking [lindex $pair 0] }
set exposed [lindex $ranking 0]
puts [format "bed surface at y = %.2f (fluid depth %.2f); most exposed grains (highest tops): %s" \
    $ySurface [expr {$Ly - $ySurface}] [join [lmap pair [lrange [lsort -real -decreasing -index 1 $tops] 0 2] {
        format "%s at {%.2f %.2f} top %.2f" [lindex $pair 0] {*}$p0([lindex $pair 0]) [lindex $pair 1]}] ", "]]

# ---- the fluid and the forcing ------------------------------------------------
sim configure -timestep $dt -gravity [list 0 [expr {-double(${-g})}]] -coupling ${-coupling} \
    -solidratio ${-solidratio}
lattice create -size [list $Lx $Ly] -spacing ${-spacing} -viscosity 1.0 -density 1.0 \
    -periodic {1 0} -walls {bottom noslip top slip} -forcing [list ${-forcing} 0]
set info [lattice info]
set t0 [dict get [sim info] time]
set steps [expr {int(round(${-time} / $dt))}]
puts [format "lattice %d x %d (%d nodes), dt %g, tau %.4f, nu %g; forcing %g, g %g; %d steps" \
    [dict get $info nx] [dict get $info ny] [dict get $info nodes] [dict get $info timestep] \
    [dict get $info tau] [dict get $info viscosity] ${-forcing} ${-g} $steps]

set csv {}
set exposedFile {}
# Pictures 1500 wide, as tall as the channel's shape asks (plus the labels).
set picture [list 1500 [expr {2 * (min(900, max(200, int(1300 * $Ly / $Lx) + 70)) / 2)}]]
if {${-out} ne {}} {
    set csv [open [file join ${-out} series.csv] w]
    puts $csv "time,moving,started,eroded,out,flux,mean_height,max_height,fluid_speed,kinetic"
    set exposedFile [file join ${-out} exposed.csv]
    output csv $exposedFile -elements $exposed -every ${-every}
    snapshot [file join ${-out} bed-start.png] -field velocity -colorby speed -size $picture
    if {[auto_execok ffmpeg] ne {}} {
        output movie [file join ${-out} bed-erosion.mp4] -every [expr {4 * ${-every}}] \
            -fps 20 -field velocity -size $picture
    }
}

set firstId {}
set firstTime {}
set started 0
set out 0
set outMass 0.0
set maxMoving 0
set maxHeight 0.0
set fluxSum 0.0
set heightSum 0.0
set heightCount 0
set samples 0
array set hasStarted {}
proc sample {} {
    global free p0 t0 csv firstId firstTime started out outMass maxMoving maxHeight fluxSum \
        heightSum heightCount samples hasStarted Lx Ly ySurface options lastEroded \
        exposed exposedFile
    set t [expr {[dict get [sim info] time] - $t0}]
    set moving 0
    set eroded 0
    set px 0.0
    set hs 0.0
    set hmax 0.0
    set keep {}
    foreach id $free {
        set i [element info $id]
        lassign [dict get $i position] x y
        lassign [dict get $i velocity] vx vy
        if {$x > $Lx} {
            # carried past the right end: out of the scene (its record ends)
            if {$id == $exposed && $exposedFile ne {}} {
                output close $exposedFile
                set exposedFile {}
            }
            incr out
            set outMass [expr {$outMass + [dict get $i mass]}]
            element delete $id
            continue
        }
        lappend keep $id
        set px [expr {$px + [dict get $i mass] * $vx}]
        lassign $p0($id) x0 y0
        set d [expr {hypot($x - $x0, $y - $y0)}]
        if {$d > [dict get $options -start] && ![info exists hasStarted($id)]} {
            set hasStarted($id) $t
            incr started
            if {$firstId eq {}} { set firstId $id; set firstTime $t }
        }
        if {$d > 3.0} { incr eroded }
        if {hypot($vx, $vy) > [dict get $options -moving]} {
            incr moving
            set h [expr {$y - $ySurface}]
            set hs [expr {$hs + $h}]
            if {$h > $hmax} { set hmax $h }
        }
    }
    set free $keep
    set lastEroded [expr {$eroded + $out}]
    set flux [expr {$px / $Lx}]
    set meanH [expr {$moving ? $hs / $moving : 0.0}]
    if {$moving > $maxMoving} { set maxMoving $moving }
    if {$hmax > $maxHeight} { set maxHeight $hmax }
    set fluxSum [expr {$fluxSum + $flux}]
    set heightSum [expr {$heightSum + $hs}]
    incr heightCount $moving
    incr samples
    set u [lindex [dict get [lattice probe [list [expr {0.5 * $Lx}] [expr {$Ly - 0.2}]]] velocity] 0]
    set ke [dict get [sim info] kinetic]
    if {$csv ne {}} {
        puts $csv [join [list [format %.2f $t] $moving $started [expr {$eroded + $out}] $out \
                             [format %.5g $flux] [format %.4g $meanH] [format %.4g $hmax] \
                             [format %.4g $u] [format %.4g $ke]] ,]
        flush $csv
    }
    return [format "t %6.1f  started %3d  moving %3d  eroded %3d  out %3d  flux %.4g  height mean %.2f max %.2f  lid speed %.3f" \
                $t $started $moving [expr {$eroded + $out}] $out $flux $meanH $hmax $u]
}

set clock1 [clock milliseconds]
puts [sample]
set reportEvery [expr {max(1, $steps / ${-every} / 20)}]
set done 0
# Pictures at about a quarter, half and the end of the run (on samples).
set shots [lsort -integer -unique [lmap f {0.25 0.5 1.0} {
    expr {max(1, int(round($f * $steps / ${-every}))) * ${-every}}}]]
while {$done < $steps} {
    set n [expr {min(${-every}, $steps - $done)}]
    run $n
    incr done $n
    set line [sample]
    if {($done / ${-every}) % $reportEvery == 0 || $done == $steps} { puts $line }
    if {$csv ne {} && $done in $shots} {
        snapshot [file join ${-out} [format "bed-t%g.png" [expr {$done * $dt}]]] \
            -field velocity -colorby speed -size $picture
    }
}
if {$csv ne {}} { close $csv; output close }
set seconds [expr {([clock milliseconds] - $clock1) / 1000.0}]
set order [lsort -real -stride 2 -index 1 [array get hasStarted]]
puts "the first grains to start (id, time, rank by height): [join [lmap {id t} [lrange $order 0 19] {
    format "%s %.1f %d" $id $t [expr {[lsearch $ranking $id] + 1}]}] {, }]"
set rank [expr {$firstId eq {} ? "-" : [lsearch $ranking $firstId] + 1}]
puts [format "summary: g %g first %s at t %s exposed %s (the first is rank %s in height) started %d eroded %d out %d max_moving %d mean_flux %.4g mean_height %.3f max_height %.3f run %.0f s" \
    ${-g} [expr {$firstId eq {} ? "none" : $firstId}] \
    [expr {$firstTime eq {} ? "never" : [format %.2f $firstTime]}] $exposed \
    $rank $started \
    $lastEroded $out $maxMoving [expr {$fluxSum / $samples}] \
    [expr {$heightCount ? $heightSum / $heightCount : 0.0}] $maxHeight $seconds]
