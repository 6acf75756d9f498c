// error: 5:10 expected an identifier, found `=`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'undeclared identifier', = found instead
// Mistake: `#declare` without a name
#declare = 1;
