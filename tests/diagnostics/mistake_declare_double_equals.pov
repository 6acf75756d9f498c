// error: 5:12 `#declare` takes a single `=`
// error-text: write `#declare A = Value;` (comparisons are written `(A = B)`)
// POV-Ray: Parse Error: Expected 'RValue to declare', = found instead
// Mistake: `==` in a `#declare`
#declare A == 1;
