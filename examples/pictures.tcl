# The pictures of docs/visualization.md, made by the commands it shows.
#
#   sandflow examples/pictures.tcl ?-out DIR? ?-quick 0|1?
#
# Two scenes: grains settling in a closed box of fluid (coupled), and a
# bonded block of grains dropped on a floor (elements only).
# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {out.arg   docs/img "folder for the pictures"}
    {quick.arg 0        "1: a tenth of the settling steps (for tests)"}
}]
dict with options {}
set out ${-out}
file mkdir $out
set steps [expr {${-quick} ? 300 : 3000}]

# ---- grains settling in fluid -------------------------------------------------
# Units with the grain diameter d = 1 and fluid density 1; 10 cells per d.
lattice create -size {16 10} -cells 160 -viscosity 0.02 -tau 0.7 \
    -walls {left noslip right noslip bottom noslip top noslip}
sim configure -gravity {0 -0.03}
set dt [dict get [lattice info] timestep]
set k [expr {2.0 * acos(-1) * 0.25 * 4 / (25 * $dt * $dt)}]
material create grain -density 2.0 -kn $k -ks $k -friction 0.3 -restitution 0.5
material create heavy -density 3.0 -kn $k -ks $k -friction 0.3 -restitution 0.5
foreach {from to} {{0 0} {16 0}  {16 0} {16 10}  {16 10} {0 10}  {0 10} {0 0}} {
    wall create -from $from -to $to -material grain
}
# Three staggered rows near the top; every fourth grain is heavier.
set n 0
for {set row 0} {$row < 3} {incr row} {
    for {set i 0} {$i < 9} {incr i} {
        set x [expr {1.4 + 1.6 * $i + 0.8 * ($row % 2)}]
        if {$x > 15} continue
        set y [expr {8.6 - 1.3 * $row}]
        disc create -center [list $x $y] -radius 0.5 -material [expr {$n % 4 == 3 ? "heavy" : "grain"}]
        incr n
    }
}
view configure -size {900 600} -materialcolors {grain #e69f00 heavy #0072b2}
run $steps
snapshot $out/view-settling.png -field velocity -vectors 1
snapshot $out/view-vorticity.png -field vorticity -streamlines 1
# A close look at one grain: the lattice cells it covers and their solid ratio.
lassign [dict get [element info 5] position] gx gy
set window [list [expr {$gx - 1}] [expr {$gy - 0.7}] [expr {$gx + 1}] [expr {$gy + 0.7}]]
snapshot $out/view-nodes.png -field nodes -region $window -size {600 420} -fill 0
snapshot $out/view-solid.png -field solid -region $window -size {600 420} -fill 0

# ---- a bonded block dropped on a floor (no lattice) ----------------------------
reset
sim configure -gravity {0 -9.81}
material create rock -density 2600 -kn 1e7 -ks 1e7 -friction 0.5 -restitution 0.3 \
    -bondstiffness 1e7 -bondstrength 1.5e4
wall create -from {-1 0} -to {3 0} -material rock
set ids {}
for {set j 0} {$j < 6} {incr j} {
    for {set i 0} {$i < 12} {incr i} {
        set x [expr {0.3 + 0.1 * $i + 0.05 * ($j % 2)}]
        lappend ids [disc create -center [list $x [expr {0.1 + 0.0866 * $j}]] -radius 0.05 -material rock]
    }
}
bond auto -elements $ids -gap 0.001
view configure -size {900 420} -materialcolors {rock #999999} -field {} -region {0.1 -0.05 1.6 0.65}
# Until a little after the impact.
while {[dict get [sim info] time] < 0.2} { run 200 }
snapshot $out/view-bonds.png -colorby bond -forces 1
snapshot $out/view-speed.png -colorby speed -bonds 0
puts "pictures in $out: view-settling.png view-vorticity.png view-nodes.png view-solid.png view-bonds.png view-speed.png"
