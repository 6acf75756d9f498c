// error: 5:2 expected a directive, block or value, found `for`
// error-text: did you mean `fog`?
// POV-Ray: Parse Error: Expected 'numeric expression', = found instead
// Mistake: C-style `#for` header
#for (I = 0; I < 3; I++)
  sphere { x*I, 0.5 }
#end
