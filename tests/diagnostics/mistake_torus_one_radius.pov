// error: 5:9 expected the minor radius, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: torus with one radius
torus { 1 }
