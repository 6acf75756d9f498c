// Where several media act at once, all their scattering takes the mean of their phase
// functions (measured in POV-Ray 3.7). Top: a Mie haze box overlapping an isotropic one,
// both seen against a light ahead (the haze's forward peak is halved where they overlap);
// middle: Mie haze and an emitting media in one interior (the emitting media counts as
// isotropic); bottom: a Mie haze box in an isotropic atmosphere (not mixed).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> direction z right x * 4 up y * 3 }
background { rgb 0 }
light_source { <0, 100, 1000>, 0.15 }
media { scattering { 1, 0.00003 extinction 0 } }
#declare Haze = media { samples 4 scattering { 2, 0.12 extinction 0 } }
box { <-3, 0.6, 0>, <3, 1.4, 4> hollow pigment { rgbf 1 } interior { media { Haze } } }
box { <-3, 0.6, 2>, <3, 1.4, 6> hollow pigment { rgbf 1 }
  interior { media { samples 2 scattering { 1, <0.1, 0.2, 0.4> extinction 0 } } } }
box { <-3, -0.4, 0>, <3, 0.4, 4> hollow pigment { rgbf 1 }
  interior { media { Haze } media { emission <0, 0, 0.02> } } }
box { <-3, -1.4, 0>, <3, -0.6, 4> hollow pigment { rgbf 1 } interior { media { Haze } } }
plane { -z, -2000 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }
