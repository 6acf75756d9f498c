// material_transform: a material without a texture keeps the object's pigment, and a transformation inside material moves what comes before it (texture and interior media), not what follows
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { rgb <0.9, 0.9, 0.85> }
camera { location <0, 0.5, -6> look_at <0, 0, 0> angle 55 }
light_source { <-4, 6, -6> rgb 1 }
#declare Checks = texture { pigment { checker rgb 1 rgb <0.8, 0.2, 0.1> scale 0.5 } }
#declare Band = interior { media { absorption 3 density { gradient x color_map { [0 rgb 0] [0.5 rgb 1] [1 rgb 0] } } } }
sphere { <-2.2, 1, 0>, 0.9 pigment { rgb <0.2, 0.4, 0.9> } material { interior { ior 1.0 } } }
sphere { <0, 1, 0>, 0.9 material { texture { Checks } translate <0.25, 0.25, 0> } }
sphere { <2.2, 1, 0>, 0.9 material { translate <0.25, 0.25, 0> texture { Checks } } }
sphere { <-1.1, -1.1, 0>, 0.9 pigment { rgbt 1 } hollow material { interior { Band } translate 0.5*x } }
sphere { <1.1, -1.1, 0>, 0.9 pigment { rgbt 1 } hollow material { translate 0.5*x interior { Band } } }
