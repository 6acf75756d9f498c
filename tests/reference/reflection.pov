// Tests: reflection: a mirror sphere reflecting coloured spheres, the checker floor and the
// sky, on a slightly reflective floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.5, -6.5> look_at <0, 0.9, 0> angle 55 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.3, 0.45, 0.7> }

plane { y, 0
  pigment { checker rgb <0.8, 0.8, 0.8> rgb <0.25, 0.25, 0.3> }
  finish { reflection 0.2 }
}
sphere { <0, 1.1, 0.5>, 1.1
  pigment { rgb <0.6, 0.6, 0.6> }
  finish { ambient 0 diffuse 0.1 reflection 0.85 phong 0.8 phong_size 60 }
}
sphere { <-2, 0.5, -0.8>, 0.5 pigment { rgb <0.9, 0.2, 0.2> } }
sphere { <2, 0.5, -0.6>, 0.5 pigment { rgb <0.2, 0.8, 0.3> } }
box { <-0.6, 0, -2.4>, <0.2, 0.4, -1.8> pigment { rgb <0.9, 0.8, 0.2> } }
