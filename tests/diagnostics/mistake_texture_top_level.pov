// error: 5:1 expected an object, camera or light, found a texture
// (durer prints no help line)
// POV-Ray: Parse Error: Expected 'object or directive', texture found instead
// Mistake: texture at file level, outside any object
texture { pigment { rgb 1 } }
