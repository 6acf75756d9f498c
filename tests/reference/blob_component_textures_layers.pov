// blob component textures: a bumpy component beside default-textured ones, filtering and transmitting components and their shadows, a layered component texture, components inheriting a union's texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0, 0> angle 55 }
light_source { <-3, 8, -4> rgb 1 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.6 } }
// the blob has no texture: the untextured component shows the default one
blob { threshold 0.5
  sphere { <-2.2, 0, 0>, 0.9, 1 texture { pigment { rgb <0.2, 0.9, 0.3> } normal { bumps 0.8 scale 0.15 } finish { phong 0.6 } } }
  sphere { <-1.4, 0, 0>, 0.9, 1 }
}
blob { threshold 0.5
  sphere { <-0.4, 0, 0>, 0.9, 1 pigment { rgbf <1, 0.2, 0.2, 0.8> } }
  sphere { <0.4, 0, 0>, 0.9, 1 pigment { rgbt <0.2, 0.2, 1, 0.7> } }
  translate <0, 0.2, -0.8>
}
union {
  blob { threshold 0.5
    sphere { <1.4, 0, 0>, 0.9, 1
      texture { pigment { rgb <1, 1, 0> } }
      texture { pigment { checker rgb <1, 0, 0> rgbt 1 scale 0.2 } }
    }
    sphere { <2.2, 0, 0>, 0.9, 1 }
    cylinder { <1.4, 0, 0>, <2.2, 0.8, 0>, 0.5, 1 texture { pigment { rgb <0, 1, 1> } finish { reflection 0.3 } } }
  }
  texture { pigment { rgb <0.7, 0.3, 0.9> } }
}
