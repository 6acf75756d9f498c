// atmosphere_constant_fog_turbulence: constant fog stirred by vector turbulence under
// the global noise_generator 1; the fog's transformations turn nothing (no up for a constant
// fog) and leave the turbulence in place
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 1 }
background { rgb <0.3, 0.4, 0.6> }
camera { location <0, 1.5, -4> look_at <0, 1, 3> angle 55 }
light_source { <-4, 9, -6> rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.85, 0.8> rgb <0.25, 0.3, 0.4> } }
sphere { <0.5, 1, 3>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
box { <-3, 0, 5>, <-1.5, 2.5, 6.5> pigment { rgb <0.3, 0.8, 0.3> } rotate y*15 }
plane { -z, -14 pigment { rgb <0.1, 0.1, 0.2> } }
fog { distance 9 colour rgbf <0.95, 0.9, 0.8, 0.2> turbulence <1.2, 0.4, 0.8> turb_depth 0.8 octaves 5 omega 0.55 lambda 2.2 rotate 30*x translate 2 }
