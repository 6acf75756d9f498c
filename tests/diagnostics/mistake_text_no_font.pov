// error: 5:12 font file `no_such_font.ttf` not found
// (durer prints no help line)
// POV-Ray: Possible Parse Error: Cannot find file 'no_such_font.ttf', even after trying to append file type extension.
// Mistake: text object whose font file does not exist
text { ttf "no_such_font.ttf" "Hi" 1, 0 }
