// Tests: a bump size given in `#default { normal { bump_size B } }` is
// kept by the patterns written after it, normal_map entries included.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8 * x up 6 * y }
light_source { <200, 200, -100> rgb 1 }
#default { pigment { rgb 1 } normal { bump_size 1.5 } finish { phong 0.8 phong_size 200 } }
box { <-4, 0, 0>, <-0.1, 3, 1> normal { gradient x normal_map { [0.3 marble turbulence 0.5] [0.7 gradient y scallop_wave scale 0.3] } scale 2 } }
box { <0.1, 0, 0>, <4, 3, 1> normal { wood scale 0.5 } }
box { <-4, -3, 0>, <-0.1, -0.1, 1> normal { bumps scale 0.3 } }
box { <0.1, -3, 0>, <4, -0.1, 1> normal { dents 2 scale 0.4 } }
