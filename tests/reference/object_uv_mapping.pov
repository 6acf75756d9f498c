// object_uv_mapping: `uv_mapping` written among an object's modifiers maps every texture, pigment and normal given after it by uv, and transformations after it leave them in place (advanced/benchmark writes it)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.2, 0> }
light_source { <3, 5, -5> rgb 1 }
sphere { <-1.4, 0.3, 0>, 0.5 uv_mapping scale 2 pigment { checker rgb 1 rgb <1, 0.2, 0.1> scale 0.1 } }
sphere { <1.2, 0.3, 0>, 1
  uv_mapping
  texture { pigment { checker rgb 1 rgb <0.1, 0.3, 1> scale <0.125, 0.25, 1> } }
  texture { pigment { gradient x color_map { [0 rgbt <0, 1, 0, 0.2>] [0.5 rgbt 1] [1 rgbt 1] } scale 0.5 } }
  normal { bumps 0.5 scale 0.05 }
  rotate 30*y
}
plane { y, -0.7 pigment { checker rgb 1 rgb 0.6 } }
