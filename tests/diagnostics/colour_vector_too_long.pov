// warning: 5:34 suspicious expression after `rgb`: 4 components where 3 are expected
// warning: 6:36 suspicious expression after `rgbt`: 5 components where 4 are expected

// povray warns "Suspicious expression after rgb." and keeps the extra components.
plane { y, 0 pigment { color rgb <0.1, 0.1, 0.1, 1> } }
sphere { 0, 1 pigment { color rgbt <1, 0, 0, 0.5, 0.2> } }
sphere { 0, 1 pigment { color rgbf <1, 0, 0, 0.5> } }
