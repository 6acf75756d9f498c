#version 3.7;
plane { y, 0 pigment { image_map { png "no_such_image.png" filter 300, 0.5 } } }
