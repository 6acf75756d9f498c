// height_field_pot: a Fractint continuous potential file (`pot`): a GIF twice as wide as the
// field whose left half holds the high bytes and right half the low bytes of 16-bit heights
// (the small ripples along x come from the low bytes). The file is interlaced: POV-Ray takes
// its rows in stored order, so the dome comes out with terraces
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.5, 1.6, -1.2> look_at <0.5, 0.1, 0.5> angle 45 }
light_source { <-3, 5, -4> rgb 1 }
height_field { pot "images/dome24.pot" smooth
  pigment { gradient y color_map { [0 rgb <0.2, 0.4, 0.9>] [1 rgb <1, 0.9, 0.6>] } }
  finish { phong 0.5 } }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.5 scale 0.1 } }
