// material_in_csg: a `material { texture { .. } interior { .. } }` written inside a CSG
// gives the whole CSG its texture and interior (a glass paperweight, as in desk.pov)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> angle 45 }
light_source { <10, 10, -5>*1000 rgb 1.1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 scale 0.5 } finish { ambient 0.15 diffuse 0.8 } }
intersection {
  sphere { <0, -0.8, 0>, 2 }
  plane { -y, 0 }
  material {
    texture {
      pigment { color rgbf <0.8, 1, 0.95, 0.9> }
      finish { specular 0.8 roughness 0.002 reflection 0.1 }
    }
    interior { ior 1.5 }
  }
  translate 0.01*y
}
