// A function pattern choosing whole textures (texture_map) and bumping a normal with an
// amount after it; the pigment form is in vector_functions.pov.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 45 }
light_source { <-4, 8, -6>, rgb 1 }
#declare Matte = texture { pigment { rgb <0.8, 0.3, 0.2> } finish { diffuse 0.8 } }
#declare Shiny = texture { pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.8 reflection 0.2 } }
plane { y, 0
  texture { function { abs(sin(x * 2) * cos(z * 2)) } texture_map { [0.3 Matte] [0.7 Shiny] } }
}
sphere { <0, 1, 0>, 1
  pigment { rgb 0.8 }
  normal { function { abs(sin(y * 8)) } 0.6 }
}
