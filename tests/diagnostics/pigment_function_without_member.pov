// error: 5:29 `P` returns a colour; pick one of its components
// error-text: add a member, e.g. `P(..).red`

#declare P = function { pigment { gradient x } }
#declare F = function { 1 + P(x, y, z) }
