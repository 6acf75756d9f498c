// Conditionals, loops, switch, macros and scopes.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#declare A = 1;
#if (A = 1) #declare B = 10; #elseif (A = 2) #declare B = 20; #else #declare B = 30; #end
Check(B = 10, "#if takes the first true branch")
#ifdef (A) #declare D = 1; #else #declare D = 0; #end
Check(D = 1, "#ifdef sees a declared identifier")
#ifndef (Nope) #declare E = 1; #end
Check(E = 1, "#ifndef sees an undeclared identifier")
#declare Sum = 0;
#declare I = 0;
#while (I < 10) #declare Sum = Sum + I; #declare I = I + 1; #end
Check(Sum = 45, "#while sums 0..9")
#declare Sum = 0;
#for (J, 1, 10, 2) #declare Sum = Sum + J; #end
Check(Sum = 25, "#for with step")
Check(J = 11, "the #for variable ends one step past the end")
#macro LoopInMacro() #for (LoopVar, 1, 3) #end #end
LoopInMacro()
#ifdef (LoopVar) #error "a #for variable inside a macro leaked out" #end
#declare Sum = 0;
#for (J, 5, 1, -1) #declare Sum = Sum + J; #end
Check(Sum = 15, "#for counting down")
#declare Hits = 0;
#for (K, 0, 100)
  #if (K = 3) #break #end
  #declare Hits = Hits + 1;
#end
Check(Hits = 3, "#break leaves a loop")
#declare S = 2;
#switch (S)
  #case (1) #declare Out = 1; #break
  #case (2) #declare Out = 2; #break
  #else #declare Out = 3;
#end
Check(Out = 2, "#switch #case")
#switch (7)
  #range (0, 5) #declare Out = 1; #break
  #range (5, 10) #declare Out = 2; #break
#end
Check(Out = 2, "#switch #range")
#switch (1)
  #case (1) #declare Fall = 1;
  #case (2) #declare Fall = 2; #break
  #else #declare Fall = 3;
#end
Check(Fall = 2, "#switch falls through into the next clause without testing it (as povray does)")
#macro Twice(X) (2 * X) #end
Check(Twice(4) = 8, "macro as a value")
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
Check(Fact(10) = 3628800, "recursive macro")
#macro SetTo(Var, Value) #declare Var = Value; #end
#declare Target = 1;
SetTo(Target, 42)
Check(Target = 42, "identifier arguments are passed by reference")
#macro LocalScope() #local Hidden = 5; Hidden #end
Check(LocalScope() = 5, "#local inside a macro")
#ifdef (Hidden) #error "a macro's #local leaked" #end
#declare G = 1;
#macro Bump() #declare G = G + 1; #end
Bump() Bump()
Check(G = 3, "#declare from a macro updates the global")
#macro Opt(A, optional OptB) #ifdef (OptB) A + OptB #else A #end #end
Check(Opt(1) = 1 & Opt(1, 2) = 3, "optional parameters")
#declare Arr = array[3] { 1, 2, 3 };
Check(dimensions(Arr) = 1 & dimension_size(Arr, 1) = 3 & Arr[2] = 3, "array initialiser")
#declare Arr[0] = 10;
Check(Arr[0] = 10, "array element assignment")
#declare M = array[2][3];
#declare M[1][2] = 7;
Check(M[1][2] = 7 & dimension_size(M, 2) = 3, "two-dimensional arrays")
#ifdef (M[0][0]) #error "unassigned element counted as defined" #end
#ifndef (M[1][2]) #error "assigned element not defined" #end
Check(strcmp(str(-1.5, -6, 2), "-01.50") = 0 & strcmp(str(3, 5, 0), "    3") = 0, "str pads with zeros or spaces")
#declare Str = concat("a", str(1.5, 0, 1), "b");
Check(strcmp(Str, "a1.5b") = 0, "concat and str")
Check(strlen("hello") = 5 & asc("A") = 65 & strcmp(chr(66), "B") = 0, "string functions")
Check(strcmp(substr("abcdef", 2, 3), "bcd") = 0 & strcmp(strupr("ab"), "AB") = 0, "substr and strupr")
Check(val("2.5") = 2.5, "val")
Check(("abc" < "abd") & ("b" = "b"), "string comparison")
#undef A
#ifdef (A) #error "#undef did not remove A" #end
/* nested /* comments */ are allowed */
// Commas between macro arguments are optional: `Obj -y` is two arguments when Obj is an object.
#macro Pick(Thing, Offset) Offset #end
#declare Thing = sphere { 0, 1 }
#declare Picked = Pick(Thing -y);
Check(Picked.y = -1, "an object followed by -y is two arguments")
Check(Pick(1, 2 -1) = 1, "numbers still subtract")
Check(strcmp(input_file_name, "directives.pov") = 0, "input_file_name is the scene's file name")
#declare Calls = 0;
#macro Counted() #declare Calls = Calls + 1; 1 #end
#macro Two(A, B) A + B #end
#declare R = Two(Counted() - 1, 0);
Check(Calls = 1 & R = 0, "an argument's macro call runs once")
