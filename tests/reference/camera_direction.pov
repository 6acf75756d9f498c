// Tests: camera given by explicit direction, right and up vectors (no look_at): a long
// direction zooms in; up is shorter than right over 4/3 so the image is stretched vertically.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.5, -8>
  direction <0, 0, 2>
  right x*4/3
  up y*0.8
}
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.25, 0.2, 0.3> }

plane { y, 0 pigment { checker rgb 0.85 rgb 0.55 } }
sphere { <-1, 0.8, 0>, 0.8 pigment { rgb <0.3, 0.5, 0.9> } }
box { <0.3, 0, -0.5>, <1.5, 1.2, 0.7> rotate y*20 pigment { rgb <0.9, 0.5, 0.2> } }
