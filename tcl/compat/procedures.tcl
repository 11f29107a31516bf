# The thesis's *ui procedures and its element procedures, each one command of
# sandflow's (docs/thesis-compat.md). Arguments are checked first, naming the
# one refused; the command they map to checks the rest and changes nothing
# when it refuses.

namespace eval ::sf::thesis {
    variable box {}   ;# addlatticeui's {xmin ymin xmax ymax ncells}, for LBON
}

# The view's world window: snapshots and the workbench's view show it.
proc ::sf::thesis::setscales {xmin ymin xmax ymax} {
    boxArgs
    ::sf::view configure -region [list $xmin $ymin $xmax $ymax]
    showView 1
}

# A lattice over the box with ncells across x, the fluid as LBVISCOSITY and
# LBFORCINGX/Y say. With LBON 0 the box is kept, and LBON 1 makes the lattice.
proc ::sf::thesis::addlatticeui {xmin ymin xmax ymax ncells} {
    variable box
    boxArgs
    count ncells 1
    set request [list $xmin $ymin $xmax $ymax $ncells]
    if {[valueOf LBON 1]} { createLattice $request }
    set box $request
    return
}

proc ::sf::thesis::createLattice {request} {
    lassign $request xmin ymin xmax ymax ncells
    set options [list -origin [list $xmin $ymin] \
                     -size [list [expr {$xmax - $xmin}] [expr {$ymax - $ymin}]] -cells $ncells]
    if {[info exists ::LBVISCOSITY]} { lappend options -viscosity $::LBVISCOSITY }
    if {[info exists ::LBFORCINGX] || [info exists ::LBFORCINGY]} {
        lappend options -forcing [forcing]
    }
    ::sf::lattice create {*}$options
}

# A disc of that material (a name, or the thesis's number), centre and
# radius, with that id -> id
proc ::sf::thesis::adddiscui {material x y radius id} {
    numbers x y radius
    ::sf::disc create -material [materialOf $material] -center [list $x $y] -radius $radius \
        -id $id
}

# The thesis numbers its materials, 1 the first; sandflow names them, in the
# order they were made (`material names`: default first). A material's name
# wins over a number; a name that is neither is left for the command to refuse.
proc ::sf::thesis::materialOf {material} {
    set names [::sf::material names]
    if {$material in $names || ![string is wideinteger -strict $material]} { return $material }
    if {$material >= 1 && $material <= [llength $names]} { return [lindex $names $material-1] }
    set numbered [lmap name $names {format "%d %s" [incr k] $name}]
    return -level 1 -code error -errorcode {SANDFLOW LOOKUP MATERIAL} \
        "no material numbered $material: [join $numbered {, }]"
}

# Flags (1 = held) for x, y and rotation, then the velocities (vx, vy, w),
# prescribed for what is held and the initial ones for the rest.
proc ::sf::thesis::set_velocity {fx fy fr vx vy w id} {
    flags fx fy fr
    numbers vx vy w
    set fix {}
    foreach flag [list $fx $fy $fr] dof {x y rot} {
        if {$flag} { lappend fix $dof }
    }
    ::sf::element configure $id -fix $fix -velocity [list $vx $vy $w]
    return
}

# Flags (1 = applied) for x, y and rotation, then the applied force and
# torque: a flagged component is set, the others keep their value.
proc ::sf::thesis::setforce {fx fy fr Fx Fy T id} {
    flags fx fy fr
    numbers Fx Fy T
    set applied [::sf::element cget $id -force]
    foreach flag [list $fx $fy $fr] value [list $Fx $Fy $T] k {0 1 2} {
        if {$flag} { lset applied $k $value }
    }
    ::sf::element configure $id -force $applied
    return
}

# The element becomes a source; its clones inherit its applied force (set it
# with setforce). -limit and -interval are sandflow's `source create` options.
proc ::sf::thesis::makesource {args} {
    if {[llength $args] % 2 == 0} {
        return -code error -errorcode {TCL WRONGARGS} \
            "wrong # args: should be \"makesource id ?-limit n? ?-interval t?\""
    }
    set options [lassign $args id]
    foreach {option value} $options {
        if {$option ni {-limit -interval}} {
            refuse option "bad option \"$option\": must be -interval or -limit"
        }
    }
    ::sf::source create $id {*}$options
}

proc ::sf::thesis::get_next_available_id {} {
    ::sf::element next
}
