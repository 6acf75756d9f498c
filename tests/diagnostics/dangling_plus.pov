// error: 4:23 expected an expression, found `;`
// error-text: expected an expression
// POV-Ray: Parse Error: Expected 'numeric expression', ; found instead
#declare Broken = 1 + ;
