// A flat colour beyond the 0..1 range over a transparent background: the output-format tests
// read the files back (8- and 16-bit values through the sRGB curve, linear floats in EXR and
// HDR unclamped, alpha 0 on the background).
#version 3.7;
global_settings { assumed_gamma 1 }
background { rgbt <0.2, 0.3, 0.4, 1> }
camera { orthographic location <0, 0, -5> look_at 0 right x*4 up y*3 }
box { <-2, -1.5, 0>, <0, 1.5, 1> pigment { rgb <0.5, 0.25, 2.0> } finish { ambient 1 diffuse 0 } }
