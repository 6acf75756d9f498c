// error: 5:18 expected a float, found a string
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'string comparison operator', ) found instead
// Mistake: `int` of a string (needs `val`)
#declare N = int("5");
