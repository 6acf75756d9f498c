#declare f_helix1 = function { internal(25) }
#declare V = f_helix1(0, 0, 0, 1, 2, 0.1, 0.4, 1, 1, 0);
