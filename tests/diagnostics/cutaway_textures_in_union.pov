// error: 4:38 `cutaway_textures` can only be used with intersection and difference
// error-text: inside `union`

union { sphere { 0, 1 } box { 0, 2 } cutaway_textures pigment { rgb 1 } }
