// error: 5:60 a `pigment_map` entry starts with its key, a float
// error-text: expected a float key

#version 3.7;
plane { y, 0 pigment { gradient x pigment_map { [0 rgb 1] [rgb 0] } } }
