// radiosity_no_radiosity: radiosity_sky with a blue wall behind the sphere that gathering rays
// pass through (no_radiosity): it shows, but neither shades nor tints the floor and sphere
#version 3.7;
global_settings { radiosity { } }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 50 }
sphere { 0, 100 inverse pigment { rgb 1 } finish { diffuse 0 emission 1 } }
box { <-3, 0, 1.5>, <3, 3, 1.7> pigment { rgb <0.2, 0.3, 0.9> } no_radiosity }
plane { y, 0 pigment { rgb 0.7 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <0.8, 0.5, 0.3> } }
