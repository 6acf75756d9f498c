// error: 5:21 found `>`
// error-text: only allowed inside parentheses, as in POV-Ray: write `(A > B)`

#version 3.7;
#declare Bigger = 3 > 2;
