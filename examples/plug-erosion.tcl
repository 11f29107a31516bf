# Plug erosion (thesis case F, Cook 2001 §6.2.1): a plug of discs in a
# periodic channel, eroded by the flow that a constant horizontal forcing
# drives through its constriction.
#
#   sandflow examples/plug-erosion.tcl ?-bonded 0|1? ?-length L? ?-height H?
#            ?-spacing h? ?-discs N? ?-time T? ?-forcing F? ?-g g? ?-seed S?
#            ?-every K? ?-frames N? ?-coupling explicit|implicit?
#            ?-integrator euler|central|verlet? ?-maxmach M? ?-threads N? ?-movie 0|1? ?-out DIR?
#
# The scene, built as the thesis built it:
# - Fluid: a channel L x H (the thesis: 100 x 40, node spacing 0.25), periodic
#   left/right, no-slip top and bottom, density 1, viscosity 0.1, dt = 0.02
#   (so tau = 0.596 at h = 0.25).
# - Grains: about N discs (the thesis: about 200) of radius 1.0 to 1.8
#   (uniform, seeded), density 2, kn = ks = 1e3, friction 0.5, packed by
#   source discs (-limit 1 each) into a bottom assembly (clones accelerated
#   downward at 0.1) and a top one (accelerated upward), row by row: a base
#   row along the wall over 90% of L, held once it has landed, then rows
#   from 70% of L narrowing to 10%; the discs roll down the pile's flanks, so
#   each assembly is a mound, and the two mounds leave a narrow gap between
#   them in the middle of the channel: the constriction. Each row's sources
#   are deleted once it has settled. Every disc touching the top or bottom
#   wall is then held (-fix {x y rot}).
# - Bonded run (-bonded 1): every pair of discs closer than 2% of the mean
#   radius is bonded (stiffness 1e3, strength 1.5, shear strength the same),
#   after the fluid has run 100 steps at rest.
# - Then the fluid is switched on at rest, and a constant horizontal forcing
#   F drives it (the thesis does not give F; default 0.003 unbonded, 0.012
#   bonded: bonds of strength 1.5 hold against four times the drive that
#   friction does). The packing acceleration becomes g = 0.02 and stays on (it
#   holds each assembly against its wall, as gravity would: the grains'
#   submerged weight per unit mass; the thesis gives no g either).
# - Integration: the thesis's first-order (Euler) integrator with the
#   explicit coupling. With the default central difference a density ratio
#   of 2 sits at the explicit coupling's stability limit (docs/coupling.md)
#   and the bonded plug shatters; the implicit coupling is stable, but its
#   start breaks a few bonds.
# - A grain that leaves the channel downstream (centre within 2 radii of
#   x = L) is taken out: the contacts of elements do not wrap round the
#   periodic edge (docs/coupling.md, Limits). The run stops early if the
#   flow passes Mach -maxmach (0.25): the forcing keeps accelerating it.
#
# What it measures (and writes to DIR):
# - erosion: a free disc is "eroded" when it has moved more than its own
#   radius since the forcing started; the order and times (eroded.csv),
# - the constriction: the two discs, one from each assembly, whose surfaces
#   are closest across the gap; the larger of the two is "the larger disc at
#   the constriction" (the thesis: it erodes first); the summary says
#   whether the first eroded disc is one of the two (at_constriction) and
#   whether it is the larger (exposed_first),
# - history.csv: time since the forcing started, the fluid flux through the
#   constriction (the sum of rho u_x h over the fluid nodes of the column at
#   its x), the pressure c_s^2 rho - p_0 at probes a quarter of the channel
#   up- and downstream at mid-height and in the gap, the eroded and removed
#   counts, broken bonds and the Mach number,
# - bonds-broken.csv: time, place and direction of each broken bond,
# - pictures plug-0.png ... plug-N.png (start, -frames more), record.csv and
#   plug.mp4 when ffmpeg is installed (-movie 1).
# The last line is "summary: key value ...", for scripts
# (scripts/validate-cases/F.sh).
#
# Size and time: the default is the thesis's 400 x 160 lattice (64,000
# nodes, h 0.25, dt 0.02, tau 0.596) and 200 discs (48 held); packing
# ~43,000 DEM steps (under a second), then T = 300 (15,000 coupled steps).
# On this 2-core machine, one thread, shared: about 80 s of CPU (1.5-3.5
# minutes of wall time) per run, a minute more with the movie.

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {bonded.arg     0         "1: bond the plug's discs"}
    {length.arg     100       "the channel's length (the thesis: 100)"}
    {height.arg     40        "the channel's height (the thesis: 40)"}
    {spacing.arg    0.25      "lattice node spacing (the thesis: 0.25)"}
    {discs.arg      200       "about how many discs (the thesis: about 200)"}
    {time.arg       300       "how long to run after the forcing starts"}
    {forcing.arg    {}        "horizontal forcing (default 0.003 unbonded, 0.012 bonded)"}
    {g.arg          0.02      "acceleration holding each assembly against its wall"}
    {seed.arg       1         "seed of the disc radii and the sources' offsets"}
    {every.arg      25        "steps between samples and record rows"}
    {frames.arg     4         "pictures after the start (with -out)"}
    {coupling.arg   explicit  "fluid coupling: explicit or implicit"}
    {integrator.arg euler     "integrator: euler, central or verlet"}
    {maxmach.arg    0.25      "stop when the flow passes this Mach number"}
    {threads.arg    0         "threads of the step (0: the default)"}
    {movie.arg      1         "1: plug.mp4 with -out, when ffmpeg is installed"}
    {out.arg        {}        "folder for the CSV files, pictures and the movie"}
}]
dict with options {}
# The drive: bonds of strength 1.5 hold against a larger one than friction does.
if {${-forcing} eq {}} { set -forcing [expr {${-bonded} ? 0.012 : 0.003}] }
set L [expr {double(${-length})}]
set H [expr {double(${-height})}]
set dt 0.02
set rmin 1.0
set rmax 1.8
set out ${-out}
# Packing acceleration: at least 0.1, so that each row settles in a few thousand steps.
set gpack [expr {max(${-g}, 0.1)}]
if {$out ne {}} { file mkdir $out }
expr {srand(${-seed})}

# ---- materials, walls ---------------------------------------------------------
sim configure -timestep $dt -coupling ${-coupling} -integrator ${-integrator}
if {${-threads} > 0} { sim configure -threads ${-threads} }
material create grain -density 2.0 -kn 1e3 -ks 1e3 -friction 0.5 -restitution 0.5 \
    -bondstiffness 1e3 -bondstrength 1.5
set floor [wall create -from {0 0} -to [list $L 0] -material grain]
set roof [wall create -from [list 0 $H] -to [list $L $H] -material grain]

# ---- packing ----------------------------------------------------------------------
# A base row along the wall (90% of L, held once settled: a rough floor), then
# rows of sources each narrower than the last, from 70% of L down to 10%; the
# rows add up to N/2 discs per assembly. Discs dropped on the pile roll down
# its flanks to the angle of repose, so each assembly becomes a mound.
set pitch [expr {2 * $rmax + 0.1}]
set half [expr {${-discs} / 2}]
set nBase [expr {min($half, max(2, int(0.9 * $L / $pitch)))}]
set nB [expr {max(2, int(0.7 * $L / $pitch))}]
set nb [expr {max(1, int(0.1 * $L / $pitch))}]
set rest [expr {$half - $nBase}]
set rows [expr {$rest <= 0 ? 0 : max(1, int(round(2.0 * $rest / ($nB + $nb))))}]
set counts [list $nBase]
for {set j 0} {$j < $rows} {incr j} {
    lappend counts [expr {$rows == 1 ? $nB : int(round($nB + ($nb - $nB) * double($j) / ($rows - 1)))}]
}
# Adjust the top rows so that the total is N/2.
set total [tcl::mathop::+ {*}$counts]
while {$total < $half} { lappend counts [expr {min($nb, $half - $total)}]; incr total [lindex $counts end] }
while {$total > $half} {
    set last [lindex $counts end]
    set cut [expr {min($last, $total - $half)}]
    if {$cut == $last} { set counts [lrange $counts 0 end-1] } else { lset counts end [expr {$last - $cut}] }
    incr total -$cut
}
set discs {}
set side {}
# Settles until the kinetic energy is small (or maxSteps pass).
proc settle {maxSteps} {
    set n 0
    while {$n < $maxSteps} {
        run 100
        incr n 100
        set s [sim info]
        set ne [expr {max(1, [dict get $s elements])}]
        if {$n >= 400 && [dict get $s kinetic] / $ne < 1e-5 * $::gpack} break
    }
    return $n
}
# The discs' extreme surface height: the highest top (dir 1) or lowest bottom (-1).
proc surface {ids dir default} {
    set best $default
    foreach id $ids {
        set e [element info $id]
        set y [expr {[lindex [dict get $e position] 1] + $dir * [dict get $e radius]}]
        if {$dir * ($y - $best) > 0} { set best $y }
    }
    return $best
}
set packSteps 0
foreach {assembly dir} {bottom 1 top -1} {
    set mine {}
    foreach n $counts {
        # Sources a little beyond this assembly's current surface.
        set y [expr {[surface $mine $dir [expr {$dir > 0 ? 0.0 : $H}]] + $dir * ($rmax + 0.6)}]
        set width [expr {$n * $pitch}]
        set x0 [expr {0.5 * ($L - $width) + 0.5 * $pitch}]
        set sources {}
        for {set k 0} {$k < $n} {incr k} {
            set r [expr {$rmin + ($rmax - $rmin) * rand()}]
            set x [expr {$x0 + $k * $pitch + 0.05 * ($pitch - 2 * $rmax) * (2 * rand() - 1)}]
            set id [element next]
            disc create -id $id -center [list $x $y] -radius $r -material grain
            source create $id -acceleration [list 0 [expr {-$dir * $gpack}]] -limit 1
            lappend sources $id
        }
        set before [element ids -type disc]
        set steps [settle 3000]
        incr packSteps $steps
        foreach id $sources { source delete $id; element delete $id }
        set row {}
        foreach id [element ids -type disc] {
            if {$id ni $before} { lappend row $id; dict set side $id $assembly }
        }
        # The base row is held where it landed.
        if {$mine eq {}} {
            foreach id $row { element configure $id -fix {x y rot} -velocity {0 0 0} }
        }
        lappend mine {*}$row
        puts [format "  row of %2d: %5d steps, kinetic %.2e" [llength $row] $steps [dict get [sim info] kinetic]]
    }
    lappend discs {*}$mine
    puts [format "%s assembly: %d discs in %d rows, surface at y = %.2f" $assembly [llength $mine] \
        [llength $counts] [surface $mine $dir [expr {$dir > 0 ? 0.0 : $H}]]]
}
# The packing acceleration becomes g (it stays on during erosion).
foreach id $discs {
    element configure $id -acceleration [list 0 [expr {[dict get $side $id] eq "bottom" ? -${-g} : ${-g}}]]
}
incr packSteps [settle 3000]
puts "packed in $packSteps DEM steps"

# ---- held edges, bonds -------------------------------------------------------
# Every disc that touches the top or bottom wall is held (the base rows, and
# any disc that rolled off the mound's foot onto the wall).
set held {}
set free {}
foreach id $discs {
    set e [element info $id]
    set y [lindex [dict get $e position] 1]
    set r [dict get $e radius]
    if {[dict get $e fix] ne {} || $y - $r < 0.01 * $rmin || $y + $r > $H - 0.01 * $rmin} {
        element configure $id -fix {x y rot} -velocity {0 0 0}
        lappend held $id
    } else {
        lappend free $id
    }
}
# ---- the constriction and the exposed disc -------------------------------------
# The pair (one disc of each assembly) whose surfaces are closest across the
# gap; the constriction is the middle of that gap.
set best 1e30
foreach b $discs {
    if {[dict get $side $b] ne "bottom"} continue
    set eb [element info $b]
    lassign [dict get $eb position] xb yb
    set rb [dict get $eb radius]
    foreach t $discs {
        if {[dict get $side $t] ne "top"} continue
        set et [element info $t]
        lassign [dict get $et position] xt yt
        set gap [expr {hypot($xt - $xb, $yt - $yb) - $rb - [dict get $et radius]}]
        if {$gap < $best} { set best $gap; set pair [list $b $t] }
    }
}
lassign $pair pb pt
set rb [dict get [element info $pb] radius]
set rt [dict get [element info $pt] radius]
set exposed [expr {$rb >= $rt ? $pb : $pt}]
set exposedR [dict get [element info $exposed] radius]
lassign [dict get [element info $pb] position] xb yb
lassign [dict get [element info $pt] position] xt yt
set ux [expr {($xt - $xb) / hypot($xt - $xb, $yt - $yb)}]
set uy [expr {($yt - $yb) / hypot($xt - $xb, $yt - $yb)}]
set xc [expr {$xb + $ux * ($rb + 0.5 * $best)}]
set yc [expr {$yb + $uy * ($rb + 0.5 * $best)}]
puts [format "constriction at {%.2f %.2f}: gap %.2f between discs %d (r %.2f, bottom) and %d (r %.2f, top); exposed: %d" \
    $xc $yc $best $pb $rb $pt $rt $exposed]

# ---- the fluid ------------------------------------------------------------------
# The fluid is switched on at rest and left 100 steps (2 time units) with the
# grains before the bonds are made and the forcing starts: the coupling's
# start shakes the packing a little, which would break a few bonds.
lattice create -size [list $L $H] -spacing ${-spacing} -viscosity 0.1 -density 1.0 \
    -periodic {1 0} -walls {bottom noslip top noslip}
run 100
set nbonds 0
if {${-bonded}} {
    set nbonds [bond auto -elements $discs -gap [expr {0.02 * 0.5 * ($rmin + $rmax)}]]
}

lattice configure -forcing [list ${-forcing} 0]
puts [format "%d discs (%d held, %d free), %d bonds" [llength $discs] [llength $held] [llength $free] $nbonds]
set info [lattice info]
set h [dict get $info spacing]
puts [format "lattice %d x %d (%d nodes), h %g, dt %g, tau %.3f; forcing %g, g %g" \
    [dict get $info nx] [dict get $info ny] [dict get $info nodes] $h $dt [dict get $info tau] \
    ${-forcing} ${-g}]
set cs2 [expr {[dict get $info cs] ** 2}]
set p0 $cs2   ;# the pressure at rest, c_s^2 rho0: pressures are written relative to it
set xup [expr {$xc - 0.25 * $L < 0 ? $xc + 0.75 * $L : $xc - 0.25 * $L}]
set xdown [expr {$xc + 0.25 * $L > $L ? $xc - 0.75 * $L : $xc + 0.25 * $L}]
set ymid [expr {0.5 * $H}]
set ny [dict get $info ny]
set t0 [dict get [sim info] time]
set start {}
foreach id $free { dict set start $id [dict get [element info $id] position] }
set eroded {}          ;# {id time x y r side} in order
set removed 0

# Fluid flux through the column at the constriction's x: sum of rho u_x h.
proc flux {} {
    global xc h ny
    set q 0.0
    for {set j 0} {$j < $ny} {incr j} {
        set p [lattice probe [list $xc [expr {($j + 0.5) * $h}]]]
        if {[dict get $p kind] ne "fluid"} continue
        set q [expr {$q + [dict get $p density] * [lindex [dict get $p velocity] 0] * (1 - [dict get $p solid]) * $h}]
    }
    return $q
}
set historyRows {}
set stopped {}
proc sample {} {
    global free start eroded removed t0 L xup xdown xc yc ymid historyRows
    set t [expr {[dict get [sim info] time] - $t0}]
    foreach id $free {
        if {![dict exists $start $id]} continue
        set e [element info $id]
        lassign [dict get $e position] x y
        set r [dict get $e radius]
        lassign [dict get $start $id] x0 y0
        if {hypot($x - $x0, $y - $y0) > $r} {
            lappend eroded [list $id [format %.2f $t] $x $y $r [dict get $::side $id]]
            dict unset start $id
        }
    }
    # Grains leaving the channel downstream are taken out.
    foreach id $free {
        if {[catch {element info $id} e]} continue
        lassign [dict get $e position] x y
        if {$x > $L - 2 * [dict get $e radius] && [dict get $e fix] eq {}} {
            element delete $id
            dict unset start $id
            incr removed
        }
    }
    set pu [expr {[dict get [lattice probe [list $xup $ymid]] pressure] - $::p0}]
    set pd [expr {[dict get [lattice probe [list $xdown $ymid]] pressure] - $::p0}]
    set pg [expr {[dict get [lattice probe [list $xc $yc]] pressure] - $::p0}]
    set s [sim info]
    set row [list [format %.2f $t] [flux] $pu $pd $pg [llength $eroded] $removed [dict get $s broken] [dict get $s mach]]
    lappend historyRows $row
    # The constant forcing keeps accelerating the flow once the plug has
    # opened: stop before the lattice's Mach limit.
    if {[dict get $s mach] > ${::-maxmach}} {
        set ::stopped [format "the flow reached Mach %.3f at t = %.1f" [dict get $s mach] $t]
    }
    return $row
}
proc tick {} {
    sample
    if {$::stopped ne {}} { return -code break }
}

# ---- output ------------------------------------------------------------------------
set fps 25
set steps [expr {int(round(${-time} / $dt))}]
set movie {}
if {$out ne {}} {
    view configure -size {800 336} -field velocity -bonds 1
    if {${-movie} && [auto_execok ffmpeg] ne {}} {
        set movie [output movie [file join $out plug.mp4] -every [expr {max(1, $steps / 250)}] -fps $fps]
    }
    record [file join $out record.csv] -every [expr {max(1, ${-every})}] \
        -quantities {kinetic contacts bonds broken mach}
}
set frame 0
proc picture {} {
    global out frame
    if {$out eq {}} return
    snapshot [file join $out [format "plug-%d.png" $frame]]
    incr frame
}

# ---- erosion ----------------------------------------------------------------------
# load: the fluid's force on the exposed disc over its weight (m g); -1 once it is gone.
puts [format "%8s %10s %10s %10s %7s %7s %7s %7s %7s" t flux p_up-p_dn p_gap eroded removed broken mach load]
proc report {} {
    global exposed
    lassign [sample] t q pu pd pg ne nr nb mach
    set load -1
    if {![catch {element info $exposed} e]} {
        lassign [dict get $e fluidforce] fx fy
        set load [expr {hypot($fx, $fy) / ([dict get $e mass] * ${::-g})}]
    }
    puts [format "%8.1f %10.4f %10.3e %10.3e %7d %7d %7d %7.4f %7.3f" $t $q [expr {$pu - $pd}] $pg $ne $nr $nb \
        $mach $load]
}
report
picture
set nframes [expr {max(1, ${-frames})}]
set chunk [expr {max(1, $steps / $nframes)}]
set every [expr {max(1, ${-every})}]
set done 0
while {$done < $steps && $stopped eq {}} {
    set n [expr {min($chunk, $steps - $done)}]
    run $n -every $every tick
    incr done $n
    report
    picture
}
if {$stopped ne {}} { puts "stopped: $stopped" }
if {$movie ne {}} { output close $movie }
if {$out ne {}} { output close [file join $out record.csv] }

# ---- results ------------------------------------------------------------------------
if {$out ne {}} {
    set f [open [file join $out history.csv] w]
    puts $f "time,flux,p_up,p_down,p_gap,eroded,removed,broken,mach"
    foreach row $historyRows { puts $f [join $row ,] }
    close $f
    set f [open [file join $out eroded.csv] w]
    puts $f "order,id,time,x,y,radius,side,exposed,at_constriction"
    set k 0
    foreach ev $eroded {
        lassign $ev id t x y r s
        puts $f [join [list [incr k] $id $t $x $y $r $s [expr {$id == $exposed}] [expr {$id in $pair}]] ,]
    }
    close $f
    set f [open [file join $out bonds-broken.csv] w]
    puts $f "time,x,y,angle"
    foreach ev [bond broken] {
        lassign $ev t x y a
        puts $f [join [list [format %.2f [expr {$t - $t0}]] $x $y $a] ,]
    }
    close $f
}
if {[llength $eroded]} {
    lassign [lindex $eroded 0] firstId firstT
    set firstR [lindex $eroded 0 4]
} else {
    lassign {-1 -1 0} firstId firstT firstR
}
set exposedAt [lsearch -index 0 $eroded $exposed]
# Whether the first eroded disc is one of the two at the constriction.
set atConstriction [expr {$firstId in $pair}]
puts [format "summary: bonded %d discs %d held %d bonds %d exposed %d exposed_r %.3f first %d first_r %.3f first_t %.2f exposed_first %d exposed_rank %d at_constriction %d eroded %d removed %d broken %d" \
    ${-bonded} [llength $discs] [llength $held] $nbonds $exposed $exposedR $firstId $firstR $firstT \
    [expr {$firstId == $exposed}] [expr {$exposedAt < 0 ? -1 : $exposedAt + 1}] $atConstriction [llength $eroded] \
    $removed [dict get [sim info] broken]]
