// radiosity_sky: a sphere on a plane lit only by an emissive sky sphere (no light sources);
// default radiosity settings, so all light is gathered indirect light
#version 3.7;
global_settings { radiosity { } }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 50 }
sphere { 0, 100 inverse pigment { rgb 1 } finish { diffuse 0 emission 1 } }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <0.8, 0.5, 0.3> } }
