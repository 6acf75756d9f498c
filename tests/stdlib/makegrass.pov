// makegrass.inc's MakeGrassPatch writing its meshes to files: probe.txt gets a small patch
// of plain blades, smooth.txt one of smooth folded blades with varied bending.
// makegrass.txt is the probe.txt POV-Ray 3.7 wrote with its own makegrass.inc
// (scripts/probe-stdlib.sh makegrass.pov), makegrass_smooth.txt its smooth.txt (same run,
// copied by hand); the includes test runs this scene with durer's file and compares the
// numbers.
#version 3.7;
#include "makegrass.inc"
MakeGrassPatch(4, 3, 60, 4, 1.5, 0.1, 0.03, false, <0, 1, 0.3>, <0, -1, 2>, 3, 459, 1, 360, 3, 0, false, true, "probe.txt")
MakeGrassPatch(3, 2, 20, 3, 1.2, 0.2, 0.05, true, <0, 1, 0>, <0, 0, 1>, 2, 18264, 0.5, 90, 2, 1, true, true, "smooth.txt")
