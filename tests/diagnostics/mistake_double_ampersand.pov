// error: 6:13 expected an expression, found `&`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'numeric expression', & found instead
// Mistake: `&&` for and (POV-Ray has `&`)
#declare A = 1;
#if (A > 0 && A < 2)
  sphere { 0, 1 }
#end
