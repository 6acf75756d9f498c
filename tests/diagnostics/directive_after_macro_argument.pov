// error: 5:58 directive after a macro argument
// error-text: POV-Ray ends the argument list here

#macro Three(A, B, C) <A, B, C> #end
#macro Broken() #if (1) union { #end sphere { Three(1, 2 #if (1) , #end 3), 1 } #if (1) } #end #end
#declare Shape = Broken()
