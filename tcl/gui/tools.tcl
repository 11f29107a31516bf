# The tool palette and what the mouse does on the view with each tool. Every
# gesture ends in one command a user could type (::sf::gui::do). Shapes are
# drawn by dragging their bounding box, as in SandFlow2D; walls from end to
# end; polygons by clicking their vertices (double-click, Return or a click on
# the first vertex closes them). Middle-drag or Shift-drag pans; the wheel zooms
# about the pointer.

namespace eval ::sf::gui::tools {
    variable tool select
    variable snap 0             ;# snap points to the grid
    variable material default
    variable cells 100          ;# lattice: cells across x
    variable viscosity 0.01     ;# lattice: kinematic viscosity
    variable forcing {0 0}      ;# lattice: body force {Fx Fy}
    variable exponents {4 4}    ;# superquadric
    variable drag {}            ;# the gesture in progress: dict
    variable vertices {}        ;# polygon being clicked
    variable preview #e8590c    ;# colour of shapes being drawn
    # name label key help
    variable palette {
        select       Select       s "Click to select (Shift adds), drag to move, drag on empty space for a rubber band"
        pan          Pan          h "Drag to pan; the wheel zooms about the pointer"
        lattice      Lattice      l "Drag a box: the lattice (cells across and viscosity below)"
        disc         Disc         d "Drag the disc's bounding box"
        polygon      Polygon      p "Click vertices; double-click, Return or the first vertex closes it"
        ellipse      Ellipse      e "Drag the ellipse's bounding box"
        superquadric Superquadric q "Drag the bounding box (exponents below)"
        wall         Wall         w "Drag from one end to the other"
        rect         Obstacle     o "Drag a fixed solid rectangle of the lattice"
        circle       {Round obstacle} c "Drag the bounding box of a fixed solid circle of the lattice"
    }
}

# Builds the palette in frame `f`: one button per tool, then the tools' options.
proc ::sf::gui::tools::create {f} {
    variable palette
    ttk::frame $f -padding 4
    ttk::label $f.title -text Tools -style Heading.TLabel
    grid $f.title -sticky w -pady {0 4}
    foreach {name label key help} $palette {
        ttk::radiobutton $f.$name -text "$label" -value $name -variable ::sf::gui::tools::tool \
            -style Toolbutton -command [list ::sf::gui::tools::choose $name]
        grid $f.$name -sticky ew -pady 1
        ::sf::gui::tip $f.$name "$help  (key: $key)"
    }
    ttk::separator $f.sep -orient horizontal
    grid $f.sep -sticky ew -pady 6
    ttk::checkbutton $f.snap -text "Snap to grid" -variable ::sf::gui::tools::snap
    grid $f.snap -sticky w
    ::sf::gui::tip $f.snap "Snap points to the lattice's nodes, or to a grid of 1/100 of the view"
    foreach {var label width help} {
        material  Material  10 "Material of new elements"
        cells     Cells     6  "Lattice: cells across x"
        viscosity Viscosity 8  "Lattice: kinematic viscosity"
        forcing   Forcing   8  "Lattice: body force {Fx Fy} (a pressure gradient)"
        exponents Exponents 6  "Superquadric: exponents {m n}"
    } {
        ttk::label $f.l$var -text $label
        if {$var eq "material"} {
            ttk::combobox $f.$var -textvariable ::sf::gui::tools::$var -width $width \
                -postcommand [list apply {{w} { $w configure -values [material names] }} $f.$var]
        } else {
            ttk::entry $f.$var -textvariable ::sf::gui::tools::$var -width $width
        }
        grid $f.l$var -sticky w -pady {4 0}
        grid $f.$var -sticky ew
        ::sf::gui::tip $f.$var $help
    }
    grid columnconfigure $f 0 -weight 1
    return $f
}

proc ::sf::gui::tools::choose {name} {
    variable tool $name
    variable vertices {}
    variable drag {}
    setOverlay {}
    foreach {n label key help} $::sf::gui::tools::palette {
        if {$n ne $name} continue
        if {$name in {rect circle} && [catch {lattice cget -cells}]} {
            ::sf::gui::status "$label: [noLattice]" error
        } else {
            ::sf::gui::status "$label: $help"
        }
    }
}

proc ::sf::gui::tools::noLattice {} {
    return "obstacles are part of the lattice, and there is none: draw one first (the Lattice tool, key l)"
}

# Mouse and key bindings on the view widget.
proc ::sf::gui::tools::bind {w} {
    ::bind $w <ButtonPress-1> {::sf::gui::tools::press %x %y %s}
    ::bind $w <B1-Motion> {::sf::gui::tools::motion %x %y}
    ::bind $w <ButtonRelease-1> {::sf::gui::tools::release %x %y %s}
    ::bind $w <Double-Button-1> {::sf::gui::tools::double %x %y %s}
    ::bind $w <ButtonPress-2> {::sf::gui::tools::panStart %x %y}
    ::bind $w <B2-Motion> {::sf::gui::tools::panMotion %x %y}
    ::bind $w <Shift-ButtonPress-1> {::sf::gui::tools::panStart %x %y}
    ::bind $w <Shift-B1-Motion> {::sf::gui::tools::panMotion %x %y}
    ::bind $w <Shift-ButtonRelease-1> {set ::sf::gui::tools::drag {}}
    ::bind $w <Control-ButtonPress-1> {::sf::gui::tools::press %x %y %s}
    ::bind $w <ButtonPress-3> {::sf::gui::tools::contextMenu %x %y %X %Y}
    ::bind $w <Button-4> {::sf::gui::view::zoom 1.25 %x %y}
    ::bind $w <Button-5> {::sf::gui::view::zoom 0.8 %x %y}
    ::bind $w <MouseWheel> {::sf::gui::view::zoom [expr {%D > 0 ? 1.25 : 0.8}] %x %y}
    ::bind $w <Motion> {::sf::gui::tools::hover %x %y}
    ::bind $w <Return> {::sf::gui::tools::closePolygon}
    ::bind $w <Escape> {::sf::gui::tools::cancel}
    ::bind $w <Enter> {focus %W}
}

# The world point under a pixel, snapped when asked.
proc ::sf::gui::tools::point {px py} {
    lassign [::sf::gui::view::toWorld $px $py] x y
    list [snapValue $x] [snapValue $y]
}

proc ::sf::gui::tools::gridStep {} {
    if {![catch {lattice info} info]} { return [dict get $info spacing] }
    lassign [::sf::gui::view::shown] x0 y0 x1 y1
    set raw [expr {($x1 - $x0) / 100.0}]
    # A round step: 1, 2 or 5 times a power of ten.
    set p [expr {10 ** floor(log10($raw))}]
    foreach m {1 2 5 10} { if {$m * $p >= $raw} { return [expr {$m * $p}] } }
}

proc ::sf::gui::tools::snapValue {v} {
    variable snap
    if {!$snap} {
        # No finer than a tenth of a pixel: commands read {0.7 0.25}, not
        # {0.6998992950654581 0.25}.
        set digits [expr {max(0, -int(floor(log10([::sf::gui::view::pixelSize] / 10))))}]
        return [expr {double([format %.${digits}f $v])}]
    }
    set h [gridStep]
    # Lattice nodes sit at cell centres: snap to the cell corners, which is where
    # boxes and boundaries fall between nodes.
    set o 0.0
    if {![catch {lattice info} info]} { set o [lindex [dict get $info origin] 0] }
    tidy [expr {$o + round(($v - $o) / $h) * $h}]
}

proc ::sf::gui::tools::setOverlay {items} {
    set ::sf::gui::view::overlay $items
    ::sf::gui::view::redraw 1
}

proc ::sf::gui::tools::press {px py state} {
    variable tool
    variable drag
    variable vertices
    focus [set ::sf::gui::view::w]
    ::sf::gui::view::hold
    set p [point $px $py]
    switch $tool {
        pan { panStart $px $py; return }
        polygon {
            # A click near the first vertex closes the outline.
            if {[llength $vertices] >= 6} {
                lassign [::sf::gui::view::toPixel {*}[lrange $vertices 0 1]] fx fy
                if {hypot($fx - $px, $fy - $py) < 8} { closePolygon; return }
            }
            lappend vertices {*}$p
            showPolygon
            return
        }
        select {
            lassign [::sf::gui::view::toWorld $px $py] x y
            set id [::sf::gui::pick $x $y [expr {4 * [::sf::gui::view::pixelSize]}]]
            set add [expr {($state & 4) != 0}]   ;# Control adds to the selection
            if {$id ne "" && !$add} {
                if {$id ni $::sf::gui::selection} { ::sf::gui::select [list $id] }
                set drag [dict create kind move start $p now $p px $px py $py]
            } elseif {$id ne ""} {
                ::sf::gui::select [list $id] 1
            } else {
                set drag [dict create kind band start $p now $p px $px py $py add $add]
            }
            return
        }
    }
    set drag [dict create kind shape start $p now $p px $px py $py]
}

proc ::sf::gui::tools::motion {px py} {
    variable drag
    variable tool
    variable preview
    if {$drag eq {}} return
    if {[dict get $drag kind] eq "pan"} { panMotion $px $py; return }
    set p [point $px $py]
    dict set drag now $p
    lassign [dict get $drag start] x0 y0
    lassign $p x1 y1
    switch [dict get $drag kind] {
        band { setOverlay [list [list box #1f6feb $x0 $y0 $x1 $y1]] }
        move {
            # The selection's outlines follow the pointer until release.
            set dx [expr {$x1 - $x0}]
            set dy [expr {$y1 - $y0}]
            set items {}
            foreach item [::sf::gui::selectionOverlay] {
                set coords [lrange $item 2 end]
                if {[lindex $item 0] eq "circle"} {
                    lassign $coords cx cy r
                    lappend items [list circle $preview [expr {$cx + $dx}] [expr {$cy + $dy}] $r]
                } else {
                    set moved {}
                    foreach {x y} $coords { lappend moved [expr {$x + $dx}] [expr {$y + $dy}] }
                    lappend items [list line $preview {*}$moved]
                }
            }
            setOverlay $items
        }
        shape { setOverlay [shapeOverlay $tool $x0 $y0 $x1 $y1] }
    }
}

proc ::sf::gui::tools::release {px py state} {
    variable drag
    variable tool
    if {$drag eq {}} return
    set d $drag
    set drag {}
    if {[dict get $d kind] eq "pan"} return
    motion $px $py
    setOverlay {}
    lassign [dict get $d start] x0 y0
    lassign [point $px $py] x1 y1
    # A click without a drag (under 3 pixels) makes nothing.
    set moved [expr {hypot($px - [dict get $d px], $py - [dict get $d py]) >= 3}]
    switch [dict get $d kind] {
        band {
            if {!$moved} { if {![dict get $d add]} { ::sf::gui::select {} }; return }
            set ids [::sf::gui::within [expr {min($x0, $x1)}] [expr {min($y0, $y1)}] \
                         [expr {max($x0, $x1)}] [expr {max($y0, $y1)}]]
            ::sf::gui::select $ids [dict get $d add]
        }
        move {
            if {$moved} {
                catch {::sf::gui::moveSelection [expr {$x1 - $x0}] [expr {$y1 - $y0}]}
            }
        }
        shape {
            # A refused command has said why (::sf::gui::do), and so has make.
            if {$moved} { catch {make $tool $x0 $y0 $x1 $y1} }
        }
    }
}

proc ::sf::gui::tools::panStart {px py} {
    variable drag [dict create kind pan px $px py $py]
}

proc ::sf::gui::tools::panMotion {px py} {
    variable drag
    if {$drag eq {} || [dict get $drag kind] ne "pan"} return
    ::sf::gui::view::pan [expr {$px - [dict get $drag px]}] [expr {$py - [dict get $drag py]}]
    dict set drag px $px
    dict set drag py $py
}

# The pointer's world position in the status bar.
proc ::sf::gui::tools::hover {px py} {
    lassign [::sf::gui::view::toWorld $px $py] x y
    set ::sf::gui::pointer [format "x %.4g  y %.4g" $x $y]
}

proc ::sf::gui::tools::cancel {} {
    variable drag {}
    variable vertices {}
    setOverlay {}
}

# The outline a drag would make, for the preview.
proc ::sf::gui::tools::shapeOverlay {tool x0 y0 x1 y1} {
    variable preview
    switch $tool {
        wall { return [list [list line $preview $x0 $y0 $x1 $y1]] }
        disc - circle {
            lassign [inscribed $x0 $y0 $x1 $y1] cx cy r
            return [list [list circle $preview $cx $cy $r] [list box #adb5bd $x0 $y0 $x1 $y1]]
        }
        ellipse - superquadric {
            set cx [expr {0.5 * ($x0 + $x1)}]
            set cy [expr {0.5 * ($y0 + $y1)}]
            set a [expr {0.5 * abs($x1 - $x0)}]
            set b [expr {0.5 * abs($y1 - $y0)}]
            # |x/a|^m + |y/b|^n = 1 as the kernel samples it; an ellipse is m = n = 2.
            lassign {2.0 2.0} m n
            if {$tool eq "superquadric"} { lassign [previewExponents] m n }
            set pts {}
            for {set k 0} {$k < 96} {incr k} {
                set t [expr {6.283185307179586 * $k / 96}]
                set c [expr {cos($t)}]
                set s [expr {sin($t)}]
                lappend pts [expr {$cx + $a * ($c < 0 ? -1 : 1) * abs($c) ** (2.0 / $m)}] \
                    [expr {$cy + $b * ($s < 0 ? -1 : 1) * abs($s) ** (2.0 / $n)}]
            }
            return [list [list closed $preview {*}$pts] [list box #adb5bd $x0 $y0 $x1 $y1]]
        }
        lattice {
            # The lattice the drag makes, its height in whole cells, over the drag.
            if {[catch {latticeBox $x0 $y0 $x1 $y1} box]} {
                return [list [list box #adb5bd $x0 $y0 $x1 $y1]]
            }
            lassign $box lo lx ly
            lassign $lo ox oy
            return [list [list box #adb5bd $x0 $y0 $x1 $y1] \
                        [list box $preview $ox $oy [expr {$ox + $lx}] [expr {$oy + $ly}]]]
        }
        default { return [list [list box $preview $x0 $y0 $x1 $y1]] }
    }
}

# The superquadric's exponents {m n} for the preview: those typed when they
# are two numbers of 1 to 100 (what `superquadric create` takes), else an
# ellipse's (the command will say what is wrong with them).
proc ::sf::gui::tools::previewExponents {} {
    variable exponents
    if {[string is list $exponents] && [llength $exponents] == 2 &&
        [string is double -strict [lindex $exponents 0]] &&
        [string is double -strict [lindex $exponents 1]] &&
        [tcl::mathfunc::min {*}$exponents] >= 1 && [tcl::mathfunc::max {*}$exponents] <= 100} {
        return $exponents
    }
    return {2.0 2.0}
}

# The lattice a box dragged from (x0, y0) to (x1, y1) makes: {origin width
# height} with `cells` across and the height rounded to whole cells (at least
# one), written so that `lattice create` finds it a whole number of spacings.
proc ::sf::gui::tools::latticeBox {x0 y0 x1 y1} {
    variable cells
    if {![string is integer -strict $cells] || $cells < 1} {
        return -code error "Cells must be a whole number of 1 or more, got \"$cells\""
    }
    set lx [tidy [expr {abs($x1 - $x0)}]]
    if {$lx <= 0 || $y1 == $y0} {
        return -code error "a lattice needs a box: drag across and up or down"
    }
    set h [expr {$lx / $cells}]
    set ny [expr {max(1, round(abs($y1 - $y0) / $h))}]
    list [list [expr {min($x0, $x1)}] [expr {min($y0, $y1)}]] $lx \
        [expr {double([format %.12g [expr {$ny * $h}]])}]
}

# The circle that fills a box's shorter side, centred in it.
proc ::sf::gui::tools::inscribed {x0 y0 x1 y1} {
    set r [expr {0.5 * min(abs($x1 - $x0), abs($y1 - $y0))}]
    lmap c [list [expr {0.5 * ($x0 + $x1)}] [expr {0.5 * ($y0 + $y1)}] $r] {tidy $c}
}

# A value derived from points (a centre, a radius) at the points' precision.
proc ::sf::gui::tools::tidy {v} {
    set step [expr {[::sf::gui::view::pixelSize] / 10}]
    if {$::sf::gui::tools::snap} { set step [expr {[gridStep] / 10}] }
    set digits [expr {max(0, -int(floor(log10($step))))}]
    expr {double([format %.${digits}f $v])}
}

# The command a finished drag makes, run through ::sf::gui::do.
proc ::sf::gui::tools::make {tool x0 y0 x1 y1} {
    variable material
    variable cells
    variable viscosity
    variable forcing
    variable exponents
    set lo [list [expr {min($x0, $x1)}] [expr {min($y0, $y1)}]]
    set hi [list [expr {max($x0, $x1)}] [expr {max($y0, $y1)}]]
    lassign $lo bx0 by0
    lassign $hi bx1 by1
    set mat [expr {$material eq "" || $material eq "default" ? {} : [list -material $material]}]
    if {$tool in {rect circle} && [catch {lattice cget -cells}]} {
        ::sf::gui::showError [noLattice]
        return -code error [noLattice]
    }
    switch $tool {
        lattice {
            if {![catch {lattice cget -cells}]} {
                set message "there is a lattice already: delete it first (lattice delete)"
            } elseif {[catch {latticeBox $x0 $y0 $x1 $y1} box]} {
                set message $box
            }
            if {[info exists message]} {
                ::sf::gui::showError "Lattice: $message"
                return -code error $message
            }
            lassign $box lo lx ly
            set cmd [list lattice create -origin $lo -size [list $lx $ly] -cells $cells \
                         -viscosity $viscosity]
            # No -forcing for none (blank, or two zeros); anything else for the command to judge.
            set zero [expr {[string is list $forcing] && [llength $forcing] == 2
                            && [string is double -strict [lindex $forcing 0]]
                            && [string is double -strict [lindex $forcing 1]]
                            && [lindex $forcing 0] == 0 && [lindex $forcing 1] == 0}]
            if {!$zero && [string trim $forcing] ne ""} { lappend cmd -forcing $forcing }
            ::sf::gui::do $cmd {lattice delete} "lattice"
        }
        rect {
            set id [nextObstacle]
            ::sf::gui::do [list lattice obstacle rect [list $bx0 $by0 $bx1 $by1] -id $id] \
                [list lattice obstacle delete $id] "obstacle $id"
        }
        circle {
            set id [nextObstacle]
            ::sf::gui::do [list lattice obstacle circle [inscribed $x0 $y0 $x1 $y1] -id $id] \
                [list lattice obstacle delete $id] "obstacle $id"
        }
        disc {
            lassign [inscribed $x0 $y0 $x1 $y1] cx cy r
            set id [element next]
            ::sf::gui::do [list disc create -id $id -center [list $cx $cy] -radius $r {*}$mat] \
                [list element delete $id] "disc $id"
        }
        ellipse - superquadric {
            set id [element next]
            set c [list [tidy [expr {0.5 * ($bx0 + $bx1)}]] [tidy [expr {0.5 * ($by0 + $by1)}]]]
            set axes [list [tidy [expr {0.5 * ($bx1 - $bx0)}]] [tidy [expr {0.5 * ($by1 - $by0)}]]]
            set extra [expr {$tool eq "superquadric" ? [list -exponents $exponents] : {}}]
            ::sf::gui::do [list $tool create -id $id -center $c -axes $axes {*}$extra {*}$mat] \
                [list element delete $id] "$tool $id"
        }
        wall {
            set id [element next]
            ::sf::gui::do [list wall create -id $id -from [list $x0 $y0] -to [list $x1 $y1] {*}$mat] \
                [list element delete $id] "wall $id"
        }
    }
}

proc ::sf::gui::tools::nextObstacle {} {
    set ids [lattice obstacles]
    expr {[llength $ids] ? [tcl::mathfunc::max {*}$ids] + 1 : 1}
}

proc ::sf::gui::tools::showPolygon {} {
    variable vertices
    variable preview
    set items [list [list line $preview {*}$vertices]]
    foreach {x y} $vertices {
        lappend items [list circle $preview $x $y [expr {3 * [::sf::gui::view::pixelSize]}]]
    }
    setOverlay $items
}

# A second click soon after the first: it closes a polygon, and is a plain
# press for every other tool (a quick click then drag must still drag).
proc ::sf::gui::tools::double {px py state} {
    variable tool
    if {$tool eq "polygon"} { closePolygon } else { press $px $py $state }
}

proc ::sf::gui::tools::closePolygon {} {
    variable vertices
    variable material
    variable tool
    if {$tool ne "polygon" || [llength $vertices] < 6} return
    set v $vertices
    set vertices {}
    setOverlay {}
    set mat [expr {$material eq "" || $material eq "default" ? {} : [list -material $material]}]
    set id [element next]
    catch {::sf::gui::do [list polygon create -id $id -vertices $v {*}$mat] \
               [list element delete $id] "polygon $id"}
}

# Right click: what can be done to the element under the pointer (selected
# first) or to the selection.
proc ::sf::gui::tools::contextMenu {px py X Y} {
    lassign [::sf::gui::view::toWorld $px $py] x y
    set id [::sf::gui::pick $x $y [expr {4 * [::sf::gui::view::pixelSize]}]]
    if {$id ne "" && $id ni $::sf::gui::selection} { ::sf::gui::select [list $id] }
    set m .contextmenu
    destroy $m
    menu $m -tearoff 0
    set n [llength $::sf::gui::selection]
    set state [expr {$n ? "normal" : "disabled"}]
    $m add command -label "Fix all degrees of freedom" -state $state \
        -command {::sf::gui::configureSelection -fix {x y rot}}
    $m add command -label "Fix position only" -state $state \
        -command {::sf::gui::configureSelection -fix {x y}}
    $m add command -label "Free" -state $state -command {::sf::gui::configureSelection -fix {}}
    $m add separator
    $m add command -label "Set velocity..." -state $state \
        -command {::sf::gui::tools::askVector -velocity "Velocity {vx vy w}"}
    $m add command -label "Set force..." -state $state \
        -command {::sf::gui::tools::askVector -force "Applied force {Fx Fy T}"}
    $m add command -label "Rotate 15\u00b0" -state $state -command {::sf::gui::rotateSelection 0.2617993877991494}
    $m add command -label "Rotate -15\u00b0" -state $state -command {::sf::gui::rotateSelection -0.2617993877991494}
    $m add separator
    $m add command -label "Make source" -state [expr {$n == 1 ? "normal" : "disabled"}] \
        -command ::sf::gui::sourceSelection
    $m add command -label "Bond selection" -state [expr {$n >= 2 ? "normal" : "disabled"}] \
        -command ::sf::gui::bondSelection
    $m add separator
    $m add command -label "Delete" -state $state -command ::sf::gui::deleteSelection
    tk_popup $m $X $Y
}

# Asks for a vector and sets it on the selection; the property panel does the
# same per element.
proc ::sf::gui::tools::askVector {option prompt} {
    set id [lindex $::sf::gui::selection 0]
    set now [element cget $id $option]
    set value [::sf::gui::askString "Set $option" $prompt $now]
    if {$value eq ""} return
    catch {::sf::gui::configureSelection $option $value}
}
