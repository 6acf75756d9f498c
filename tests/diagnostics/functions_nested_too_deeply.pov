#declare F = function { pigment { rgb 0.5 } }
#for (I, 1, 100)
  #declare F = function { pigment { function { F(x, y, z).red } } }
#end
