// radiosity_final_pass: a coarse pretrace with a low error_bound leaves most points to the
// final pass, which stores the samples it gathers and reuses them (two bounces, an inside
// corner and a sphere close to the walls)
#version 3.7;
global_settings { radiosity { pretrace_start 0.16 pretrace_end 0.16 count 30 error_bound 0.4 nearest_count 3 recursion_limit 2 } }
#default { finish { ambient 0 diffuse 0.8 } }
camera { location <0, 1, -2.5> look_at <0, 0.9, 0> angle 70 }
light_source { <-0.8, 1.9, 0.6> rgb 1 }
box { <-1.5, 0, -3>, <1.5, 2, 1.5> inverse pigment { rgb 0.9 } }
box { <-1.5, 0, -3>, <-1.45, 2, 1.5> pigment { rgb <0.9, 0.2, 0.1> } }
box { <0.3, 0, 0.3>, <1.2, 0.9, 1.2> rotate y*20 pigment { rgb <0.2, 0.7, 0.3> } }
sphere { <-0.6, 0.35, -0.2>, 0.35 pigment { rgb <0.3, 0.4, 0.9> } }
