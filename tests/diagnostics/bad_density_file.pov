#version 3.7;
sphere { 0, 1 pigment { density_file df3 "broken.df3" } }
