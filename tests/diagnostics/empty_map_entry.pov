#version 3.7;
#declare M = texture_map { [0.5] }
