// error: 5:10 unterminated string
// error-text: this string runs over 2 lines to the end of the file
// POV-Ray: Parse Error: No end quote for string.
// Mistake: `#include` file name without its closing quote
#include "colors.inc
sphere { 0, 1 }
