# The simulation view: a Togl widget drawing the same draw list as `snapshot`
# (::sf::gui::draw into Togl's GLX context), or, where no GLX visual is to be
# had (plain X forwarding), the same picture drawn off-screen into a Tk photo.
# It owns the world window (pan, zoom, zoom to fit) and the mapping between
# pixels and world coordinates that the drawing tools use.

namespace eval ::sf::gui::view {
    variable w ""            ;# the widget: a togl, or a label showing the photo
    variable mode ""         ;# togl | photo
    variable why ""          ;# why the photo fallback is in use
    variable region {}       ;# the world window; {} follows the scene (zoom to fit)
    variable geometry {}     ;# last frame: dict world {x y} pixel {px py} scale s
    variable overlay {}      ;# rubber bands, shapes being drawn, the selection
    variable pending 0       ;# a redraw is scheduled
    variable frames 0        ;# frames drawn (for the frame rate)
    variable lastError ""
}

# Creates the view in `parent` and returns its widget. SANDFLOW_VIEW=photo
# forces the fallback (tests, and users whose GLX is broken).
proc ::sf::gui::view::create {path} {
    variable w
    variable mode
    variable why
    set forced [expr {[info exists ::env(SANDFLOW_VIEW)] && $::env(SANDFLOW_VIEW) eq "photo"}]
    set mode photo
    if {$forced} {
        set why "SANDFLOW_VIEW=photo"
    } elseif {[catch {package require Togl 2.0} err]} {
        set why "no Togl: $err"
    } elseif {[catch {togl $path -width 800 -height 560 -rgba 1 -double 1 \
                         -createcommand ::sf::gui::view::glCreated \
                         -displaycommand ::sf::gui::view::glDisplay \
                         -reshapecommand ::sf::gui::view::glReshape} err]} {
        set why "no OpenGL visual: $err"
        catch {destroy $path}
    } else {
        set mode togl
    }
    if {$mode eq "photo"} {
        image create photo ::sf::gui::view::photo -width 800 -height 560
        label $path -image ::sf::gui::view::photo -borderwidth 0 -background #f0f0f0 \
            -width 800 -height 560
        bind $path <Configure> {::sf::gui::view::redraw}
    }
    set w $path
    $path configure -cursor crosshair
    return $path
}

proc ::sf::gui::view::glCreated {togl} {}
proc ::sf::gui::view::glReshape {togl} { redraw }
proc ::sf::gui::view::glDisplay {togl} { draw 0 }

# Schedules one redraw when the application is idle (many changes, one frame).
proc ::sf::gui::view::redraw {{overlayOnly 0}} {
    variable pending
    variable w
    if {$w eq ""} return
    if {$pending} {
        # A full redraw already queued covers an overlay one.
        if {!$overlayOnly} { set pending 2 }
        return
    }
    set pending [expr {$overlayOnly ? 1 : 2}]
    after idle ::sf::gui::view::flush
}

proc ::sf::gui::view::flush {} {
    variable pending
    set reuse [expr {$pending == 1}]
    set pending 0
    draw $reuse
}

# Draws one frame now. With `reuse`, only the overlay changed since the last.
proc ::sf::gui::view::draw {{reuse 0}} {
    variable w
    variable mode
    variable region
    variable geometry
    variable overlay
    variable frames
    variable lastError
    if {$w eq "" || ![winfo exists $w]} return
    set width [winfo width $w]
    set height [winfo height $w]
    if {$width < 2 || $height < 2} return
    set items [concat $overlay [::sf::gui::selectionOverlay]]
    if {$mode eq "togl"} {
        $w makecurrent
        set code [catch {::sf::gui::draw $width $height $region $items $reuse} result]
        if {!$code} { $w swapbuffers }
    } else {
        set code [catch {::sf::gui::picture $width $height $region $items} result]
        if {!$code} {
            ::sf::gui::view::photo configure -width $width -height $height
            ::sf::gui::view::photo put [lindex $result 0] -format ppm
            set result [lindex $result 1]
        }
    }
    if {$code} {
        # A world window that no longer shows the scene (it was deleted or
        # moved away): show the whole scene again.
        if {$region ne {} && [string match "*-region*" $result]} {
            set region {}
            return [draw 0]
        }
        if {$result ne $lastError} { ::sf::gui::status "view: $result" error }
        set lastError $result
        return
    }
    set lastError ""
    set geometry $result
    incr frames
}

# Pixel (Tk, origin top-left) -> world {x y}, and back.
proc ::sf::gui::view::toWorld {px py} {
    variable geometry
    if {$geometry eq {}} { return [list 0.0 0.0] }
    lassign [dict get $geometry world] wx wy
    lassign [dict get $geometry pixel] ox oy
    set s [dict get $geometry scale]
    list [expr {$wx + ($px - $ox) / $s}] [expr {$wy + ($oy - $py) / $s}]
}

proc ::sf::gui::view::toPixel {x y} {
    variable geometry
    lassign [dict get $geometry world] wx wy
    lassign [dict get $geometry pixel] ox oy
    set s [dict get $geometry scale]
    list [expr {$ox + ($x - $wx) * $s}] [expr {$oy - ($y - $wy) * $s}]
}

# World length of one pixel (pick tolerances, snapping).
proc ::sf::gui::view::pixelSize {} {
    variable geometry
    if {$geometry eq {}} { return 1.0 }
    expr {1.0 / [dict get $geometry scale]}
}

# The world window now shown (the automatic one when following the scene).
proc ::sf::gui::view::shown {} {
    variable region
    if {$region ne {}} { return $region }
    ::sf::gui::region
}

# Zoom by `factor` (> 1 in) keeping the world point under pixel (px, py)
# fixed: the window keeps its aspect, so its place in the widget does not move.
proc ::sf::gui::view::zoom {factor px py} {
    variable region
    lassign [shown] x0 y0 x1 y1
    lassign [toWorld $px $py] cx cy
    set f [expr {1.0 / $factor}]
    set region [list [expr {$cx + ($x0 - $cx) * $f}] [expr {$cy + ($y0 - $cy) * $f}] \
                    [expr {$cx + ($x1 - $cx) * $f}] [expr {$cy + ($y1 - $cy) * $f}]]
    redraw
}

# Pan by a pixel offset (the scene follows the pointer).
proc ::sf::gui::view::pan {dx dy} {
    variable region
    set s [expr {1.0 / [pixelSize]}]
    lassign [shown] x0 y0 x1 y1
    set ddx [expr {-$dx / $s}]
    set ddy [expr {$dy / $s}]
    set region [list [expr {$x0 + $ddx}] [expr {$y0 + $ddy}] [expr {$x1 + $ddx}] [expr {$y1 + $ddy}]]
    redraw
}

proc ::sf::gui::view::fit {} {
    variable region {}
    redraw
}

# What the status bar says about how the view draws.
proc ::sf::gui::view::describe {} {
    variable mode
    variable why
    if {$mode eq "togl"} { return "OpenGL view (Togl)" }
    return "off-screen view ($why)"
}
