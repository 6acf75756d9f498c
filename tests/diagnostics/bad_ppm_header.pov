#version 3.7;
box { 0, 1 pigment { image_pattern { ppm "bad_header.ppm" } } }
