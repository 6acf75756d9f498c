// error: 6:18 expected an expression, found `size`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'RValue to declare', size found instead
// Mistake: identifier with the wrong case
#declare Size = 1;
#declare Size2 = size * 2;
