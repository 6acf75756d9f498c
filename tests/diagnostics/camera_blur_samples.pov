camera { location <0, 1, -3> aperture 0.5 blur_samples 0 }
