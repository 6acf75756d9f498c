// error: 6:24 directive after a macro argument
// error-text: POV-Ray ends the argument list here
// error-text: a directive may follow `(` or a comma

#macro Pair(A, B) <A, B> #end
#declare P = Pair(1, 2 #declare Z = 3; );
