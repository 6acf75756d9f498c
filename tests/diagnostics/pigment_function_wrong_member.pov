#declare P = function { pigment { gradient x } }
#declare F = function { P(x, y, z).w * 2 }
