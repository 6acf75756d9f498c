// The height-field macros of shapes.inc (HF_Square, HF_Sphere, HF_Cylinder, HF_Torus), with
// and without smoothing, their heights from a function of the point or of (u, v).
// shapes_hf.png is POV-Ray 3.7's render with its own shapes.inc, made like the reference
// images (povray -D +Ishapes_hf.pov +Oshapes_hf.png +W160 +H120 +WT1 -GA); the includes
// test renders this scene with durer's embedded shapes.inc and with POV-Ray's and compares.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1 }
camera { location <2, 3, -6> look_at <0, 0.3, 0> angle 50 }
light_source { <-5, 8, -6>, rgb 1 }
light_source { <6, 3, -3>, rgb 0.5 }
background { rgb <0.2, 0.3, 0.5> }
#declare Ripple = function (x, y, z) { sin(x * 5) * 0.1 + y * 0.3 + z * z * 0.2 }
#declare Tan = pigment { rgb <1, 0.6, 0.3> }
object { HF_Square(Ripple, 0, 0, <20, 15>, 1, "", <-2, 0, -1>, <0, 0.5, 1>) pigment { Tan } }
object { HF_Sphere(Ripple, 1, 0, 16, 1, "", <0.8, 1, 0>, 0.7, 0.3) pigment { Tan } }
object { HF_Cylinder(Ripple, 0, 0, <12, 8>, 0, "", <1, -1, 0>, <1.4, 0, 0.3>, 0.5, 0.5) pigment { Tan } }
object { HF_Torus(Ripple, 1, 0, 20, 1, "", 0.8, 0.2, 0.5) pigment { Tan } translate <-1, 1.5, 1> }
