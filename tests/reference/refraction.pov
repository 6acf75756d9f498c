// Tests: refraction: a glass sphere (ior 1.5) and a smaller water-like one (ior 1.33) in
// front of a checker wall and floor; the big sphere shows the wall inverted.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 1.5, -6> look_at <0, 1, 0> angle 50 }
light_source { <-3, 7, -6> rgb 1 }

plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.9> rgb <0.3, 0.3, 0.3> } }
plane { z, 2.5 pigment { checker rgb <0.9, 0.3, 0.2> rgb <0.95, 0.9, 0.8> scale 0.5 } }
sphere { <-0.6, 1.1, 0>, 1.1
  pigment { rgbf <0.98, 0.98, 0.98, 0.95> }
  finish { ambient 0 diffuse 0 phong 0.6 phong_size 80 }
  interior { ior 1.5 }
}
sphere { <1.6, 0.6, -0.8>, 0.6
  pigment { rgbf <0.8, 0.9, 1, 0.9> }
  finish { ambient 0 diffuse 0.05 }
  interior { ior 1.33 }
}
