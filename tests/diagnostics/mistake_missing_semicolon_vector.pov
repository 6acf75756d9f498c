// error: 6:1 expected an object, camera or light, found a vector
// (durer prints no help line)
// POV-Ray: Parse Error: All #declares of float, vector, and color require semi-colon ';' at end if the language version is set to 3.5 or higher. Either add the semi-colon or set the language version to 3.1 or lower.
// Mistake: missing `;` after a float `#declare` followed by a vector
#declare Offset = 1
<1, 0, 0>
