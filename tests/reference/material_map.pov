// material_map: palette indices (palette PNG) and 8-bit red values (RGB PNG) choose
// textures; an index equal to the texture count picks the last, larger ones wrap (measured)
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.3, 0.4, 0.5> }
camera { location <0, 3, -4> look_at <0, 0.3, 0> angle 60 }
light_source { <-3, 8, -6> rgb 1 }
plane { y, 0
  texture { material_map { png "images/palette8.png"
      texture { pigment { rgb <1, 0.2, 0.1> } }
      texture { pigment { rgb <0.1, 0.8, 0.2> } finish { phong 0.8 } }
      texture { pigment { checker rgb 1 rgb 0.2 scale 0.05 } }
      texture { pigment { rgb <0.2, 0.3, 1> } } }
    rotate x*90 scale 3 translate <-1.5, 0, -1> }
}
sphere { <1.3, 1, 0.5>, 1
  texture { material_map { png "images/red_index8.png" map_type 1
      texture { pigment { rgb <1, 1, 0> } }
      texture { pigment { rgb <0, 1, 1> } finish { phong 0.5 } }
      texture { pigment { rgb <1, 0, 1> } } } }
}
