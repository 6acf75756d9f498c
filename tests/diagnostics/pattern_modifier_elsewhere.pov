// error: 4:45 `mortar` only applies to brick

#version 3.7;
plane { y, 0 pigment { checker rgb 1, rgb 0 mortar 0.2 } }
