// photons_light_items: a light's own `photons { refraction on reflection on }` makes
// objects without their own `refraction` / `reflection` item refract and reflect its
// photons: the left glass target and the mirror cast caustics; the right glass target
// says `refraction off` itself and casts only a shadow.
#version 3.7;
global_settings { photons { spacing 0.01 } }
camera { location <0, 7, -4> look_at <0, 0, 0> angle 55 }
light_source { <-3, 15, -2> rgb 1 photons { refraction on reflection on } }
plane { y, 0 pigment { rgb 0.7 } }
#declare Glass = material {
  texture { pigment { rgbf <1, 0.85, 0.7, 1> } }
  interior { ior 1.5 }
}
sphere { <-1.8, 1, 0>, 0.6 material { Glass } photons { target } }
sphere { <1.8, 1, 0>, 0.6 material { Glass } photons { target refraction off } }
box {
  <-0.6, 0, -0.05>, <0.6, 1.5, 0.05> rotate y*20 translate <0, 0, 1.5>
  pigment { rgb 0.1 } finish { reflection 0.9 }
  photons { target }
}
