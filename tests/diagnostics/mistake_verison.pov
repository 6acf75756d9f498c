// error: 5:2 undefined identifier `verison`
// error-text: did you mean `version`?
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'verison' found instead
// Mistake: `#version` misspelt `#verison`
#verison 3.7;
