// The compiled functions of isosurfaces and height fields agree with the scene language's own
// evaluation, and POV-Ray's internal functions give povray's values.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#declare Eps = 1e-9;

// Internal functions, declared as functions.inc declares them; values printed by povray 3.7.
#declare f_sphere = function { internal(61) }
#declare f_torus = function { internal(70) }
#declare f_rounded_box = function { internal(60) }
#declare f_superellipsoid = function { internal(68) }
#declare f_th = function { internal(69) }
Check(abs(f_sphere(0.3, 0.4, 0.5, 0.7) - 0.007106781187) < Eps, "f_sphere")
Check(abs(f_torus(0.3, 0.4, 0.5, 0.7, 0.2) - 0.216733409654) < Eps, "f_torus")
Check(abs(f_rounded_box(1.3, -0.4, 0.5, 0.1, 0.5, 0.3, 0.25) - 0.886153146166) < Eps, "f_rounded_box")
Check(abs(f_superellipsoid(0.3, 0.4, 0.5, 0.5, 0.7) - 0.405067003168) < Eps, "f_superellipsoid")
Check(abs(f_th(0.3, 0.4, 0.5) - 0.540419500271) < Eps, "f_th")

// A user function using operators, built-ins, a declared constant, select, a call of another
// user function and an internal function. Where a ray meets the isosurface of it, the scene
// language's evaluation of the same function is at the threshold.
#declare Offset = 0.1;
#declare Inner = function(a, b) { a * a + b * b }
#declare Shape = function {
  sqrt(Inner(x, y) + pow(z, 2)) - 0.6
  + Offset * sin(4 * x) * cos(3 * y)
  + select(z, 0, 0.05 * z) * (x > 5 ? 1 : 0.5)
  + 0.1 * min(abs(x), 0.2, max(y, -1)) + 0.01 * f_sphere(x, y, z, 1)
}
#declare Iso = isosurface {
  function { Shape(x, y, z) }
  contained_by { box { -1, 1 } }
  accuracy 1e-7
  max_gradient 4
}
#declare Normal = <0, 0, 0>;
#for (I, 0, 7)
  #declare Start = <-3 + I * 0.7, 2.5 - I * 0.4, -3>;
  #declare Direction = vnormalize(<0.05, -0.03, 0> * I - Start);
  #declare Hit = trace(Iso, Start, Direction, Normal);
  Check(vlength(Normal) > 0, concat("ray ", str(I, 0, 0), " hits the isosurface"))
  Check(abs(Shape(Hit.x, Hit.y, Hit.z)) < 1e-5, concat("ray ", str(I, 0, 0), ": value at the hit"))
#end

// The same with a threshold and sum() (compiled only; the check spells the sum out).
#declare Sea = isosurface {
  function { y - sum(K, 1, 3, 0.1 * sin(K * x) / K) }
  threshold 0.25 accuracy 1e-7 max_gradient 2
}
#declare Hit = trace(Sea, <0.3, 3, 0.2>, -y, Normal);
#declare Expected = 0.25 + 0.1 * sin(0.3) + 0.05 * sin(0.6) + 0.1 * sin(0.9) / 3;
Check(abs(Hit.y - Expected) < 1e-5, "threshold and sum()")

// A height field of a function samples it at x = column / (W - 1), y = 1 - z, in 16 bits.
#declare Ramp = function { 0.2 + 0.5 * x * y }
#declare Field = height_field { function 5, 5 { Ramp(x, y, z) } }
#declare Hit = trace(Field, <0.5, 3, 0.25>, -y, Normal);
Check(abs(Hit.y - floor(Ramp(0.5, 0.75, 0) * 65535) / 65536) < 1e-9, "function height field grid point")
