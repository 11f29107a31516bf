# checkpoint_scene.tcl -- the coupled scene the checkpoint tests continue
# (sourced by checkpoint.test, and by the script that made the version-1
# fixture): a channel with an obstacle, grains of three shapes in contact, a
# bond that holds and one that breaks, a source that clones.
proc checkpointScene {} {
    reset
    lattice create -origin {0 0} -size {2 1} -cells 60 -viscosity 0.02 -tau 0.8 \
        -periodic {1 0} -walls {bottom noslip top noslip} -forcing {0.005 0}
    lattice obstacle rect {0.9 0 1.1 0.15}
    sim configure -gravity {0 -0.5}
    material create grain -density 5 -kn 200 -ks 200 -friction 0.4 -restitution 0.5 \
        -bondstiffness 200 -bondstrength 100
    disc create -center {0.5 0.5} -radius 0.06 -material grain
    disc create -center {0.625 0.5} -radius 0.06 -material grain
    disc create -center {0.5 0.12} -radius 0.07 -material grain -velocity {0.05 0 0}
    polygon create -vertices {1.4 0.3 1.5 0.3 1.5 0.4 1.4 0.4} -material grain
    ellipse create -center {0.3 0.2} -axes {0.08 0.05} -material grain
    bond auto -elements {0 1} -gap 0.01
    disc create -center {1.7 0.5} -radius 0.06 -material grain
    disc create -center {1.82 0.5} -radius 0.06 -material grain -velocity {0.2 0 0}
    bond create 5 6 -strength 0.001
    disc create -center {1.2 0.8} -radius 0.05 -material grain
    source create 7 -acceleration {0 -0.5} -limit 3 -interval 0.3
    view configure -field vorticity -colorby speed
}
