// photons_pass_through: where photons cross objects unchanged. Left: a part's own
// `pass_through` inside a target union is dropped (the part refracts its caustic).
// Middle: a `pass_through` sphere under a small glass target stops the photons the target
// bent (pass_through holds only on the way from the light). Right: a `no_shadow` sphere
// under a small glass target lets them through at any bounce.
#version 3.7;
global_settings { photons { spacing 0.01 } }
camera { location <0, 7, -3> look_at <0, 0, 0> angle 55 }
light_source { <0, 20, 0> rgb 1 }
plane { y, 0 pigment { rgb 0.7 } }
#declare Glass = material {
  texture { pigment { rgbf <1, 0.9, 0.7, 1> } }
  interior { ior 1.5 }
}
union {
  sphere { <-2, 1, 0>, 0.6 material { Glass } photons { pass_through } }
  sphere { <-2, 1, 1.5>, 0.4 material { Glass } }
  photons { target refraction on }
}
sphere { <0, 1, 0>, 0.6 pigment { rgbf <0.9, 1, 0.9, 0.9> } photons { pass_through } }
sphere { <0, 2.4, 0>, 0.4 material { Glass } photons { target refraction on } }
sphere { <2, 1, 0>, 0.6 pigment { rgbf <0.9, 1, 0.9, 0.9> } no_shadow }
sphere { <2, 2.4, 0>, 0.4 material { Glass } photons { target refraction on } }
