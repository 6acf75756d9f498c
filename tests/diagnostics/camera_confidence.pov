// error: 3:47 confidence 1.5 is not a probability

camera { aperture 1 blur_samples 4 confidence 1.5 }
