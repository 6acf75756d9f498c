// Tests: density_file df3 with 8- and 16-bit voxels (data/grid*.df3: 4 x 3 x 5 random
// voxels written by a Python script), interpolate 0, 1 and 2, turbulence; a box face cuts each
// grid at a fixed depth.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-10> look_at 0 right 8*x up 6*y }
#macro B(X, Y, P) box { <X,Y,0>, <X+2.6,Y+2.9,1> pigment { P } finish { ambient 1 diffuse 0 } } #end
B(-4,0, pigment { density_file df3 "data/grid8.df3" interpolate 0 color_map { [0 rgb 0] [1 rgb <1,0.8,0.3>] } scale <2.6,2.9,1> translate <-4,0,-0.5> })
B(-1.3,0, pigment { density_file df3 "data/grid8.df3" interpolate 1 color_map { [0 rgb 0] [1 rgb <1,0.8,0.3>] } scale <2.6,2.9,1> translate <-1.3,0,-0.5> })
B(1.4,0, pigment { density_file df3 "data/grid16.df3" interpolate 1 scale <2.6,2.9,1> translate <1.4,0,-0.5> })
B(-4,-3, pigment { density_file df3 "data/grid16.df3" scale <2.6,2.9,1> translate <-4,-3,-0.3> })
B(-1.3,-3, pigment { density_file df3 "data/grid8.df3" interpolate 2 scale <2.6,2.9,1> translate <-1.3,-3,-0.5> })
B(1.4,-3, pigment { density_file df3 "data/grid8.df3" interpolate 1 turbulence 0.2 scale <1.3,1.45,1> translate <1.4,-3,-0.5> })
