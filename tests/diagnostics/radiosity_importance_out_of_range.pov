#version 3.7;
sphere { 0, 1 pigment { rgb 1 } radiosity { importance 1.5 } }
