// error: 6:9 expected an expression, found `=`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'numeric expression', = found instead
// Mistake: `==` used for comparison (POV-Ray's is `=`)
#declare A = 1;
#if (A == 1)
  sphere { 0, 1 }
#end
