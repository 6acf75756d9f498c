// error: 5:14 array index [5] out of range
// error-text: size is [3]

#declare A = array[3];
#declare B = A[5];
