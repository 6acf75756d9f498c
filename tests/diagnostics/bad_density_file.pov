// error: 5:42 cannot read density file "broken.df3"
// error-text: do not fit 2 x 2 x 2 voxels

#version 3.7;
sphere { 0, 1 pigment { density_file df3 "broken.df3" } }
