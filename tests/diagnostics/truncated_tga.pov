// error: 6:40 cannot read image "truncated.tga"
// error-text: the file ends before its last pixel
// error-text: unreadable image

#version 3.7;
plane { z, 1 pigment { image_map { tga "truncated.tga" } } }
