//! Writing rendered images: every output format, written atomically.
//!
//! In: a [`RenderedImage`] (traced colours with coverage) or an 8-bit [`Image`], a
//! [`FileFormat`] with bit depth and alpha, a path. Out: the file's bytes, and the file
//! itself written through a temporary file and a rename, so it appears complete or not at
//! all and a failed write never destroys an existing image.
//!
//! How values are stored (measured against `povray` 3.7's files):
//! - PNG, TGA, BMP, PPM, JPEG: the traced value goes through the scene's output encoding
//!   ([`OutputEncoding`]: `assumed_gamma`, sRGB curve) at the file's depth (8 bits, or up
//!   to 16 for PNG and PPM); PNG carries the `gAMA` (1/2.2) and `sRGB` chunks POV-Ray
//!   writes. With alpha the colour is stored straight (divided by the coverage), as
//!   POV-Ray 3.7 does for PNG, TGA and BMP.
//! - OpenEXR and Radiance HDR: linear light, not clamped: the traced value raised to
//!   `assumed_gamma` (a scene without one, before 3.7, is sRGB-decoded), as `povray`
//!   writes them; EXR stores associated (premultiplied) alpha, as POV-Ray documents.
//! - `File_Gamma` other than sRGB replaces the sRGB curve by that power.

use super::encoding::OutputEncoding;
use super::Image;
use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};
use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Distinguishes temporary files of concurrent writes from one process.
static TEMPORARY_COUNTER: AtomicU64 = AtomicU64::new(0);

/// An output file format (POV-Ray's `+F` letters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileFormat {
    /// `N`: PNG, 8 or 16 bits, alpha.
    Png,
    /// `P`: binary PPM, 8 or 16 bits.
    Ppm,
    /// `T`: uncompressed Targa, alpha.
    Tga,
    /// `C`: run-length compressed Targa, alpha.
    TgaCompressed,
    /// `B`: BMP, alpha.
    Bmp,
    /// `J`: JPEG.
    Jpeg,
    /// `E`: OpenEXR, 32-bit float, linear.
    Exr,
    /// `H`: Radiance RGBE, linear.
    Hdr,
}

impl FileFormat {
    /// The format of a `+F` letter (`S`, the system format, is TGA on Unix as in POV-Ray).
    pub fn from_letter(letter: char) -> Option<FileFormat> {
        Some(match letter.to_ascii_uppercase() {
            'N' => FileFormat::Png,
            'P' => FileFormat::Ppm,
            'T' | 'S' => FileFormat::Tga,
            'C' => FileFormat::TgaCompressed,
            'B' => FileFormat::Bmp,
            'J' => FileFormat::Jpeg,
            'E' => FileFormat::Exr,
            'H' => FileFormat::Hdr,
            _ => return None,
        })
    }

    /// The format a file name's extension names, if any.
    pub fn from_extension(path: &Path) -> Option<FileFormat> {
        let extension = path.extension()?.to_str()?.to_ascii_lowercase();
        Some(match extension.as_str() {
            "png" => FileFormat::Png,
            "ppm" | "pnm" => FileFormat::Ppm,
            "tga" => FileFormat::Tga,
            "bmp" => FileFormat::Bmp,
            "jpg" | "jpeg" => FileFormat::Jpeg,
            "exr" => FileFormat::Exr,
            "hdr" | "pic" => FileFormat::Hdr,
            _ => return None,
        })
    }

    /// The extension POV-Ray gives files of this format.
    pub fn extension(self) -> &'static str {
        match self {
            FileFormat::Png => "png",
            FileFormat::Ppm => "ppm",
            FileFormat::Tga | FileFormat::TgaCompressed => "tga",
            FileFormat::Bmp => "bmp",
            FileFormat::Jpeg => "jpg",
            FileFormat::Exr => "exr",
            FileFormat::Hdr => "hdr",
        }
    }

    /// Whether files of this format can hold an alpha channel.
    pub fn has_alpha(self) -> bool {
        matches!(
            self,
            FileFormat::Png
                | FileFormat::Tga
                | FileFormat::TgaCompressed
                | FileFormat::Bmp
                | FileFormat::Exr
        )
    }
}

/// How to store a rendered image.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputOptions {
    pub format: FileFormat,
    /// Bits per colour channel, 5 to 16 (PNG and PPM; the others store 8 or floats).
    pub bits: u32,
    /// Write the coverage as an alpha channel (formats that have one).
    pub alpha: bool,
    /// JPEG quality, 2 to 100.
    pub jpeg_quality: u8,
    /// `File_Gamma`: `None` for the sRGB curve, else `1 / gamma` is applied to linear light.
    pub file_gamma: Option<f64>,
}

impl OutputOptions {
    /// 8-bit PNG without alpha, POV-Ray's default.
    pub fn png() -> OutputOptions {
        OutputOptions {
            format: FileFormat::Png,
            bits: 8,
            alpha: false,
            jpeg_quality: 85,
            file_gamma: None,
        }
    }
}

/// A rendered image before it is stored: per pixel the traced colour (in the scene's working
/// space, premultiplied by coverage) and the coverage (1 where no background shows; with
/// alpha off always 1).
#[derive(Clone, Debug, PartialEq)]
pub struct RenderedImage {
    pub width: u32,
    pub height: u32,
    /// Row by row, top row first: red, green, blue, coverage.
    pub pixels: Vec<[f64; 4]>,
    /// How traced values become file values.
    pub encoding: OutputEncoding,
}

impl RenderedImage {
    /// The 8-bit image POV-Ray writes to an RGB PNG.
    pub fn to_image(&self) -> Image {
        let pixels = self
            .pixels
            .iter()
            .map(|p| {
                let [r, g, b] = straight(*p);
                [
                    self.encoding.encode(r),
                    self.encoding.encode(g),
                    self.encoding.encode(b),
                ]
            })
            .collect();
        Image {
            width: self.width,
            height: self.height,
            pixels,
        }
    }

    /// The pixel's colour as linear light, straight (not premultiplied), not clamped.
    fn linear(&self, pixel: [f64; 4]) -> [f32; 3] {
        straight(pixel).map(|v| self.encoding.to_linear(v) as f32)
    }

    /// One channel at `max` (255, 65535 ...) through the output curve.
    fn quantise(&self, value: f64, max: f64, options: &OutputOptions) -> u32 {
        match options.file_gamma {
            None => self.encoding.encode_to(value, max),
            Some(gamma) => {
                let linear = self.encoding.to_linear(value);
                let clipped = if linear.is_nan() {
                    0.0
                } else {
                    linear.clamp(0.0, 1.0)
                };
                (clipped.powf(1.0 / gamma) * max + 0.5)
                    .floor()
                    .clamp(0.0, max) as u32
            }
        }
    }

    /// Integer samples: `channels` (3 or 4) per pixel at `bits` (5..=16), each scaled into
    /// the container of 8 or 16 bits.
    fn samples(&self, channels: usize, bits: u32, options: &OutputOptions) -> Vec<u16> {
        let bits = bits.clamp(1, 16);
        let max = f64::from((1u32 << bits) - 1);
        let container = if bits <= 8 { 255.0 } else { 65535.0 };
        let scale = |q: u32| -> u16 {
            if max == container {
                q as u16
            } else {
                (f64::from(q) * container / max + 0.5).floor() as u16
            }
        };
        let mut out = Vec::with_capacity(self.pixels.len() * channels);
        for pixel in &self.pixels {
            for value in straight(*pixel) {
                out.push(scale(self.quantise(value, max, options)));
            }
            if channels == 4 {
                let coverage = pixel[3];
                let coverage = if coverage.is_nan() {
                    1.0
                } else {
                    coverage.clamp(0.0, 1.0)
                };
                out.push(scale((coverage * max + 0.5).floor() as u32));
            }
        }
        out
    }
}

/// A pixel's colour divided by its coverage (0 where nothing is covered).
fn straight(pixel: [f64; 4]) -> [f64; 3] {
    let coverage = pixel[3];
    let rgb = [pixel[0], pixel[1], pixel[2]];
    if coverage >= 1.0 || coverage.is_nan() {
        rgb
    } else if coverage <= 0.0 {
        [0.0; 3]
    } else {
        rgb.map(|v| v / coverage)
    }
}

/// The bytes of `image` stored in the format `options` names.
pub fn encode(image: &RenderedImage, options: &OutputOptions) -> io::Result<Vec<u8>> {
    let expected = (image.width as usize).checked_mul(image.height as usize);
    if image.width == 0 || image.height == 0 || expected != Some(image.pixels.len()) {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!(
                "image of {}x{} pixels holds {} pixels",
                image.width,
                image.height,
                image.pixels.len()
            ),
        ));
    }
    let (width, height) = (image.width, image.height);
    let alpha = options.alpha && options.format.has_alpha();
    let channels = if alpha { 4 } else { 3 };
    let mut encoded = Vec::new();
    let bytes8 = |bits: u32| -> Vec<u8> {
        image
            .samples(channels, bits.min(8), options)
            .into_iter()
            .map(|v| v as u8)
            .collect()
    };
    // image's encoders take 16-bit samples in native byte order.
    let bytes16 = || -> Vec<u8> {
        image
            .samples(channels, options.bits, options)
            .into_iter()
            .flat_map(u16::to_ne_bytes)
            .collect()
    };
    let colour_type = |wide: bool| match (alpha, wide) {
        (false, false) => ExtendedColorType::Rgb8,
        (true, false) => ExtendedColorType::Rgba8,
        (false, true) => ExtendedColorType::Rgb16,
        (true, true) => ExtendedColorType::Rgba16,
    };
    let failed = io::Error::other;
    match options.format {
        FileFormat::Png => {
            let wide = options.bits > 8;
            let data = if wide {
                bytes16()
            } else {
                bytes8(options.bits)
            };
            PngEncoder::new(&mut encoded)
                .write_image(&data, width, height, colour_type(wide))
                .map_err(failed)?;
            return Ok(with_colour_space_chunks(encoded));
        }
        FileFormat::Ppm => {
            let three = OutputOptions {
                alpha: false,
                ..*options
            };
            if options.bits > 8 {
                // Binary PPM with 16-bit samples (maximum 65535, big-endian). image's PNM
                // encoder writes 16-bit samples only as PAM, not as P6, so the three header
                // lines are written here.
                let max = (1u32 << options.bits.min(16)) - 1;
                encoded.extend_from_slice(format!("P6\n{width} {height}\n{max}\n").as_bytes());
                let bits = options.bits;
                let samples = image.samples(3, bits, &three);
                // samples() scales into the 16-bit container; PPM keeps the file's own maximum.
                for value in samples {
                    let own = (f64::from(value) * f64::from(max) / 65535.0 + 0.5).floor() as u16;
                    encoded.extend_from_slice(&own.to_be_bytes());
                }
            } else {
                use image::codecs::pnm::{PnmEncoder, PnmSubtype, SampleEncoding};
                let data: Vec<u8> = image
                    .samples(3, options.bits.min(8), &three)
                    .into_iter()
                    .map(|v| v as u8)
                    .collect();
                PnmEncoder::new(&mut encoded)
                    .with_subtype(PnmSubtype::Pixmap(SampleEncoding::Binary))
                    .write_image(&data, width, height, ExtendedColorType::Rgb8)
                    .map_err(failed)?;
            }
        }
        FileFormat::Tga | FileFormat::TgaCompressed => {
            use image::codecs::tga::TgaEncoder;
            let mut encoder = TgaEncoder::new(&mut encoded);
            if options.format == FileFormat::Tga {
                encoder = encoder.disable_rle();
            }
            encoder
                .write_image(&bytes8(8), width, height, colour_type(false))
                .map_err(failed)?;
        }
        FileFormat::Bmp => {
            use image::codecs::bmp::BmpEncoder;
            BmpEncoder::new(&mut encoded)
                .write_image(&bytes8(8), width, height, colour_type(false))
                .map_err(failed)?;
        }
        FileFormat::Jpeg => {
            use image::codecs::jpeg::JpegEncoder;
            let three = OutputOptions {
                alpha: false,
                ..*options
            };
            let data: Vec<u8> = image
                .samples(3, 8, &three)
                .into_iter()
                .map(|v| v as u8)
                .collect();
            JpegEncoder::new_with_quality(&mut encoded, options.jpeg_quality.clamp(1, 100))
                .write_image(&data, width, height, ExtendedColorType::Rgb8)
                .map_err(failed)?;
        }
        FileFormat::Exr => {
            use image::codecs::openexr::OpenExrEncoder;
            let mut data = Vec::with_capacity(image.pixels.len() * channels * 4);
            for pixel in &image.pixels {
                let linear = image.linear(*pixel);
                let coverage = if alpha {
                    pixel[3].clamp(0.0, 1.0) as f32
                } else {
                    1.0
                };
                for value in linear {
                    let value = if value.is_finite() { value } else { 0.0 };
                    data.extend_from_slice(&(value * coverage).to_ne_bytes());
                }
                if alpha {
                    data.extend_from_slice(&coverage.to_ne_bytes());
                }
            }
            let kind = if alpha {
                ExtendedColorType::Rgba32F
            } else {
                ExtendedColorType::Rgb32F
            };
            OpenExrEncoder::new(io::Cursor::new(&mut encoded))
                .write_image(&data, width, height, kind)
                .map_err(failed)?;
        }
        FileFormat::Hdr => {
            use image::codecs::hdr::HdrEncoder;
            let data: Vec<image::Rgb<f32>> = image
                .pixels
                .iter()
                .map(|p| {
                    let coverage = if options.alpha {
                        p[3].clamp(0.0, 1.0) as f32
                    } else {
                        1.0
                    };
                    image::Rgb(image.linear(*p).map(|v| {
                        if v.is_finite() {
                            (v * coverage).max(0.0)
                        } else {
                            0.0
                        }
                    }))
                })
                .collect();
            HdrEncoder::new(&mut encoded)
                .encode(&data, width as usize, height as usize)
                .map_err(failed)?;
        }
    }
    Ok(encoded)
}

/// Writes `bytes` to `path` via a temporary file in the same folder and a rename. A path
/// that is a symbolic link is written through (the file it names is replaced, the link
/// stays); one that is not a regular file (a device such as `/dev/null`, a FIFO) is opened
/// and written, never replaced by a file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> io::Result<()> {
    if let Ok(metadata) = fs::symlink_metadata(path) {
        if metadata.file_type().is_symlink() {
            let target = fs::canonicalize(path)?;
            return write_atomic(&target, bytes);
        }
        if !metadata.file_type().is_file() && !metadata.is_dir() {
            let mut file = File::options().write(true).open(path)?;
            file.write_all(bytes)?;
            return file.flush();
        }
    }
    let file_name = path.file_name().ok_or_else(|| {
        io::Error::new(io::ErrorKind::InvalidInput, "the output path names no file")
    })?;
    let folder = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let serial = TEMPORARY_COUNTER.fetch_add(1, Ordering::Relaxed);
    let mut temporary_name = std::ffi::OsString::from(".");
    temporary_name.push(file_name);
    temporary_name.push(format!(".{}-{serial}.tmp", std::process::id()));
    let temporary = folder.join(temporary_name);
    let result = write_then_rename(&temporary, path, bytes);
    if result.is_err() {
        // Best effort: the temporary may not even exist.
        let _ = fs::remove_file(&temporary);
    }
    result
}

/// Writes `bytes` to `temporary`, flushes them to disk and renames the file to `target`.
fn write_then_rename(temporary: &Path, target: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut file = File::options()
        .write(true)
        .create_new(true)
        .open(temporary)?;
    file.write_all(bytes)?;
    file.sync_all()?;
    drop(file);
    fs::rename(temporary, target)
}

/// Inserts `gAMA` and `sRGB` chunks after the `IHDR` chunk of an encoded PNG.
fn with_colour_space_chunks(png: Vec<u8>) -> Vec<u8> {
    // Signature (8 bytes), then IHDR: length (4), type (4), 13 data bytes, CRC (4).
    const IHDR_END: usize = 8 + 4 + 4 + 13 + 4;
    if png.len() < IHDR_END || &png[12..16] != b"IHDR" {
        return png;
    }
    let mut out = Vec::with_capacity(png.len() + 32);
    out.extend_from_slice(&png[..IHDR_END]);
    // gAMA holds 100000 / 2.2 = 45455; sRGB rendering intent 0 (perceptual), as POV-Ray.
    push_chunk(&mut out, b"gAMA", &45455u32.to_be_bytes());
    push_chunk(&mut out, b"sRGB", &[0]);
    out.extend_from_slice(&png[IHDR_END..]);
    out
}

/// Appends one PNG chunk (length, type, data, CRC) to `out`.
fn push_chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    let crc = crc32(kind.iter().chain(data));
    out.extend_from_slice(&crc.to_be_bytes());
}

/// The CRC-32 (ISO 3309, as PNG uses) of a byte sequence.
fn crc32<'a>(bytes: impl Iterator<Item = &'a u8>) -> u32 {
    let mut crc = 0xFFFF_FFFFu32;
    for &byte in bytes {
        crc ^= u32::from(byte);
        for _ in 0..8 {
            let mask = (crc & 1).wrapping_neg();
            crc = (crc >> 1) ^ (0xEDB8_8320 & mask);
        }
    }
    !crc
}

#[cfg(test)]
mod tests {
    use super::*;

    fn test_folder(name: &str) -> PathBuf {
        let folder =
            std::env::temp_dir().join(format!("durer-output-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&folder);
        fs::create_dir_all(&folder).unwrap();
        folder
    }

    /// Two pixels written as [255, 0, 0] and [0, 128, 255].
    fn small_image() -> RenderedImage {
        RenderedImage {
            width: 2,
            height: 1,
            pixels: vec![[1.0, 0.0, 0.0, 1.0], [0.0, 128.0 / 255.0, 1.0, 1.0]],
            encoding: OutputEncoding::Unchanged,
        }
    }

    /// `image` as an 8-bit PNG at `path`, written atomically.
    fn write_png_atomic(path: &Path, image: &RenderedImage) -> io::Result<()> {
        write_atomic(path, &encode(image, &OutputOptions::png())?)
    }

    #[test]
    #[cfg(unix)]
    fn devices_and_links_are_written_through() {
        let folder = test_folder("through");
        // A device stays a device.
        write_atomic(Path::new("/dev/null"), b"image").unwrap();
        assert!(!fs::metadata("/dev/null").unwrap().is_file());
        // /dev/full refuses the bytes: an error, not a regular file in its place.
        if Path::new("/dev/full").exists() {
            assert!(write_atomic(Path::new("/dev/full"), b"image").is_err());
            assert!(!fs::metadata("/dev/full").unwrap().is_file());
        }
        // A link keeps pointing at its file, which gets the bytes.
        let target = folder.join("target.png");
        fs::write(&target, b"old").unwrap();
        let link = folder.join("link.png");
        std::os::unix::fs::symlink(&target, &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read(&target).unwrap(), b"new");
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn crc_of_known_chunk() {
        // The CRC of the IEND chunk type is fixed in every PNG file.
        assert_eq!(crc32(b"IEND".iter()), 0xAE42_6082);
    }

    #[test]
    fn round_trip_keeps_pixels_and_adds_srgb() {
        let folder = test_folder("round-trip");
        let path = folder.join("out.png");
        write_png_atomic(&path, &small_image()).unwrap();
        let bytes = fs::read(&path).unwrap();
        assert!(bytes.windows(4).any(|w| w == b"sRGB"));
        assert!(bytes.windows(4).any(|w| w == b"gAMA"));
        let decoded = image::load_from_memory(&bytes).unwrap().to_rgb8();
        assert_eq!(decoded.get_pixel(1, 0).0, [0, 128, 255]);
        let leftovers = fs::read_dir(&folder).unwrap().count();
        assert_eq!(leftovers, 1, "the temporary file must be gone");
        fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn failed_write_leaves_old_file_intact() {
        let folder = test_folder("failure");
        // The target is a directory holding an old image: the rename must fail.
        let target = folder.join("out.png");
        fs::create_dir(&target).unwrap();
        fs::write(target.join("old.png"), b"old").unwrap();
        assert!(write_png_atomic(&target, &small_image()).is_err());
        assert_eq!(fs::read(target.join("old.png")).unwrap(), b"old");
        assert_eq!(
            fs::read_dir(&folder).unwrap().count(),
            1,
            "no temporary left behind"
        );

        // An invalid image is refused before the old file is touched.
        let old = folder.join("old.png");
        fs::write(&old, b"old image").unwrap();
        let broken = RenderedImage {
            width: 3,
            height: 3,
            pixels: vec![[0.0; 4]; 2],
            encoding: OutputEncoding::Unchanged,
        };
        assert!(write_png_atomic(&old, &broken).is_err());
        assert_eq!(fs::read(&old).unwrap(), b"old image");

        // A folder that does not exist fails without creating anything.
        let missing = folder.join("missing").join("out.png");
        assert!(write_png_atomic(&missing, &small_image()).is_err());
        fs::remove_dir_all(&folder).unwrap();
    }
}
