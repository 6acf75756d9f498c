// error: 5:12 expected `,`, a block or something else, found `=`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'delcare' found instead
// Mistake: `#declare` misspelt `#delcare`
#delcare R = 1;
