// error: 4:45 the noise generator must be 0, 1, 2 or 3

#version 3.7;
plane { y, 0 pigment { bozo noise_generator 4 } }
