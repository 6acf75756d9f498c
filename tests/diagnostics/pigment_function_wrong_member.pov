// error: 5:25 `P` returns a colour, which has no member `.w`
// error-text: .gray .hf

#declare P = function { pigment { gradient x } }
#declare F = function { P(x, y, z).w * 2 }
