#version 3.7;
#declare Bigger = 3 > 2;
