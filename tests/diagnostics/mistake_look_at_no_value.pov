// error: 5:30 expected a vector, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: `look_at` without its point
camera { location <0, 1, -5> look_at }
