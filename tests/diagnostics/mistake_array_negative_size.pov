// error: 5:21 array size -1 is not between 1 and
// error-text: this is the `array-size` limit
// POV-Ray: Parse Error: Invalid dimension size for an array
// Mistake: array of negative size
#declare Ar = array[-1];
