// material_declared: a declared material keeps its interior (ior, fade colour) when an
// object uses it through `material { M }`
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 3, -6> look_at <0, 1, 0> angle 45 }
light_source { <10, 10, -5>*1000 rgb 1.1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.6 } finish { ambient 0.15 diffuse 0.8 } }
#declare Glass = material {
  texture { pigment { rgbf 1 } finish { specular 0.8 roughness 0.002 reflection 0.1 } }
  interior { ior 1.5 fade_distance 1 fade_power 2 fade_color rgb <0.35, 0.42, 0.85> }
}
#declare Tinted = material { Glass interior { ior 1.3 fade_distance 0.5 fade_power 1 fade_color rgb <0.9, 0.3, 0.2> } }
object { sphere { <-1.1, 1, 0>, 1 } material { Glass } }
object { sphere { <1.1, 1, 0>, 1 } material { Tinted } }
