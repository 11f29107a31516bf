# The thesis's source ring (Cook 2001, §2.4 and §4.2.2): a ring of source discs
# whose clones are accelerated outward, packing a graded assembly against a
# circle of walls. Pure DEM: no lattice is created, so no fluid cost.
#
#   sandflow examples/source-ring.tcl ?-steps N?

# The options (-help lists them), each ${-name} below.
set options [::sf::scriptOptions {
    {steps.arg 20000 "steps to run (a line every tenth)"}
}]
dict with options {}

material create rock -density 2650 -kn 1e7 -ks 1e7 -friction 0.5 -restitution 0.3

# A container: a 40-sided ring of walls of radius 2 m.
set sides 40
for {set k 0} {$k < $sides} {incr k} {
    set a0 [expr {2 * acos(-1) * $k / $sides}]
    set a1 [expr {2 * acos(-1) * ($k + 1) / $sides}]
    wall create -from [list [expr {2 * cos($a0)}] [expr {2 * sin($a0)}]] \
                -to   [list [expr {2 * cos($a1)}] [expr {2 * sin($a1)}]] -material rock
}

# The ring of sources, built the thesis's way: a procedure and the next free id.
proc sourceRing {n radius grain accel} {
    for {set k 0} {$k < $n} {incr k} {
        set theta [expr {2 * acos(-1) * $k / $n}]
        set id [element next]
        disc create -id $id -material rock -radius $grain \
            -center [list [expr {$radius * cos($theta)}] [expr {$radius * sin($theta)}]]
        source create $id -acceleration [list [expr {$accel * cos($theta)}] [expr {$accel * sin($theta)}]] \
            -limit 12
    }
}
sourceRing 16 0.4 0.05 20.0

puts [format "timestep %.3g s (critical %.3g s)" [sim cget -timestep] [dict get [sim info] critical]]
run ${-steps} -every [expr {${-steps} / 10}] {
    set s [sim info]
    puts [format "t = %.3f s  elements %d  contacts %d  kinetic %.3g J/m" \
        [dict get $s time] [dict get $s elements] [dict get $s contacts] [dict get $s kinetic]]
}
