// Function patterns: `pigment { function { .. } }` with colour maps, values beyond [0, 1]
// (which wrap), a declared function called inside, and a wave type.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -5> look_at 0 right 4 * x up 3 * y }
light_source { <0, 0, -10> rgb 1 }
#declare Ring = function(a, b) { sqrt(a * a + b * b) }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <0.9, 0.5, 0.1>] [1 rgb <1, 1, 0.8>] }
box { <-2, 0, 0>, <0, 1.5, 1> pigment { function { abs(y) } color_map { Map } } finish { ambient 1 diffuse 0 } }
box { <0, 0, 0>, <2, 1.5, 1> pigment { function { Ring(x, y) * 1.7 } color_map { Map } } finish { ambient 1 diffuse 0 } }
box { <-2, -1.5, 0>, <0, 0, 1> pigment { function { x * y * 3 } color_map { Map } } finish { ambient 1 diffuse 0 } }
box { <0, -1.5, 0>, <2, 0, 1> pigment { function { sin(x * 6) + y } triangle_wave color_map { Map } } finish { ambient 1 diffuse 0 } }
