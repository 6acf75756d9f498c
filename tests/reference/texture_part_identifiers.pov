// texture_part_identifiers: pigment, finish and normal identifiers written straight inside texture { }, and `y (-1)` read as a normal and a distance
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -5> look_at <0, 0.3, 0> angle 50 }
light_source { <-4, 6, -5> rgb 1 }
#declare Red = pigment { rgb <0.9, 0.2, 0.1> }
#declare Blue = pigment { rgb <0.2, 0.3, 0.9> }
#declare Shiny = finish { phong 0.9 phong_size 40 }
#declare Bumpy = normal { bumps 0.6 scale 0.15 }
#declare Green = texture { pigment { rgb <0.2, 0.8, 0.3> } finish { Shiny } }
#declare Down = <0, 1, 0>;
plane { y (-1) pigment { checker rgb 0.9 rgb 0.4 } }
plane { Down (-3) pigment { rgb 1 } }
sphere { <-1.6, 0, 0>, 0.7 texture { Red Shiny Bumpy } }
sphere { <0, 0, 0>, 0.7 texture { Green Blue } }
sphere { <1.6, 0, 0>, 0.7 texture { Bumpy Blue Shiny scale 2 } }
