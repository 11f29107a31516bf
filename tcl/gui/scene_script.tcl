# scene_script.tcl -- the workbench's "Save scene as script": the text of a
# Tcl script that rebuilds the current scene with the public commands of
# docs/commands.md, and the file it is saved to. Needs no Tk.
#
#   ::sf::gui::sceneScript              -> the script
#   ::sf::gui::saveSceneScript FILE ?-state 0|1?   -> FILE, written whole or not at all
#       -state 1 also saves the state no command sets (the flow, contact and
#       bond histories, the clock) in a checkpoint beside FILE (FILE's name
#       with .sfck), which the script's last line loads: after a run, the
#       script then gives back the scene exactly as it was.
#   ::sf::gui::elementScript ID         -> the commands that remake one element
#
# Numbers are written as Tcl prints a double with tcl_precision 0: the
# shortest form that reads back as the same double, so what the commands
# report comes back bit for bit. Which of viscosity, tau and timestep (and
# cells or spacing) were given, and a wall's own pose and thickness, the
# kernel reports. A polygon's outline in its own frame it does not: that is
# found by redoing the kernel's arithmetic here on candidate inputs and
# keeping the one that gives back exactly what is reported; where none does,
# the script says so in a comment. What no command can set (the clock, the
# fluid's populations, contact and bond histories) the script's header lists.

namespace eval ::sf::gui {}
namespace eval ::sf::gui::scenescript {
    # The options an element takes by default: left out of its create
    # command, which then reads more easily (the same strings, so the same bits).
    variable defaults {
        -angle 0.0 -material default -velocity {0.0 0.0 0.0} -fix {}
        -force {0.0 0.0 0.0} -acceleration {0.0 0.0}
    }
    variable pi 3.141592653589793  ;# std::numbers::pi
}

# ---- the entry points ------------------------------------------------------

proc ::sf::gui::sceneScript {} {
    scenescript::fullPrecision {
        set parts {}
        foreach part {header materials sim lattice elements bonds sources view} {
            set lines [scenescript::$part]
            if {[llength $lines]} {lappend parts [join $lines \n]}
        }
        string cat [join $parts \n\n] \n
    }
}

proc ::sf::gui::saveSceneScript {file args} {
    if {[llength $args] % 2} {
        return -code error -errorcode {TCL WRONGARGS} \
            {wrong # args: should be "::sf::gui::saveSceneScript FILE ?-state 0|1?"}
    }
    set state 0
    foreach {option value} $args {
        if {$option ne "-state"} {
            return -code error -errorcode [list TCL LOOKUP INDEX option $option] \
                "bad option \"$option\": must be -state"
        }
        if {$value eq "" || ![string is boolean -strict $value]} {
            return -code error -errorcode {TCL VALUE NUMBER} \
                "expected boolean value but got \"$value\""
        }
        set state [string is true $value]
    }
    if {[catch {sceneScript} text options]} {
        return -code error -errorcode [dict get $options -errorcode] \
            "cannot write \"$file\": $text"
    }
    # "file rename" onto a folder would move the file into it.
    if {[file isdirectory $file]} {
        return -code error -errorcode {SANDFLOW IO WRITE} \
            "cannot write \"$file\": Is a directory"
    }
    if {$state} {
        # The checkpoint first: a script is never left loading a file that is not there.
        set checkpoint [file rootname $file].sfck
        ::sf::checkpoint save $checkpoint
        append text \n [scenescript::stateLines [file tail $checkpoint]] \n
    }
    set part $file.tmp
    if {[catch {open $part w} channel options]} {
        return -code error -errorcode {SANDFLOW IO OPEN} [scenescript::cannotWrite $file $options]
    }
    try {
        puts -nonewline $channel $text
        close $channel
        file rename -force -- $part $file
    } on error {message options} {
        catch {close $channel}
        catch {file delete -- $part}
        return -code error -errorcode {SANDFLOW IO WRITE} [scenescript::cannotWrite $file $options]
    }
    return $file
}

proc ::sf::gui::elementScript {id} {
    scenescript::fullPrecision {
        join [scenescript::element $id] \n
    }
}

# ---- helpers -----------------------------------------------------------------

namespace eval ::sf::gui::scenescript {

# The script's last lines with -state 1: the checkpoint that holds what no
# command sets, found beside the script wherever the two are moved.
proc stateLines {checkpoint} {
    set info [::sf::sim info]
    join [list \
        "# The state at step [dict get $info step] (the flow, contact and bond histories,\
            bond breaks, sources' clones, the clock)," \
        "# saved beside this script: loading it replaces the scene the lines above build, so\
            an edit above" \
        "# takes effect only without this line." \
        "checkpoint load \[file join \[file dirname \[info script\]\] [list $checkpoint]\]"] \n
}

# Runs a script in the caller with tcl_precision 0 and returns its result: a
# user's "set tcl_precision 6" would otherwise cut every number written.
proc fullPrecision {script} {
    set precision $::tcl_precision
    set ::tcl_precision 0
    try {
        uplevel 1 $script
    } finally {
        set ::tcl_precision $precision
    }
}

# The message of a failed save in the phrasing of the C++ writers
# ('cannot write "FILE": No such file or directory'): FILE, not FILE.tmp.
proc cannotWrite {file options} {
    set code [dict get $options -errorcode]
    if {[lindex $code 0] eq "POSIX"} {
        set reason [string toupper [lindex $code 2] 0 0]
    } else {
        set reason [lindex [split [dict get $options -errorinfo] \n] 0]
    }
    return "cannot write \"$file\": $reason"
}

# Option-value pairs less those whose value is {} (unset: a material's
# -damping while -restitution rules).
proc setOnly {pairs} {
    set out {}
    foreach {option value} $pairs {
        if {$value ne ""} {lappend out $option $value}
    }
    return $out
}

# Option-value pairs less the options named.
proc without {pairs options} {
    set out {}
    foreach {option value} $pairs {
        if {$option ni $options} {lappend out $option $value}
    }
    return $out
}

# A value as it was probably typed: 12 significant digits. A setting typed
# by hand is found again this way when arithmetic has blurred its last bits.
proc typed {value} {
    expr {double([format %.12g $value])}
}
proc typedList {values} {
    lmap value $values {typed $value}
}

# Whether two numbers, or two lists of numbers, are the same doubles.
proc same {a b} {
    expr {[lmap x $a {expr {double($x)}}] eq [lmap x $b {expr {double($x)}}]}
}

# ---- header, materials, sim ----------------------------------------------------

proc header {} {
    set info [::sf::sim info]
    set version [expr {[catch {package present sandflow} v] ? "" : " $v"}]
    set date [clock format [clock seconds] -format {%Y-%m-%d %H:%M:%S}]
    list "# sandflow$version scene, saved by the workbench (Save scene as script) on $date." \
        "# Run it with \"sandflow FILE\" or \"source FILE\"; it uses only the commands of\
            docs/commands.md." \
        "# Saved at step [dict get $info step], t = [dict get $info time]. No command sets\
            the clock, the fluid's populations (its flow)," \
        "# contact or bond histories, bond breaks or a source's count of clones: the\
            script rebuilds the scene at t = 0," \
        "# the fluid at rest at its density, and every element where it was, as fast as\
            it was." \
        reset
}

proc materials {} {
    set lines [list "# Materials (\"default\" exists after reset)."]
    foreach name [::sf::material names] {
        set verb [expr {$name eq "default" ? "configure" : "create"}]
        lappend lines [list material $verb $name {*}[setOnly [::sf::material configure $name]]]
    }
    return $lines
}

proc sim {} {
    set options [without [::sf::sim configure] {-threads -timestep}]
    lappend options {*}[dict get [stepping] sim]
    list "# Settings. -threads is not saved: it is this machine's, and results do\
            not depend on it." \
        [list sim configure {*}$options]
}

# How the timestep comes back: {sim OPTIONS lattice OPTIONS comment TEXT}.
# The kernel says which settings were given (sim info's and lattice info's
# "given"); the derived ones follow from them as before.
proc stepping {} {
    set dt [::sf::sim cget -timestep]
    if {[catch {::sf::lattice info} info]} {
        set given [dict get [::sf::sim info] given]
        set sim [expr {"-timestep" in $given ? [list -timestep $dt] : {}}]
        return [list sim $sim lattice {} comment {}]
    }
    set given [dict get $info given]
    set lattice {}
    foreach option {-viscosity -tau} {
        if {$option in $given} {lappend lattice $option [::sf::lattice cget $option]}
    }
    set sim [expr {"-timestep" in $given ? [list -timestep $dt] : {}}]
    list sim $sim lattice $lattice comment {}
}

# ---- the lattice -------------------------------------------------------------

proc lattice {} {
    if {[catch {::sf::lattice configure} options]} {return {}}
    set stepping [stepping]
    set create [list -origin [dict get $options -origin] -size [dict get $options -size]]
    # -cells or -spacing, whichever the lattice was given
    set option [expr {"-cells" in [dict get [::sf::lattice info] given] ? "-cells" : "-spacing"}]
    lappend create $option [dict get $options $option]
    lappend create {*}[dict get $stepping lattice] \
        {*}[without $options {-origin -size -cells -spacing -viscosity -tau}]
    set lines [list "# The lattice and its obstacles."]
    if {[dict get $stepping comment] ne ""} {lappend lines [dict get $stepping comment]}
    lappend lines [list lattice create {*}$create]
    foreach id [::sf::lattice obstacles] {
        lappend lines [obstacle $id]
    }
    return $lines
}

proc obstacle {id} {
    set o [::sf::lattice obstacle info $id]
    switch -- [dict get $o type] {
        rect {
            list lattice obstacle rect [dict get $o rect] -slip [dict get $o slip] -id $id
        }
        circle {
            list lattice obstacle circle [dict get $o circle] -outside [dict get $o outside] \
                -velocity [dict get $o velocity] -id $id
        }
        default {
            error "cannot save obstacle $id: unknown type \"[dict get $o type]\""
        }
    }
}

# ---- elements ----------------------------------------------------------------

# In id order, which is also the order of their slots after the script.
proc elements {} {
    set ids [::sf::element ids]
    if {![llength $ids]} {return {}}
    set lines [list "# Elements, with their ids, poses and velocities."]
    foreach id $ids {
        lappend lines {*}[element $id]
    }
    return $lines
}

# The commands that remake element ID: its create command, and where that
# cannot give the pose or the holds, an "element configure".
proc element {id} {
    variable defaults
    set info [::sf::element info $id]
    set density [::sf::material cget [dict get $info material] -density]
    set common [list -id $id]
    foreach {option key} {-angle angle -material material -velocity velocity -fix fix
                          -force applied -acceleration acceleration} {
        set value [dict get $info $key]
        if {$value ne [dict get $defaults $option]} {lappend common $option $value}
    }
    switch -- [dict get $info type] {
        disc {
            list [list disc create -center [dict get $info position] \
                      -radius [dict get $info radius] {*}$common]
        }
        superquadric {
            list [list superquadric create -center [dict get $info position] \
                      -axes [dict get $info axes] -exponents [dict get $info exponents] \
                      -sides [dict get $info sides] {*}$common]
        }
        polygon {polygon $info $common $density}
        wall {wall $info $common $density}
        default {
            error "cannot save element $id: unknown type \"[dict get $info type]\""
        }
    }
}

# ---- polygons: the kernel's arithmetic (src/dem/polygon.cpp), step for step ----

# A flat list of points {x1 y1 x2 y2 ...}, started at its second point, and
# in the reverse order.
proc shifted {points} {
    concat [lrange $points 2 end] [lrange $points 0 1]
}
proc reversed {points} {
    set out {}
    for {set i [expr {[llength $points] - 2}]} {$i >= 0} {incr i -2} {
        lappend out {*}[lrange $points $i [expr {$i + 1}]]
    }
    return $out
}

proc signedArea {points} {
    set a 0.0
    foreach {ux uy} $points {vx vy} [shifted $points] {
        set a [expr {$a + ($ux * $vy - $vx * $uy)}]
    }
    expr {0.5 * $a}
}

# Relative to the first point, as the kernel does.
proc centroid {points} {
    lassign $points ox oy
    set rest [lrange $points 2 end]
    set a 0.0
    set cx 0.0
    set cy 0.0
    foreach {px py} [lrange $rest 0 end-2] {qx qy} [lrange $rest 2 end] {
        set ux [expr {$px - $ox}]
        set uy [expr {$py - $oy}]
        set vx [expr {$qx - $ox}]
        set vy [expr {$qy - $oy}]
        set t [expr {$ux * $vy - $vx * $uy}]
        set a [expr {$a + $t}]
        set cx [expr {$cx + $t * ($ux + $vx)}]
        set cy [expr {$cy + $t * ($uy + $vy)}]
    }
    set d [expr {3 * $a}]
    list [expr {$ox + $cx / $d}] [expr {$oy + $cy / $d}]
}

# What "polygon create -vertices POINTS" makes: {centroid local area perMass}.
proc outline {points} {
    set area [signedArea $points]
    if {$area < 0} {
        set points [reversed $points]
        set area [expr {-$area}]
    }
    lassign [set centroid [centroid $points]] cx cy
    set local {}
    foreach {x y} $points {
        lappend local [expr {$x - $cx}] [expr {$y - $cy}]
    }
    set j 0.0
    foreach {px py} $local {qx qy} [shifted $local] {
        set cross [expr {$px * $qy - $qx * $py}]
        set j [expr {$j + $cross * (($px * $px + $py * $py) + ($px * $qx + $py * $qy)
                                    + ($qx * $qx + $qy * $qy))}]
    }
    dict create centroid $centroid local $local area $area perMass [expr {$j / 12.0 / $area}]
}

# The corners of an outline at a pose.
proc world {local x y angle} {
    set c [expr {cos($angle)}]
    set s [expr {sin($angle)}]
    set out {}
    foreach {px py} $local {
        lappend out [expr {$x + $c * $px - $s * $py}] [expr {$y + $s * $px + $c * $py}]
    }
    return $out
}

# Whether an outline, at the element's pose, is exactly what "element info"
# reported: corners, area, mass and inertia.
proc samePolygon {shape info density} {
    lassign [dict get $info position] x y
    set area [dict get $shape area]
    set mass [expr {$density * $area}]
    expr {[same [world [dict get $shape local] $x $y [dict get $info angle]] \
               [dict get $info vertices]]
          && [same $area [dict get $info area]] && [same $mass [dict get $info mass]]
          && [same [expr {$mass * [dict get $shape perMass]}] [dict get $info inertia]]}
}

# The corners relative to the centre, turned back to angle 0: the polygon's
# own outline, up to rounding.
proc ownOutline {info} {
    lassign [dict get $info position] x y
    set a [dict get $info angle]
    set c [expr {cos($a)}]
    set s [expr {sin($a)}]
    set out {}
    foreach {wx wy} [dict get $info vertices] {
        set dx [expr {$wx - $x}]
        set dy [expr {$wy - $y}]
        lappend out [expr {$c * $dx + $s * $dy}] [expr {$c * $dy - $s * $dx}]
    }
    return $out
}

# The same about the centre: the corners in the frame "polygon create" took
# them in.
proc unturned {info} {
    lassign [dict get $info position] x y
    set out {}
    foreach {px py} [ownOutline $info] {
        lappend out [expr {$x + $px}] [expr {$y + $py}]
    }
    return $out
}

# The axes {a b} of the "ellipse create" that made this polygon, or {} when
# none is found: an ellipse's outline follows from its axes and side count.
proc ellipseAxes {info density} {
    variable pi
    set sides [expr {[llength [dict get $info vertices]] / 2}]
    if {$sides < 3 || $sides > 10000} {return {}}
    set local [ownOutline $info]
    # a from the first corner (at t = 0), b from the one nearest t = pi/2.
    set k [expr {int(round($sides / 4.0))}]
    set a0 [lindex $local 0]
    set b0 [expr {[lindex $local [expr {2 * $k + 1}]] / sin(2 * $pi * $k / $sides)}]
    foreach {a b} [list [typed $a0] [typed $b0] $a0 $b0] {
        if {!($a > 0 && $b > 0)} continue
        set points {}
        for {set i 0} {$i < $sides} {incr i} {
            set t [expr {2 * $pi * $i / $sides}]
            lappend points [expr {$a * cos($t)}] [expr {$b * sin($t)}]
        }
        if {![catch {outline $points} shape] && [samePolygon $shape $info $density]} {
            return [list $a $b]
        }
    }
    return {}
}

# {vertices centroid exact}: corners for "polygon create" (at the element's
# angle) that give back the reported polygon, else the reported corners
# turned back (exact 0).
proc polygonCorners {info density} {
    set unturned [unturned $info]
    set candidates {}
    if {[dict get $info angle] == 0} {
        lappend candidates [typedList [dict get $info vertices]] [dict get $info vertices]
    }
    lappend candidates [typedList $unturned] $unturned
    foreach points $candidates {
        foreach order [list $points [reversed $points]] {
            # (rounding may collapse a tiny polygon: such a candidate fails)
            if {![catch {outline $order} shape] && [samePolygon $shape $info $density]} {
                return [list $order [dict get $shape centroid] 1]
            }
        }
    }
    set points [expr {[dict get $info angle] == 0 ? [dict get $info vertices] : $unturned}]
    list $points [dict get [outline $points] centroid] 0
}

proc polygon {info common density} {
    set id [dict get $info id]
    set position [dict get $info position]
    set axes [ellipseAxes $info $density]
    if {$axes ne ""} {
        set sides [expr {[llength [dict get $info vertices]] / 2}]
        return [list [list ellipse create -center $position -axes $axes -sides $sides {*}$common]]
    }
    lassign [polygonCorners $info $density] vertices centroid exact
    set lines {}
    if {!$exact} {
        lappend lines "# polygon $id: rebuilt from its corners; they, its area and inertia may\
            differ in the last digit (no command reports a polygon's own outline)."
    }
    lappend lines [list polygon create -vertices $vertices {*}$common]
    if {![same $centroid $position]} {
        lappend lines [list element configure $id -center $position]
    }
    return $lines
}

# ---- walls ---------------------------------------------------------------------

# A wall's own pose (centre, length, angle) and thickness, as element info
# reports them: "wall create -center -length" makes it again exactly.
proc wall {info common density} {
    set id [dict get $info id]
    set extra [list -length [dict get $info length] -thickness [dict get $info thickness]]
    set stress [::sf::element cget $id -stress]
    if {$stress ne ""} {lappend extra -stress $stress}
    # Walls are held unless freed, so -fix is always written.
    set fix [dict get $info fix]
    set common [without $common {-angle -fix}]
    set lines [list [list wall create -center [dict get $info position] {*}$extra \
        -angle [dict get $info angle] {*}$common -fix $fix]]
    # the holds a plate's -stress sets
    if {$stress ne "" && $fix ne {x y rot}} {
        lappend lines [list element configure $id -fix $fix]
    }
    return $lines
}

# ---- bonds, sources, view ------------------------------------------------------

proc bonds {} {
    set ids [::sf::bond ids]
    if {![llength $ids]} {return {}}
    set lines [list "# Bonds. bond create takes a bond's rest length and anchors from where\
            the elements are now" \
        "# (they cannot be set): each bond's saved rest length follows it. It takes no\
            -id either: the ids of" \
        "# deleted or broken bonds are used up by making and deleting the bond."]
    set next 0
    foreach id $ids {
        lappend lines {*}[bond $id $next]
        set next [expr {$id + 1}]
    }
    return $lines
}

# The lines that remake bond ID when the next bond made would get id NEXT.
proc bond {id next} {
    set b [::sf::bond info $id]
    lassign [dict get $b elements] a c
    set create [list bond create $a $c -stiffness [dict get $b stiffness] \
                    -strength [dict get $b strength] -shearstrength [dict get $b shearstrength]]
    set lines {}
    if {$id > $next} {
        lappend lines [format {foreach _ [lrepeat %d {}] {bond delete [bond create %d %d]}} \
                           [expr {$id - $next}] $a $c]
    }
    # Discs, and discs and walls, bond across a gap; other shapes only where
    # they touch, which after a run they may no longer do.
    set types [lmap e [list $a $c] {dict get [::sf::element info $e] type}]
    if {[lsort $types] in {{disc disc} {disc wall}}} {
        lappend lines "$create ;# rest length [dict get $b length]"
        return $lines
    }
    lappend lines $create
    list "# rest length [dict get $b length]" \
        [format "if {\[catch {\n    %s\n} _\]} {::sf::warn \"bond %d is not rebuilt: \$_\"}" \
             [join $lines "\n    "] $id]
}

proc sources {} {
    set lines {}
    foreach id [::sf::source ids] {
        set s [::sf::source info $id]
        if {[dict get $s made] > 0} {
            lappend lines "# source $id: clones made so far [dict get $s made] (now elements\
                of their own); its count starts again from 0."
        }
        lappend lines [list ::sf::source create $id -acceleration [dict get $s acceleration] \
                           -interval [dict get $s interval] -limit [dict get $s limit]]
    }
    if {![llength $lines]} {return {}}
    linsert $lines 0 "# Sources (::sf::source: Tcl's own \"source\" in a plain tclsh)."
}

proc view {} {
    list "# What pictures show. -offscreen (the picture back end) is not saved: it is\
            this machine's." \
        [list view configure {*}[without [::sf::view configure] -offscreen]]
}

}
