// normal_slope_map_hermite: slope_map heights between entries follow the cubic Hermite curve
// with each entry's slope taken per unit of the interpolation parameter (not scaled by the
// entries' spacing), on gradient, onion and mandel normals
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -6> look_at <0, 0, 0> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } finish { specular 0.6 }
  normal { gradient x 1 slope_map { [0 <0, 0>] [0.5 <0.5, 1>] [1 <1, 0>] } scale 1.5 } }
sphere { <-1.6, 1, 0>, 1 pigment { rgb <1, 0.8, 0.6> }
  normal { onion 2 slope_map { [0 <0, 2>] [0.3 <0.6, -1>] [1 <0.2, 0>] } scale 0.4 } }
box { <-1, 0, -1>, <1, 0.4, 1> translate <1.5, 0, 0.5> pigment { rgb <0.7, 0.9, 1> } finish { specular 0.8 }
  normal { mandel 60 1 interior 1, 5 slope_map { [0 <0, 0>] [0.5 <0.5, 1>] [1 <1, 0>] } rotate x*90 translate <0.5, 0, 0> } }
