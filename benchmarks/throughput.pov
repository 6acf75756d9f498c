// Ray throughput: 100,000 spheres on a jittered lattice under one light, seen from above at
// an angle; every pixel's camera ray hits a sphere or the ground plane and casts one shadow ray.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 60, -80> look_at <0, 0, 0> angle 60 }
light_source { <-200, 400, -300> rgb 1 }
plane { y, 0 pigment { rgb 0.8 } }
#declare R = seed(7);
#for (I, -158, 157)
  #for (J, -158, 157)
    sphere { <I * 0.5 + rand(R) * 0.2, 0.2, J * 0.5 + rand(R) * 0.2>, 0.2 pigment { rgb <rand(R), 0.6, 0.4> } }
  #end
#end
