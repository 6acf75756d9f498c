// error: 5:24 unclosed `{`
// error-text: add the matching `}`
// POV-Ray: Parse Error: No matching } in '{', ; found instead
// Mistake: array initialiser without its closing `}`
#declare Ar = array[3] { 1, 2, 3;
