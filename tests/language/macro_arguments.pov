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
// Directives among a call's arguments run in the caller's scope, in order: after the
// arguments before them are read and before the ones after them (POV-Ray reads them after
// `(` or a comma in a macro call; in a built-in function's call also after an argument).
Check((vlength(Two(1,
#declare R = 5;
R) - <1, 5>) = 0), "#declare before the last argument")
Check((vlength(Two(
#local Q = 7;
Q, 2) - <7, 2>) = 0), "#local before the first argument")
#declare Z = 1;
Check((vlength(Two(Z + 0, #undef Z 4) - <1, 4>) = 0), "#undef between arguments")
#ifdef (Z) #error "failed: #undef among arguments" #end
Check((vlength(Two(#declare X = 2; X, #declare Y = 3; Y) - <2, 3>) = 0), "a directive before each argument")
Check((vlength(Two(1, 2, #declare Z = 3;) - <1, 2>) = 0 & Z = 3), "a directive after a trailing comma")
Check((vlength(Two(1, #if (1) #declare Y = 6; #end Y) - <1, 6>) = 0), "#if before an argument")
Check((vlength(Two(1, 2, #if (1) #declare Y = 8; #end) - <1, 2>) = 0 & Y = 8), "#if after a trailing comma")
#declare I = 0;
Check((vlength(Two(1, #while (I < 2) #declare I = I + 1; #end I) - <1, 2>) = 0), "#while between arguments")
Check((vlength(Two(1, #for (J, 0, 3) #declare K = J; #end K) - <1, 3>) = 0), "#for between arguments")
Check((vlength(Two(1, #switch (1) #case (1) #declare K = 5; #break #end K) - <1, 5>) = 0), "#switch between arguments")
Check((vlength(Two(1, #macro Nine() 9 #end Nine()) - <1, 9>) = 0), "#macro between arguments")
Check((vlength(Two(1, #debug "" 4) - <1, 4>) = 0), "#debug between arguments")
// Arguments before a directive are read before it; a plain name passes by reference, so it
// reads the variable when the macro runs.
#declare X = 1;
Check((vlength(Two(X + 0, #declare X = 5; X) - <1, 5>) = 0), "an argument before a directive is read first")
#declare X = 1;
Check((vlength(Two(X, #declare X = 5; X) - <5, 5>) = 0), "a name passed by reference sees the directive")
#macro SetNine(P) #declare P = 9; #end
SetNine(#declare W = 2; W)
Check((W = 9), "a name after a directive passes by reference")
#macro Bump(P) #declare P = P + 1; P #end
#declare X = 3;
Check((vlength(Two(Bump(X), #declare X = X * 10; X) - <4, 40>) = 0), "a directive after a macro call argument")
Check((vlength(Two(1, Two(#declare X = 4; X, 3).y) - <1, 3>) = 0 & X = 4), "a directive in a nested call")
#macro InMacro()
  #local L = 3;
  #local Result = Two(#local L = 4; L, L);
  Check((vlength(Result - <4, 4>) = 0 & L = 4), "#local in a macro's call runs in the macro's scope")
#end
InMacro()
#ifdef (L) #error "failed: #local among arguments leaked out of the macro" #end
// Built-in functions, user functions and splines.
Check((max(1, #declare X = 2; X) = 2), "a directive in a built-in call")
Check((max(#declare X = 2; X, 1) = 2), "a directive before a built-in's first argument")
Check((max(1, 2 #declare X = 3; ) = 2 & X = 3), "a directive after a built-in's last argument")
Check((max(1 #declare X = 4; , 2) = 2 & X = 4), "a directive after a built-in's argument")
#declare X = 1;
Check((min(X, #declare X = 5; X) = 1), "a built-in's argument before a directive is read first")
Check((select(-1, #declare A = 1; 5, #declare B = 2; 6) = 5 & A = 1 & B = 2), "directives before arguments select skips")
Check((max(1, #if (1) 2 #else 3 #end) = 2), "#if as a whole argument of a built-in")
Check((max(1, #ifdef (Undeclared) 2 #else 3 #end) = 3), "#ifdef as a whole argument of a built-in")
Check((max(1, #switch (2) #case (1) 4 #break #case (2) 5 #break #end) = 5), "#switch as a whole argument")
// A directive alone between commas may leave the argument, as an included file does.
#fopen Out "macro_arguments_value.tmp" write
#write(Out, "#local Inside = 11; Inside\n")
#fclose Out
Check((vlength(Two(1, #include "macro_arguments_value.tmp") - <1, 11>) = 0), "a macro argument read from an included file")
Check((max(1, #include "macro_arguments_value.tmp") = 11), "a built-in's argument read from an included file")
#declare Sum = function(a, b) { a + b }
Check((Sum(1, #declare X = 3; X) = 4), "a directive in a user function's call")
#declare F = function(x) { max(x, #declare K = 2; K) }
Check((F(1) = 2 & K = 2), "a directive in a call inside a function body")
#declare S = spline { linear_spline 0, <0, 0, 0>, 1, <1, 1, 1> }
Check((S(#declare X = 1; X).x = 1), "a directive in a spline's call")
// Deeply nested calls with directives still parse in linear time.
#declare Deep = max(#declare D = 1; max(#declare D = 2; max(#declare D = 3; max(#declare D = 4; max(#declare D = 5; max(#declare D = 6; max(#declare D = 7; max(#declare D = 8; max(#declare D = 9; max(#declare D = 10; max(#declare D = 11; max(#declare D = 12; max(#declare D = 13; max(#declare D = 14; max(#declare D = 15; max(#declare D = 16; max(#declare D = 17; max(#declare D = 18; max(#declare D = 19; max(#declare D = 20; D, 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0), 0);
Check((Deep = 20), "20 nested calls with directives")
