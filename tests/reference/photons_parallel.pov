// photons_parallel: a parallel light's photons focus through a glass sphere onto the floor
#version 3.7;
global_settings { photons { spacing 0.02 } }
camera { location <0, 6, -6> look_at <0, 0, 0> angle 30 }
light_source { <2, 10, -1> rgb 0.6 parallel point_at <0, 0, 0> }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 1, 0>, 0.6
  pigment { rgbf <1, 0.9, 0.7, 0.95> }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}
