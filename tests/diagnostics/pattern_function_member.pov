#declare Q = function { pattern { bozo } }
#declare F = function { Q(x, y, z).red }
