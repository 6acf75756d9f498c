// box_with_infinite_corner: boxes with a corner at infinity (a division by zero, which POV-Ray turns into positive infinity with a warning) run on forever that way, also when rotated or scaled, as POV-Ray renders them; durer dropped them (wild: poliana-girl aug31.pov, `<.., .., Count/clock>` at clock 0)
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare Zero = 0;
camera { location <0, 3, -10> look_at <0, 0, 0> angle 60 }
light_source { <5, 10, -10> rgb 1 }
background { rgb <0.5, 0.6, 0.9> }
plane { y, -1 pigment { checker rgb 1 rgb 0.5 } }
box { <-4, -0.5, 1>, <-2.5, 1, 5/Zero> pigment { rgb <1, 0.2, 0.1> } }
box { <-1, -0.5, 3>, <0.5, 0.5, -5/Zero> rotate y*25 pigment { rgb <0.1, 0.8, 0.2> } }
box { <2, -1, 0>, <3, 0/Zero, 1> scale <1, 0.5, 1> translate x*0.5 pigment { rgb <0.2, 0.3, 1> } }
