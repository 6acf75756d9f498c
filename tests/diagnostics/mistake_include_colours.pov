// error: 5:1 cannot find include file `colours.inc`
// error-text: searched:
// POV-Ray: Parse Error: Cannot open include file colours.inc.
// Mistake: British spelling of colors.inc
#include "colours.inc"
