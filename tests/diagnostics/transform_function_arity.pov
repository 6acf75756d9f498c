// error: 5:25 function `T` takes 3 arguments, found 2
// error-text: the function is declared here

#declare T = function { transform { scale 2 } }
#declare F = function { T(x, y).x }
