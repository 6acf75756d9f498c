#declare A = array[3];
#declare B = A[5];
