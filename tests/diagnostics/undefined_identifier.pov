#declare Radius = 1;
sphere { 0, Raduis }
