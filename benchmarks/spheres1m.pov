// Benchmark: 1,000,000 spheres from nested #for loops (issue 4).
// Parse speed and memory: scripts/bench.py --width 1 --height 1 --runs 1 benchmarks/spheres1m.pov
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <50, 120, -160> look_at <50, 0, 50> angle 50 }
light_source { <200, 400, -300> rgb 1 }
background { rgb <0.1, 0.12, 0.16> }

#for (I, 0, 99)
  #for (J, 0, 99)
    #for (K, 0, 99)
      sphere { <I, J * 0.1, K>, 0.35 pigment { rgb <I / 99, J / 99, K / 99> } }
    #end
  #end
#end
