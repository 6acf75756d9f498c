// error: 5:1 unknown function or macro `Make_Ball`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'Make_Ball' found instead
// Mistake: call of a macro never defined
Make_Ball(1)
