// error: 6:14 `dimension_size` takes 2 arguments, found 1
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', ) found instead
// Mistake: `dimension_size` without the dimension
#declare Ar = array[3] { 1, 2, 3 };
#declare N = dimension_size(Ar);
