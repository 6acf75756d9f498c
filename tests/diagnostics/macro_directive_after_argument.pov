#macro Pair(A, B) <A, B> #end
#declare P = Pair(1, 2 #declare Z = 3; );
