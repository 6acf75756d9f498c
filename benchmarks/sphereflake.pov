// Sphereflake of depth 5: a recursive macro placing nine smaller spheres around each sphere
// (66,430 spheres), mirrored, over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <2.2, 2.6, -3.4> look_at <0, 0.1, 0> angle 45 }
light_source { <6, 10, -8> rgb 1 }
light_source { <-8, 6, -4> rgb 0.4 }

#declare Flake_Texture = texture {
  pigment { rgb <0.85, 0.85, 0.9> }
  finish { diffuse 0.6 phong 0.8 phong_size 60 reflection 0.35 }
}

// Children sit on a ring of six around the parent's equator and three on its upper cap, each
// a third of the parent's size, facing away from the parent.
#macro Flake(Centre, Radius, Axis, Depth)
  sphere { Centre, Radius texture { Flake_Texture } }
  #if (Depth > 0)
    #local Side = vnormalize(vcross(Axis, (abs(Axis.x) < 0.9 ? x : y)));
    #local Other = vcross(Axis, Side);
    #local Child = Radius / 3;
    #for (I, 0, 5)
      #local A = radians(I * 60);
      #local D = vnormalize(Side * cos(A) + Other * sin(A));
      Flake(Centre + D * (Radius + Child), Child, D, Depth - 1)
    #end
    #for (I, 0, 2)
      #local A = radians(I * 120 + 30);
      #local D = vnormalize(Axis * 1.2 + Side * cos(A) + Other * sin(A));
      Flake(Centre + D * (Radius + Child), Child, D, Depth - 1)
    #end
  #end
#end

union { Flake(<0, 0, 0>, 0.5, y, 5) }
plane { y, -0.5 pigment { checker rgb 1 rgb 0.3 } finish { reflection 0.1 } }
