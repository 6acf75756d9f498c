// Tests: interior fading with fade_power 0: camera rays through the objects fade by one half,
// shadow rays do not fade at all (POV-Ray skips shadow fading unless fade_power > 0); a
// fade_power 1 box beside them fades both.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> angle 55 }
light_source { <2, 8, -4> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.2, 0.5> } }
box { <-3, 0.3, -0.6>, <-1.4, 1.5, 0.6> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { fade_distance 0.5 fade_power 0 } }
sphere { <0, 0.9, 0>, 0.8 pigment { rgbf <1, 0.8, 0.6, 1> } finish { ambient 0 diffuse 0 }
  interior { fade_distance 1 fade_power 0 fade_color <0.2, 0.5, 1> } }
box { <1.4, 0.3, -0.6>, <3, 1.5, 0.6> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }
  interior { fade_distance 0.5 fade_power 1 } }
