// error: 6:1 `look_at` cannot stand at the top level of a scene
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', look_at found instead
// Mistake: `look_at` outside the camera
camera { location <0, 1, -5> }
look_at <0, 0, 0>
