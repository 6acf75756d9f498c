// error: 5:10 undefined identifier `colors`
// error-text: did you mean `color`?
// POV-Ray: Parse Error: Expected 'string expression', undeclared identifier 'colors' found instead
// Mistake: `#include` without quotes
#include colors.inc
