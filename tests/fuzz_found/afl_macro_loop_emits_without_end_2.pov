// Found by AFL++ (render target); the same endless #while in a macro body, other bytes around it
// command: render
// expect: emits more than 67108864 bytes of scene text
// exit: 1
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
    sphere { <I * 2,ßÏÓßÏÁÓßÏÑÊß‚õßßßßÜ“œž“ß¶ßÂß¶ßÔßÎÄõßßÜš‘›õßßÜ–™ß×²š˜š›Öß‚ßÜš“Œe } #end
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

// A macro call whose argument list runs across directives (in a text macro): a directive
// may start an argument, and the rest of the list, even its `)`, may lie in one branch.
#macro Three(A, B, C) <A, B, C> #end
#macro Crossing(Which)
  #if (1) union { #end
  sphere { Three(1, #if (Which) 2, 3) #else 4, 5) #end, 1 }
  #if (1) } #end
#end
#declare Crossed = Crossing(true)
Check(Near(max_extent(Crossed).z, 4), "a call's arguments and `)` inside the chosen branch")
#declare Crossed = Crossing(false)
Check(Near(max_extent(Crossed).z, 6), "a call's arguments and `)` in the #else branch")
#macro Mixed()
  #if (1) union { #end
  sphere { Three(#local Q = 7; Q, -#if (1) 2, #end <1, #if (1) 3 #end, 5>.y), 0.5 }
  #if (1) } #end
#end
#declare Mixed_ = Mixed()
Check(Near(max_extent(Mixed_).x, 7.5), "a directive before an argument")
Check(Near(min_extent(Mixed_).y, -2.5), "a directive after an operator")
Check(Near(max_extent(Mixed_).z, 3.5), "a directive inside a vector argument")
// Arguments are read when the call completes: a plain name is passed by reference, one
// bound only inside an included file is read before that file's scope ends.
#macro SetNine(X) #declare X = 9; #end
#declare Target = 0;
#macro ByReference() SetNine(#if (1) Target) #end #end
ByReference()
Check((Target = 9), "a plain name passes by reference across directives")
#fopen Out "text_macros_value.tmp" write
#write(Out, "#local Inside = 11; Inside\n")
#fclose Out
#macro Add(A, B) (A + B) #end
#macro FromInclude() Add(1, #include "text_macros_value.tmp" ) #end
Check((FromInclude() = 12), "an argument read from an included file")

// An included file need not parse on its own: here it closes the union the macro opened.
#fopen Out "text_macros_close.tmp" write
#write(Out, "sphere { <3, 0, 0>, 1 }\n}\n")
#fclose Out
#macro Closed()
  union { sphere { 0, 1 }
  #include "text_macros_close.tmp"
#end
#declare Closed_ = Closed()
Check(Near(max_extent(Closed_).x, 4), "an included file closing the macro's block")
