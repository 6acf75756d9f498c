// error: 6:34 expected an object, found
// error-text: the `object` pattern needs an object

#version 3.7;
#declare Size = 3;
sphere { 0, 1 pigment { object { Size color rgb 0, color rgb 1 } } }
