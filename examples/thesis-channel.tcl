# Case A of the thesis (Cook 2001, §4.2.2, the GUI example) written as the
# thesis writes it: global variables and *ui procedures (docs/thesis-compat.md).
# The same scene as examples/channel-disc.tcl: a lattice over [0,2] x [0,1],
# 200 cells across x, viscosity 0.001, forcing 0.0025 in x, timestep 0.005,
# and a fixed disc of radius 0.051 at (0.5, 0.5).
#
#   sandflow -gui examples/thesis-channel.tcl     then Run: 10000 steps, a
#                                                 redraw every 100
#   sandflow -c 'source examples/thesis-channel.tcl; run'    headless; with
#       `set SNAPSHOTPREFIX frames/channel_` before `run`, a picture every 100

set MAXDTCR 0.005
set TIMESTEPS 10000
set GRAPHICSFRAMES 100

set LBON 1
set LBVISCOSITY 0.001
set LBFORCINGX 0.0025
set LBFORCINGY 0.0
set LBSHOWLATTICE 1
set LBSHOWVECTORS 1
set LBSHOWSOLUTION velocity

setscales -0.1 -0.1 2.1 1.1
addlatticeui 0.0 0.0 2.0 1.0 200

# The disc, of material 1 (the first: default): held in x, y and rotation,
# at rest.
set disc [get_next_available_id]
adddiscui 1 0.5 0.5 0.051 $disc
set_velocity 1 1 1 0.0 0.0 0.0 $disc

printLB
