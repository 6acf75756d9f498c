#version 3.7;
plane { y, 0 pigment { bozo noise_generator 4 } }
