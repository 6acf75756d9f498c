// Tests: looks_like: the shape sits at the light's position (moved with the light) and
// does not block its light; projected_through: light only passes through a ring.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.8, 0> angle 50 }
light_source { <0, 2.5, 0> rgb 0.8
  looks_like { sphere { 0, 0.3 pigment { rgb <1, 0.9, 0.5> } finish { ambient 1 diffuse 0 } } }
  translate <-1.5, 0, 0> }
#declare Hole = disc { <0, 4, 0>, y, 1.2, 0.5 }
light_source { <2, 7, 0> rgb 0.5 projected_through { Hole } }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <0.6, 0.6, -0.5>, 0.6 pigment { rgb <0.3, 0.6, 0.9> } }
