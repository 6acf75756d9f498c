#macro Pair(A, B) <A, B> #end
#declare P = Pair(1, #for (I, 0, 1) 5, #end);
