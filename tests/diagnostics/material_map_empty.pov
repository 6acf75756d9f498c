// error: 5:24 lists no textures
// error-text: expected `texture { .. }` entries

#version 3.7;
plane { y, 0 texture { material_map { png "images/palette8.png" } } }
