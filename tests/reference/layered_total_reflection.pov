// layered_total_reflection: where light is totally reflected inside a glass box, the layer that passes light makes the surface a perfect mirror and the reflection of layers above it adds nothing
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 15 }
light_source { <500, 50, -5> rgb 1 }
camera { location <2, 1, -4> look_at <0, 0.9, 0> angle 50 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.3, 0.05, 0.15>] [1 rgb 1] } translate -0.1*y } }
plane { y, 0 pigment { checker rgb 1 rgb <0, 0, 1> scale 0.5 } }
box { <-0.5, 0, -0.5>, <0.5, 1.8, 0.5>
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 } }
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0.3 } }
  interior { ior 1.5 } rotate 20*y translate -0.7*x }
box { <-0.5, 0, -0.5>, <0.5, 1.8, 0.5>
  texture { pigment { rgbf 0.9 } }
  texture { pigment { rgbf <0.98, 1, 0.98, 1> } finish { specular 1 roughness 0.001 ambient 0 diffuse 0 reflection { 0, 1 fresnel } } }
  interior { ior 1.5 } rotate -20*y translate 0.8*x }
