// slope_bare_direction: POV-Ray 3.5's `slope DIRECTION` without braces, in a pigment and straight inside a texture with a texture_map (advanced/balcony writes it)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 0.3, 0> }
light_source { <3, 5, -5> rgb 1 }
sphere { <-1.3, 0.3, 0>, 1 pigment { slope y color_map { [0 rgb <1, 0.2, 0.1>] [1 rgb <0.1, 0.3, 1>] } } }
sphere { <1.3, 0.3, 0>, 1
  texture {
    slope -z
    texture_map {
      [0.4 pigment { rgb <0.2, 0.7, 0.2> } finish { phong 0.5 }]
      [0.4 pigment { rgb <0.9, 0.8, 0.7> }]
    }
  }
}
plane { y, -0.7 pigment { checker rgb 1 rgb 0.6 } }
