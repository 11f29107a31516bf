# Live plots: a chosen series sampled while the run goes (from the run's tick)
# and drawn with tklib's Plotchart. "Save PNG" writes the samples as CSV and
# draws them with the `plot` command (gnuplot), as a script would.

namespace eval ::sf::gui::plots {
    variable f ""
    variable series kinetic
    variable samples {}         ;# {time value} pairs of the current series
    variable maxSamples 2000
    variable lastDraw 0
    # name label: what can be plotted
    variable choices {
        kinetic   "kinetic energy"
        mach      "Mach number"
        broken    "broken bonds"
        contacts  "contacts"
        fluidfx   "fluid force x on the selection"
        fluidfy   "fluid force y on the selection"
    }
}

proc ::sf::gui::plots::create {path} {
    variable f
    variable choices
    package require Plotchart
    ttk::frame $path -padding 4
    ttk::frame $path.bar
    ttk::label $path.bar.l -text Plot
    set labels [dict values $choices]
    ttk::combobox $path.bar.series -state readonly -values $labels -width 22
    $path.bar.series set [dict get $choices kinetic]
    ::bind $path.bar.series <<ComboboxSelected>> ::sf::gui::plots::choose
    ttk::button $path.bar.clear -text Clear -command ::sf::gui::plots::clear
    ttk::button $path.bar.save -text "Save PNG\u2026" -command ::sf::gui::plots::saveDialog
    pack $path.bar.l $path.bar.series -side left -padx 2
    pack $path.bar.save $path.bar.clear -side right -padx 2
    canvas $path.c -background white -highlightthickness 0 -width 360 -height 200
    pack $path.bar -fill x
    pack $path.c -fill both -expand 1
    ::bind $path.c <Configure> {::sf::gui::plots::draw 1}
    set f $path
    return $path
}

proc ::sf::gui::plots::choose {} {
    variable f
    variable choices
    variable series
    set label [$f.bar.series get]
    dict for {name l} $choices { if {$l eq $label} { set series $name } }
    clear
}

proc ::sf::gui::plots::clear {} {
    variable samples {}
    sample
    draw 1
}

# The chosen series' value now.
proc ::sf::gui::plots::value {info} {
    variable series
    switch $series {
        fluidfx - fluidfy {
            set ids $::sf::gui::selection
            set sum 0.0
            foreach id $ids {
                set force [dict get [element info $id] fluidforce]
                set sum [expr {$sum + [lindex $force [expr {$series eq "fluidfx" ? 0 : 1}]]}]
            }
            return $sum
        }
        default { return [dict get $info $series] }
    }
}

# Takes one sample (the run's tick calls this at the view's frame rate).
proc ::sf::gui::plots::sample {{info {}}} {
    variable samples
    variable maxSamples
    variable lastDraw
    if {$info eq {} && [catch {sim info} info]} return
    if {[catch {value $info} v]} return
    set t [dict get $info time]
    if {[llength $samples] && [lindex $samples end 0] == $t} {
        lset samples end [list $t $v]
    } else {
        lappend samples [list $t $v]
    }
    # Keep the plot light: every other sample once there are too many.
    if {[llength $samples] > $maxSamples} {
        set kept {}
        foreach {a b} $samples { lappend kept $a }
        set samples $kept
    }
    set now [clock milliseconds]
    if {$now - $lastDraw > 250} {
        set lastDraw $now
        draw
    }
}

proc ::sf::gui::plots::draw {{force 0}} {
    variable f
    variable samples
    variable series
    variable choices
    if {$f eq "" || ![winfo ismapped $f.c]} return
    set c $f.c
    $c delete all
    if {[llength $samples] < 2} {
        $c create text [expr {[winfo width $c] / 2}] [expr {[winfo height $c] / 2}] \
            -text "[dict get $choices $series]: run to plot" -fill #868e96
        return
    }
    set ts [lmap s $samples {lindex $s 0}]
    set vs [lmap s $samples {lindex $s 1}]
    set tmin [tcl::mathfunc::min {*}$ts]
    set tmax [tcl::mathfunc::max {*}$ts]
    set vmin [tcl::mathfunc::min {*}$vs]
    set vmax [tcl::mathfunc::max {*}$vs]
    if {$vmax == $vmin} { set vmax [expr {$vmin + max(1e-12, abs($vmin) * 0.1 + 1e-12)}] }
    if {$tmax == $tmin} { set tmax [expr {$tmin + 1e-12}] }
    set xs [::Plotchart::determineScale $tmin $tmax]
    set ys [::Plotchart::determineScale $vmin $vmax]
    ::Plotchart::plotconfig xyplot background outercolor white
    set p [::Plotchart::createXYPlot $c $xs $ys]
    $p dataconfig s -colour #1f6feb -width 2
    $p xtext time
    $p title [dict get $choices $series]
    foreach t $ts v $vs { $p plot s $t $v }
}

proc ::sf::gui::plots::saveDialog {} {
    set file [tk_getSaveFile -parent . -title "Save plot as PNG" -defaultextension .png \
                  -filetypes {{{PNG pictures} {.png}}}]
    if {$file eq ""} return
    if {[catch {save $file} err]} { ::sf::gui::showError $err }
}

# The samples as CSV beside the picture, drawn by `plot`.
proc ::sf::gui::plots::save {file} {
    variable samples
    variable series
    variable choices
    if {[llength $samples] < 2} { error "nothing to plot yet: run first" }
    set csv [file rootname $file].csv
    set ch [open $csv w]
    puts $ch "time,$series"
    foreach s $samples { puts $ch [join $s ,] }
    close $ch
    ::sf::gui::do [list plot $file $csv -y $series -title [dict get $choices $series] \
                       -size {800 450}]
}
