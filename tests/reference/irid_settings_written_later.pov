// `irid_wavelength` and `noise_generator` written in a `global_settings` after the finish
// still apply to its irid (POV-Ray reads the scene's last settings when shading).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at 0 angle 40 }
light_source { <-3, 5, -4> rgb 1 }
sphere { 0, 1.5
  pigment { rgb 0.5 }
  finish { irid { 0.6 thickness 0.5 turbulence 0.8 } }
}
plane { y, -1.5 pigment { rgb 0.4 } finish { irid { 0.5 thickness 0.3 } } }
global_settings { irid_wavelength rgb <0.3, 0.5, 0.7> noise_generator 3 }
