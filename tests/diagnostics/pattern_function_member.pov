// error: 4:25 `Q` returns a float, which has no member `.red`

#declare Q = function { pattern { bozo } }
#declare F = function { Q(x, y, z).red }
