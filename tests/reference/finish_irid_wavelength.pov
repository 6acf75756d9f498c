// finish_irid_wavelength: `global_settings { irid_wavelength }` sets the wavelengths of
// red, green and blue as written, and irid turbulence follows the global noise_generator
#version 3.7;
global_settings { assumed_gamma 1.0 irid_wavelength rgb <0.3, 0.2, 0.45> noise_generator 1 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 30 }
light_source { <150, 150, -2500> rgb 0.9 }
sphere { <-1.5, 0.9, 0>, 1 pigment { rgb 1 } finish { diffuse 0.4 specular 0.6 roughness 0.01 irid { 0.7 thickness 0.4 } } }
sphere { <1.5, 0.9, 0>, 1 pigment { rgb 1 } finish { diffuse 0.4 irid { 0.7 thickness 0.5 turbulence 0.6 } } }
plane { z, 1.5 pigment { rgb 0.8 } finish { diffuse 0.6 irid { 0.5 thickness 0.3 turbulence 0.3 } } }
