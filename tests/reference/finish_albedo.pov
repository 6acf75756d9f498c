// Tests: brilliance and albedo: `diffuse albedo` scales by (brilliance + 1) / 2, `phong
// albedo` by (phong_size + 1) / 2 and `specular albedo` by the normalised Blinn factor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 0.8, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
sphere { <-2.4, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.3> } finish { brilliance 4 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.3, 0.6, 0.9> }
  finish { diffuse albedo 0.5 brilliance 2 phong albedo 0.05 phong_size 20 } }
sphere { <2.4, 1, 0>, 1 pigment { rgb <0.4, 0.8, 0.3> }
  finish { diffuse albedo 0.6 brilliance 0.5 specular albedo 0.1 roughness 0.02 } }
