// Commas between macro-call arguments are optional, as in POV-Ray (its argument reader
// takes an optional comma); a `<` after an argument starts the next one, a vector. Values
// checked against POV-Ray 3.7.
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#macro Three(A, B, C) <A, B, C> #end
#macro Vectors(A, B, C) (A + B * 10 + C * 100) #end

Check((vlength(Three(1 2 3) - <1, 2, 3>) = 0), "numbers without commas")
Check((vlength(Three(1 (2) 3) - <1, 2, 3>) = 0), "a parenthesised argument without commas")
#macro Two(A, B) <A, B> #end
Check((vlength(Two(1 -2 3) - <-1, 3>) = 0), "`1 -2` is one argument, a difference")
#declare A = 4;
Check((vlength(Three(A A A) - <4, 4, 4>) = 0), "names without commas")
Check((vlength(Three(1, 2, 3,) - <1, 2, 3>) = 0), "a trailing comma")
Check((vlength(Three(sin(0) cos(0) 3) - <0, 1, 3>) = 0), "calls without commas")
// portfolio/o_shapes.pov: `HF_Square(F, off, off <100,100>, on, ...)`.
Check((vlength(Vectors(<1, 2> <3, 4> <5, 6>) - <531, 642>) = 0), "vectors without commas")
Check((vlength(Vectors(<1, 2>, 0 <3, 4>) - <301, 402>) = 0), "a number then a vector")
Check((vlength(Vectors(<1, 2>, 2 - 2 <3, 4>) - <301, 402>) = 0), "a difference then a vector")
#macro Mixed(A, B, C) (A + B * 10 + C * 100) #end
Check((vlength(Mixed(1 <3, 4> 5) - <531, 541>) = 0), "a vector between numbers, no commas")
Check((vlength(Mixed(<1, 2> <3, 4> A) - <431, 442>) = 0), "a vector before a name")
Check((vlength(Mixed(0 <3, 4> (5)) - <530, 540>) = 0), "a vector before a parenthesis")
// Inside functions `<` still compares.
#declare Negative = function(x) { max(x < 0, 0.5) }
Check((Negative(-3) = 1 & Negative(3) = 0.5), "`<` compares in a function's call")
// Deeply nested calls parse in linear time (each argument is read once: a grammar that read
// an argument twice took 2^depth steps, minutes at this depth).
#declare Deep = max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(max(1, 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0);
Check((Deep = 1), "26 nested calls")
#if (2 < 3) #else #error "failed: `<` compares in an #if" #end
Check((((1 < 2) + (2 <3)) = 2), "`<` before a number compares inside parentheses")
