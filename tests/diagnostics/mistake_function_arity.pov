// error: 6:14 function `F` takes 1 arguments, found 2
// (durer prints no help line)
// POV-Ray: Parse Error: Expected ')', ,  found instead
// Mistake: user function called with too many arguments
#declare F = function(a) { a * 2 }
#declare B = F(1, 2);
