# The thesis's global variables. Each is traced: setting it acts at once (the
# lattice, `sim` or the view change), and a value that is refused leaves the
# variable as it was, with the error (`can't set "LBBR": bad LBBR ...`) and the
# scene unchanged. Settings the lattice needs before it exists (LBVISCOSITY,
# LBFORCINGX/Y) are also read by addlatticeui. TIMESTEPS, GRAPHICSFRAMES and
# SNAPSHOTPREFIX are read by `run` with no count (src/tcl/run_cmd.cpp).

namespace eval ::sf::thesis {
    variable accepted          ;# the value each variable last took
    array set accepted {}
    # the traced variables: setting NAME calls ::sf::thesis::setting::NAME
    variable traced {MAXDTCR TIMESTEPS GRAPHICSFRAMES LBON LBVISCOSITY LBBR LBFORCINGX
        LBFORCINGY LBSHOWLATTICE LBSHOWVECTORS LBSHOWSOLUTION}
    # LBBR's accuracies as subcells per side of the solid ratio (sim -solidratio)
    variable subcells {low 2 med 4 high 8}
}

proc ::sf::thesis::armAll {} {
    variable traced
    foreach name $traced { arm $name }
}

# A variable that is unset loses its traces: they are put back, so that the
# next `set` acts again.
proc ::sf::thesis::arm {name} {
    trace add variable ::$name {write unset} [list ::sf::thesis::written $name]
}

proc ::sf::thesis::written {name name1 name2 op} {
    variable accepted
    if {$op eq "unset"} {
        unset -nocomplain accepted($name)
        arm $name
        return
    }
    if {$name2 ne ""} return   ;# an array of that name is not the thesis's setting
    upvar #0 $name value
    if {[catch {setting::$name $value} message]} {
        if {[info exists accepted($name)]} {
            set value $accepted($name)
        } else {
            unset value
        }
        return -code error $message
    }
    set accepted($name) $value
}

# A global variable's value, or a default while it is not set.
proc ::sf::thesis::valueOf {name default} {
    if {[info exists ::$name]} { return [set ::$name] }
    return $default
}

# The fluid's forcing as LBFORCINGX and LBFORCINGY give it.
proc ::sf::thesis::forcing {} {
    list [valueOf LBFORCINGX 0] [valueOf LBFORCINGY 0]
}

# The field the view draws: the solution, else the nodes when the lattice is
# shown, else `none` if asked for, else sandflow's default (velocity).
proc ::sf::thesis::field {} {
    set solution [valueOf LBSHOWSOLUTION ""]
    if {$solution ni {"" none}} { return $solution }
    if {[valueOf LBSHOWLATTICE 0]} { return nodes }
    return $solution
}

namespace eval ::sf::thesis::setting {}

proc ::sf::thesis::setting::MAXDTCR {MAXDTCR} {
    ::sf::sim configure -timestep $MAXDTCR
}

proc ::sf::thesis::setting::TIMESTEPS {TIMESTEPS} {
    ::sf::thesis::count TIMESTEPS 0
    ::sf::thesis::showRun
}

proc ::sf::thesis::setting::GRAPHICSFRAMES {GRAPHICSFRAMES} {
    ::sf::thesis::count GRAPHICSFRAMES 0
    ::sf::thesis::showRun
}

# 1 makes the lattice addlatticeui described (if it is not there yet); 0
# deletes the lattice, and its fluid with it.
proc ::sf::thesis::setting::LBON {LBON} {
    if {![string is boolean -strict $LBON]} {
        ::sf::thesis::refuse LBON "LBON must be 0 or 1, got \"$LBON\""
    }
    set on [::sf::thesis::hasLattice]
    if {$LBON && !$on && [llength $::sf::thesis::box]} {
        ::sf::thesis::createLattice $::sf::thesis::box
    } elseif {!$LBON && $on} {
        ::sf::lattice delete
    }
}

proc ::sf::thesis::setting::LBVISCOSITY {LBVISCOSITY} {
    ::sf::thesis::numbers LBVISCOSITY
    if {$LBVISCOSITY <= 0} {
        ::sf::thesis::refuse LBVISCOSITY "LBVISCOSITY must be > 0, got $LBVISCOSITY"
    }
    if {[::sf::thesis::hasLattice]} { ::sf::lattice configure -viscosity $LBVISCOSITY }
}

proc ::sf::thesis::setting::LBBR {LBBR} {
    if {![dict exists $::sf::thesis::subcells $LBBR]} {
        ::sf::thesis::refuse LBBR "bad LBBR \"$LBBR\": must be low, med, or high"
    }
    ::sf::sim configure -solidratio [dict get $::sf::thesis::subcells $LBBR]
}

proc ::sf::thesis::setting::LBFORCINGX {LBFORCINGX} {
    ::sf::thesis::numbers LBFORCINGX
    if {[::sf::thesis::hasLattice]} { ::sf::lattice configure -forcing [::sf::thesis::forcing] }
}

proc ::sf::thesis::setting::LBFORCINGY {LBFORCINGY} {
    ::sf::thesis::numbers LBFORCINGY
    if {[::sf::thesis::hasLattice]} { ::sf::lattice configure -forcing [::sf::thesis::forcing] }
}

proc ::sf::thesis::setting::LBSHOWLATTICE {LBSHOWLATTICE} {
    if {![string is boolean -strict $LBSHOWLATTICE]} {
        ::sf::thesis::refuse LBSHOWLATTICE "LBSHOWLATTICE must be 0 or 1, got \"$LBSHOWLATTICE\""
    }
    ::sf::view configure -field [::sf::thesis::field]
    ::sf::thesis::showView
}

proc ::sf::thesis::setting::LBSHOWVECTORS {LBSHOWVECTORS} {
    if {![string is boolean -strict $LBSHOWVECTORS]} {
        ::sf::thesis::refuse LBSHOWVECTORS "LBSHOWVECTORS must be 0 or 1, got \"$LBSHOWVECTORS\""
    }
    ::sf::view configure -vectors [string is true $LBSHOWVECTORS]
    ::sf::thesis::showView
}

proc ::sf::thesis::setting::LBSHOWSOLUTION {LBSHOWSOLUTION} {
    ::sf::view configure -field [::sf::thesis::field]
    ::sf::thesis::showView
}
