// photons_mirror: a tilted mirror reflects a patch of photons onto a wall, a slab of
// index 1 lets photons through to the floor as bright as direct light
#version 3.7;
global_settings { photons { spacing 0.02 } }
camera { location <0, 4, -7> look_at <0, 1, 0> angle 45 }
light_source { <-1, 9, -2> rgb 0.7 }
plane { y, 0 pigment { rgb 0.6 } }
plane { z, 3 pigment { rgb <0.8, 0.85, 0.9> } finish { diffuse 0.8 } }
box { <-0.6, -0.05, -0.6>, <0.6, 0.05, 0.6>
  pigment { rgb 0.2 } finish { reflection { 0.9 metallic } diffuse 0.1 }
  rotate x * 40 translate <1.2, 1.2, -1>
  photons { target reflection on collect off }
}
box { <-0.7, 0, -0.7>, <0.7, 0.1, 0.7>
  pigment { rgbf <1, 1, 1, 1> }
  interior { ior 1.0 }
  translate <-1.5, 2.2, -1.5>
  photons { target refraction on collect off }
}
