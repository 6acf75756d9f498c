// error: 6:12 `||` is not an operator in POV-Ray
// error-text: POV-Ray's *or* is a single `|`: `(A < 0 | A > 2)`
// POV-Ray: Parse Error: Expected 'numeric expression', | found instead
// Mistake: `||` for or (POV-Ray has `|`)
#declare A = 1;
#if (A < 0 || A > 2)
  sphere { 0, 1 }
#end
