// error: 5:31 the tiling number must be between 1 and 27
// error-text: this is 28

// A tiling number outside 1 to 27 is an error, as in POV-Ray.
plane { y, 0 pigment { tiling 28 } }
