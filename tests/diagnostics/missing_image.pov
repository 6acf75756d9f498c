// error: 6:40 cannot find image file `no_such_image.png`
// error-text: searched:
// error-text: diagnostics

#version 3.7;
plane { y, 0 pigment { image_map { png "no_such_image.png" } } }
