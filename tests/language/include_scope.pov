// Include scopes, #version in includes, #undef and macro redefinition; checked against
// POV-Ray 3.7's output.
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
#include "include_scope.inc"
Check((FromInclude = 6), "#declare in an include is global")
Check((!defined(FileLocal)), "#local in an include stays in the file")
Check((VersionInside = 3.7), "an include starts with the includer's version")
Check((version = 3.5), "#version in an include holds after it")
#version 3.7;
#macro Twice() 1 #end
#macro Twice() 2 #end
Check((Twice() = 2), "a macro defined again replaces the first")
#declare Gone = 1;
#undef Gone
Check((!defined(Gone)), "#undef")
#macro LocalUndef() #local L = 3; #undef L Check((!defined(L)), "#undef of a local") #end
LocalUndef()
#declare Outer = 9;
#macro Shadow() #local Outer = 1; #undef Outer Check((Outer = 9), "#undef uncovers the global") #end
Shadow()
#declare Count = 0;
#while (1)
  #declare Count = Count + 1;
  #if (Count > 4) #break #end
#end
Check((Count = 5), "#break leaves #while")
// A `#` that starts no directive is ignored; `# declare` with a space is a directive.
# declare Spaced = 2;
#declare Stray = <1, 2, 3>;
#
Check((Spaced = 2 & Stray.z = 3), "stray and spaced #")
