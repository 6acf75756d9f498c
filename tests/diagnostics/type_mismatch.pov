// error: 3:14 cannot combine a vector and a string

#declare A = <1, 2, 3> + "text";
