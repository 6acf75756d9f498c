// error: 5:23 expected `,`, a block or something else, found `{`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ']', { found instead
// Mistake: array size without its closing `]`
#declare Ar = array[3 { 1, 2, 3 };
