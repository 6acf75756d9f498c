// interior_fade_hit_object: an interior's fade darkens light only on the way to the object's
// own surface: nothing fades on the way out through a clipped-away part (left hemisphere),
// to another object inside (middle, a white bar), and a sphere inside a sphere fades by its
// own distance only (right)
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 8, -3> look_at <0, 0, 0> angle 50 }
plane { y, -2 pigment { checker rgb 1 rgb 0.6 scale 0.5 } finish { ambient 1 diffuse 0 } }
#declare Faded = material {
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 } }
  interior { ior 1.0 fade_distance 0.5 fade_power 1 fade_color rgb <0.9, 0.2, 0.1> }
}
sphere { <-2.2, 0, 0>, 1 clipped_by { plane { -y, 0 } } material { Faded } }
sphere { <0, 0, 0>, 1 material { Faded } }
box { <-0.3, -0.2, -1.5>, <0.3, -0.1, 1.5> pigment { rgb 1 } finish { ambient 1 diffuse 0 } }
sphere { <2.2, 0, 0>, 1 material { Faded } }
sphere { <2.2, 0, 0>, 0.5 pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.0 fade_distance 0.2 fade_power 1 fade_color rgb <0.1, 0.3, 0.9> } }
