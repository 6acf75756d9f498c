// Tests: triangles: a four-sided pyramid built from triangles (vertices wound both ways),
// a large upright triangle and a small tilted one.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <1, 3, -6> look_at <0, 0.8, 0> angle 55 }
light_source { <-5, 8, -5> rgb 1 }
background { rgb <0.2, 0.2, 0.25> }

plane { y, 0 pigment { rgb <0.75, 0.7, 0.65> } }
#declare Apex = <-1.2, 1.8, 0>;
union {
  triangle { <-2.2, 0, -1>, <-0.2, 0, -1>, Apex }
  triangle { <-0.2, 0, -1>, <-0.2, 0, 1>, Apex }
  triangle { Apex, <-0.2, 0, 1>, <-2.2, 0, 1> }
  triangle { Apex, <-2.2, 0, 1>, <-2.2, 0, -1> }
  pigment { rgb <0.9, 0.7, 0.2> }
}
triangle { <0.5, 0, 1.5>, <2.8, 0, 1>, <1.8, 2.5, 1.2> pigment { rgb <0.3, 0.5, 0.9> } }
triangle { <0.6, 0.2, -1.5>, <1.8, 0.9, -1.2>, <1.2, 0.5, -0.4> pigment { rgb <0.9, 0.3, 0.4> } }
