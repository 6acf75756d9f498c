// error: 4:30 `control1` only applies to quilted

#version 3.7;
plane { y, 0 pigment { agate control1 0.2 } }
