// error: 5:15 array initialiser has 3 elements, the array holds 2
// (durer prints no help line)
// POV-Ray: Parse Error: No matching } in '{', float function 'float constant' found instead
// Mistake: array initialiser with more values than its size
#declare Ar = array[2] { 1, 2, 3 };
