// error: 5:22 expected an object, found a float

// inside() on a value that is not an object.
#declare Radius = 2;
#declare In = inside(Radius, <0,0,0>);
