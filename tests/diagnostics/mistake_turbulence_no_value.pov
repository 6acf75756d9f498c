// error: 5:30 expected a float or vector, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: `turbulence` without its value
sphere { 0, 1 pigment { bozo turbulence } }
