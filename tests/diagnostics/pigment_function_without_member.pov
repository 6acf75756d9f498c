#declare P = function { pigment { gradient x } }
#declare F = function { 1 + P(x, y, z) }
