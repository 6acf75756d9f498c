// polygon (with a hole, 2-D points) and smooth_triangle (interpolated normals).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> angle 50 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <6, 4, -3> rgb 0.4 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
polygon { 10, <-1,0>, <1,0>, <1,2>, <-1,2>, <-1,0>, <-0.5,0.5>, <0.5,0.5>, <0.5,1.5>, <-0.5,1.5>, <-0.5,0.5>
  pigment { rgb <0.9, 0.3, 0.2> } rotate y*-30 translate <-1.8, 0.1, 0.5> }
smooth_triangle { <0,0,0>, <-1,0,-1>, <2,0,0>, <1,0,-1>, <1,2,0>, <0,1,-1>
  pigment { rgb <0.2, 0.6, 0.9> } finish { phong 0.6 } translate <0.2, 0, 0> }
