// error: 5:38 expected `,`, a block or something else, found `>`
// error-text: comparisons, `&`, `|` and `? :` are only allowed inside parentheses, as in POV-Ray: write `(A > B)`
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: an extra `>` after a vector
sphere { 0, 1 pigment { rgb <1, 0, 0>> } }
