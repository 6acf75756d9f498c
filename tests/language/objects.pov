// Every supported object statement evaluates (no rendering).
#version 3.7;
#declare Ball = sphere { <0, 0, 0> 1 }   // no comma between centre and radius
#declare Red = rgb <1, 0, 0>;
camera { location <0, 2, -5> look_at 0 angle 60 }
light_source { <10, 10, -10> color rgb 1 }
light_source { <0, 5, 0>, rgb <1, 1, 1> spotlight point_at 0 radius 10 falloff 20 tightness 5 }
background { color rgb <0.1, 0.2, 0.3> }
global_settings { assumed_gamma 1.0 max_trace_level 8 ambient_light rgb 1 }
object { Ball pigment { Red } translate x }
box { -1, 1 texture { pigment { checker rgb 1, rgb 0 scale 0.5 } finish { phong 0.5 } } }
plane { y, -1 pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } } }
cylinder { 0, y, 0.5 open }
cone { 0, 1, y, 0.5 }
torus { 1, 0.25 rotate 90*x }
disc { 0, y, 1, 0.5 }
quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 }
triangle { 0, x, y }
union { sphere { 0, 1 } box { 0, 1 } pigment { Red } }
intersection { sphere { 0, 1 } box { 0, 1 } }
difference { sphere { 0, 1 } box { 0, 1 } inverse }
merge { sphere { 0, 1 } sphere { x, 1 } pigment { rgbf <1, 1, 1, 0.9> } interior { ior 1.5 } hollow }
sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0> transform { scale 2 translate y } no_shadow }
sphere { 0, 1 finish { ambient 0.2 diffuse 0.7 brilliance 2 specular 0.5 roughness 0.01 metallic reflection 0.3 } }
#if (true) union { #else merge { #end sphere { 0, 1 } }
