// error: 4:59 a sor's radius must not be negative, found -0.4

// A sor's radius must not be negative, not even in the first or last point.
sor { 5, <0.5, -1.5>, <0.6, -1>, <1.0, -0.5>, <0.7, 0.6>, <-0.4, 1.6> }
