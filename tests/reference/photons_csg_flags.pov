// photons_csg_flags: a union's photons block merges into its children's item by item.
// The union's `refraction on` beats the left child's own `refraction off` (left caustic),
// the middle child keeps its own `collect off` and still casts a caustic, and the right
// child's `no_shadow` lets photons pass (no caustic, no shadow).
#version 3.7;
global_settings { photons { spacing 0.008 } }
camera { location <0, 6, -6> look_at <0, 0, 0> angle 40 }
light_source { <0, 30, 0> rgb 0.35 }
plane { y, 0 pigment { rgb 0.7 } }
#declare Glass = material {
  texture { pigment { rgbf <1, 0.85, 0.6, 0.95> } }
  interior { ior 1.5 }
}
union {
  sphere { <-1.3, 1, 0>, 0.5 material { Glass } photons { refraction off } }
  sphere { <0, 1, 0>, 0.5 material { Glass } photons { collect off } }
  sphere { <1.3, 1, 0>, 0.5 material { Glass } no_shadow }
  photons { target refraction on reflection off }
}
