// blob component textures: filtering components of a refracting blob cut by an intersection, and a difference cut into a two-coloured blob.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 8, -4> rgb 1 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
intersection {
  blob { threshold 0.5
    sphere { <-0.7, 0, 0>, 1.2, 1 pigment { rgbf <1, 0.3, 0.3, 0.9> } finish { specular 0.6 } }
    sphere { <0.7, 0, 0>, 1.2, 1 pigment { rgbf <0.3, 1, 0.3, 0.9> } finish { specular 0.6 } }
    cylinder { <0, -0.5, 0>, <0, 0.8, 0>, 0.7, 1 }
    pigment { rgbf <0.4, 0.4, 1, 0.9> }
    interior { ior 1.4 }
  }
  box { <-3, -3, -0.3>, <3, 3, 3> }
  rotate y*20
}
difference {
  blob { threshold 0.5
    sphere { <-0.5, 0, 0>, 0.8, 1 pigment { rgb <1, 1, 0> } }
    sphere { <0.5, 0, 0>, 0.8, 1 pigment { rgb <1, 0, 1> } }
  }
  sphere { <0, 0.3, -0.4>, 0.35 pigment { rgb <0, 1, 1> } }
  translate <1.6, -0.6, -1.2>
}
