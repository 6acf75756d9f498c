// area_light_modifiers_first: `circular` and `orient` written before `area_light` still
// shape the area light (POV-Ray keeps them whatever the order); `jitter` on the plain
// point light is ignored
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at 0 }
light_source { <0, 1.5, 0> rgb 1 circular orient adaptive 0 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 }
light_source { <-5, 8, -6> rgb 0.3 jitter shadowless }
box { <-0.3, 0.5, -0.3>, <0.3, 0.6, 0.3> pigment { rgb 1 } }
plane { y, 0 pigment { rgb 1 } }
