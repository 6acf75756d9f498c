// Macros whose directives cut across braces, parentheses and argument lists ("text
// macros"): POV-Ray reads them as a token stream. Values checked against POV-Ray 3.7.
#version 3.7;
#macro Check(Condition, Message)
  #if (!(Condition)) #error concat("failed: ", Message) #end
#end
// Bounding boxes may be padded by a hair.
#macro Near(A, B) (abs(A - B) < 1e-6) #end

// A block opened in one #if branch and closed in another, its items emitted by a loop.
#macro Row(Merged, N)
  #if (Merged) merge { #else union { #end
  #local I = 0;
  #while (I < N)
    sphere { <I * 2, 0, 0>, 0.5 }
    #local I = I + 1;
  #end
  #if (Merged) } #else } #end
#end
#declare Three = Row(true, 3)
Check(Near(max_extent(Three).x, 4.5), "a loop emits one sphere per pass")
Check(Near(min_extent(Three).x, -0.5), "the first sphere is at the origin")
#declare Four = object { Row(false, 4) translate y }
Check(Near(max_extent(Four).x, 6.5), "a text macro used inside an object")
Check(Near(min_extent(Four).y, 0.5), "modifiers after a text macro apply to its object")

// Names are read when they are met: each emitted J is that pass's J.
#macro Sum() #local J = 1; #if (1) ( #end J #local J = 2; + J #local J = 3; + J #if (1) ) #end #end
Check((Sum() = 6), "names are snapshotted as they are met")

// A value whose operator comes from a branch.
#macro Pick(X) #if (X > 1) X * #else 2 * #end 10 #end
Check((Pick(3) = 30), "the first branch's operator")
Check((Pick(0) = 20), "the #else branch's operator")

// A modifier list cut inside a vector.
#macro Grow(Big) #if (Big) scale <3, #else scale <1, #end 1, 1> #end
#declare Grown = sphere { 0, 1 Grow(true) }
Check((Near(max_extent(Grown).x, 3) & Near(max_extent(Grown).y, 1)), "modifiers cut inside a vector")
#declare Kept = sphere { 0, 1 Grow(false) }
Check(Near(max_extent(Kept).x, 1), "the other branch of the modifiers")

// #for, #switch and #break inside a block whose braces are cut.
#macro Pick2(Kind) #switch (Kind) #case (1) union { #break #else merge { #end
  #for (K, 1, 5)
    #if (K = 4) #break #end
    box { <K, 0, 0>, <K + 0.5, 1, 1> }
  #end
  #if (1) } #end
#end
#declare Boxes = Pick2(1)
Check(Near(max_extent(Boxes).x, 3.5), "#break leaves the #for inside a text macro")
#declare Boxes = Pick2(2)
Check(Near(min_extent(Boxes).x, 1), "#switch chooses the block keyword")

// Macro calls inside run in order with the text macro's own directives.
#declare Calls = 0;
#macro Count() #declare Calls = Calls + 1; Calls #end
#macro Counted() #if (1) ( #end Count() #if (Calls = 1) + 10 #end ) #end
Check((Counted() = 11), "a call inside a text macro runs when it is met")

// A #write whose argument list runs across directives.
#macro WriteList(Name, N)
  #fopen Out Name write
  #write(Out, "1",
  #for (K, 2, N) ",", K, #end
  "\n")
  #fclose Out
#end
WriteList("text_macros_list.tmp", 4)
#fopen In "text_macros_list.tmp" read
#read(In, A, B, C, D)
#fclose In
Check((A = 1 & B = 2 & C = 3 & D = 4), "#write collects its arguments across directives")

// A #local whose block value opens under an #if.
#macro Lens(Filled)
  #local Shape =
  #if (Filled) intersection { #end
    sphere { <0, 0, -0.5>, 1 }
  #if (Filled) sphere { <0, 0, 0.5>, 1 } } #end
  object { Shape }
#end
#declare Lensed = Lens(true)
Check((max_extent(Lensed).z < 1), "a declaration's block closed under a later #if")
#declare Lensed = Lens(false)
Check(Near(max_extent(Lensed).z, 0.5), "the declaration without the block")

// An #include inside a text macro is read into its token stream: here it opens no block of
// its own but fills the object the macro opened.
#fopen Out "text_macros_row.tmp" write
#write(Out, "sphere { <4, 0, 0>, 1 }\n")
#fclose Out
#macro Use(FromFile, Scale)
  #if (FromFile) object { #include "text_macros_row.tmp" #else union { sphere { 0, 1 } #end scale Scale }
#end
#declare Used = Use(true, 2)
Check(Near(max_extent(Used).x, 10), "an included file's items inside a text macro")
#declare Used = Use(false, 2)
Check(Near(max_extent(Used).x, 2), "the other branch of the include")
