// A difference of one slab and 3,600 cylinders: a CSG node with thousands of children.
// durer indexes the children of wide CSG nodes by their boxes (src/geometry/csg.rs).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -8> look_at 0 angle 40 }
light_source { <5, 10, -6> rgb 1 }
difference {
  box { <-2, -0.5, -2>, <2, 0.5, 2> }
  #for (I, 0, 59)
    #for (J, 0, 59)
      cylinder { <-2 + (I + 0.5) * 4 / 60, -1, -2 + (J + 0.5) * 4 / 60>, <-2 + (I + 0.5) * 4 / 60, 1, -2 + (J + 0.5) * 4 / 60>, 0.025 }
    #end
  #end
  pigment { rgb <1, 0.8, 0.6> }
}
plane { y, -0.5 pigment { checker rgb 1 rgb 0.5 } }
