// error: 5:11 `#for` needs a start and an end value
// error-text: POV-Ray's loop is written `#for (Identifier, Start, End [, Step])`
// POV-Ray: Parse Error: Expected 'numeric expression', ) found instead
// Mistake: `#for` without its end value
#for (I, 0)
  sphere { x*I, 0.5 }
#end
