// error: 5:15 expected a parameter, found `=`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'identifier or expression.', = found instead
// Mistake: default parameter value in a `#macro` (not POV-Ray syntax)
#macro Ball(R = 1)
  sphere { 0, R }
#end
