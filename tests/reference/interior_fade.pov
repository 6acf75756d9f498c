// Tests: interior fading: fade_distance, fade_power 1 and 2 and exponential (1001), with a
// fade_color, on transparent slabs and a glass sphere.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.9, 0.9, 0.9> }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.2, 0.5> } }
box { <-3, 0.01, -1>, <-1.2, 2, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { fade_distance 1 fade_power 1 } }
box { <-1, 0.01, -0.5>, <1, 2, 0.5> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { fade_distance 0.6 fade_power 2 fade_color <1, 0.4, 0.1> } }
sphere { <2.1, 1, 0>, 1 pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 phong 0.5 }
  interior { ior 1.4 fade_distance 0.8 fade_power 1001 fade_color <0.2, 0.6, 1> } }
