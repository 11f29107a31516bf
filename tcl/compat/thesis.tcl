# The thesis's command language (Cook 2001, §4.2.2; docs/thesis-compat.md):
# global variables such as LBVISCOSITY and TIMESTEPS, and `*ui` procedures
# such as addlatticeui and adddiscui, as a thin layer over sandflow's own
# commands. The application sources this file at start, headless and in the
# workbench, so that the thesis's scripts run unchanged, without a line to
# load it. It calls the commands by their ::sf:: names, which is what they
# are in any interpreter that has loaded sandflow.
#
# What shows things (the run's settings, the view, a text) goes through the
# show* procedures below; the workbench (tcl/gui/thesis.tcl) redefines them.

namespace eval ::sf::thesis {
    # The *ui procedures, in the global namespace as the thesis has them.
    namespace export setscales addlatticeui adddiscui set_velocity setforce makesource \
        get_next_available_id printLB dumpLattice
}

# TIMESTEPS or GRAPHICSFRAMES changed. Headless, `run` reads them as it starts.
proc ::sf::thesis::showRun {} {}

# The view's settings changed (LBSHOW*; with fit, setscales' window).
# Headless, the next snapshot shows them.
proc ::sf::thesis::showView {{fit 0}} {}

# printLB's text: headless, on standard output.
proc ::sf::thesis::showText {title text} {
    puts $text
}

foreach part {checks variables procedures lattice_report} {
    source [file join $::sf::thesis::library $part.tcl]
}
unset part

namespace eval :: { namespace import ::sf::thesis::* }
::sf::thesis::armAll
