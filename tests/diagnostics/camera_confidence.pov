camera { aperture 1 blur_samples 4 confidence 1.5 }
