#declare Point = <1, 2, 3>;
#declare Moved = vturbulence(2, 0.5, Point);
