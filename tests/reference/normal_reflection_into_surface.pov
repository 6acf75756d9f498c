// normal_reflection_into_surface: reflections a steep perturbed normal sends into the
// surface — mirrored about the unperturbed normal where the ray meets the perturbed normal
// from behind, otherwise mirrored once more about the surface plane. The sky's colour
// shows the reflected direction.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -4> look_at <0, 0, 0> angle 60 }
sky_sphere { pigment { average pigment_map {
  [1 function { 0.5 + 0.5 * x } color_map { [0 rgb 0] [1 rgb <3, 0, 0>] }]
  [1 function { 0.5 + 0.5 * y } color_map { [0 rgb 0] [1 rgb <0, 3, 0>] }]
  [1 function { 0.5 + 0.5 * z } color_map { [0 rgb 0] [1 rgb <0, 0, 3>] }] } } }
plane { y, 0 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } normal { gradient x 12 scale 4 } }
sphere { <1.2, 0.6, 1>, 0.6 pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } normal { bumps 3 scale 0.2 } }
