// error: 6:14 array index [1] out of range
// (durer prints no help line)
// POV-Ray: Parse Error: Expected '[', + found instead
// Mistake: two-dimensional array read with one index
#declare Ar = array[2][2] { {1, 2}, {3, 4} };
#declare B = Ar[1] + 1;
