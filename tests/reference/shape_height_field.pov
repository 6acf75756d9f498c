// shape_height_field: an 8-bit grey PNG height field (flat triangles), the same image smooth
// with a water level, and a function height field.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.2, -5> look_at <0, 0.3, 0.4> angle 55 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
height_field { png "data/hf_wave.png"
  pigment { rgb <0.9, 0.3, 0.2> }
  translate <-0.5, 0, -0.5> scale <1.6, 0.6, 1.6> rotate <0, 20, 0> translate <-1.7, 0, 0.4> }
height_field { png "data/hf_wave.png" smooth water_level 0.45
  pigment { rgb <0.2, 0.5, 0.9> } finish { phong 0.4 }
  translate <-0.5, 0, -0.5> scale <1.6, 0.6, 1.6> translate <0, 0, 0.6> }
height_field { function 20, 16 { 0.5 + 0.4 * sin(6 * x) * y }
  pigment { rgb <0.3, 0.8, 0.3> }
  translate <-0.5, 0, -0.5> scale <1.6, 0.6, 1.6> rotate <0, -20, 0> translate <1.7, 0, 0.4> }
