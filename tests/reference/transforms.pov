// Tests: transformations of one declared object (an L-shaped union): rotate, non-uniform
// scale before and after a rotation (which differ), translate, a shearing matrix and a
// transform block.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0.2, 3.2, -5> look_at <0.2, 0.7, 0.8> angle 68 }
light_source { <-5, 10, -6> rgb 1 }
background { rgb <0.2, 0.2, 0.2> }

plane { y, 0 pigment { checker rgb 0.75 rgb 0.55 } }
#declare Ell = union {
  box { <0, 0, 0>, <1, 0.3, 0.3> }
  box { <0, 0, 0>, <0.3, 1, 0.3> }
}
object { Ell translate <-3, 0, 0> pigment { rgb <0.15, 0.15, 0.15> } }
object { Ell rotate y*45 translate <-1.5, 0, 0> pigment { rgb <0.9, 0.3, 0.2> } }
object { Ell scale <1, 2, 1> rotate z*-30 translate <0, 0.5, 0> pigment { rgb <0.3, 0.8, 0.3> } }
object { Ell rotate z*-30 scale <1, 2, 1> translate <1.5, 0.5, 0> pigment { rgb <0.3, 0.5, 0.9> } }
object { Ell
  matrix < 1, 0, 0,
           0.8, 1, 0,
           0, 0, 1,
           2.5, 0, 0 >
  pigment { rgb <0.9, 0.8, 0.2> }
}
object { Ell
  transform { scale 1.5 rotate x*-90 translate <-0.5, 0.3, 2.5> }
  pigment { rgb <0.8, 0.3, 0.8> }
}
