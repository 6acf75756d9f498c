// error: 5:32 expected an expression, found `}`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'operand', } found instead
// Mistake: function body ending in an operator
#declare F = function(a) { a * }
