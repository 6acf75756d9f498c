// Found by the mutation test; an endless #for among macro arguments collected its values until the allocator aborted (4.8 GB); the values are now read up to the second one, already an error
// command: check
// expect: a directive standing as a macro argument left two values
// exit: 1

#macro Pair(A, B) <A, B> #end
#declare P = Pair(1, #for (I, 0, 1e400) 5, #end);
