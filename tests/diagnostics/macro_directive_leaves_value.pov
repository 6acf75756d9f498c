// error: 5:37 a directive standing as a macro argument left two values
// error-text: separate arguments with commas outside the directive

#macro Pair(A, B) <A, B> #end
#declare P = Pair(1, #for (I, 0, 1) 5, #end);
