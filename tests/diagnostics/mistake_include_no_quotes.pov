// error: 5:10 the file name of `#include` needs quotes
// error-text: write `#include "colors.inc"`
// POV-Ray: Parse Error: Expected 'string expression', undeclared identifier 'colors' found instead
// Mistake: `#include` without quotes
#include colors.inc
