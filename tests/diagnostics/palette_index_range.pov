// error: 5:60 palette index 300 is outside 0 to 255
// error-text: no such palette entry

#version 3.7;
plane { y, 0 pigment { image_map { png "no_such_image.png" filter 300, 0.5 } } }
