// inside() on a value that is not an object.
#declare Radius = 2;
#declare In = inside(Radius, <0,0,0>);
