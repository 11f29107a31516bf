# One point of scripts/stability's sweeps (docs/stability.md): builds a small
# scene at one extreme setting, runs it, and says what a user gets.
#
#   sandflow tests/stability/stability.tcl SWEEP CASE VALUE
#
#   SWEEP CASE                 VALUE
#   tau   poiseuille|poiseuille-trt|cavity|cavity-trt      tau
#   mach  poiseuille|cavity|inlet|disc                     |u|/c (c = h/dt)
#   density settle-explicit|settle-implicit|nudge-explicit|nudge-implicit   rho_s/rho_f
#   timestep wall|pair|elastic|resting|stiffen             dt / dt_crit
#   size  noflow|drag|wrap|settle                          disc diameter in cells
#
#   sandflow tests/stability/stability.tcl map CASE X Y
#
#   map (scripts/stability --maps: two settings at once; the cases above)
#   CASE              X                    Y
#   cavity-bgk        tau                  lid speed |u|/c      (tau cavity, lid at Y)
#   cavity-trt        tau                  lid speed |u|/c
#   settle-explicit   rho_s/rho_f          tau                  (density settle at tau Y)
#   settle-implicit   rho_s/rho_f          tau
#   pair              dt / dt_crit         restitution          (timestep pair, e = Y)
#   resting           dt / dt_crit         restitution          (timestep resting, e = Y)
#   size-settle       diameter in cells    tau                  (size settle at tau Y)
#   disc              |u|/c                diameter in cells    (mach disc, Y across)
#
# Lattice units throughout (h = 1, dt = 1 unless the sweep is the timestep:
# c = 1, so a speed is its Mach number u/c). One thread. The last line is
#   RESULT<tab>OUTCOME<tab>MEASURE<tab>MESSAGE
# OUTCOME: ok, warned (a ::sf::warn warning), refused (a command refused it
# before any step: MESSAGE names the command), stopped (the run ended with a
# SANDFLOW UNSTABLE error: MESSAGE is it), SILENT-NAN (a NaN or an infinity in
# the state, or a broken `sim check`, with no error) or SILENT-BAD (the state
# was garbage -- see each case's `garbage` test -- at a step before any
# warning or error). MEASURE is the case's error against its reference.
# Warnings also go to stderr as they come.

lassign $argv sweep case value value2
if {$value eq "" || ![string is double -strict $value] ||
    ($sweep eq "map" && ($value2 eq "" || ![string is double -strict $value2]))} {
    puts stderr "usage: sandflow tests/stability/stability.tcl SWEEP CASE VALUE\n   or: sandflow tests/stability/stability.tcl map CASE X Y"
    exit 2
}
set pi [expr {acos(-1)}]
set ::warnings {}       ;# {step message} as they come
set ::garbage {}        ;# {step what}: the first step the state was garbage
set ::refused {}        ;# {command message}
set ::stopped {}        ;# the run's error
set ::measure {}
set ::notes {}

proc ::sf::warn {message} {
    lappend ::warnings [list [dict get [sim info] step] $message]
    puts stderr "warning (step [dict get [sim info] step]): $message"
}

# A number that is finite (NaN, Inf and non-numbers are not).
proc finite {x} {
    if {![string is double -strict $x]} { return 0 }
    if {[catch {expr {$x * 0.0}} z]} { return 0 }
    return [expr {$z == 0.0}]
}
proc allFinite {list} {
    foreach x $list { if {![finite $x]} { return 0 } }
    return 1
}
proc fmt {x} {
    if {![finite $x]} { return $x }
    return [format %.3g $x]
}

# Runs a setup command; a refusal ends the point as "refused", naming it.
proc do {args} {
    if {[catch {uplevel 1 $args} result]} {
        set ::refused [list [join [lrange $args 0 1]] $result]
        return -code error -errorcode {STABILITY REFUSED} $result
    }
    return $result
}

# The first time the state is garbage (a case's own test; KIND nan: a value
# that is not finite), remembered with the step.
proc garbage {what {kind bad}} {
    if {$::garbage eq {}} { set ::garbage [list [dict get [sim info] step] $what $kind] }
}

# Runs N steps, calling MONITOR every EVERY steps; an error of the run is
# remembered (stopped, or refused when no step was taken).
proc go {n every {monitor {}}} {
    set check [list apply {{monitor} {
        if {[hasLattice]} {
            set i [lattice info]
            if {![allFinite [list [dict get $i mass] {*}[dict get $i momentum] [dict get $i mach]]]} {
                garbage "lattice mass, momentum or Mach not finite: [dict get $i mass] [dict get $i momentum] [dict get $i mach]" nan
            }
        }
        checkElements
        if {$monitor ne {}} { uplevel #0 $monitor }
    }} $monitor]
    set before [dict get [sim info] step]
    if {[catch {run $n -every $every $check} message opts]} {
        set code [dict get $opts -errorcode]
        if {[lindex $code 1] ne "UNSTABLE" && [dict get [sim info] step] == $before} {
            set ::refused [list run $message]
        } else {
            set ::stopped $message
        }
    }
}

proc hasLattice {} { expr {![catch {lattice info}]} }

proc checkElements {} {
    foreach id [element ids] {
        set e [element info $id]
        set values {}
        foreach key {position velocity force torque fluidforce fluidtorque angle} {
            lappend values {*}[dict get $e $key]
        }
        if {![allFinite $values]} { garbage "element $id has a value that is not finite: $values" nan }
    }
}

# After the run: NaN anywhere is the failure this script hunts.
proc nanCheck {} {
    set bad {}
    set check [sim check]
    if {$check ne {}} { lappend bad "sim check: [join $check {; }]" }
    if {[hasLattice]} {
        set i [lattice info]
        if {![allFinite [list [dict get $i mass] {*}[dict get $i momentum] [dict get $i mach]]]} {
            lappend bad "lattice info: mass [dict get $i mass] momentum [dict get $i momentum] mach [dict get $i mach]"
        }
        set h [dict get $i spacing]
        lassign [dict get $i origin] x0 y0
        set nan 0
        for {set j 0} {$j < [dict get $i ny]} {incr j} {
            for {set k 0} {$k < [dict get $i nx]} {incr k} {
                set p [lattice probe [list [expr {$x0 + ($k + 0.5) * $h}] [expr {$y0 + ($j + 0.5) * $h}]]]
                if {![allFinite [list [dict get $p density] {*}[dict get $p velocity]]]} {
                    if {[incr nan] == 1} { set first "node ($k, $j): $p" }
                }
            }
        }
        if {$nan} { lappend bad "lattice probe: $nan nodes not finite, first $first" }
    }
    foreach id [element ids] {
        set e [element info $id]
        set values {}
        foreach key {position velocity force torque fluidforce fluidtorque angle} {
            lappend values {*}[dict get $e $key]
        }
        if {![allFinite $values]} { lappend bad "element info $id: $values" }
    }
    return $bad
}

# ---- helpers shared by the fluid cases -----------------------------------------
# The viscosity for tau at h = dt = 1; at tau <= 0.5 that of tau 1, so that
# the lattice's refusal is about tau.
proc nu {tau} { expr {$tau > 0.5 ? (2.0 * $tau - 1.0) / 6.0 : 1.0 / 6} }

# Relative L2 error of u_x over the column x = X at rows y = j + 1/2 against
# the proc EXACT (called with y).
proc profileError {x H exact} {
    set num 0.0; set den 0.0
    for {set j 0} {$j < $H} {incr j} {
        set y [expr {$j + 0.5}]
        set u [lindex [dict get [lattice probe [list $x $y]] velocity] 0]
        set ue [{*}$exact $y]
        if {![finite $u]} { return $u }
        set num [expr {$num + ($u - $ue) ** 2}]
        set den [expr {$den + $ue ** 2}]
    }
    if {$den == 0} { return [expr {sqrt($num)}] }
    return [expr {sqrt($num / $den)}]
}

# Plane Poiseuille flow started from rest under the forcing F (walls at y = 0
# and H): the exact series solution at time t.
proc startup {F nu H t y} {
    set u [expr {$F / (2 * $nu) * $y * ($H - $y)}]
    if {$t eq "inf"} { return $u }
    for {set n 1} {$n < 20000} {incr n 2} {
        set k [expr {$n * $::pi / $H}]
        set e [expr {exp(-$k * $k * $nu * $t)}]
        if {$e < 1e-30} break
        set u [expr {$u - 4 * $F * $H * $H / ($nu * ($::pi * $n) ** 3) * sin($k * $y) * $e}]
    }
    return $u
}

# Largest |rho/rho0 - 1| over the lattice.
proc densitySpread {} {
    set i [lattice info]
    set worst 0.0
    for {set j 0} {$j < [dict get $i ny]} {incr j} {
        for {set k 0} {$k < [dict get $i nx]} {incr k} {
            set p [lattice probe [list [expr {$k + 0.5}] [expr {$j + 0.5}]]]
            if {[dict get $p kind] ni {fluid velocity pressure}} continue
            set worst [expr {max($worst, abs([dict get $p density] - 1.0))}]
        }
    }
    return $worst
}

# ---- sweep: tau -------------------------------------------------------------------
# Plane Poiseuille flow started from rest, 16 nodes across, 1000 steps, forced
# so that the exact centreline speed at the end is 0.02: relative L2 error
# against the exact start-up series. BGK nodal (the defaults) or TRT + Guo.
# Garbage: an error over 100% (the profile is off by more than itself).
proc poiseuilleTau {tau options} {
    set H 16; set T 1000
    set nu [nu $tau]
    set F [expr {$tau > 0.5 ? 0.02 / [startup 1.0 $nu $H $T [expr {$H / 2.0}]] : 0.0}]
    do lattice create -size [list 4 $H] -cells 4 -tau $tau -viscosity $nu -forcing [list $F 0] {*}$options
    go $T 50 {
        if {[dict get [lattice info] mach] > 0.04} {
            garbage "the fluid moves at [fmt [dict get [lattice info] mach]], twice the exact centreline speed 0.02 or more"
        }
    }
    set err [profileError 2.5 $H [list startup $F $nu $H [dict get [sim info] step]]]
    set ::measure "L2 error [fmt $err] vs the start-up series"
    if {![finite $err] || $err > 1.0} { garbage "the profile is off by [fmt $err] of itself" }
    if {[finite $err] && $err > 0.1} { lappend ::notes inaccurate }
}
proc case_tau_poiseuille {tau} { poiseuilleTau $tau {} }
proc case_tau_poiseuille-trt {tau} { poiseuilleTau $tau {-collision trt -forcescheme guo} }

# Lid-driven cavity, 32 x 32, lid at 0.02 c, 2000 steps: there is no exact
# answer, but no fluid may move faster than the lid. Garbage: the fluid at
# over twice the lid's speed (a growing instability before the Mach limits
# see it).
proc cavityTau {tau options {lid 0.02}} {
    do lattice create -size {32 32} -cells 32 -tau $tau -viscosity [nu $tau] -periodic {0 0} \
        -walls [list left noslip right noslip bottom noslip top [list noslip [list $lid 0]]] {*}$options
    set ::top 0.0
    go 2000 10 [list apply {{lid} {
        set m [dict get [lattice info] mach]
        set ::top [expr {max($::top, $m)}]
        if {$m > 2 * $lid} { garbage "the fluid moves at [fmt $m], [fmt [expr {$m / $lid}]] times the lid's speed" }
    }} $lid]
    set ::measure "fastest fluid [fmt [expr {$::top / $lid}]] x the lid's speed"
}
proc case_tau_cavity {tau} { cavityTau $tau {} }
proc case_tau_cavity-trt {tau} { cavityTau $tau {-collision trt} }

# ---- sweep: Mach (|u|/c; the acoustic Mach number is sqrt(3) times it) -------------
# Steady plane Poiseuille flow, tau 1, 16 across, forced for a centreline
# speed of MA: relative L2 error against the parabola after 3000 steps (20
# decay times). Garbage: an error over 100%.
proc case_mach_poiseuille {ma} {
    set H 16; set nu [nu 1.0]
    set F [expr {8 * $nu * $ma / ($H * $H)}]
    do lattice create -size [list 4 $H] -cells 4 -tau 1.0 -viscosity $nu -forcing [list $F 0]
    go 3000 50 [list apply {{ma} {
        set m [dict get [lattice info] mach]
        if {$m > 2 * $ma && $m > 1e-12} { garbage "the fluid moves at [fmt $m], over twice the exact [fmt $ma]" }
    }} $ma]
    set err [profileError 2.5 $H [list startup $F $nu $H inf]]
    set ::measure "L2 error [fmt $err] vs the parabola"
    if {![finite $err] || $err > 1.0} { garbage "the profile is off by [fmt $err] of itself" }
    if {[finite $err] && $err > 0.1} { lappend ::notes inaccurate }
}

# Lid-driven cavity, 32 x 32, tau 0.8, lid at MA, 1000 steps: the largest
# density change (the compressibility error, ~ Ma^2). Garbage: fluid faster
# than twice the lid.
proc case_mach_cavity {ma} {
    do lattice create -size {32 32} -cells 32 -tau 0.8 -viscosity [nu 0.8] -periodic {0 0} \
        -walls [list left noslip right noslip bottom noslip top [list noslip [list $ma 0]]]
    go 1000 10 [list apply {{ma} {
        set m [dict get [lattice info] mach]
        if {$m > 2 * $ma && $m > 1e-12} { garbage "the fluid moves at [fmt $m], over twice the lid's [fmt $ma]" }
    }} $ma]
    set ::measure "density varies by [fmt [densitySpread]]"
}

# Channel 48 x 16, Zou-He velocity inlet at MA (uniform), pressure outlet,
# tau 0.8, 1500 steps: the mass flux at x = 36 against the inlet's.
# Garbage: fluid faster than three times the inlet (a developed profile
# reaches 1.5 times it).
proc case_mach_inlet {ma} {
    set H 16
    do lattice create -size [list 48 $H] -cells 48 -tau 0.8 -viscosity [nu 0.8] -periodic {0 0} \
        -walls [list left [list velocity [list $ma 0]] right [list pressure [expr {1.0 / 3}]] bottom noslip top noslip]
    go 1500 10 [list apply {{ma} {
        set m [dict get [lattice info] mach]
        if {$m > 3 * $ma && $m > 1e-12} { garbage "the fluid moves at [fmt $m], over three times the inlet's [fmt $ma]" }
    }} $ma]
    set q 0.0; set q0 0.0
    for {set j 0} {$j < $H} {incr j} {
        set p [lattice probe [list 36.5 [expr {$j + 0.5}]]]
        set q [expr {$q + [dict get $p density] * [lindex [dict get $p velocity] 0]}]
        set p [lattice probe [list 0.5 [expr {$j + 0.5}]]]
        set q0 [expr {$q0 + [dict get $p density] * [lindex [dict get $p velocity] 0]}]
    }
    if {$ma == 0} {
        set ::measure "flux [fmt $q] (exact 0)"
        if {![finite $q] || abs($q) > 1e-9} { garbage "a flux [fmt $q] with the inlet at rest" }
    } else {
        set ::measure "flux at x = 36 / inlet flux - 1 = [fmt [expr {$q / $q0 - 1}]]"
    }
}

# A disc 8 cells across, held, driven at MA through periodic fluid at rest
# (64 x 32, tau 0.8), 300 steps: its drag (which sound waves crossing the
# small periodic box make swing, at low speed even briefly forwards).
# Garbage: the fluid faster than twice the disc.
proc case_mach_disc {ma {d 8}} {
    # 64 x 32 up to 8 across (the Mach sweep's disc), else 8d x 4d
    set H [expr {max(32, 4 * int(ceil($d)))}]
    set W [expr {2 * $H}]
    do lattice create -size [list $W $H] -cells $W -tau 0.8 -viscosity [nu 0.8] -periodic {1 1}
    do material create grain -density 3 -kn 1 -ks 1
    set ::disc [do disc create -center [list [expr {$W / 4 + 0.3}] [expr {$H / 2 + 0.2}]] -radius [expr {$d / 2.0}] \
                    -material grain -fix {x y rot} -velocity [list $ma 0 0]]
    go 300 1 [list apply {{ma} {
        set m [dict get [lattice info] mach]
        if {$m > 2 * $ma && $m > 1e-12} { garbage "the fluid moves at [fmt $m], over twice the disc's [fmt $ma]" }
    }} $ma]
    set fx [lindex [dict get [element info $::disc] fluidforce] 0]
    set ::measure "drag [fmt $fx] (rho nu U = [fmt [expr {[nu 0.8] * $ma}]])"
}

# ---- sweep: density ratio rho_s / rho_f -------------------------------------------
# A disc 12 cells across in a closed 48 x 64 box of fluid (tau 0.6), gravity
# 1e-4 downwards, 400 steps, explicit or implicit coupling: its speed after
# 50 steps against the start of the fall, (rho_s - rho_f) g t / (rho_s + 2 rho_f)
# (the fluid inside it and the added mass outside). Garbage: a change of
# velocity in one step over ten times g (1 + rho_f/rho_s) (a force ten times
# its weight and buoyancy: the light-element oscillation growing).
proc settle {ratio coupling g nudge {tau 0.6}} {
    do lattice create -size {48 64} -cells 48 -tau $tau -viscosity [nu $tau] -periodic {0 0} \
        -walls {left noslip right noslip bottom noslip top noslip}
    do sim configure -coupling $coupling -gravity [list 0 [expr {-$g}]]
    do material create grain -density $ratio -kn 1 -ks 1
    set ::disc [do disc create -center {24.3 32.2} -radius 6 -material grain -velocity [list 0 $nudge 0]]
    set ::last $nudge
    set ::v50 {}
    set ::peak [expr {abs($nudge)}]
    set limit [expr {10 * max($g, 1e-5) * (1 + 1.0 / $ratio)}]
    go 400 1 [list apply {{limit} {
        set v [lindex [dict get [element info $::disc] velocity] 1]
        if {![finite $v]} { garbage "the disc's velocity is $v" nan; return }
        if {abs($v - $::last) > $limit} {
            garbage "the disc's velocity jumped from [fmt $::last] to [fmt $v] in one step"
        }
        set ::last $v
        set ::peak [expr {max($::peak, abs($v))}]
        if {[dict get [sim info] step] == 50} { set ::v50 $v }
    }} $limit]
    return $limit
}
proc settleCase {ratio coupling {tau 0.6}} {
    set g 1e-4
    settle $ratio $coupling $g 0 $tau
    set a0 [expr {($ratio - 1) * (-$g) / ($ratio + 2)}]
    if {$::v50 eq {}} {
        set ::measure "no step 50"
    } elseif {$a0 == 0} {
        set ::measure "speed [fmt $::v50] at step 50 (exact 0)"
    } else {
        set ::measure "v(50) / (a0 t) = [fmt [expr {$::v50 / ($a0 * 50)}]]"
    }
}
proc case_density_settle-explicit {ratio} { settleCase $ratio explicit }
proc case_density_settle-implicit {ratio} { settleCase $ratio implicit }

# The same disc without gravity, nudged at 1e-5: the fluid brakes it. Its
# largest speed after the start against the nudge (at most 1). Garbage: a
# speed over ten times the nudge, or a jump as above.
proc nudgeCase {ratio coupling} {
    set nudge 1e-5
    settle $ratio $coupling 0 $nudge
    set ::measure "largest speed / nudge = [fmt [expr {$::peak / $nudge}]]"
    if {$::peak > 10 * $nudge} { garbage "the nudged disc sped up to [fmt [expr {$::peak / $nudge}]] times the nudge" }
}
proc case_density_nudge-explicit {ratio} { nudgeCase $ratio explicit }
proc case_density_nudge-implicit {ratio} { nudgeCase $ratio implicit }

# ---- sweep: DEM timestep, dt / dt_crit ---------------------------------------------
# No lattice. Discs of radius 1, density 1, kn = ks = 1e4, no friction;
# dt_crit = 2 sqrt(m/k) = 0.0354 (sim info critical), dt = VALUE x dt_crit.
proc demScene {e} {
    do material create m -density 1 -kn 1e4 -ks 1e4 -restitution $e -friction 0
}
# One impact at each of five entry phases: the first step of contact begins
# at an overlap of (k + 1/2)/5 of one step's closing travel, k = 0..4 (a
# contact starts between steps, wherever the approach puts it). KIND: wall
# (a disc at 1 onto a fixed wall, m_eff = m: dt_crit is this contact's
# limit), pair (two equal free discs at 1 each, head-on, m_eff = m/2) or
# stiffen (the wall impact at 0.1 with the timestep fixed at dt_crit / 2 and
# then the material's stiffness scaled so that the step is F x the new
# dt_crit: the late way over the limit). Each runs 8 dt_crit past contact.
# The measure: the restitution over the phases (or, for e = 1, the energy
# after / before). Garbage: a damped collision that gains energy, an
# undamped one that gains more than 10%.
proc impacts {f e kind} {
    set worst 0.0
    set rs {}
    set es {}
    for {set k 0} {$k < 5} {incr k} {
        reset
        sim configure -threads 1
        demScene $e
        set v [expr {$kind eq "stiffen" ? 0.1 : 1.0}]
        set a [do disc create -center {0 0} -radius 1 -material m -velocity [list $v 0 0]]
        if {$kind eq "pair"} {
            set b [do disc create -center {5 0} -radius 1 -material m -velocity [list -$v 0 0]]
            set closing [expr {2 * $v}]
        } else {
            set b {}
            set w [do wall create -from {5 -5} -to {5 5} -material m]
            set closing $v
        }
        set crit [dict get [sim info] critical]
        if {$kind eq "stiffen"} {
            do sim configure -timestep [expr {0.5 * $crit}]
            set kn [expr {1e4 * ($f / 0.5) ** 2}]
            do material configure m -kn $kn -ks $kn
            set crit [dict get [sim info] critical]
        } else {
            do sim configure -timestep [expr {$f * $crit}]
        }
        set dt [sim cget -timestep]
        set gap [expr {(1.0 - ($k + 0.5) / 5) * $closing * $dt}]
        if {$b ne {}} {
            do element configure $b -center [list [expr {2 + $gap}] 0]
        } else {
            do element configure $w -from [list [expr {1 + $gap}] -5] -to [list [expr {1 + $gap}] 5]
        }
        set e0 [dict get [sim info] kinetic]
        go [expr {int(ceil(8.0 * $crit / $dt)) + 1}] 1
        if {$::stopped ne {} || $::refused ne {}} return
        set va [lindex [dict get [element info $a] velocity] 0]
        set vb [expr {$b eq {} ? 0.0 : [lindex [dict get [element info $b] velocity] 0]}]
        lappend rs [expr {($vb - $va) / $closing}]
        set energy [expr {[dict get [sim info] kinetic] / $e0}]
        lappend es $energy
        # Garbage: a damped collision that gains energy, an undamped one that
        # gains over 10% (the scheme's own error is about 0.5% at dt_crit / 10).
        if {![finite $energy] || $energy > ($e == 1.0 ? 1.1 : 1.0 + 1e-3)} {
            garbage "the collision gained energy: after / before [fmt $energy] (entry phase $k)"
        }
    }
    set rs [lsort -real $rs]
    set es [lsort -real $es]
    if {$e == 1.0} {
        set ::measure "energy after / before [fmt [lindex $es 0]]..[fmt [lindex $es end]] (exact 1)"
        set off [expr {max(abs([lindex $es 0] - 1), abs([lindex $es end] - 1))}]
    } else {
        set ::measure "restitution [fmt [lindex $rs 0]]..[fmt [lindex $rs end]] (set $e)"
        set off [expr {max(abs([lindex $rs 0] / $e - 1), abs([lindex $rs end] / $e - 1))}]
    }
    if {[finite $off] && $off > 0.1} { lappend ::notes inaccurate }
}
proc case_timestep_wall {f} { impacts $f 0.5 wall }
proc case_timestep_pair {f} { impacts $f 0.5 pair }
proc case_timestep_elastic {f} { impacts $f 1.0 pair }
proc case_timestep_stiffen {f} { impacts $f 0.5 stiffen }

# A disc set down on a floor under gravity 10 (e 0.5), 200 dt_crit: it must
# come to rest at the static overlap m g / kn. Garbage: kinetic energy above
# m g r (what the fall from a radius up would give).
proc case_timestep_resting {f {e 0.5}} {
    demScene $e
    do sim configure -gravity {0 -10}
    set a [do disc create -center {0 1} -radius 1 -material m]
    do wall create -from {-5 0} -to {5 0} -material m
    set crit [dict get [sim info] critical]
    do sim configure -timestep [expr {$f * $crit}]
    set m [dict get [element info $a] mass]
    go [expr {int(ceil(200.0 / $f))}] 1 [list apply {{limit} {
        if {[dict get [sim info] kinetic] > $limit} {
            garbage "the resting disc's kinetic energy reached [fmt [dict get [sim info] kinetic]], over m g r"
        }
    }} [expr {$m * 10}]]
    set y [lindex [dict get [element info $a] position] 1]
    set overlap [expr {1 - $y}]
    set static [expr {$m * 10 / 1e4}]
    set ::measure "overlap / (m g / kn) = [fmt [expr {$overlap / $static}]], kinetic [fmt [dict get [sim info] kinetic]]"
}
# ---- sweep: element size (disc diameter in cells) ----------------------------------
# The box: 32 cells for discs up to 8 across, 64 up to 32, else 128.
proc box {d} { expr {$d <= 8 ? 32 : $d <= 32 ? 64 : 128} }
proc fixedDisc {d} {
    set L [box $d]
    do lattice create -size [list $L $L] -cells $L -tau 1.0 -viscosity [nu 1.0] -periodic {1 1}
    do material create grain -density 3 -kn 0.1 -ks 0.1
    set c [expr {$L / 2.0}]
    return [do disc create -center [list [expr {$c + 0.3}] [expr {$c + 0.17}]] -radius [expr {$d / 2.0}] \
                -material grain -fix {x y rot}]
}
# A held disc in fluid at rest, 300 steps: nothing may move (exact 0).
# Garbage: any speed over 1e-6 c, or a force on the disc over 1e-6.
proc case_size_noflow {d} {
    set ::disc [fixedDisc $d]
    set ::top 0.0
    go 300 10 {
        set m [dict get [lattice info] mach]
        set f [dict get [element info $::disc] fluidforce]
        set ::top [expr {max($::top, $m)}]
        if {$m > 1e-6} { garbage "fluid at rest round a held disc moves at [fmt $m]" }
        if {abs([lindex $f 0]) + abs([lindex $f 1]) > 1e-6} { garbage "fluid at rest pushes the disc with $f" }
    }
    set ::measure "fastest fluid [fmt $::top] (exact 0)"
}
# A periodic square array of held discs (one in an L x L box) under a body
# force, tau 1, for a mean speed near 0.01 c: the drag coefficient
# K = F / (mu U) (F the disc's fluid force, U the mean velocity over the box)
# against Sangani & Acrivos (1982) for the solid fraction c: the dilute
# series 4 pi / (-ln(c)/2 - 0.738 + c - 0.887 c^2 + 2.038 c^3) up to c = 0.3,
# the lubrication limit 9 pi / (2 sqrt 2) (1 - sqrt(c / (pi/4)))^(-5/2) above.
# Garbage: K off by more than 100% (a factor 2 too high, or half too low ...)
# -- see the message.
proc case_size_drag {d} {
    set L [box $d]
    set c [expr {$::pi * $d * $d / 4.0 / ($L * $L)}]
    if {$c <= 0.3} {
        set K [expr {4 * $::pi / (-0.5 * log($c) - 0.738 + $c - 0.887 * $c * $c + 2.038 * $c ** 3)}]
    } else {
        set K [expr {9 * $::pi / (2 * sqrt(2)) * (1 - sqrt($c / ($::pi / 4))) ** -2.5}]
    }
    set ::disc [fixedDisc $d]
    set nu [nu 1.0]
    set G [expr {0.01 * $nu * $K / ($L * $L)}]
    do lattice configure -forcing [list $G 0]
    # To the steady state: until the drag carries the body force within 1%
    # (about five times L^2 / (K nu)), at most 4000 steps in the smallest box,
    # 12000 in the others.
    set cap [expr {$L <= 32 ? 4000 : 12000}]
    while {1} {
        go 500 100 {
            set m [dict get [lattice info] mach]
            if {$m > 0.2} { garbage "the fluid moves at [fmt $m], twenty times the intended mean 0.01" }
        }
        set F [lindex [dict get [element info $::disc] fluidforce] 0]
        if {$::stopped ne {} || ![finite $F] || abs($F / ($G * $L * $L) - 1) < 0.01 ||
            [dict get [sim info] step] >= $cap} break
    }
    set F [lindex [dict get [element info $::disc] fluidforce] 0]
    set U [expr {[lindex [dict get [lattice info] momentum] 0] / double($L * $L)}]
    set Km [expr {$F / ($nu * $U)}]
    set err [expr {$Km / $K - 1}]
    set ::measure [format "c %.3g: K %.3g vs %.3g, error %s; drag / body force %.3f at step %d" $c $Km $K \
                       [fmt $err] [expr {$F / ($G * $L * $L)}] [dict get [sim info] step]]
    if {![finite $err] || abs($err) > 1.0 || $Km < 0.5 * $K} { garbage "the drag is off by [fmt $err]" }
    if {[finite $err] && abs($err) > 0.1} { lappend ::notes inaccurate }
}
# A held disc of diameter d in a periodic 64 x 64 lattice (a disc wider than
# the box overlaps its own periodic images), one step: each cell's solid
# ratio (lattice probe) against the geometry -- 1 where the cell centre lies
# deeper than half a cell diagonal inside the disc or one of its images, 0
# as far outside. Garbage: any cell that disagrees.
proc case_size_wrap {d} {
    set L 64
    do lattice create -size [list $L $L] -cells $L -tau 1.0 -viscosity [nu 1.0] -periodic {1 1}
    do material create grain -density 3 -kn 0.1 -ks 0.1
    set cx [expr {$L / 2.0 + 0.3}]; set cy [expr {$L / 2.0 + 0.17}]
    set r [expr {$d / 2.0}]
    do disc create -center [list $cx $cy] -radius $r -material grain -fix {x y rot}
    go 1 1
    set bad 0
    set first {}
    set margin [expr {sqrt(0.5)}]
    for {set j 0} {$j < $L} {incr j} {
        for {set i 0} {$i < $L} {incr i} {
            set x [expr {$i + 0.5}]; set y [expr {$j + 0.5}]
            set near 1e300
            foreach ox {-1 0 1} {
                foreach oy {-1 0 1} {
                    set near [expr {min($near, hypot($x - $cx - $ox * $L, $y - $cy - $oy * $L))}]
                }
            }
            set solid [dict get [lattice probe [list $x $y]] solid]
            if {($near < $r - $margin && $solid < 1) || ($near > $r + $margin && $solid > 0)} {
                if {[incr bad] == 1} {
                    set first "cell ($i, $j), [fmt [expr {$r - $near}]] inside the disc, has solid ratio [fmt $solid]"
                }
            }
        }
    }
    set ::measure "cells covered wrongly: $bad of [expr {$L * $L}] (exact 0)"
    if {$bad} { garbage "$bad cells are covered wrongly, e.g. $first" }
}

# A free disc (density 3) settling in periodic fluid, gravity 1e-5, 300
# steps: a check of stability only (no reference: in a periodic box the
# fluid is dragged along). The measure: its speed at the end, downwards.
# Garbage: a jump of velocity in one step over ten times g (1 + rho_f/rho_s)
# (as in the density sweep), or a disc that rises.
proc case_size_settle {d {tau 1.0}} {
    set L [box $d]
    set g 1e-5
    do lattice create -size [list $L $L] -cells $L -tau $tau -viscosity [nu $tau] -periodic {1 1}
    do sim configure -gravity [list 0 [expr {-$g}]]
    do material create grain -density 3 -kn 0.01 -ks 0.01
    set c [expr {$L / 2.0}]
    set ::disc [do disc create -center [list [expr {$c + 0.3}] [expr {$c + 0.17}]] -radius [expr {$d / 2.0}] -material grain]
    set ::last 0.0
    go 300 1 [list apply {{limit} {
        set v [lindex [dict get [element info $::disc] velocity] 1]
        if {![finite $v]} { garbage "the disc's velocity is $v" nan; return }
        if {abs($v - $::last) > $limit} { garbage "the disc's velocity jumped from [fmt $::last] to [fmt $v] in one step" }
        if {$v > 1e-12} { garbage "the disc (density 3 in fluid of 1) rises at [fmt $v]" }
        set ::last $v
    }} [expr {10 * $g * (1 + 1.0 / 3)}]]
    set ::measure "falls at [fmt [expr {-$::last}]] after [dict get [sim info] step] steps"
}

# ---- maps: two settings at once (scripts/stability --maps) -------------------------
# Each is a case above with a second setting; the garbage tests are theirs.
proc case_map_cavity-bgk {tau lid} { cavityTau $tau {} $lid }
proc case_map_cavity-trt {tau lid} { cavityTau $tau {-collision trt} $lid }
proc case_map_settle-explicit {ratio tau} { settleCase $ratio explicit $tau }
proc case_map_settle-implicit {ratio tau} { settleCase $ratio implicit $tau }
proc case_map_pair {f e} { impacts $f $e pair }
proc case_map_resting {f e} { case_timestep_resting $f $e }
proc case_map_size-settle {d tau} { case_size_settle $d $tau }
proc case_map_disc {ma d} { case_mach_disc $ma $d }

# ---- the point ---------------------------------------------------------------------
set proc case_${sweep}_$case
if {[info commands $proc] eq ""} {
    puts stderr "no case \"$case\" in sweep \"$sweep\""
    exit 2
}
sim configure -threads 1
if {[catch {$proc $value {*}[expr {$sweep eq "map" ? [list $value2] : {}}]} message opts] && $::refused eq {}} {
    # A fault of this driver, not an outcome.
    puts stderr [dict get $opts -errorinfo]
    exit 3
}
set bad [nanCheck]
set step [dict get [sim info] step]
set firstWarning [expr {[llength $::warnings] ? [lindex $::warnings 0 0] : {}}]
if {$bad ne {}} {
    set outcome SILENT-NAN
    set text [join $bad "; "]
    if {$::stopped ne {}} { append text " (after the run stopped: $::stopped)" }
} elseif {$::refused ne {}} {
    set outcome refused
    set text "[lindex $::refused 0]: [lindex $::refused 1]"
    set ::measure {}
} elseif {$::garbage ne {} && ($firstWarning eq {} || $firstWarning > [lindex $::garbage 0])} {
    set outcome [expr {[lindex $::garbage 2] eq "nan" ? "SILENT-NAN" : "SILENT-BAD"}]
    set text "step [lindex $::garbage 0]: [lindex $::garbage 1], with no warning or error before it"
    if {$firstWarning ne {}} { append text "; first warning at step $firstWarning" }
    if {$::stopped ne {}} {
        append text "; stopped: $::stopped"
    } else {
        append text "; ran to step $step"
    }
} elseif {$::stopped ne {}} {
    set outcome stopped
    set text $::stopped
    if {$::measure ne {}} { append ::measure " (the state before the stop)" }
} elseif {$::warnings ne {}} {
    set outcome warned
    set text "step $firstWarning: [lindex $::warnings 0 1]"
    if {[llength $::warnings] > 1} { append text " (+[expr {[llength $::warnings] - 1}] more)" }
} else {
    set outcome ok
    set text ""
}
if {"inaccurate" in $::notes && $outcome in {ok warned}} { set ::measure "$::measure (inaccurate)" }
if {$::garbage ne {} && $outcome in {warned stopped}} {
    append text " (after the warning: step [lindex $::garbage 0]: [lindex $::garbage 1])"
}
regsub -all {[\t\n]+} $text " " text
regsub -all {[\t\n]+} $::measure " " ::measure
puts "RESULT\t$outcome\t$::measure\t$text"
