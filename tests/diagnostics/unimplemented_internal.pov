// error: 6:14 `f_comma`: POV-Ray's internal function 9 is not implemented in durer
// error-text: called here
// error-text: every function of functions.inc except f_comma (9)

#declare f_comma = function { internal(9) }
#declare V = f_comma(0, 0, 0, 1);
