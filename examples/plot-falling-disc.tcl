# A disc dropped onto a floor, bouncing with restitution 0.7: records its
# height and vertical velocity (output csv) and the scene's kinetic energy
# (record) while it runs, then plots both with gnuplot (plot). The plot in
# docs/output.md ("Time series and plots"), docs/img/plot-falling-disc.png, is
# this script's DIR/plot-falling-disc.png with the default options.
#
#   sandflow examples/plot-falling-disc.tcl ?-out DIR? ?-time T? ?-every K?
#
# Writes DIR/falling-disc.csv, DIR/falling-disc-scene.csv,
# DIR/plot-falling-disc.png and DIR/plot-falling-disc-energy.png, and prints
# the files and the height of each bounce's top.

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {out.arg   .    "folder for the CSV files and the plots"}
    {time.arg  1.5  "how long to run"}
    {every.arg 20   "steps between the CSV files' rows"}
}]
dict with options {}
file mkdir ${-out}

sim configure -gravity {0 -9.81} -timestep 1e-4
material create rubber -density 1000 -kn 1e6 -ks 1e6 -restitution 0.7 -friction 0.3
wall create -from {-1 0} -to {1 0} -material rubber
set disc [disc create -center {0 0.5} -radius 0.05 -material rubber]

set series [file join ${-out} falling-disc.csv]
set scene [file join ${-out} falling-disc-scene.csv]
output csv $series -elements $disc -every ${-every}
record $scene -every ${-every} -quantities {kinetic contacts}
run [expr {round(${-time} / 1e-4)}]
output close

puts [plot [file join ${-out} plot-falling-disc.png] $series -y [list y_$disc vy_$disc] \
          -title "A disc dropped onto a floor (restitution 0.7)" -xlabel "time (s)" \
          -ylabel "height (m), vertical velocity (m/s)" -size {800 450}]
puts [plot [file join ${-out} plot-falling-disc-energy.png] $scene -y kinetic \
          -title "Kinetic energy" -xlabel "time (s)" -ylabel "J per unit thickness" -size {800 450}]

# The tops of the bounces: where vy changes sign from + to -.
set f [open $series]
gets $f
set last {}
set tops {}
while {[gets $f line] >= 0} {
    lassign [split $line ,] step t x y angle vx vy
    if {$last ne "" && [lindex $last 1] > 0 && $vy <= 0} {lappend tops [format %.3f $y]}
    set last [list $y $vy]
}
close $f
puts "bounce tops: $tops"
