// atmosphere_mixed: a translated and scaled sky_sphere seen in mirrors through a filtering fog and a ground fog
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 1, 2> angle 60 }
light_source { <-5, 8, -6> rgb 1 }
sky_sphere { pigment { gradient y colour_map { [0 rgb <0.9, 0.8, 0.6>] [1 rgb <0.1, 0.2, 0.6>] } } translate <0.3, -0.5, 0> scale <1, 1.5, 1> }
plane { y, 0 pigment { rgb 0.5 } finish { reflection 0.5 } }
sphere { <0, 1, 2>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { reflection 0.6 } }
box { <1, 0, 4>, <2, 2, 5> pigment { rgb <0.3, 0.8, 0.3> } }
fog { distance 12 colour rgbf <0.7, 0.7, 0.8, 0.3> }
fog { fog_type 2 distance 2 colour rgbt <1, 1, 1, 0.1> fog_offset 0.2 fog_alt 0.3 }
