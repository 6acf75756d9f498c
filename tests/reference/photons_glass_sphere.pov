// photons_glass_sphere: a tinted glass sphere focuses a photon caustic on the floor
#version 3.7;
global_settings { photons { spacing 0.008 } }
camera { location <0, 6, -6> look_at <0, 0, 0> angle 30 }
light_source { <0, 30, 0> rgb 0.35 }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 1, 0>, 0.5
  pigment { rgbf <1, 0.85, 0.6, 0.95> }
  interior { ior 1.5 }
  photons { target refraction on reflection off collect off }
}
