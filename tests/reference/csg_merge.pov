// Tests: merge versus union with transparent children: the union (left) shows the inner
// surfaces where the three spheres overlap, the merge (right) does not. A checker wall
// behind shows the transparency.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2, -6> look_at <0, 1, 0> angle 55 }
light_source { <-3, 8, -8> rgb 1 }

plane { y, 0 pigment { rgb <0.7, 0.7, 0.7> } }
plane { z, 3 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.3, 0.5> scale 0.5 } }
#declare Clear = pigment { rgbt <1, 0.5, 0.2, 0.5> }
union {
  sphere { <-0.45, 0, 0>, 0.8 }
  sphere { <0.45, 0, 0>, 0.8 }
  sphere { <0, 0.6, -0.2>, 0.7 }
  pigment { Clear }
  translate <-1.6, 1, 0>
}
merge {
  sphere { <-0.45, 0, 0>, 0.8 }
  sphere { <0.45, 0, 0>, 0.8 }
  sphere { <0, 0.6, -0.2>, 0.7 }
  pigment { Clear }
  hollow
  translate <1.6, 1, 0>
}
