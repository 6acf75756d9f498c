// error: 7:1 expected `,`, a block or something else, found end of file
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ']', ; found instead
// Mistake: array index without its closing `]`
#declare Ar = array[3] { 1, 2, 3 };
#declare B = Ar[1;
