// A tiling number outside 1 to 27 is an error, as in POV-Ray.
plane { y, 0 pigment { tiling 28 } }
