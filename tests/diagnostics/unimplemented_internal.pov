#declare f_comma = function { internal(9) }
#declare V = f_comma(0, 0, 0, 1);
