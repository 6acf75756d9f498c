// error: 6:28 the element called cannot depend on the parameters
// error-text: the index must be known when the function is declared

#declare Fns = array[2] { function(x) { x }, function(x) { -x } }
// POV-Ray also refuses an index that changes with the parameters.
#declare F = function(x) { Fns[x](x) }
