// Benchmark: a Menger sponge from a recursive macro, depth 4 (160,000 boxes).
// Parse speed: scripts/bench.py --width 1 --height 1 benchmarks/menger4.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Depth = 4;

#macro Menger(Centre, Size, Level)
  #if (Level = 0)
    box { Centre - Size / 2, Centre + Size / 2 }
  #else
    #local Step = Size / 3;
    #for (I, -1, 1)
      #for (J, -1, 1)
        #for (K, -1, 1)
          // Keep the 20 sub-cubes that are not on a centre axis.
          #if (abs(I) + abs(J) + abs(K) > 1)
            Menger(Centre + <I, J, K> * Step, Step, Level - 1)
          #end
        #end
      #end
    #end
  #end
#end

camera { location <2.2, 1.8, -2.6> look_at <0, -0.05, 0> angle 50 }
light_source { <6, 8, -4> rgb 1 }
light_source { <-5, 3, -6> rgb 0.35 shadowless }
background { rgb <0.1, 0.12, 0.16> }
plane { y, -0.5 pigment { rgb <0.8, 0.78, 0.72> } }

union {
  Menger(<0, 0, 0>, 1, Depth)
  pigment { rgb <0.95, 0.55, 0.2> }
  finish { diffuse 0.75 specular 0.3 roughness 0.02 }
  rotate 15*y
}
