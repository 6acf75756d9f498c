// error: 5:10 expected an expression, found `“`
// (durer prints no help line)
// POV-Ray: Parse Error: Illegal character in input file, value is e2.
// Mistake: typographic quotes pasted from a web page
#include “colors.inc”
