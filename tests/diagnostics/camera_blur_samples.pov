// error: 4:56 0 is not a number of samples
// error-text: at least 1

camera { location <0, 1, -3> aperture 0.5 blur_samples 0 }
