// error: 6:14 `f_spare`: POV-Ray's internal function 77 is not implemented in durer
// error-text: called here
// error-text: internal(0) to internal(76) and internal(78)

#declare f_spare = function { internal(77) }
#declare V = f_spare(0, 0, 0, 1);
