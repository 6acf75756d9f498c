// error: 6:48 functions call each other too deeply
// error-text: more than 64 nested calls

#declare F = function { pigment { rgb 0.5 } }
#for (I, 1, 100)
  #declare F = function { pigment { function { F(x, y, z).red } } }
#end
