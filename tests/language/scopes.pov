// Scopes and macro parameters: values checked against POV-Ray 3.7's output.
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
// A parameter passed an identifier is the caller's variable, for #local as for #declare.
#macro SetLocal(P) #local P = 5; #end
#macro SetDeclared(P) #declare P = 6; #end
#declare A = 1; SetLocal(A)
Check((A = 5), "#local on a parameter writes through to the caller")
#declare B = 1; SetDeclared(B)
Check((B = 6), "#declare on a parameter writes through to the caller")
#macro AddTen(P) #local Q = 1; #local P = Q + 10; #end
#macro Outer() #local C = 1; AddTen(C) Check((C = 11), "write-through reaches a caller's local") #end
Outer()
#ifdef (C) #error "a macro's local leaked out" #end
#macro Twice(P) #local I = 0; #while (I < 2) #local P = P + 1; #local I = I + 1; #end #end
#declare E = 1; Twice(E)
Check((E = 3), "a parameter updated in a loop")
// A parameter passed an expression is a plain local.
#macro Scratch(P) #local P = 99; #end
#declare F = 1; Scratch(F + 1)
Check((F = 1), "an expression argument is a copy")
// Deep recursion sees the caller's locals (POV-Ray scopes are dynamic).
#macro Depth(N) #if (N > 0) #local Level = N; Depth(N - 1) #else #declare Seen = Level; #end #end
Depth(60)
Check((Seen = 1), "the innermost caller's local is visible")
// Array elements assigned one by one are not copied each time.
#declare Big = array[20000];
#for (I, 0, 19999) #declare Big[I] = I; #end
Check((Big[19999] = 19999), "array element assignment")
