// Tests: conserve_energy: transparent spheres with fresnel reflection let through only what
// they do not reflect; the right one has no conserve_energy for comparison.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.3, 0.45, 0.7> }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.2, 0.2, 0.5> } }
box { <-3, 0, -1>, <-1, 2, 1> pigment { rgbt <1, 1, 1, 0.8> }
  finish { ambient 0 diffuse 0.1 reflection { 0.2, 1 fresnel } conserve_energy } interior { ior 1.3 } }
box { <-0.9, 0, -1>, <0.9, 2, 1> pigment { rgbf <0.6, 1, 0.6, 0.9> }
  finish { ambient 0 diffuse 0.1 reflection <0.5, 0.2, 0.1> conserve_energy } }
box { <1, 0, -1>, <3, 2, 1> pigment { rgbt <1, 1, 1, 0.8> }
  finish { ambient 0 diffuse 0.1 reflection { 0.2, 1 fresnel } } interior { ior 1.3 } }
