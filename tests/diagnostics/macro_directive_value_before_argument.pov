// error: 5:44 a directive among a call's arguments left a value where POV-Ray reads none
// error-text: left by this directive

#macro Pair(A, B) <A, B> #end
#declare P = Pair(1, #switch (1) #case (1) 5 #break #end 6);
