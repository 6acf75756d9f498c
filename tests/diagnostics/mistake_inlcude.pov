// error: 5:2 undefined identifier `inlcude`
// error-text: did you mean `include`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'inlcude' found instead
// Mistake: `#include` misspelt `#inlcude`
#inlcude "colors.inc"
