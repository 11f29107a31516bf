# The simulation view: a Togl widget drawing the same draw list as `snapshot`
# (::sf::gui::draw into Togl's GLX context), or, where no GLX visual is to be
# had (plain X forwarding), the same picture drawn off-screen into a Tk photo.
# It owns the world window (pan, zoom, zoom to fit) and the mapping between
# pixels and world coordinates that the drawing tools use. The world fills the
# whole widget (::sf::gui::draw widens the window to the widget's shape; the
# scene, when fitted, goes where the time and the colour keys leave room).
#
# The window moves only when the user moves it: the wheel, pan, `f`, a typed
# `view configure -region`. Fitted (`f`, New, at start), it follows the scene
# only until a frame shows something or the user presses on the view; from
# then on it stays, so that what is drawn next does not rescale it.

namespace eval ::sf::gui::view {
    variable w ""            ;# the widget: a togl, or a label showing the photo
    variable mode ""         ;# togl | photo
    variable why ""          ;# why the photo fallback is in use
    variable region {}       ;# the world window; {} follows `view cget -region`, else the scene
    variable typed {}        ;# the last `view cget -region` seen (a new one moves the view)
    variable show            ;# View menu: -grid -axes -scalebar, as `view cget` has them
    array set show {-grid 0 -axes 0 -scalebar 0}
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
        bind $path <Configure> {::sf::gui::view::resized}
    }
    set w $path
    $path configure -cursor crosshair
    variable typed [view cget -region]
    return $path
}

# The View menu's guides (main.tcl calls this while it builds the menu): each
# a `view configure` through ::sf::gui::viewSet, echoed and undoable.
proc ::sf::gui::view::menuEntries {m} {
    foreach {label option} {Grid -grid Axes -axes "Scale bar" -scalebar} {
        $m add checkbutton -label $label -variable ::sf::gui::view::show($option) \
            -command [list ::sf::gui::view::toggle $option]
    }
}

proc ::sf::gui::view::toggle {option} {
    variable show
    ::sf::gui::viewSet $option $show($option)
}

# The menu's ticks follow `view configure`, however it was set.
proc ::sf::gui::view::syncMenu {} {
    variable show
    foreach option [array names show] {
        if {![catch {view cget $option} on]} { set show($option) $on }
    }
}

proc ::sf::gui::view::glCreated {togl} {}
proc ::sf::gui::view::glReshape {togl} { resized }

# The widget resized (the window, a pane's sash, a scrollbar shown beside the
# properties): a window held keeps its scale and its top-left corner, so
# that the scene stays where it is on the screen; only the room at the right
# and the bottom changes. A fitted view fits again.
proc ::sf::gui::view::resized {} {
    variable region
    variable geometry
    variable w
    if {$region ne {} && $geometry ne {}} {
        set s [dict get $geometry scale]
        lassign [toWorld 0 0] x0 y1
        set x1 [expr {$x0 + [winfo width $w] / $s}]
        set y0 [expr {$y1 - [winfo height $w] / $s}]
        set region [list $x0 $y0 $x1 $y1]
        moved
        return
    }
    redraw
}
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
    variable typed
    if {$w eq "" || ![winfo exists $w]} return
    set width [winfo width $w]
    set height [winfo height $w]
    if {$width < 2 || $height < 2} return
    adoptTyped
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
    # Following the scene: the first frame that shows something is where the
    # view stays (all of the widget's window: the same picture from then on).
    if {$region eq {} && $typed eq {} && [sceneShown]} { set region [shown] }
    syncMenu
}

proc ::sf::gui::view::sceneShown {} {
    expr {[llength [element ids]] > 0 || ![catch {lattice cget -cells}]}
}

# A window set with `view configure -region` (typed, or by a script) is where
# the view goes (the view follows it: ::sf::gui::draw's {} is that -region);
# `view configure -region {}` fits the scene again.
proc ::sf::gui::view::adoptTyped {} {
    variable typed
    variable region
    if {[catch {view cget -region} now] || $now eq $typed} return
    set typed $now
    set region {}
}

# Keeps the window shown now: called as the user starts a gesture on the view,
# so that what the gesture makes does not move it.
proc ::sf::gui::view::hold {} {
    variable region
    variable typed
    if {$region eq {} && $typed eq {}} { set region [shown] }
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

# The world window now shown, all of the widget: {x0 y0 x1 y1}.
proc ::sf::gui::view::shown {} {
    variable region
    variable geometry
    variable w
    if {$geometry eq {}} { return [expr {$region ne {} ? $region : [::sf::gui::region]}] }
    lassign [toWorld 0 [winfo height $w]] x0 y0
    lassign [toWorld [winfo width $w] 0] x1 y1
    list $x0 $y0 $x1 $y1
}

# Zoom by `factor` (> 1 in) keeping the world point under pixel (px, py)
# fixed, within a factor of 1e6 of the scene's size either way.
proc ::sf::gui::view::zoom {factor px py} {
    variable region
    lassign [shown] x0 y0 x1 y1
    lassign [toWorld $px $py] cx cy
    set f [expr {1.0 / $factor}]
    lassign [::sf::gui::region] fx0 fy0 fx1 fy1
    set across [expr {($x1 - $x0) * $f / max($fx1 - $fx0, $fy1 - $fy0)}]
    if {$across < 1e-6 || $across > 1e6} {
        ::sf::gui::status "the view goes no [expr {$across < 1 ? "closer" : "further"}]:\
            its window stays within a factor of 1e6 of the scene's size (f fits it)" error
        return
    }
    set region [list [expr {$cx + ($x0 - $cx) * $f}] [expr {$cy + ($y0 - $cy) * $f}] \
                    [expr {$cx + ($x1 - $cx) * $f}] [expr {$cy + ($y1 - $cy) * $f}]]
    moved
}

# Pan by a pixel offset (the scene follows the pointer).
proc ::sf::gui::view::pan {dx dy} {
    variable region
    set s [expr {1.0 / [pixelSize]}]
    lassign [shown] x0 y0 x1 y1
    set ddx [expr {-$dx / $s}]
    set ddy [expr {$dy / $s}]
    set region [list [expr {$x0 + $ddx}] [expr {$y0 + $ddy}] [expr {$x1 + $ddx}] [expr {$y1 + $ddy}]]
    moved
}

# After a zoom or pan: the mapping is the new window's at once (the next
# frame draws exactly it), so that gestures before that frame build on it.
proc ::sf::gui::view::moved {} {
    variable region
    variable geometry
    variable w
    if {$geometry ne {}} {
        lassign $region x0 y0 x1 y1
        set height [winfo height $w]
        set geometry [dict create world [list $x0 $y0] pixel [list 0.0 $height] \
                          scale [expr {[winfo width $w] / ($x1 - $x0)}]]
    }
    redraw
}

# Zoom to fit: the scene (its lattice, else its elements, else the unit
# square), followed until it shows something.
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
