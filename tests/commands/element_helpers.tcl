# element_helpers.tcl -- what the element_*.test files share: the usage
# messages of the creators and of element configure, the options and info
# keys, a default disc's mass; sourced after helpers.tcl and dem_helpers.tcl
# (for $pi), not a test file itself.

set discUsage {wrong # args: should be "disc create -center {x y} -radius r ?-option value ...?"}
set polygonUsage {wrong # args: should be "polygon create -vertices {x1 y1 x2 y2 ...} ?-option value ...?"}
set ellipseUsage {wrong # args: should be "ellipse create -center {x y} -axes {a b} ?-sides N? ?-option value ...?"}
set superquadricUsage {wrong # args: should be "superquadric create -center {x y} -axes {a b} -exponents {m n} ?-sides N? ?-option value ...?"}
set wallUsage {wrong # args: should be "wall create -from {x y} -to {x y} ?-option value ...?"}
set configureUsage {wrong # args: should be "element configure ID ?-option value ...?"}
set configureOptions {-center -radius -from -to -material -angle -velocity -fix -force -acceleration -stress}
set badConfigure {bad option "-foo": must be -center, -radius, -from, -to, -material, -angle, -velocity, -fix, -force, -acceleration, or -stress}
set infoKeys {id type position angle velocity force torque mass inertia area material fix applied acceleration contacts contactforce}

# A disc of radius 0.1 of the default material (density 2650).
set discMass [expr {2650 * $pi * 0.01}]
