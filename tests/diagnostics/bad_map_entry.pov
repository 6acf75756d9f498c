#version 3.7;
plane { y, 0 pigment { gradient x pigment_map { [0 rgb 1] [rgb 0] } } }
