// error: 5:14 expected a block or an expression, found `"`
// (durer prints no help line)
// POV-Ray: Parse Error: No end quote for string.
// Mistake: string without its closing quote
#declare S = "hello;
sphere { 0, 1 }
