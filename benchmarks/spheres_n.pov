// N spheres (`--define N=...`, default 1000) on a cubic lattice, seen whole from a corner:
// the scene of the scaling chart (scripts/scaling.py, docs/benchmarks.md).
#version 3.7;
global_settings { assumed_gamma 1 }
#ifndef (N) #declare N = 1000; #end
#declare Side = ceil(pow(N, 1 / 3));
camera { location <-0.6, 1.4, -1.2> * Side look_at <0.5, 0.4, 0.5> * Side angle 50 }
light_source { <-1, 3, -2> * Side rgb 1 }
#declare Count = 0;
#for (I, 0, Side - 1)
  #for (J, 0, Side - 1)
    #for (K, 0, Side - 1)
      #if (Count < N)
        sphere { <I, J, K>, 0.35 pigment { rgb <I / Side, J / Side, K / Side> } }
        #declare Count = Count + 1;
      #end
    #end
  #end
#end
