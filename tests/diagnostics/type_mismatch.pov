#declare A = <1, 2, 3> + "text";
