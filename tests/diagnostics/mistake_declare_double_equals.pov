// error: 5:13 expected a block or an expression, found `=`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'RValue to declare', = found instead
// Mistake: `==` in a `#declare`
#declare A == 1;
