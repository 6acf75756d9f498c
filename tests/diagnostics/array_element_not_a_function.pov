// error: 6:14 this element of `Points` is a vector, not a function
// error-text: called here

#declare Points = array[2] { <1, 2, 3>, <4, 5, 6> }
// POV-Ray refuses this too: only a function or spline element can be called.
#declare P = Points[1](0.5, 2);
