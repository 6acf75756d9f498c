// Map entry forms POV-Ray accepts: colour components written as keywords in a colour_map entry
// (`[0.5 green 0.6]`), and `average` map entries without a weight (weighed 1).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
light_source { <0, 0, -10> rgb 1 }
box { <-2, 0, 0>, <2, 1.5, 1>
  pigment { gradient x color_map { [0 rgb <0.2, 0, 0>] [0.5 green 0.6] [1 rgb 1 blue 0.2] } scale 4 translate -2 * x }
  finish { ambient 1 diffuse 0 }
}
box { <-2, -1.5, 0>, <2, 0, 1>
  pigment { average pigment_map { [gradient x color_map { [0 rgb 0] [1 rgb <1, 0, 0>] }] [2 gradient y color_map { [0 rgb 0] [1 rgb <0, 0, 1>] }] } scale 2 }
  finish { ambient 1 diffuse 0 }
}
