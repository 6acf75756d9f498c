// error: 6:11 in the text this macro produced: expected `,`, a block or something else, found `=`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'locl' found instead
// Mistake: `#local` misspelt `#locl`
#macro Ball()
  #locl R = 1;
  sphere { 0, R }
#end
Ball()
