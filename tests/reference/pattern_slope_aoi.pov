// Tests: slope (direction, range, altitude, point_at, turbulence) and aoi; their
// directions, points, normals and rays stay in world space whatever the pattern's
// transformations (measured), values outside the range wrap like any pattern value.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0,0,-10> look_at 0 right 8*x up 6*y }
#declare M = color_map { [0 rgb 0] [1 rgb 1] }
#macro S(P, X, Y) sphere { <X,Y,0>, 0.95 pigment { P } finish { ambient 1 diffuse 0 } } #end
S(pigment { slope { y } color_map { M } }, -3, 2)
S(pigment { slope { -y*3, 0, 0.5 } color_map { M } }, -1, 2)
S(pigment { slope { y, 0.3, 0.7 altitude y, -0.5, 0.5 } color_map { M } }, 1, 2)
S(pigment { slope { x altitude y*2, 1.5, 2.5 } color_map { M } }, 3, 2)
S(pigment { slope { y } color_map { M } rotate 90*z }, -3, 0)
S(pigment { slope { y } color_map { M } scale <1,3,1> }, -1, 0)
S(pigment { slope { point_at <1,0,-3> } color_map { M } }, 1, 0)
S(pigment { slope { point_at <0,0,-3>, 0.2, 0.8 } color_map { M } translate <3,0,0> }, 3, 0)
S(pigment { aoi color_map { M } }, -3, -2)
S(pigment { aoi color_map { M } scale <3,1,1> }, -1, -2)
S(pigment { slope { y, 0.5, 1 } turbulence 0.3 color_map { M } }, 1, -2)
S(pigment { aoi frequency 2 color_map { M } }, 3, -2)
