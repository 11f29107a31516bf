# The workbench: `sandflow -gui ?script.tcl? ?arg ...?`. One window: the tool
# palette (left), the view (middle) over the console and the live plot, the
# property panel (right), run controls above and the status bar below. Every
# gesture runs a command a user could type; see docs/gui.md.

# Tk reads its own options (-geometry, -display, -help, ...) from argv as it
# loads, which would take a script's -g or -help: it sees none of them.
set ::sf::scriptArgv $::argv
set ::argv {}
package require Tk 8.6
set ::argv $::sf::scriptArgv
unset ::sf::scriptArgv
catch {package require tooltip}

namespace eval ::sf::gui {
    variable W                 ;# the main widgets by role
    array set W {}
    variable message ""        ;# the status bar's message
    variable messageAt 0       ;# commands started when it was given
    variable messageLife 6000  ;# milliseconds a message stays at most
    variable messageTimer ""
    variable pointer ""        ;# the pointer's world position
    variable scriptDir [pwd]   ;# where the file dialogs start
}

foreach part {actions view tools runbar props plots console scene_script thesis} {
    if {[file exists [file join $::sf::gui::library $part.tcl]]} {
        source [file join $::sf::gui::library $part.tcl]
    }
}

# A tooltip where tklib has one.
proc ::sf::gui::tip {w text} {
    if {[llength [info commands ::tooltip::tooltip]]} { ::tooltip::tooltip $w $text }
}

# A message in the status bar (errors in red): it stays until a command
# started after it succeeds, or for messageLife milliseconds.
proc ::sf::gui::status {text {kind info}} {
    variable message
    variable messageAt
    variable messageLife
    variable messageTimer
    variable started
    variable W
    set message $text
    set messageAt $started
    after cancel $messageTimer
    if {$text ne ""} { set messageTimer [after $messageLife [list ::sf::gui::status ""]] }
    if {[info exists W(status)] && [winfo exists $W(status).message]} {
        $W(status).message configure -foreground [expr {$kind eq "error" ? "#c92a2a" : "#555555"}]
    }
}

# A one-line question; "" when cancelled.
proc ::sf::gui::askString {title prompt initial} {
    set d .ask
    destroy $d
    toplevel $d -padx 10 -pady 10
    wm title $d $title
    wm transient $d .
    ttk::label $d.l -text $prompt
    ttk::entry $d.e -width 30
    $d.e insert 0 $initial
    ttk::frame $d.b
    ttk::button $d.b.ok -text OK -command {set ::sf::gui::answer [.ask.e get]; destroy .ask}
    ttk::button $d.b.cancel -text Cancel -command {set ::sf::gui::answer ""; destroy .ask}
    pack $d.l -anchor w
    pack $d.e -fill x -pady 6
    pack $d.b.cancel $d.b.ok -side right -padx 2
    pack $d.b -fill x
    bind $d <Return> {$::sf::gui::askOk invoke}
    set ::sf::gui::askOk $d.b.ok
    bind $d <Escape> {$::sf::gui::askCancel invoke}
    set ::sf::gui::askCancel $d.b.cancel
    set ::sf::gui::answer ""
    focus $d.e
    $d.e selection range 0 end
    tkwait window $d
    return $::sf::gui::answer
}

proc ::sf::gui::style {} {
    ttk::style theme use clam
    ttk::style configure . -font TkDefaultFont
    ttk::style configure Heading.TLabel -font TkHeadingFont
    ttk::style configure Toolbutton -anchor w -padding {6 3}
    ttk::style map TEntry -fieldbackground {invalid #fff0f0}
    catch {font configure TkHeadingFont -weight bold}
    option add *Menu.tearOff 0
}

proc ::sf::gui::menus {} {
    set m .menu
    menu $m
    . configure -menu $m
    menu $m.file
    $m add cascade -label File -underline 0 -menu $m.file
    $m.file add command -label "New" -accelerator Ctrl+N -command ::sf::gui::runbar::resetPressed
    $m.file add command -label "Open script\u2026" -accelerator Ctrl+O -command ::sf::gui::openScript
    $m.file add command -label "Save scene as script\u2026" -accelerator Ctrl+S \
        -command ::sf::gui::saveScript
    $m.file add command -label "Open checkpoint\u2026" -command ::sf::gui::openCheckpoint
    $m.file add command -label "Save checkpoint\u2026" -command ::sf::gui::saveCheckpoint
    $m.file add separator
    $m.file add command -label "Export snapshot\u2026" -command ::sf::gui::exportSnapshot
    $m.file add command -label "Export VTK\u2026" -command ::sf::gui::exportVtk
    $m.file add command -label "Record movie\u2026" -command ::sf::gui::exportMovie
    $m.file add command -label "Record VTK series\u2026" -command ::sf::gui::exportVtkSeries
    $m.file add command -label "Stop recordings" -command {catch {::sf::gui::do {output close}}}
    $m.file add separator
    $m.file add command -label "Quit" -accelerator Ctrl+Q -command ::sf::gui::quit

    menu $m.edit
    $m add cascade -label Edit -underline 0 -menu $m.edit
    $m.edit add command -label Undo -accelerator Ctrl+Z -command ::sf::gui::undo
    $m.edit add command -label Redo -accelerator Ctrl+Y -command ::sf::gui::redo
    $m.edit add separator
    $m.edit add command -label Delete -accelerator Del -command ::sf::gui::deleteSelection
    $m.edit add command -label "Select all" -accelerator Ctrl+A -command ::sf::gui::selectAll
    $m.edit add command -label "Bond selection" -accelerator Ctrl+B -command ::sf::gui::bondSelection

    menu $m.view
    $m add cascade -label View -underline 0 -menu $m.view
    menu $m.view.field
    foreach field {none nodes solid density pressure velocity vorticity} {
        $m.view.field add radiobutton -label $field -value $field \
            -variable ::sf::gui::viewField -command {::sf::gui::viewSet -field $::sf::gui::viewField}
    }
    $m.view add cascade -label Field -menu $m.view.field
    $m.view add checkbutton -label "Velocity arrows" -variable ::sf::gui::viewVectors \
        -command {::sf::gui::viewSet -vectors $::sf::gui::viewVectors}
    $m.view add checkbutton -label "Streamlines" -variable ::sf::gui::viewStreamlines \
        -command {::sf::gui::viewSet -streamlines $::sf::gui::viewStreamlines}
    $m.view add checkbutton -label "Contact forces" -variable ::sf::gui::viewForces \
        -command {::sf::gui::viewSet -forces $::sf::gui::viewForces}
    $m.view add command -label "Colour range\u2026" -command ::sf::gui::askRange
    view::menuEntries $m.view
    $m.view add separator
    $m.view add command -label "Zoom to fit" -accelerator F -command ::sf::gui::view::fit
    $m.view add command -label "Zoom in" -accelerator + -command {::sf::gui::zoomCentre 1.25}
    $m.view add command -label "Zoom out" -accelerator - -command {::sf::gui::zoomCentre 0.8}

    menu $m.run
    $m add cascade -label Run -underline 0 -menu $m.run
    $m.run add command -label Run -accelerator F5 -command ::sf::gui::runbar::runPressed
    $m.run add command -label Pause -accelerator Esc -command ::sf::gui::runbar::pausePressed
    $m.run add command -label Step -accelerator F7 -command ::sf::gui::runbar::stepPressed
    $m.run add command -label Reset -command ::sf::gui::runbar::resetPressed

    menu $m.help
    $m add cascade -label Help -underline 0 -menu $m.help
    $m.help add command -label "Command reference" -command ::sf::gui::showReference
    $m.help add command -label "About sandflow" -command ::sf::gui::about
}

# Keys for the frequent actions; those without a modifier only on the view, so
# that typing at the console is not taken for them.
proc ::sf::gui::keys {} {
    variable W
    bind . <Control-z> ::sf::gui::undo
    bind . <Control-y> ::sf::gui::redo
    bind . <Control-Z> ::sf::gui::redo
    bind . <Control-o> ::sf::gui::openScript
    bind . <Control-s> ::sf::gui::saveScript
    bind . <Control-n> ::sf::gui::runbar::resetPressed
    bind . <Control-q> ::sf::gui::quit
    bind . <Control-b> ::sf::gui::bondSelection
    bind . <F5> ::sf::gui::runbar::runPressed
    bind . <F6> ::sf::gui::runbar::pausePressed
    bind . <F7> ::sf::gui::runbar::stepPressed
    bind all <Escape> {+::sf::gui::runbar::pausePressed}
    set v $W(view)
    bind $v <Delete> ::sf::gui::deleteSelection
    bind $v <BackSpace> ::sf::gui::deleteSelection
    bind $v <Control-a> ::sf::gui::selectAll
    bind $v <Key-f> ::sf::gui::view::fit
    bind $v <Key-plus> {::sf::gui::zoomCentre 1.25}
    bind $v <Key-equal> {::sf::gui::zoomCentre 1.25}
    bind $v <Key-minus> {::sf::gui::zoomCentre 0.8}
    bind $v <Key-bracketleft> {::sf::gui::rotateSelection 0.08726646259971647}
    bind $v <Key-bracketright> {::sf::gui::rotateSelection -0.08726646259971647}
    foreach {name label key help} $::sf::gui::tools::palette {
        bind $v <Key-$key> [list ::sf::gui::tools::choose $name]
    }
}

proc ::sf::gui::zoomCentre {factor} {
    set v $::sf::gui::W(view)
    view::zoom $factor [expr {[winfo width $v] / 2}] [expr {[winfo height $v] / 2}]
}

# The View menu's settings are `view configure`, like a typed one.
proc ::sf::gui::viewSet {option value} {
    catch {do [list view configure $option $value] [list view configure $option [view cget $option]] "view $option"}
    syncViewMenu
}

proc ::sf::gui::syncViewMenu {} {
    set field [view cget -field]
    set ::sf::gui::viewField [expr {$field eq {} ? "velocity" : $field}]
    set ::sf::gui::viewVectors [view cget -vectors]
    set ::sf::gui::viewStreamlines [view cget -streamlines]
    set ::sf::gui::viewForces [view cget -forces]
}

proc ::sf::gui::askRange {} {
    set now [view cget -range]
    set value [askString "Colour range" "Range {lo hi} of the field's colours ({} automatic)" $now]
    if {$value eq "" && $now eq ""} return
    viewSet -range $value
}

# A pane whose content (made by `make PATH`) scrolls up and down, with a
# scrollbar while the window is too short for it (the wheel scrolls it too)
# -> the content's path.
proc ::sf::gui::scrollPane {path make} {
    ttk::frame $path
    canvas $path.c -highlightthickness 0 -borderwidth 0 \
        -background [ttk::style lookup TFrame -background] \
        -yscrollcommand [list ::sf::gui::scrollShown $path]
    ttk::scrollbar $path.sb -orient vertical -command [list $path.c yview]
    set inner [{*}$make $path.c.in]
    $path.c create window 0 0 -window $inner -anchor nw -tags inner
    grid $path.c $path.sb -sticky ns
    grid configure $path.c -sticky nsew
    grid columnconfigure $path 0 -weight 1
    grid rowconfigure $path 0 -weight 1
    grid remove $path.sb
    ::bind $inner <Configure> [list ::sf::gui::scrollFit $path]
    # Its width with or without the scrollbar: the panes are fitted again.
    ::bind $path <Configure> {after idle ::sf::gui::fitPanes}
    ::bind $path.c <Configure> {%W itemconfigure inner -width %w}
    foreach {event delta} {<Button-4> -1 <Button-5> 1} {
        ::bind ScrollPane$path $event [list $path.c yview scroll $delta units]
    }
    return $inner
}

# The pane asks for its content's width; its scroll region is the content.
proc ::sf::gui::scrollFit {path} {
    set inner $path.c.in
    $path.c configure -width [winfo reqwidth $inner] -scrollregion [list 0 0 0 [winfo reqheight $inner]]
    # The wheel scrolls it over any of its parts, those made since too.
    set pending [list $inner]
    while {[llength $pending]} {
        set pending [lassign $pending w]
        if {"ScrollPane$path" ni [bindtags $w]} { bindtags $w [linsert [bindtags $w] end ScrollPane$path] }
        lappend pending {*}[winfo children $w]
    }
}

proc ::sf::gui::scrollShown {path first last} {
    if {$first <= 0 && $last >= 1} { grid remove $path.sb } else { grid $path.sb }
    $path.sb set $first $last
}

# As the window narrows the panes give up width in order: the middle (view,
# console, plot) down to centreMin pixels, then the properties down to
# propsMin; the tools keep theirs.
namespace eval ::sf::gui { variable centreMin 520; variable propsMin 190 }
proc ::sf::gui::fitPanes {} {
    variable centreMin
    variable propsMin
    variable fitted
    set width [winfo width .main]
    if {$width < 100 || [llength [.main panes]] < 3} return
    set tools [winfo reqwidth .main.tools]
    set props [winfo reqwidth .main.props]
    # Once for each window width and pair of wants: moving a sash configures
    # the panes again, which must not fit them again.
    set wants [list $width $tools $props $centreMin $propsMin]
    if {[info exists fitted] && $fitted eq $wants} return
    set fitted $wants
    set sash [expr {max(1, [winfo x .main.centre] - [winfo width .main.tools] - [winfo x .main.tools])}]
    set centre [expr {$width - $tools - $props - 2 * $sash}]
    if {$centre < $centreMin} { set props [expr {max($propsMin, $props - ($centreMin - $centre))}] }
    .main sashpos 0 $tools
    .main sashpos 1 [expr {$width - $props - $sash}]
}

proc ::sf::gui::layout {} {
    variable W
    style
    wm title . "sandflow"
    # The least size at which every control shows whole (the run bar's width).
    wm minsize . 1000 600
    menus
    set W(runbar) [runbar::create .runbar]
    set W(status) [runbar::statusBar .status]
    ttk::separator .sep -orient horizontal
    pack $W(runbar) -side top -fill x
    pack .sep -side top -fill x
    pack $W(status) -side bottom -fill x

    ttk::panedwindow .main -orient horizontal
    set W(tools) [scrollPane .main.tools tools::create]
    ttk::panedwindow .main.centre -orient vertical
    ttk::frame .main.centre.viewframe -borderwidth 1 -relief sunken
    set W(view) [view::create .main.centre.viewframe.view]
    pack $W(view) -fill both -expand 1
    tools::bind $W(view)
    ttk::panedwindow .main.centre.bottom -orient horizontal
    ttk::labelframe .main.centre.bottom.con -text Console -padding 2
    set W(console) [console::create .main.centre.bottom.con.c -width 40 -height 8]
    pack $W(console) -fill both -expand 1
    ttk::labelframe .main.centre.bottom.plot -text "Live plot" -padding 2
    set W(plots) [plots::create .main.centre.bottom.plot.p]
    pack $W(plots) -fill both -expand 1
    .main.centre.bottom add .main.centre.bottom.con -weight 3
    .main.centre.bottom add .main.centre.bottom.plot -weight 2
    .main.centre add .main.centre.viewframe -weight 4
    .main.centre add .main.centre.bottom -weight 1
    set W(props) [scrollPane .main.props props::create]
    .main add .main.tools -weight 0
    .main add .main.centre -weight 1
    .main add .main.props -weight 0
    pack .main -fill both -expand 1
    ::bind .main <Configure> {after idle ::sf::gui::fitPanes}
    keys
    syncViewMenu
    # Most of the screen, leaving room for a panel or a dock.
    set sw [winfo screenwidth .]
    set sh [winfo screenheight .]
    wm geometry . [expr {min(1500, $sw - 40)}]x[expr {min(960, $sh - 60)}]+10+10
    wm protocol . WM_DELETE_WINDOW ::sf::gui::quit
}

# Warnings of the kernel go to the console and are counted in the status bar.
proc ::sf::warn {message} {
    if {[info exists ::sf::gui::W(console)]} {
        ::sf::gui::console::write $::sf::gui::W(console) "warning: $message\n" warning
    }
    ::sf::gui::status "warning: $message" error
}

# Each command typed at the console is numbered as it starts; after it, the
# scene may have changed.
proc ::sf::gui::console::beforeEval {} {
    lappend ::sf::gui::typing [::sf::gui::begin]
}
proc ::sf::gui::console::afterEval {code result} {
    set serial [lindex $::sf::gui::typing end]
    set ::sf::gui::typing [lrange $::sf::gui::typing 0 end-1]
    if {$code != 1 && $serial ne ""} { ::sf::gui::succeeded $serial }
    ::sf::gui::syncViewMenu
    ::sf::gui::changed
}
set ::sf::gui::typing {}   ;# the numbers of the typed commands running, innermost last

proc ::sf::gui::openScript {} {
    variable scriptDir
    set file [tk_getOpenFile -parent . -title "Open script" -initialdir $scriptDir \
                  -filetypes {{{Tcl scripts} {.tcl}} {{All files} *}}]
    if {$file eq ""} return
    set scriptDir [file dirname $file]
    catch {do [list source $file]}
    syncViewMenu
    view::fit
}

proc ::sf::gui::saveScript {} {
    variable scriptDir
    set file [tk_getSaveFile -parent . -title "Save scene as script" -initialdir $scriptDir \
                  -defaultextension .tcl -filetypes {{{Tcl scripts} {.tcl}}}]
    if {$file eq ""} return
    set scriptDir [file dirname $file]
    # After a run the commands rebuild the scene at t = 0; its state can go
    # beside the script in a checkpoint that the script loads.
    set state 0
    set step [dict get [::sf::sim info] step]
    if {$step > 0} {
        set answer [tk_messageBox -parent . -icon question -type yesnocancel \
            -title "Save scene as script" \
            -message "The scene has run $step steps. Save its state too?" \
            -detail "Yes: the flow, contact and bond histories and the clock go into\
                [file rootname [file tail $file]].sfck beside the script, which loads it:\
                the script gives back the scene exactly as it is now.\n\nNo: the script\
                rebuilds the scene at t = 0, the fluid at rest."]
        if {$answer eq "cancel"} return
        set state [expr {$answer eq "yes"}]
    }
    if {![catch {do [list ::sf::gui::saveSceneScript $file -state $state]}]} {
        status "saved $file"
    }
}

proc ::sf::gui::openCheckpoint {} {
    variable scriptDir
    set file [tk_getOpenFile -parent . -title "Open checkpoint" -initialdir $scriptDir \
                  -filetypes {{{Checkpoints} {.sfck}} {{All files} *}}]
    if {$file eq ""} return
    set scriptDir [file dirname $file]
    if {[running]} {
        status "pause the run first" error
        return
    }
    if {![catch {do [list checkpoint load $file]}]} {
        forgetHistory  ;# the loaded scene starts a new history, as after New
        syncViewMenu
        view::fit
        status "loaded $file"
    }
}

proc ::sf::gui::saveCheckpoint {} {
    variable scriptDir
    set file [tk_getSaveFile -parent . -title "Save checkpoint" -initialdir $scriptDir \
                  -defaultextension .sfck -filetypes {{{Checkpoints} {.sfck}}}]
    if {$file eq ""} return
    set scriptDir [file dirname $file]
    if {![catch {do [list checkpoint save $file]}]} {
        status "saved $file"
    }
}

proc ::sf::gui::exportSnapshot {} {
    set file [tk_getSaveFile -parent . -title "Export snapshot" -defaultextension .png \
                  -filetypes {{{PNG pictures} {.png}}}]
    if {$file eq ""} return
    set v $::sf::gui::W(view)
    set region $::sf::gui::view::region
    set extra [expr {$region eq {} ? {} : [list -region $region]}]
    catch {do [list snapshot $file -size [list [winfo width $v] [winfo height $v]] {*}$extra]}
}

proc ::sf::gui::exportVtk {} {
    set file [tk_getSaveFile -parent . -title "Export VTK (prefix)" \
                  -filetypes {{{VTK prefix} {*}}}]
    if {$file eq ""} return
    catch {do [list output vtk [file rootname $file]]}
}

proc ::sf::gui::exportMovie {} {
    set file [tk_getSaveFile -parent . -title "Record a movie of the next runs" \
                  -defaultextension .mp4 -filetypes {{{MP4 movies} {.mp4}}}]
    if {$file eq ""} return
    set every [askString "Movie" "A frame every how many steps?" 10]
    if {$every eq ""} return
    catch {do [list output movie $file -every $every]}
}

# A ParaView series of the next runs: numbered files and PREFIX.pvd, the
# prefix being the chosen file's name without .pvd.
proc ::sf::gui::exportVtkSeries {} {
    set file [tk_getSaveFile -parent . -title "Record a VTK series of the next runs" \
                  -defaultextension .pvd -filetypes {{{ParaView collections} {.pvd}}}]
    if {$file eq ""} return
    set every [askString "VTK series" "Files every how many steps?" 100]
    if {$every eq ""} return
    catch {do [list output vtk [file rootname $file] -every $every]}
}

proc ::sf::gui::showReference {} {
    set t .reference
    if {[winfo exists $t]} { raise $t; return }
    toplevel $t
    wm title $t "sandflow command reference"
    text $t.text -wrap word -width 100 -height 40 -font TkFixedFont -padx 8 -pady 8 \
        -yscrollcommand [list $t.sy set]
    ttk::scrollbar $t.sy -command [list $t.text yview]
    pack $t.sy -side right -fill y
    pack $t.text -fill both -expand 1
    $t.text insert end [referenceText]
    $t.text configure -state disabled
}

# docs/commands.md of the source tree the workbench runs from (tcl/gui's
# grandparent); where there is none (an installed program), `help` and the
# help of every command that has a `help` verb.
proc ::sf::gui::referenceText {{doc ""}} {
    if {$doc eq ""} {
        set doc [file join [file dirname [file dirname $::sf::gui::library]] docs commands.md]
    }
    if {![catch {open $doc} ch]} {
        set text [read $ch]
        close $ch
        return $text
    }
    set text [::sf::help]
    foreach cmd [lsort [info commands ::sf::*]] {
        if {[namespace ensemble exists $cmd] &&
                [dict exists [namespace ensemble configure $cmd -map] help]} {
            append text \n\n [$cmd help]
        }
    }
    return $text
}

proc ::sf::gui::about {} {
    tk_messageBox -parent . -title "About sandflow" -icon info -message "sandflow [package present sandflow]" \
        -detail "Grains in a lattice-Boltzmann fluid, fully coupled: a workbench after B. K. Cook's\
                 SandFlow2D (MIT, 2001).\n\n[view::describe]"
}

proc ::sf::gui::quit {} {
    if {[running]} { runbar::pausePressed; after 100 ::sf::gui::quit; return }
    destroy .
}

# Opens the window, then sources the script (if any) into this interpreter.
proc ::sf::gui::main {{script ""}} {
    view configure -offscreen egl
    layout
    update
    status "[view::describe] \u00b7 draw with the tools on the left; type commands below"
    if {$script ne ""} {
        set ::sf::gui::scriptDir [file dirname [file normalize $script]]
        console::echo $::sf::gui::W(console) [list source $script]
        if {[catch {uplevel #0 [list source $script]} err]} {
            console::write $::sf::gui::W(console) "$err\n" error
            status "$script: $err" error
        }
    }
    syncViewMenu
    changed
}
