# lattice_helpers.tcl -- what the lattice_*.test files share: the usual
# options of a small lattice and the messages of a bad option and of a bad
# create; sourced after helpers.tcl, not a test file itself.

set badOption {bad option "-foo": must be -origin, -size, -cells, -spacing, -viscosity, -density, -tau, -periodic, -walls, -forcing, -collision, -forcescheme, or -magic}
set createUsage {wrong # args: should be "lattice create -size {Lx Ly} (-cells NX | -spacing h) ?-option value ...?"}
set base {-size {1 1} -cells 10 -viscosity 0.01}
