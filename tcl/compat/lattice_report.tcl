# printLB and dumpLattice: the lattice's parameters as text (headless on
# standard output, in the workbench a window), and its nodes' values to a file.

# The parameters of the lattice (or that there is none), one per line.
proc ::sf::thesis::latticeText {} {
    if {![hasLattice]} {
        return "lattice-Boltzmann: off (no lattice; LBON 1 and addlatticeui make one)"
    }
    set i [::sf::lattice info]
    set lines [list "lattice-Boltzmann: on"]
    foreach {label value} [list \
            nodes "[dict get $i nx] x [dict get $i ny] ([dict get $i nodes])" \
            origin [dict get $i origin] \
            size [dict get $i size] \
            spacing [dict get $i spacing] \
            timestep [dict get $i timestep] \
            tau [dict get $i tau] \
            viscosity [dict get $i viscosity] \
            density [dict get $i density] \
            "lattice speed" [dict get $i c] \
            "sound speed" [dict get $i cs] \
            forcing [dict get $i forcing] \
            collision "[dict get $i collision], [dict get $i forcescheme] forcing" \
            walls [dict get $i walls] \
            "solid ratio" [::sf::sim cget -solidratio] \
            Mach [format %.4g [dict get $i mach]] \
            mass [format %.10g [dict get $i mass]]] {
        lappend lines [format "%-14s %s" $label $value]
    }
    join $lines \n
}

proc ::sf::thesis::printLB {} {
    showText "Lattice-Boltzmann parameters" [latticeText]
    return
}

# Every node, row by row from the lower left: x y density pressure vx vy
# solid kind, after the parameters as # comments. The file appears whole or
# not at all. (About 30 microseconds a node: for large lattices `output vtk`
# is the faster way.)
proc ::sf::thesis::dumpLattice {file} {
    if {![hasLattice]} {
        return -code error -errorcode {SANDFLOW LOOKUP LATTICE} \
            "dumpLattice: there is no lattice (LBON 1 and addlatticeui make one)"
    }
    set info [::sf::lattice info]
    lassign [dict get $info origin] x0 y0
    set h [dict get $info spacing]
    set part $file.part
    if {[catch {open $part w} out options]} {
        # Tcl's message, about the file asked for rather than its part file.
        return -options $options [string map [list $part $file] $out]
    }
    set code [catch {
        foreach line [split [latticeText] \n] { puts $out "# $line" }
        puts $out "# step [dict get [::sf::sim info] step]"
        puts $out "# x y density pressure vx vy solid kind"
        for {set j 0} {$j < [dict get $info ny]} {incr j} {
            for {set i 0} {$i < [dict get $info nx]} {incr i} {
                set p [::sf::lattice probe [list [expr {$x0 + ($i + 0.5) * $h}] \
                                                 [expr {$y0 + ($j + 0.5) * $h}]]]
                puts $out [join [list {*}[dict get $p position] [dict get $p density] \
                                     [dict get $p pressure] {*}[dict get $p velocity] \
                                     [dict get $p solid] [dict get $p kind]]]
            }
        }
        close $out
        file rename -force -- $part $file
    } message options]
    if {$code} {
        catch {close $out}
        file delete -- $part
        return -options $options $message
    }
    return
}
