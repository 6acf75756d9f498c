// error: 5:9 `#for` is not written as in C
// error-text: POV-Ray's loop is written `#for (Identifier, Start, End [, Step])`: `#for (I, 0, 2)` counts I from 0 to 2
// POV-Ray: Parse Error: Expected 'numeric expression', = found instead
// Mistake: C-style `#for` header
#for (I = 0; I < 3; I++)
  sphere { x*I, 0.5 }
#end
