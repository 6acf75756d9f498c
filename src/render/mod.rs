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
//! from: [`camera`] (pixel to ray), [`surface`] (layered and patterned textures at a hit),
//! [`lights`] (fading, spotlights), [`shadows`] (shadow rays), [`extinction`] (media
//! dimming shadow rays), [`media`] (media along viewing rays), [`shading`] (ambient,
//! diffuse, highlights), [`optics`] (reflection, refraction, fading inside objects),
//! [`trace`] (transparency, refraction, reflection, trace levels), [`encoding`] (gamma and
//! rounding to bytes) and [`output`] (PNG file). Pigments, normals and image maps are
//! [`crate::texture`]'s.

pub mod antialias;
pub mod area_light;
pub mod atmosphere;
pub mod camera;
pub mod dispersion;
pub mod encoding;
pub mod extinction;
pub mod focal_blur;
pub mod interiors;
pub mod iridescence;
pub mod lights;
pub mod media;
pub mod mesh_camera;
pub mod optics;
pub mod output;
pub mod photons;
pub mod radiosity;
pub mod radiosity_index;
pub mod shading;
pub mod shadows;
pub mod surface;
pub mod trace;

#[cfg(test)]
mod tests;

pub use output::write_png_atomic;

use crate::geometry::World;
use crate::scene::Scene;
use antialias::{Antialias, Method};
use camera::CameraRays;
use encoding::OutputEncoding;
use glam::DVec3;
use rayon::prelude::*;
use trace::Tracer;

/// Size of the image to render and how to sample it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Anti-aliasing (`None`: one ray through each pixel centre).
    pub antialias: Option<Antialias>,
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
///
/// Where a projection has no ray (outside a fisheye's circle, a degenerate camera) the
/// pixel is black, as in POV-Ray. With focal blur every pixel is already a mean of many
/// rays, and anti-aliasing options are not applied on top.
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
    let point = |x: f64, y: f64| {
        camera
            .ray_at(x, y)
            .map_or(DVec3::ZERO, |ray| tracer.trace_camera_ray(&ray))
    };
    let blur = scene
        .camera
        .focal_blur
        .as_ref()
        .filter(|_| camera.has_focal_blur());
    let mesh = scene.camera.mesh.as_deref();
    let first = |column: u32, row: u32| match (mesh, blur) {
        (Some(mesh), _) => mesh_camera::mesh_pixel(mesh, width, height, column, row, &|ray| {
            tracer.trace_camera_ray(ray)
        })
        .unwrap_or(DVec3::ZERO),
        (None, Some(blur)) => focal_blur::blurred_pixel(column, row, &camera, blur, &|ray| {
            tracer.trace_camera_ray(ray)
        }),
        (None, None) => point(f64::from(column) + 0.5, f64::from(row) + 0.5),
    };
    if let Some(radiosity) = tracer.radiosity() {
        radiosity::pretrace(radiosity, width, height, &first);
    }
    // Mesh cameras and focal blur choose their own rays; anti-aliasing does not apply.
    let colours = match options
        .antialias
        .filter(|_| blur.is_none() && mesh.is_none())
    {
        None => match tracer.radiosity() {
            // The final render stores the radiosity samples it gathers, as POV-Ray does.
            Some(radiosity) => {
                radiosity::map_rows_storing(radiosity, width, height, Some(progress), first)
            }
            None => map_rows(width, height, Some(progress), first),
        },
        Some(aa) if aa.method == Method::NonRecursive => {
            let centres = map_rows(width, height, None, first);
            // Supersample in parallel every pixel the first samples alone mark; the scan
            // below decides which are used and traces the few others it needs.
            let likely = antialias::pixels_to_supersample(&centres, width as usize, aa.threshold);
            let grid = |column: u32, row: u32| {
                let index = row as usize * width as usize + column as usize;
                antialias::grid_mean(column, row, centres[index], &aa, &point)
            };
            let prepared = map_rows(width, height, Some(progress), |column, row| {
                let index = row as usize * width as usize + column as usize;
                if likely[index] {
                    grid(column, row)
                } else {
                    centres[index]
                }
            });
            antialias::scan_supersample(&centres, width, aa.threshold, |index| {
                if likely[index] {
                    prepared[index]
                } else {
                    let (column, row) = (index % width as usize, index / width as usize);
                    grid(column as u32, row as u32)
                }
            })
        }
        Some(aa) => {
            // Pixel corners, shared between neighbouring pixels.
            let corners = map_rows(width + 1, height + 1, None, |x, y| {
                point(f64::from(x), f64::from(y))
            });
            let stride = width as usize + 1;
            map_rows(width, height, Some(progress), |column, row| {
                let at = |x: u32, y: u32| corners[y as usize * stride + x as usize];
                let four = [
                    at(column, row),
                    at(column + 1, row),
                    at(column, row + 1),
                    at(column + 1, row + 1),
                ];
                antialias::recursive_mean(column, row, four, &aa, &point)
            })
        }
    };
    let encoding = OutputEncoding::for_settings(&scene.settings);
    let pixels = colours
        .iter()
        .map(|colour| {
            [
                encoding.encode(colour.x),
                encoding.encode(colour.y),
                encoding.encode(colour.z),
            ]
        })
        .collect();
    Image {
        width,
        height,
        pixels,
    }
}

/// `colour(column, row)` for every pixel of a `width` × `height` grid, rows in parallel;
/// `progress` (when given) hears of each finished row.
fn map_rows(
    width: u32,
    height: u32,
    progress: Option<&(dyn Fn(u32) + Sync)>,
    colour: impl Fn(u32, u32) -> DVec3 + Sync,
) -> Vec<DVec3> {
    let mut colours = vec![DVec3::ZERO; width as usize * height as usize];
    colours
        .par_chunks_mut(width.max(1) as usize)
        .enumerate()
        .for_each(|(row, line)| {
            for (column, slot) in line.iter_mut().enumerate() {
                *slot = colour(column as u32, row as u32);
            }
            if let Some(progress) = progress {
                progress(1);
            }
        });
    colours
}
