# Argument checks for the thesis's procedures: each names the argument it
# refuses, in Tcl's phrasing, with errorCode SANDFLOW VALUE <ARG>, before
# anything is changed.

proc ::sf::thesis::refuse {what message} {
    return -level 2 -code error -errorcode [list SANDFLOW VALUE [string toupper $what]] $message
}

# Each named variable of the caller holds a finite number.
proc ::sf::thesis::numbers {args} {
    foreach name $args {
        upvar 1 $name value
        # (Inf passes `string is double`; NaN makes expr fail)
        if {![string is double -strict $value] || [catch {expr {abs($value) < Inf}} finite] ||
                !$finite} {
            refuse $name "expected floating-point number for $name but got \"$value\""
        }
    }
}

# Each named variable of the caller holds a flag: 1 (held, applied) or 0.
proc ::sf::thesis::flags {args} {
    foreach name $args {
        upvar 1 $name value
        if {$value ni {0 1}} {
            refuse $name "expected 0 or 1 for $name but got \"$value\""
        }
    }
}

# The caller's variable holds a whole number >= least.
proc ::sf::thesis::count {name least} {
    upvar 1 $name value
    if {![string is wideinteger -strict $value] || $value < $least} {
        refuse $name "$name must be a whole number >= $least, got \"$value\""
    }
}

# The caller's xmin ymin xmax ymax are numbers and enclose a box.
proc ::sf::thesis::boxArgs {} {
    uplevel 1 { ::sf::thesis::numbers xmin ymin xmax ymax }
    upvar 1 xmin xmin ymin ymin xmax xmax ymax ymax
    if {$xmax <= $xmin} { refuse xmax "xmax $xmax must exceed xmin $xmin" }
    if {$ymax <= $ymin} { refuse ymax "ymax $ymax must exceed ymin $ymin" }
}

# Whether there is a lattice (cget asks nothing of its nodes).
proc ::sf::thesis::hasLattice {} {
    expr {![catch {::sf::lattice cget -spacing}]}
}
