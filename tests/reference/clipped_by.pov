// clipped_by: a poly, a sphere, a box clipped by an inverted sphere, and clipped_by { bounded_by }.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, -1 pigment { rgb <0.8, 0.8, 0.7> } }
cubic {
  < 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -0.3 >
  pigment { rgb <0.3, 0.6, 0.9> }
  clipped_by { sphere { 0, 1 } }
  translate <1.8, 0, 0>
}
sphere { 0, 1 pigment { rgb <0.9, 0.4, 0.2> } clipped_by { box { <-2, -2, -2>, <2, 0.3, 2> } } scale <1, 0.8, 1> translate <-1.5, 0, 0> }
box { -0.7, 0.7 pigment { rgb <0.3, 0.8, 0.3> } clipped_by { sphere { 0, 0.9 inverse } } rotate y*30 translate <0, 0, 1.5> }
quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 4, 0, 0, 0, 0, 1, 0, -5, 0, 4 >
  bounded_by { sphere { 0, 2.1 } }
  clipped_by { bounded_by }
  pigment { rgb <0.9, 0.8, 0.2> } scale 0.5 translate <0, -0.5, -1.5>
}
