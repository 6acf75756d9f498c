// error: 5:20 cannot read height field image "bad.hdr"
// error-text: the resolution line `-Y four +X 4` is not `-Y height +X width`

#version 3.7;
height_field { hdr "bad.hdr" }
