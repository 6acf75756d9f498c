// Tests: layered textures — a layered #declare, several textures on one object (the later
// one lies on top), filter and transmit in upper layers, pigment after layers changing the
// top layer, finish per layer.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -6> look_at <0, 0.7, 0> angle 60 }
light_source { <4, 9, -6> rgb 1 }
background { rgb <0.15, 0.15, 0.2> }

#declare Layered = texture { pigment { rgb <0.9, 0.2, 0.1> } finish { phong 0.6 } }
  texture { pigment { gradient y color_map { [0 rgbt <0, 0, 0, 1>] [0.5 rgbt <1, 1, 1, 1>] [0.5 rgb 1] [1 rgb 1] } scale 0.4 } }

plane { y, 0 texture { pigment { checker rgb 0.8 rgb 0.3 } } texture { pigment { gradient x color_map { [0 rgbf <0, 0, 1, 1>] [0.5 rgbf <0, 0, 1, 0.5>] [1 rgbt <1, 0, 0, 0.7>] } scale 2 } } }
sphere { <-1.7, 0.9, 0>, 0.9 texture { Layered } }
sphere { <0, 0.9, 0>, 0.9 texture { pigment { rgb <0.1, 0.7, 0.2> } } texture { pigment { checker rgbt <1, 1, 0, 0.6> rgbt 1 scale 0.3 } finish { ambient 0.3 diffuse 0.4 } } }
sphere { <1.7, 0.9, 0>, 0.9 texture { Layered } pigment { rgbf <0.2, 0.4, 1, 0.7> } }
