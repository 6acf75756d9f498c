//! The recursive ray tracer: camera rays, shading, lights, output image.
//!
//! In: a [`Scene`] (camera, lights, background, global settings) and the [`World`] built
//! from it, [`RenderOptions`] (size, region, anti-aliasing, alpha, [`quality`]). Out: a
//! [`RenderedImage`] of traced values and coverage, which [`output`] stores in any format
//! (or an 8-bit [`Image`] with the values POV-Ray 3.7 writes to its PNG). Holds: the image does not depend on the number of
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
//! rounding to bytes) and [`output`] (image files). Pigments, normals and image maps are
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
pub mod quality;
pub mod radiosity;
pub mod radiosity_index;
pub mod shading;
pub mod shadows;
pub mod subsurface;
pub mod surface;
pub mod trace;

#[cfg(test)]
mod tests;

pub use output::RenderedImage;

use crate::geometry::World;
use crate::scene::Scene;
use antialias::{Antialias, Method};
use camera::CameraRays;
use encoding::OutputEncoding;
use glam::{DVec3, DVec4};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
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
    /// The part of the image to render (`None`: all of it); the rest is black.
    pub region: Option<Region>,
    /// Compute coverage for an alpha channel: the background's share of each pixel (by
    /// the background's filter and transmit) leaves the colour and lowers the coverage.
    pub alpha: bool,
    /// What is computed (`+Q`; [`quality`]).
    pub quality: quality::Quality,
}

impl RenderOptions {
    /// The whole image at `width` × `height`, one ray per pixel, no alpha.
    pub fn new(width: u32, height: u32) -> RenderOptions {
        RenderOptions {
            width,
            height,
            antialias: None,
            region: None,
            alpha: false,
            quality: quality::Quality::default(),
        }
    }
}

/// A rectangle of pixels: columns `left..right`, rows `top..bottom` (row 0 at the top).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Region {
    pub left: u32,
    pub top: u32,
    pub right: u32,
    pub bottom: u32,
}

/// Set when the render should stop (Ctrl-C): rows not yet begun are skipped and
/// [`render_image`] returns `None`.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// Asks every render in progress to stop soon.
pub fn interrupt() {
    INTERRUPTED.store(true, Ordering::SeqCst);
}

/// Lets renders run again after [`interrupt`] (`durer watch` abandons a render when a file
/// changes, then starts the next).
pub fn clear_interrupt() {
    INTERRUPTED.store(false, Ordering::SeqCst);
}

/// Whether [`interrupt`] was called.
pub fn interrupted() -> bool {
    INTERRUPTED.load(Ordering::Relaxed)
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

/// Renders `scene` (whose objects `world` holds) at the size in `options`, as the 8-bit
/// image of an RGB PNG.
///
/// `progress(n)` is called, from worker threads, each time `n` more rows are finished. An
/// image with a zero dimension (or too large to address) comes back empty.
pub fn render(
    scene: &Scene,
    world: &World,
    options: &RenderOptions,
    progress: &(dyn Fn(u32) + Sync),
) -> Image {
    match render_image(scene, world, options, progress) {
        Some(image) if !image.pixels.is_empty() => image.to_image(),
        _ => Image {
            width: 0,
            height: 0,
            pixels: Vec::new(),
        },
    }
}

/// Renders `scene` at the size in `options`, keeping traced values and coverage for any
/// output format; `None` when [`interrupt`] stopped it.
///
/// Where a projection has no ray (outside a fisheye's circle, a degenerate camera) the
/// pixel is black, as in POV-Ray. With focal blur every pixel is already a mean of many
/// rays, and anti-aliasing options are not applied on top (nor is coverage computed: such
/// pixels are opaque).
///
/// A region's pixels are those of the whole render. Anti-aliasing method 1 decides in scan
/// order from the top left and radiosity stores samples in row order, so with either the
/// rows above the region are traced too (at the cost of those rows; with method 1 also the
/// row below, whose scan can supersample the region's last row); otherwise only the region
/// is traced.
pub fn render_image(
    scene: &Scene,
    world: &World,
    options: &RenderOptions,
    progress: &(dyn Fn(u32) + Sync),
) -> Option<RenderedImage> {
    let (width, height) = (options.width, options.height);
    let encoding = OutputEncoding::for_settings(&scene.settings);
    let Some(count) = (width as usize).checked_mul(height as usize) else {
        return Some(RenderedImage {
            width: 0,
            height: 0,
            pixels: Vec::new(),
            encoding,
        });
    };
    if count == 0 {
        return Some(RenderedImage {
            width,
            height,
            pixels: Vec::new(),
            encoding,
        });
    }
    let region = options
        .region
        .map(|r| Region {
            left: r.left.min(width),
            top: r.top.min(height),
            right: r.right.min(width),
            bottom: r.bottom.min(height),
        })
        .unwrap_or(Region {
            left: 0,
            top: 0,
            right: width,
            bottom: height,
        });
    let camera = CameraRays::new(&scene.camera, width, height);
    let blur = scene
        .camera
        .focal_blur
        .as_ref()
        .filter(|_| camera.has_focal_blur());
    let mesh = scene.camera.mesh.as_deref();
    let reduced = options.quality.reduced(scene);
    let scene = reduced.as_ref().unwrap_or(scene);
    let tracer = Tracer::new(scene, world)
        .with_alpha(options.alpha && blur.is_none() && mesh.is_none())
        .with_quality(options.quality);
    let point = |x: f64, y: f64| {
        camera
            .ray_at(x, y)
            .map_or(DVec4::ZERO, |ray| tracer.trace_camera_sample(&ray))
    };
    let opaque = |colour: DVec3| colour.extend(0.0);
    let first = |column: u32, row: u32| match (mesh, blur) {
        (Some(mesh), _) => opaque(
            mesh_camera::mesh_pixel(mesh, width, height, column, row, &|ray| {
                tracer.trace_camera_ray(ray)
            })
            .unwrap_or(DVec3::ZERO),
        ),
        (None, Some(blur)) => opaque(focal_blur::blurred_pixel(
            column,
            row,
            &camera,
            blur,
            &|ray| tracer.trace_camera_ray(ray),
        )),
        (None, None) => point(f64::from(column) + 0.5, f64::from(row) + 0.5),
    };
    if let Some(radiosity) = tracer.radiosity() {
        radiosity::pretrace(radiosity, width, height, &|c, r| first(c, r));
    }
    let antialias = options
        .antialias
        .filter(|_| blur.is_none() && mesh.is_none());
    // The window of pixels traced: the region, or everything above it too when decisions
    // depend on earlier rows. Method 1's scan of a pixel also supersamples its left and
    // upper neighbours, so a region's last row depends on the row below it: that row is
    // scanned too.
    let method_1 = antialias.is_some_and(|aa| aa.method == Method::NonRecursive);
    let scan_from_top = tracer.radiosity().is_some() || method_1;
    let window = if scan_from_top {
        Region {
            left: 0,
            top: 0,
            right: width,
            bottom: if method_1 {
                (region.bottom + 1).min(height)
            } else {
                region.bottom
            },
        }
    } else {
        region
    };
    let window_width = window.right.saturating_sub(window.left);
    let window_height = window.bottom.saturating_sub(window.top);
    let at = |column: u32, row: u32| (column + window.left, row + window.top);
    let samples = match antialias {
        None => match tracer.radiosity() {
            // The final render stores the radiosity samples it gathers, as POV-Ray does.
            Some(radiosity) => radiosity::map_rows_storing(
                radiosity,
                window_width,
                window_height,
                Some(progress),
                |c, r| {
                    let (c, r) = at(c, r);
                    first(c, r)
                },
            ),
            None => map_rows(window_width, window_height, Some(progress), |c, r| {
                let (c, r) = at(c, r);
                first(c, r)
            }),
        },
        Some(aa) if aa.method == Method::NonRecursive => {
            // The window starts at the image's top-left corner here.
            let centres = map_rows(window_width, window_height, None, first);
            // Supersample in parallel every pixel the first samples alone mark; the scan
            // below decides which are used and traces the few others it needs.
            let likely =
                antialias::pixels_to_supersample(&centres, window_width as usize, aa.threshold);
            let grid = |column: u32, row: u32| {
                let index = row as usize * window_width as usize + column as usize;
                antialias::grid_mean(column, row, centres[index], &aa, &point)
            };
            let prepared = map_rows(
                window_width,
                window_height,
                Some(progress),
                |column, row| {
                    let index = row as usize * window_width as usize + column as usize;
                    if likely[index] {
                        grid(column, row)
                    } else {
                        centres[index]
                    }
                },
            );
            antialias::scan_supersample(&centres, window_width, aa.threshold, |index| {
                if likely[index] {
                    prepared[index]
                } else {
                    let (column, row) =
                        (index % window_width as usize, index / window_width as usize);
                    grid(column as u32, row as u32)
                }
            })
        }
        Some(aa) => {
            // Pixel corners, shared between neighbouring pixels.
            let corners = map_rows(window_width + 1, window_height + 1, None, |x, y| {
                let (x, y) = at(x, y);
                point(f64::from(x), f64::from(y))
            });
            let stride = window_width as usize + 1;
            map_rows(
                window_width,
                window_height,
                Some(progress),
                |column, row| {
                    let corner = |x: u32, y: u32| corners[y as usize * stride + x as usize];
                    let four = [
                        corner(column, row),
                        corner(column + 1, row),
                        corner(column, row + 1),
                        corner(column + 1, row + 1),
                    ];
                    let (x, y) = at(column, row);
                    antialias::recursive_mean(x, y, four, &aa, &point)
                },
            )
        }
    };
    if interrupted() {
        return None;
    }
    // Black, opaque, outside the region (as povray writes a partial render).
    let mut pixels = vec![[0.0, 0.0, 0.0, 1.0]; count];
    for row in region.top..region.bottom {
        for column in region.left..region.right {
            let index = (row - window.top) as usize * window_width as usize
                + (column - window.left) as usize;
            let sample = samples[index];
            let coverage = if options.alpha {
                (1.0 - sample.w).clamp(0.0, 1.0)
            } else {
                1.0
            };
            pixels[row as usize * width as usize + column as usize] =
                [sample.x, sample.y, sample.z, coverage];
        }
    }
    Some(RenderedImage {
        width,
        height,
        pixels,
        encoding,
    })
}

/// `colour(column, row)` for every pixel of a `width` × `height` grid, rows in parallel;
/// `progress` (when given) hears of each finished row.
fn map_rows(
    width: u32,
    height: u32,
    progress: Option<&(dyn Fn(u32) + Sync)>,
    colour: impl Fn(u32, u32) -> DVec4 + Sync,
) -> Vec<DVec4> {
    let mut colours = vec![DVec4::ZERO; width as usize * height as usize];
    colours
        .par_chunks_mut(width.max(1) as usize)
        .enumerate()
        .for_each(|(row, line)| {
            if interrupted() {
                return;
            }
            for (column, slot) in line.iter_mut().enumerate() {
                *slot = colour(column as u32, row as u32);
            }
            if let Some(progress) = progress {
                progress(1);
            }
        });
    colours
}
