// error: 5:14 `substr` takes 3 arguments, found 2
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', ) found instead
// Mistake: `substr` with two arguments
#declare S = substr("abc", 2);
