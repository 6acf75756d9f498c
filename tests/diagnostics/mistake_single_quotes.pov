// error: 5:10 expected an expression, found `'`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'string expression', ' found instead
// Mistake: single quotes around a file name
#include 'colors.inc'
