// Tests: interior fading dims only the light that comes through a surface from inside, not
// the finish reflection met there: thick glass slabs with fade, seen from above (no total
// internal reflection), with `reflection 0.5`, `reflection { 0, 1 fresnel }` and
// conserve_energy; opaque bars above the slabs hide where they meet.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 9, -4> look_at <0, 0, 0> angle 60 }
light_source { <-3, 10, -6> rgb 1 }
background { rgb 1 }
plane { y, -3 pigment { checker rgb 0.3 rgb <0.05, 0.2, 0.1> } finish { ambient 0.3 diffuse 0.7 } }
#declare Fade = interior { ior 1.5 fade_distance 1 fade_power 1001 fade_color <0.35, 0.42, 0.85> }
box { <-20, -1, -20>, <-1.5, 0, 20>
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0.5 } }
  interior { Fade } }
box { <-1.5, -1, -20>, <1.5, 0, 20>
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } conserve_energy } }
  interior { Fade } }
box { <1.5, -1, -20>, <20, 0, 20>
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0.5 conserve_energy } }
  interior { Fade } }
box { <-2.1, 0.01, -20>, <-0.9, 0.3, 20> pigment { rgb 0.3 } }
box { <0.9, 0.01, -20>, <2.1, 0.3, 20> pigment { rgb 0.3 } }
