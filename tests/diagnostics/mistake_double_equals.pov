// error: 6:8 `==` is not an operator in POV-Ray
// error-text: POV-Ray compares with a single `=`, inside parentheses: `(A = 1)`
// POV-Ray: Parse Error: Expected 'numeric expression', = found instead
// Mistake: `==` used for comparison (POV-Ray's is `=`)
#declare A = 1;
#if (A == 1)
  sphere { 0, 1 }
#end
