// error: 5:42 cannot read image "bad_header.ppm"
// error-text: preamble

#version 3.7;
box { 0, 1 pigment { image_pattern { ppm "bad_header.ppm" } } }
