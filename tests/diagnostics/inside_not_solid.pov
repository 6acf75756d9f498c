// error: 6:22 `inside` needs a solid object
// error-text: contains a triangle

// inside() on a shape without an inside.
#declare Flat = triangle { <0,0,0>, <1,0,0>, <0,1,0> }
#declare In = inside(Flat, <0,0,0>);
