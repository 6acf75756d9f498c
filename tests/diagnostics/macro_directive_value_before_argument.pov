#macro Pair(A, B) <A, B> #end
#declare P = Pair(1, #switch (1) #case (1) 5 #break #end 6);
