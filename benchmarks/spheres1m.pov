// One million spheres from three nested #for loops: a 100x100x100 lattice, seen from a corner.
// Parse speed and memory: scripts/bench.py --width 1 --height 1 --runs 1 benchmarks/spheres1m.pov
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-60, 140, -120> look_at <50, 40, 50> angle 50 }
light_source { <-100, 300, -200> rgb 1 }
#for (I, 0, 99)
  #for (J, 0, 99)
    #for (K, 0, 99)
      sphere { <I, J, K>, 0.35 pigment { rgb <I / 99, J / 99, K / 99> } }
    #end
  #end
#end
