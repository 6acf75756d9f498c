// error: 5:14 macro `Add` takes 2 arguments, found 1
// error-text: parameters: (A, B)

#macro Add(A, B) A + B #end
#declare X = Add(1);
