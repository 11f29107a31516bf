# The thesis's source ring (Cook 2001, §2.4 and §4.2.2) written as the thesis
# writes it: a procedure that places each source disc with
# get_next_available_id and adddiscui, holds it with set_velocity, gives it
# an outward force with setforce (its clones inherit the force) and makes it
# a source with makesource (docs/thesis-compat.md). The same scene as
# examples/source-ring.tcl, whose clones get the same push as an acceleration.
#
#   sandflow -gui examples/thesis-source-ring.tcl   then Run
#   sandflow -c 'source examples/thesis-source-ring.tcl; run'

set TIMESTEPS 20000
set GRAPHICSFRAMES 200

# Material and container are sandflow's own commands (the table of the
# thesis's names has none for them).
material create rock -density 2650 -kn 1e7 -ks 1e7 -friction 0.5 -restitution 0.3
set sides 40
for {set k 0} {$k < $sides} {incr k} {
    set a0 [expr {2 * acos(-1) * $k / $sides}]
    set a1 [expr {2 * acos(-1) * ($k + 1) / $sides}]
    wall create -from [list [expr {2 * cos($a0)}] [expr {2 * sin($a0)}]] \
                -to   [list [expr {2 * cos($a1)}] [expr {2 * sin($a1)}]] -material rock
}

# n sources of radius `grain` on a circle of radius `radius`, each pushed
# outward with the force that gives its clones the acceleration `accel`.
# (-limit is sandflow's: at most 12 clones each, as in source-ring.tcl.)
proc sourceRing {n radius grain accel} {
    set mass [expr {2650 * acos(-1) * $grain * $grain}]
    for {set k 0} {$k < $n} {incr k} {
        set theta [expr {2 * acos(-1) * $k / $n}]
        set id [get_next_available_id]
        adddiscui rock [expr {$radius * cos($theta)}] [expr {$radius * sin($theta)}] $grain $id
        set_velocity 1 1 1 0.0 0.0 0.0 $id
        setforce 1 1 0 [expr {$mass * $accel * cos($theta)}] [expr {$mass * $accel * sin($theta)}] 0.0 $id
        makesource $id -limit 12
    }
}
sourceRing 16 0.4 0.05 20.0
