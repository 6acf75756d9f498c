// error: 6:16 unclosed `[`
// error-text: add the matching `]`
// POV-Ray: Parse Error: Expected ']', ; found instead
// Mistake: array index without its closing `]`
#declare Ar = array[3] { 1, 2, 3 };
#declare B = Ar[1;
