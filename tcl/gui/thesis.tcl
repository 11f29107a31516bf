# The thesis's command language in the workbench (docs/thesis-compat.md): its
# TIMESTEPS and GRAPHICSFRAMES set the Run button's steps and the redraw rate,
# setscales and LBSHOW* the view, and printLB opens a window. These replace
# the headless show* procedures of tcl/compat/thesis.tcl.

if {![namespace exists ::sf::thesis]} return

proc ::sf::thesis::showRun {} {
    if {[info exists ::TIMESTEPS]} { set ::sf::gui::runbar::steps $::TIMESTEPS }
    if {[info exists ::GRAPHICSFRAMES]} { set ::sf::gui::runbar::stepsPerFrame $::GRAPHICSFRAMES }
}

# The view draws with `view configure`'s options; fitted, it shows its -region.
proc ::sf::thesis::showView {{fit 0}} {
    ::sf::gui::syncViewMenu
    if {$fit} { ::sf::gui::view::fit } else { ::sf::gui::view::redraw }
}

proc ::sf::thesis::showText {title text} {
    set t .thesisText
    if {![winfo exists $t]} {
        toplevel $t
        text $t.text -wrap none -width 60 -height 20 -font TkFixedFont -padx 8 -pady 8
        ttk::button $t.close -text Close -command [list destroy $t]
        pack $t.close -side bottom -anchor e -padx 6 -pady 6
        pack $t.text -fill both -expand 1
        bind $t <Escape> [list destroy $t]
    }
    wm title $t $title
    $t.text configure -state normal
    $t.text delete 1.0 end
    $t.text insert end $text
    $t.text configure -state disabled
    raise $t
}

# Values set before the window was up (a script sourced at start).
::sf::thesis::showRun
