// error: 5:18 `vturbulence` takes 4 arguments, found 3
// error-text: called here

#declare Point = <1, 2, 3>;
#declare Moved = vturbulence(2, 0.5, Point);
