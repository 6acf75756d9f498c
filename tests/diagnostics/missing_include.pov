// error: 4:1 cannot find include file `no_such_file.inc`
// error-text: searched:

#include "no_such_file.inc"
