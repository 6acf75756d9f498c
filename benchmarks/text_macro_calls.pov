// Parsing speed of text macros: 20,000 calls of a small macro whose `#if` cuts across braces
// (run token by token). Set Structured to 1 for the same shapes from a structured macro, the
// baseline (`durer check` prints the evaluation time).
#version 3.7;
#declare Structured = 0;
#macro TextShape(I)
  #if (mod(I, 2) = 0) box { <I, 0, 0>, <I + 0.5, 1, 1> #else sphere { <I, 0, 0>, 0.5 #end
  }
#end
#macro PlainShape(I)
  #if (mod(I, 2) = 0) box { <I, 0, 0>, <I + 0.5, 1, 1> } #else sphere { <I, 0, 0>, 0.5 } #end
#end
camera { location <10000, 40, -300> look_at <10000, 0, 0> angle 90 }
light_source { <10000, 100, -100> rgb 1 }
union {
  #for (I, 0, 19999)
    #if (Structured) PlainShape(I) #else TextShape(I) #end
  #end
  pigment { rgb 1 }
}
