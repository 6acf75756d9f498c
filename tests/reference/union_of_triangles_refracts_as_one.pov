// union_of_triangles_refracts_as_one: a glass cube built from twelve loose triangles (mixed winding) in a union with one texture and interior refracts like a solid box: the children share the union's interior, so a ray enters at one triangle and leaves at another (durer gave each triangle a material of its own, so every face was "entered" and the cube showed the checker almost straight through; wild: khayyam90 diamond.pov)
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
background { rgb 1 }
camera { location <1.5, 2.5, -4> look_at <0, 0.3, 0> angle 40 }
light_source { <5, 10, -5> rgb 1 }
plane { z, 5 pigment { checker rgb <0.9, 0.9, 0> rgb <0.2, 0, 0.4> } }
#declare P = array[8] {<-1,-1,-1>,<1,-1,-1>,<1,1,-1>,<-1,1,-1>,<-1,-1,1>,<1,-1,1>,<1,1,1>,<-1,1,1>}
union {
  triangle { P[0], P[1], P[2] } triangle { P[0], P[3], P[2] }
  triangle { P[4], P[5], P[6] } triangle { P[4], P[7], P[6] }
  triangle { P[0], P[1], P[5] } triangle { P[0], P[5], P[4] }
  triangle { P[3], P[2], P[6] } triangle { P[3], P[7], P[6] }
  triangle { P[0], P[3], P[7] } triangle { P[0], P[7], P[4] }
  triangle { P[1], P[2], P[6] } triangle { P[1], P[5], P[6] }
  texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection 0 } }
  interior { ior 1.5 }
}
