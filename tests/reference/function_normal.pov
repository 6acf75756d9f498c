// A pigment function's member as a function pattern, and a pattern function as a normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0,0,-3> look_at 0 }
light_source { <-3,5,-5> rgb 1 }
#declare Q = function { pattern { bozo scale 0.2 } }
#declare P = function { pigment { checker rgb 1, rgb <1,0,0> scale 0.5 } }
sphere { 0, 1 pigment { function { P(x,y,z).green } color_map { [0 rgb <1,0,0>] [1 rgb 1] } } normal { function { Q(x,y,z) } 0.5 } }
