// error: 5:10 expected an identifier, found `2Balls`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'undeclared identifier', float function 'float constant' found instead
// Mistake: identifier starting with a digit
#declare 2Balls = 2;
