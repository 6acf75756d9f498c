// radiosity_room: a closed room lit by one point light; radiosity (one bounce) brightens the
// shadows and bleeds the red and green walls' colour onto the floor, ceiling and sphere
#version 3.7;
global_settings { radiosity { recursion_limit 1 } }
camera { location <0, 1, -3.5> look_at <0, 1, 0> angle 70 }
light_source { <0.5, 1.8, -0.5> rgb 1 }
box { <-2, 0, -4>, <2, 2, 2> inverse pigment { rgb 0.9 } }
box { <-2.01, -0.1, -4>, <-1.99, 2.1, 2> pigment { rgb <0.9, 0.1, 0.1> } }
box { <1.99, -0.1, -4>, <2.01, 2.1, 2> pigment { rgb <0.1, 0.9, 0.1> } }
sphere { <0, 0.4, 0.3>, 0.4 pigment { rgb 0.8 } }
