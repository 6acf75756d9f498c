// error: 4:28 this `texture_map` entry has a key but nothing after it

#version 3.7;
#declare M = texture_map { [0.5] }
