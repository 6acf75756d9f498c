// error: 1:1 expected the cap radius, found the end of the block
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'numeric expression', } found instead
// Mistake: cone with one radius
cone { 0, 1, y }
