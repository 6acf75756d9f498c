// One blob of 2,000 components (1,500 spheres and 500 cylinders, a few of them negative)
// scattered with a seeded random stream through a box, over a checkered floor.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -14> look_at <0, 1.5, 0> angle 50 }
light_source { <-8, 14, -10> rgb 1 }
light_source { <10, 6, -6> rgb 0.4 }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.6 scale 2 } }

#declare Stream = seed(2000);
#declare Spread = <6, 3, 4>;

blob {
  threshold 0.6
  #for (Index, 1, 2000)
    #declare Centre = (<rand(Stream), rand(Stream), rand(Stream)> * 2 - 1) * Spread + <0, 2, 0>;
    #declare Radius = 0.35 + 0.4 * rand(Stream);
    #declare Strength = (rand(Stream) < 0.05 ? -1 : 1);
    #if (mod(Index, 4) = 0)
      #declare Axis = (<rand(Stream), rand(Stream), rand(Stream)> * 2 - 1) * 0.8;
      cylinder { Centre - Axis, Centre + Axis, Radius, Strength }
    #else
      sphere { Centre, Radius, Strength }
    #end
  #end
  pigment { rgb <0.9, 0.45, 0.2> }
  finish { phong 0.6 }
}
