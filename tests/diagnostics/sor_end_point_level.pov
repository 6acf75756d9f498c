// error: 5:10 a sor's point may not lie at the height of the point two places from it (1)
// error-text: divide by a zero height difference

#version 3.7;
sor { 4, <1, 1>, <1, 0>, <1, 1>, <1, 2> }
