#version 3.7;
plane { y, 0 pigment { agate control1 0.2 } }
