//! The recursive ray tracer: camera rays, shading, lights, output image.
//!
//! In: a [`Scene`] (camera, lights, background, global settings) and the [`World`] built
//! from it. Out: an 8-bit [`Image`] with the values POV-Ray 3.7 writes to its PNG, and
//! [`write_png_atomic`] to store it. Holds: the image does not depend on the number of
//! threads (rows are traced independently with rayon, nothing random, nothing shared and
//! mutable); tracing allocates nothing per ray; no input makes it panic (non-finite values
//! end as black pixels).
//!
//! Each module states the POV-Ray rules it implements and the renders they were measured
//! from: [`camera`] (pixel to ray), [`pattern`] (checker, gradient, colour maps),
//! [`lights`] (fading, spotlights, shadows), [`shading`] (ambient, diffuse, highlights),
//! [`trace`] (transparency, refraction, reflection, trace levels), [`encoding`] (gamma and
//! rounding to bytes) and [`output`] (PNG file).

pub mod area_light;
pub mod camera;
pub mod dispersion;
pub mod encoding;
pub mod lights;
pub mod output;
pub mod pattern;
pub mod reflection;
pub mod shading;
pub mod trace;

#[cfg(test)]
mod tests;

pub use output::write_png_atomic;

use crate::geometry::World;
use crate::scene::Scene;
use camera::CameraRays;
use encoding::OutputEncoding;
use rayon::prelude::*;
use trace::Tracer;

/// Size of the image to render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RenderOptions {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

/// A rendered image: 8-bit RGB, as POV-Ray writes its PNG.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Pixels row by row, top row first, each `[red, green, blue]`.
    pub pixels: Vec<[u8; 3]>,
}

impl Image {
    /// The pixel at `column`, `row` (row 0 at the top), if inside the image.
    pub fn pixel(&self, column: u32, row: u32) -> Option<[u8; 3]> {
        if column >= self.width || row >= self.height {
            return None;
        }
        let index = row as usize * self.width as usize + column as usize;
        self.pixels.get(index).copied()
    }
}

/// Renders `scene` (whose objects `world` holds) at the size in `options`.
///
/// `progress(n)` is called, from worker threads, each time `n` more rows are finished. An
/// image with a zero dimension (or too large to address) comes back empty.
pub fn render(
    scene: &Scene,
    world: &World,
    options: &RenderOptions,
    progress: &(dyn Fn(u32) + Sync),
) -> Image {
    let (width, height) = (options.width, options.height);
    let Some(count) = (width as usize).checked_mul(height as usize) else {
        return Image {
            width: 0,
            height: 0,
            pixels: Vec::new(),
        };
    };
    if count == 0 {
        return Image {
            width,
            height,
            pixels: Vec::new(),
        };
    }
    let camera = CameraRays::new(&scene.camera, width, height);
    let tracer = Tracer::new(scene, world);
    let encoding = OutputEncoding::for_settings(&scene.settings);
    let mut pixels = vec![[0u8; 3]; count];
    pixels
        .par_chunks_mut(width as usize)
        .enumerate()
        .for_each(|(row, line)| {
            for (column, pixel) in line.iter_mut().enumerate() {
                let colour = match camera.ray(column as u32, row as u32) {
                    Some(ray) => tracer.trace_camera_ray(&ray),
                    None => scene.background.rgb_vec(),
                };
                *pixel = [
                    encoding.encode(colour.x),
                    encoding.encode(colour.y),
                    encoding.encode(colour.z),
                ];
            }
            progress(1);
        });
    Image {
        width,
        height,
        pixels,
    }
}
