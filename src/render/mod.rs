//! The recursive ray tracer: camera rays, shading, lights, output image.
