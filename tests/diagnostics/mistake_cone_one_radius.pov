// error: 5:14 expected the cap radius, found the end of the block
// error-text: after this
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: cone with one radius
cone { 0, 1, y }
