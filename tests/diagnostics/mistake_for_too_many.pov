// error: 5:20 `#for` has too many values
// error-text: POV-Ray's loop is written `#for (Identifier, Start, End [, Step])`
// POV-Ray: Parse Error: Expected ')', , found instead
// Mistake: `#for` with five values
#for (I, 0, 5, 1, 2)
  sphere { x*I, 0.5 }
#end
