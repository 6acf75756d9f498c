// error: 4:77 `pattern` of this pavement must be between 1 and 2

#version 3.7;
plane { y, 0 pigment { pavement number_of_sides 4 number_of_tiles 3 pattern 3 } }
