// error: 5:32 undefined identifier `b`
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'parameter identifier or floating-point constant identifier', } found instead
// Mistake: function body using a parameter that was not declared
#declare F = function(a) { a + b }
