// error: 5:44 a viewing angle cannot be negative
// error-text: angle -5

// POV-Ray refuses this too ("Negative viewing angle").
camera { fisheye location <0, 0, -5> angle -5 }
