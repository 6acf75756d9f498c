// Tests: variable reflection: min/max with falloff, fresnel (with the interior's ior),
// reflection metallic and exponent, on spheres over a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> angle 55 }
light_source { <-4, 8, -6> rgb 1 }
background { rgb <0.3, 0.45, 0.7> }
plane { y, 0
  pigment { checker rgb <0.8, 0.8, 0.8> rgb <0.25, 0.25, 0.3> }
  finish { reflection { 0.05, 0.8 falloff 2 } }
}
sphere { <-2.2, 1, 0>, 1 pigment { rgb <0.2, 0.2, 0.25> }
  finish { diffuse 0.3 reflection { 1 fresnel } } interior { ior 1.5 } }
sphere { <0, 1, 0.5>, 1 pigment { rgb <0.9, 0.6, 0.2> }
  finish { ambient 0 diffuse 0.2 reflection { 0.9 metallic } } }
sphere { <2.2, 1, 0>, 1 pigment { rgb <0.3, 0.3, 0.3> }
  finish { diffuse 0.3 reflection { 0.1, 0.7 exponent 0.6 } } }
