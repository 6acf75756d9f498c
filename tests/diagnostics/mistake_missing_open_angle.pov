// error: 5:32 expected `,`, a block or something else, found `>`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: No matching } in 'sphere', ,  found instead
// Mistake: vector without its opening `<`
sphere { 0, 1 translate 1, 2, 3> }
