#macro Add(A, B) A + B #end
#declare X = Add(1);
