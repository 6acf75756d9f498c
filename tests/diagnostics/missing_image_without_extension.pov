// error: 7:41 cannot find image file `no_such_image`
// error-text: searched:
// error-text: also tried `no_such_image.jpg`, `no_such_image.jpeg`

#version 3.7;
// POV-Ray tries the type's extensions for a name without one; none exists here.
plane { y, 0 pigment { image_map { jpeg "no_such_image" } } }
