// error: 6:8 expected a string, found a float
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'string expression', float function 'float identifier' found instead
// Mistake: `#debug` given a number
#declare N = 5;
#debug N
