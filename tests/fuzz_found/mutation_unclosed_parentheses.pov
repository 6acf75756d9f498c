// Found by the mutation test; 100 unclosed parentheses: exponential backtracking, now stopped by the parse-steps limit (1.5 s)
// command: render
// expect: the parser gave up after
// exit: 1
// inside() of hypercomplex julia_fractals, as povray 3.7 answers it (each check measured):
// for functions other than sqr, cube and reciprocal its test reads the point's y for z, so
// the answer does not depend on z; a NaN orbit (ln 0) stays inside; 0 raised to a power is 0.
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end

#declare C = <-0.083, 0.0, -0.83, -0.025>;
#declare Sin = julia_fractal { C hypercomplex sin max_iteration 8 }
#declare Exp = julia_fractal { C hypercomplex exp max_iteration 8 }
#declare Sqr = julia_fractal { C hypercomplex sqr max_iteration 8 }
#declare Ln = julia_fractal { C hypercomplex ln max_iteration 8 }
#declare Pwr = julia_fractal { C hypercomplex pwr(2, 0) max_iteration 8 }
Check((inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp(inside(Exp, <-1.5, 0, -2.5>) & inside(Exp, <-1.5, 0, 2.5>)), "exp ignores z (inside)")
Check((!inside(Exp, <2.5, 0, 0>) & !inside(Exp, <2.5, 0, -2.5>)), "exp ignores z (outside)")
Check((!inside(Exp, <0.066, 2.922, -0.231>)), "exp's bailout counts y twice")
Check((inside(Exp, <-2.739, 1.22, 2.899>)), "exp's bailout does not see z")
Check((inside(Sin, <-1.7, -0.467, -2.826>) = inside(Sin, <-1.7, -0.467, 0>)), "sin ignores z")
Check((!inside(Sqr, <-1.7, -0.467, -2.826>)), "sqr reads z")
Check((inside(Ln, <0, 0, 1>))"a NaN orbit stays inside")
Check((inside(Pwr, <0, 0, -2>)), "0 to a power is 0")
