// error: 5:10 expected an expression, found `"`
// (durer prints no help line)
// POV-Ray: Parse Error: No end quote for string.
// Mistake: `#include` file name without its closing quote
#include "colors.inc
sphere { 0, 1 }
