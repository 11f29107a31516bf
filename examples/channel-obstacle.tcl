# Body-forced channel flow around a fixed square obstacle.
# Periodic in x, no-slip walls top and bottom. Prints progress and writes
# ParaView files (.vti) into the output folder it names; at the end it reports
# the Reynolds number reached and writes a picture of the final flow (flow.png).
#
#   sandflow examples/channel-obstacle.tcl ?-steps N? ?-every K? ?-out DIR?

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {steps.arg 40000                "steps to run"}
    {every.arg 4000                 "steps between progress lines and ParaView files"}
    {out.arg   out/channel-obstacle "folder for the ParaView files and flow.png"}
}]
dict with options {}
set out ${-out}
file mkdir $out

# Fluid in consistent units; the forcing accelerates it from rest.
lattice create -origin {0 0} -size {4 1} -cells 400 \
    -viscosity 0.001 -density 1.0 -tau 0.56 \
    -periodic {1 0} -walls {bottom noslip top noslip} \
    -forcing {0.003 0}
set block [lattice obstacle rect {0.8 0.4 1.0 0.6}]

set info [lattice info]
puts [format "lattice %d x %d (%d nodes), spacing %g, timestep %g, tau %g, %.0f bytes/node" \
    [dict get $info nx] [dict get $info ny] [dict get $info nodes] \
    [dict get $info spacing] [dict get $info timestep] [dict get $info tau] \
    [dict get $info bytespernode]]
puts "writing ParaView files to [file normalize $out]"
puts [format "%8s %10s %8s %9s %12s %12s" step time MLUPS "max Mach" "mass drift" "drag x"]

set mass0 [dict get $info mass]
set frame 0
proc report {} {
    global mass0 block out frame
    set s [sim info]
    set l [lattice info]
    set drift [expr {([dict get $l mass] - $mass0) / $mass0}]
    set drag [lindex [dict get [lattice obstacle info $block] force] 0]
    puts [format "%8d %10.3f %8.1f %9.4f %12.2e %12.5g" [dict get $s step] [dict get $s time] \
        [dict get $s mlups] [dict get $s mach] $drift $drag]
    output vtk [file join $out [format "flow_%04d" $frame]]
    incr frame
}
report
run ${-steps} -every ${-every} report
# A picture of the final flow (headless: OSMesa or EGL).
snapshot [file join $out flow.png] -field velocity -vectors 1 -size {1000 560}
set umax [expr {[dict get [sim info] mach] * [dict get [lattice info] c]}]
puts [format "peak speed %.4g: Reynolds number on the obstacle's size %.1f" $umax \
    [expr {$umax * 0.2 / [lattice cget -viscosity]}]]
puts "done: $frame ParaView files in [file normalize $out] (open flow_*.vti as a series),"
puts "and a picture of the final flow: [file normalize [file join $out flow.png]]"
