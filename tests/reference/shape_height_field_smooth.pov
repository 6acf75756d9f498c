// shape_height_field_smooth: POV-Ray's smoothed normals on a coarse function height field
// under a non-uniform scale, a palette PNG height field (heights from the palette index, not
// the colour) and a function whose values above 1 wrap around to low heights.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.4, -5> look_at <0, 0.2, 0.3> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
height_field { function 7, 5 { 0.3 + 0.3 * sin(5 * x) * cos(4 * y) + 0.2 * x * y } smooth
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.6 phong_size 20 }
  translate <-0.5, 0, -0.5> scale <2.2, 1.4, 1.4> rotate <0, 15, 0> translate <-1.2, 0, 0.2> }
height_field { png "images/palette8.png"
  pigment { rgb <0.9, 0.3, 0.2> }
  translate <-0.5, 0, -0.5> scale <1.4, 12, 1.4> rotate <0, -25, 0> translate <1.5, 0, 1.3> }
height_field { function 12, 8 { 0.3 + 1.0 * x * (1 - y) } smooth
  pigment { rgb <0.3, 0.8, 0.3> }
  translate <-0.5, 0, -0.5> scale <1.4, 0.7, 1.2> translate <1.3, 0, -0.6> }
