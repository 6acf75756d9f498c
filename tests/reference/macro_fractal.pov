// A recursive macro: a sphereflake of depth 3 (each sphere carries six smaller ones).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.2, -4.2> look_at <0, 0.3, 0> angle 50 }
light_source { <5, 8, -6> rgb 1 }
plane { y, -1.2 pigment { checker rgb 0.9, rgb 0.4 } }

#macro Flake(Centre, Radius, Level, Skip)
  sphere { Centre, Radius }
  #if (Level > 0)
    #local Directions = array[6] { x, -x, y, -y, z, -z };
    #for (I, 0, 5)
      #if (I != Skip)
        // The child sits on the parent's surface, facing away from it.
        Flake(Centre + Directions[I] * Radius * 1.45, Radius * 0.45, Level - 1, bitwise_xor(I, 1))
      #end
    #end
  #end
#end

union {
  Flake(<0, 0, 0>, 0.8, 3, -1)
  pigment { rgb <0.9, 0.6, 0.3> }
  finish { phong 0.6 }
  rotate <0, 25, 0>
}
