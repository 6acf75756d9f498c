// functions.inc's internal functions, called by their names from POV-Ray's own include file,
// give the values povray 3.7 prints for the same calls (one of each kind: an algebraic surface
// with its field clipping, a 2d curve swept by the SOR switch, a helix, a noise fractal).
#include "functions.inc"
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#declare Eps = 1e-9;

Check((abs(f_heart(-0.7, 0.2, 0.9, 1) + 0.506906) < Eps), "f_heart")
Check((f_klein_bottle(2.3, 0.75, -1.6, 1) = 10), "f_klein_bottle clips at 10")
Check((abs(f_algbr_cyl1(0.3, 0.4, 0.5, -1, 5, 1, 0.2, 30) - -0.27432314585746) < Eps), "f_algbr_cyl1 swept")
Check((abs(f_helix1(-0.7, 0.2, 0.9, 3, 2, 0.25, 0.7, 0.8, 2, 10) - 0.47613161652765) < Eps), "f_helix1")
Check((abs(f_ridged_mf(0.3, 0.4, 0.5, 0.5, 2, 3, 1, 1, 2) - 1.45186802141338) < Eps), "f_ridged_mf")
Check((abs(f_snoise3d(0.3, 0.4, 0.5) - (2 * f_noise3d(0.3, 0.4, 0.5) - 1)) < Eps), "f_snoise3d")
