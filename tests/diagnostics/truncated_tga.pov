#version 3.7;
plane { z, 1 pigment { image_map { tga "truncated.tga" } } }
