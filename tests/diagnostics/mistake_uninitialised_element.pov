// error: 7:14 array element used before it was assigned
// (durer prints no help line)
// POV-Ray: Parse Error: Attempt to access uninitialized array element.
// Mistake: array element read before it is set
#declare Ar = array[3];
#declare Ar[0] = 1;
#declare B = Ar[1];
