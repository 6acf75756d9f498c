// error: 5:14 `str` takes 3 arguments, found 2
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', ) found instead
// Mistake: `str` with two arguments (needs three)
#declare S = str(5, 0);
