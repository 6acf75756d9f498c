// error: 6:23 expected a string, found a float
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'string expression', float function 'float identifier' found instead
// Mistake: `concat` given a number (needs `str`)
#declare N = 5;
#debug concat("N = ", N, "\n")
