// image_pattern_normal: image_pattern as a normal's height field (numeric slope of the grey
// level, bump_size after the block) and in a texture_map with a spherical map_type
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -4> look_at <0, 0, 0.3> angle 55 }
light_source { <-6, 3, -2> rgb 1 }
plane { y, 0 pigment { rgb 0.8 }
  normal { image_pattern { png "images/bumps16.png" interpolate 2 } 0.8 rotate x*90 scale 1.5 } }
sphere { <1.5, 1, 1>, 1 texture { image_pattern { png "images/colours16.png" map_type 1 }
  texture_map { [0 pigment { rgb <1,0,0> }] [1 pigment { rgb <0,0,1> } finish { phong 1 }] } } }
