// error: 4:25 the `slope` direction must not be zero

#version 3.7;
sphere { 0, 1 pigment { slope { 0 } } }
