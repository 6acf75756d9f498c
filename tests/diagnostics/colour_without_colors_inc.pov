// error: 4:1 undefined identifier `White`
// error-text: add `#include "colors.inc"`
// POV-Ray: Parse Error: Expected 'object or directive', undeclared identifier 'White' found instead
White
