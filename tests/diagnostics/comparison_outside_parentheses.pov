// error: 5:21 `>` outside parentheses
// error-text: as in POV-Ray, write `(3 > 2)`: comparisons, `&`, `|` and `? :` need parentheses around them

#version 3.7;
#declare Bigger = 3 > 2;
