// error: 6:44 a sor's heights must increase: -0.5 follows -0.5
// error-text: last but one

// A sor's heights must increase from the second point to the last but one (POV-Ray:
// "Incorrect point in surface of revolution"); the first and last points may lie anywhere.
sor { 6, <0.5, 2>, <0.6, -1>, <1.0, -0.5>, <0.7, -0.5>, <0.4, 1.2>, <0.3, -3> }
