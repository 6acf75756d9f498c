// Tests: interior fading dims only the light that comes through a surface from inside (and
// the total internal reflection standing in for it), not the finish reflection: glass boxes
// with fade, `reflection { 0, 1 fresnel }` with and without conserve_energy, and a plain
// `reflection 0.3 conserve_energy` one.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 6, -9> look_at <0, 1.2, 0> angle 50 }
light_source { <10, 10, -5>*1000 rgb 1.1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.6, 0.6, 0.7> } finish { ambient 0.15 diffuse 0.8 } }
#declare Fade = interior { ior 1.5 fade_distance 0.5 fade_power 1001 fade_color <0.35, 0.42, 0.85> }
box { <-1, 0, -1>, <1, 2, 1> translate <-2.6, 0.01, 0>
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } conserve_energy } }
  interior { Fade } }
box { <-1, 0, -1>, <1, 2, 1> translate <0, 0.01, 0>
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } } }
  interior { Fade } }
box { <-1, 0, -1>, <1, 2, 1> translate <2.6, 0.01, 0>
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0.3 conserve_energy } }
  interior { Fade } }
