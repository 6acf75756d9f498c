// error: 5:56 radiosity importance 1.5 is out of range
// error-text: above 0 and at most 1

#version 3.7;
sphere { 0, 1 pigment { rgb 1 } radiosity { importance 1.5 } }
