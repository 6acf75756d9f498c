// light_group_nested: nested light groups: the inner sphere is lit by the inner group's
// light only (not the outer one's), and by the scene light because the outer group has
// global_lights on while the inner one leaves it off (the outermost setting counts)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 55 }
background { rgb 0.1 }
light_source { <-6, 8, -5> rgb <0.5, 0.5, 0.6> }
plane { y, 0 pigment { rgb 0.8 } }
light_group {
  light_source { <3, 3, -3> rgb <1, 0.3, 0.2> }
  sphere { <-1.5, 1, 0>, 0.9 pigment { rgb 1 } }
  light_group {
    light_source { <-3, 3, -3> rgb <0.2, 0.3, 1> }
    sphere { <1.5, 1, 0>, 0.9 pigment { rgb 1 } }
  }
  global_lights on
}
