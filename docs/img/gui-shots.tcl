# Takes the workbench's screenshots for docs/gui.md and README.md from the
# code as it is, by driving the window as a user would (tests/gui/driver.tcl).
# From the repository's root, with a screen of 1600 x 1000:
#
#   xvfb-run -a -s "-screen 0 1600x1000x24" build/release/sandflow -gui docs/img/gui-shots.tcl
#
# It writes docs/img/gui-{window,view,guides,props,console}.png; the example
# it runs writes its ParaView files under out/gui-shots (relative paths only:
# the pictures show no path of the machine that made them).

set here [file dirname [file normalize [info script]]]
set root [file dirname [file dirname $here]]
cd $root
source [file join $root tests gui driver.tcl]
namespace import ::driver::*
set v $::sf::gui::W(view)
set tools .main.tools.c.in
set console $::sf::gui::W(console)
update

# A widget as the screen shows it (its top `height` pixels, if given),
# cropped, as docs/img/NAME.png.
proc shotOf {w name {height ""}} {
    drawNow
    after 200 {set ::driver::tick 1}
    vwait ::driver::tick
    set file [file join $::here $name.png]
    if {$height eq ""} { set height [winfo height $w] }
    exec import -window root -crop [winfo width $w]x${height}+[winfo rootx $w]+[winfo rooty $w] \
        +repage -define png:compression-level=9 $file
    puts "wrote $file"
}
# The whole window with its menu bar.
proc shotWindow {name} {
    set ::driver::shots [file dirname [file join $::here $name.png]]
    set file [shot $name]
    file rename -force $file [file join $::here $name.png]
    puts "wrote [file join $::here $name.png]"
}
proc fileNew {} {
    if {[llength [element ids]] || ![catch {lattice info}]} { answer .__tk__messagebox button OK }
    invokeEntry .menu.file New
    waitFor {![llength $::driver::answers]} 60
    drawNow
}

# ---- the window: the channel with a fixed disc, run from the console -------------

::sf::gui::console::Clear $console
typeCommand {set argv {-steps 3000 -every 1000 -out out/gui-shots}}
typeCommand {source examples/channel-disc.tcl}
waitFor {![::sf::gui::running]} 600
invokeEntry .menu.view "Velocity arrows"
set combo $::sf::gui::plots::f.bar.series
$combo set "Mach number"
event generate $combo <<ComboboxSelected>>
viewKey f
shotWindow gui-window

# ---- the view: a disc being drawn beside the selected one ----------------------------

tool select
click 0.5 0.5
tool disc
lassign [px 1.3 0.62] X0 Y0
lassign [px 1.5 0.38] X1 Y1
pressAt $X0 $Y0
moveAt [expr {($X0 + $X1) / 2}] [expr {($Y0 + $Y1) / 2}]
moveAt $X1 $Y1
shotOf $v gui-view
viewKey Escape
releaseAt $X1 $Y1

# ---- the guides: grid, axes and scale bar over a lattice with two obstacles --------------

fileNew
set ::sf::gui::tools::snap 1
typeInto $tools.cells 40
typeInto $tools.viscosity 0.01
typeInto $tools.forcing "1e-4 0"
lassign [px 0.5 0.5] cx cy
wheel $cx $cy -4
tool lattice
drag 0 0 2 1
viewKey f
tool rect
drag 0.4 0.35 0.5 0.65
tool circle
drag 0.95 0.35 1.25 0.65
tool disc
drag 1.45 0.38 1.65 0.58
typeCommand "element configure [lindex [element ids] end] -fix {x y rot}"
typeInto $::sf::gui::W(runbar).steps 300
$::sf::gui::W(runbar).run invoke
waitFor {![::sf::gui::running]}
foreach label {Grid Axes "Scale bar"} { invokeEntry .menu.view $label }
tool superquadric
lassign [px 0.62 0.12] X0 Y0
lassign [px 0.92 0.42] X1 Y1
pressAt $X0 $Y0
moveAt [expr {($X0 + $X1) / 2}] [expr {($Y0 + $Y1) / 2}]
moveAt $X1 $Y1
shotOf $v gui-guides
viewKey Escape
releaseAt $X1 $Y1
set ::sf::gui::tools::snap 0

# ---- the properties: a disc's radius refused ------------------------------------------------

tool select
click 1.55 0.48
set radius $::sf::gui::props::f.rows.eradius
typeInto $radius -0.1
shotOf .main.props gui-props [expr {[winfo reqheight .main.props.c.in] + 8}]
event generate $radius <Escape>

# ---- the console: a result, an error with its details, completion ---------------------------

::sf::gui::console::Clear $console
typeCommand {lattice obstacles}
typeCommand {dict get [lattice info] spacing}
typeCommand {disc create -center {1 0.5} -radius 0}
typeCommand {lattice ob} ""
event generate $console.text <Tab>
update
shotOf .main.centre.bottom.con gui-console

exit
