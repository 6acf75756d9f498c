//! Image files read as rasters: the pixels behind `image_map`, `bump_map`, `image_pattern`
//! and `height_field`.
//!
//! In: a file path and POV-Ray's format keyword (`png`, `jpeg`, `tga`, `ppm`, `pgm`, `hdr`,
//! `gif`, `pot`, `bmp`, `sys`). Out: a [`Raster`] of raw channel values in [0, 1] (HDR values may be
//! larger), rows from the top of the image. Holds: no gamma is applied here; what a value means
//! (colour to linearise, height to use as is) is for the caller to decide, helped by
//! [`StoredEncoding`]. Palette files (PNG, GIF, colour-mapped TGA) also give each pixel's
//! palette index (for `material_map`, `use_index`, `filter`/`transmit` entries, height fields).
//! TGA ([`tga`]), Radiance HDR ([`hdr`]) and GIF ([`gif_file`]) have readers of their own
//! (palette indices, POV-Ray's RGBE rounding, interlaced rows); the others use `image`.
//!
//! `pot` (Fractint continuous potential) is a GIF twice as wide as the picture: the palette
//! indices of the left half are the high bytes of 16-bit levels, those of the right half the
//! low bytes. It is read as a 16-bit grey raster of the left half's size, its rows in the
//! order the file stores them (an interlaced file is not put back in order, as in POV-Ray).

mod gif_file;
mod hdr;
mod tga;

use std::path::Path;

/// A decoded image.
#[derive(Clone, Debug)]
pub struct Raster {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Red, green, blue, alpha per pixel, row by row from the top; alpha is 1 when the file
    /// has none.
    pub pixels: Vec<[f32; 4]>,
    /// The file stores grey levels only.
    pub grey: bool,
    /// The file stores 16 bits per channel (height fields then use the full precision).
    pub sixteen_bit: bool,
    /// The file is high dynamic range (values are linear light, not encoded).
    pub high_dynamic_range: bool,
    /// The file stores transparency (an alpha channel or a transparent palette entry).
    pub alpha: bool,
    /// Each pixel's palette index, row by row from the top, for palette files.
    pub palette_indices: Option<Vec<u8>>,
    /// How the stored values encode light.
    pub encoding: StoredEncoding,
}

impl Raster {
    /// Whether POV-Ray's `use_alpha` reads this file's red channel instead of its
    /// transparency (measured on colour and grey files without alpha: PNG, PPM, PGM, TGA,
    /// JPEG; not on palette files or HDR files, which give 1 − alpha, so 0).
    pub fn use_alpha_reads_red(&self) -> bool {
        !self.alpha && !self.high_dynamic_range && self.palette_indices.is_none()
    }
}

/// How a file's stored values encode light, as POV-Ray 3.7 reads them when the image block
/// gives no `gamma` (measured with pigment functions of each format).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StoredEncoding {
    /// sRGB (JPEG, TGA, GIF, BMP and PNG files that state their gamma).
    Srgb,
    /// A PNG file that states no gamma (no `gAMA`, `sRGB` or `iCCP` chunk): sRGB under
    /// `#version 3.7`, as stored in older scenes.
    UnstatedPng,
    /// PPM and PGM: the stored values are used as they are under any `assumed_gamma`
    /// (measured: a stored 26/255 gives 0.101961 at `assumed_gamma` 1 and 2.2 alike).
    AsStored,
    /// Radiance HDR: linear light.
    Linear,
}

impl Raster {
    /// The pixel at `column`, `row` (clamped into the image).
    pub fn pixel(&self, column: i64, row: i64) -> [f32; 4] {
        let column = column.clamp(0, self.width as i64 - 1) as usize;
        let row = row.clamp(0, self.height as i64 - 1) as usize;
        self.pixels[row * self.width as usize + column]
    }
}

/// The image formats POV-Ray names, by keyword.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RasterFormat {
    Png,
    Jpeg,
    Tga,
    Ppm,
    Pgm,
    Hdr,
    Gif,
    /// Fractint continuous potential: a double-width GIF of 16-bit levels.
    Pot,
    Bmp,
    /// `sys`: the platform's default format (PNG here... detected from the contents).
    System,
}

impl RasterFormat {
    /// The format for a POV-Ray keyword such as `png` or `jpeg`.
    pub fn from_keyword(keyword: &str) -> Option<RasterFormat> {
        Some(match keyword {
            "png" => RasterFormat::Png,
            "jpeg" => RasterFormat::Jpeg,
            "tga" => RasterFormat::Tga,
            "ppm" => RasterFormat::Ppm,
            "pgm" => RasterFormat::Pgm,
            "hdr" => RasterFormat::Hdr,
            "gif" => RasterFormat::Gif,
            "pot" => RasterFormat::Pot,
            "bmp" => RasterFormat::Bmp,
            "sys" => RasterFormat::System,
            _ => return None,
        })
    }

    /// The format's keyword in SDL.
    pub fn keyword(self) -> &'static str {
        match self {
            RasterFormat::Png => "png",
            RasterFormat::Jpeg => "jpeg",
            RasterFormat::Tga => "tga",
            RasterFormat::Ppm => "ppm",
            RasterFormat::Pgm => "pgm",
            RasterFormat::Hdr => "hdr",
            RasterFormat::Gif => "gif",
            RasterFormat::Pot => "pot",
            RasterFormat::Bmp => "bmp",
            RasterFormat::System => "sys",
        }
    }

    /// The file extensions tried, in order, for a file name written without one (POV-Ray
    /// adds the type's extension: `png "wood"` reads `wood.png`).
    pub fn extensions(self) -> &'static [&'static str] {
        match self {
            RasterFormat::Png | RasterFormat::System => &["png"],
            RasterFormat::Jpeg => &["jpg", "jpeg"],
            RasterFormat::Tga => &["tga"],
            RasterFormat::Ppm => &["ppm"],
            RasterFormat::Pgm => &["pgm"],
            RasterFormat::Hdr => &["hdr"],
            RasterFormat::Gif => &["gif"],
            RasterFormat::Pot => &["pot"],
            RasterFormat::Bmp => &["bmp"],
        }
    }

    fn image_format(self) -> Option<image::ImageFormat> {
        Some(match self {
            RasterFormat::Png => image::ImageFormat::Png,
            RasterFormat::Jpeg => image::ImageFormat::Jpeg,
            RasterFormat::Tga => image::ImageFormat::Tga,
            RasterFormat::Ppm | RasterFormat::Pgm => image::ImageFormat::Pnm,
            RasterFormat::Hdr => image::ImageFormat::Hdr,
            RasterFormat::Gif | RasterFormat::Pot => image::ImageFormat::Gif,
            RasterFormat::Bmp => image::ImageFormat::Bmp,
            RasterFormat::System => return None,
        })
    }
}

/// Largest image accepted, in pixels (a guard against hostile headers).
const MAX_PIXELS: u64 = 1 << 26;

/// Widest or tallest image accepted, in pixels.
const MAX_SIDE: u32 = 1 << 16;

/// Reads and decodes `path` as `format` (`System` guesses from the contents).
pub fn load(path: &Path, format: RasterFormat) -> Result<Raster, String> {
    let bytes =
        std::fs::read(path).map_err(|error| format!("cannot read {}: {error}", path.display()))?;
    decode(&bytes, format).map_err(|message| format!("cannot decode {}: {message}", path.display()))
}

/// Decodes a file's `bytes` as `format` (`System` guesses from the contents).
fn decode(bytes: &[u8], format: RasterFormat) -> Result<Raster, String> {
    if let Some(decode) = own_decoder(format, bytes) {
        return decode(bytes);
    }
    let guessed = image::guess_format(bytes).ok();
    let chosen = format
        .image_format()
        .or(guessed)
        .ok_or("cannot tell the image format")?;
    // TGA has no signature; trust the keyword. Others: prefer what the contents say.
    let chosen = match (chosen, guessed) {
        (image::ImageFormat::Tga, _) => image::ImageFormat::Tga,
        (_, Some(actual)) => actual,
        (keyword, None) => keyword,
    };
    let mut reader = image::ImageReader::with_format(std::io::Cursor::new(bytes), chosen);
    // Refuse oversized images from their header, before any pixel memory is allocated.
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_SIDE);
    limits.max_image_height = Some(MAX_SIDE);
    limits.max_alloc = Some(MAX_PIXELS * 16);
    reader.limits(limits);
    let decoded = reader.decode().map_err(|error| error.to_string())?;
    let (width, height) = (decoded.width(), decoded.height());
    if width == 0 || height == 0 || width as u64 * height as u64 > MAX_PIXELS {
        return Err(format!("unsupported image size {width}x{height}"));
    }
    use image::ColorType as C;
    let colour_type = decoded.color();
    let grey = matches!(colour_type, C::L8 | C::La8 | C::L16 | C::La16);
    let sixteen_bit = matches!(colour_type, C::L16 | C::La16 | C::Rgb16 | C::Rgba16);
    let high_dynamic_range = matches!(colour_type, C::Rgb32F | C::Rgba32F);
    let pixels = decoded.to_rgba32f().pixels().map(|p| p.0).collect();
    let palette_indices = match chosen {
        image::ImageFormat::Png => png_palette_indices(bytes, width, height),
        _ => None,
    };
    let encoding = match chosen {
        image::ImageFormat::Png if !png_states_gamma(bytes) => StoredEncoding::UnstatedPng,
        image::ImageFormat::Pnm => StoredEncoding::AsStored,
        _ if high_dynamic_range => StoredEncoding::Linear,
        _ => StoredEncoding::Srgb,
    };
    Ok(Raster {
        width,
        height,
        pixels,
        grey,
        sixteen_bit,
        high_dynamic_range,
        alpha: colour_type.has_alpha(),
        palette_indices,
        encoding,
    })
}

/// A decoder of a whole file's bytes.
type Decoder = fn(&[u8]) -> Result<Raster, String>;

/// durer's own decoder for a file, if it has one: chosen by the contents' signature (HDR
/// `#?`, GIF `GIF8`), else by the keyword (TGA has no signature; an `hdr` file without one
/// gets the HDR reader's message).
fn own_decoder(format: RasterFormat, bytes: &[u8]) -> Option<Decoder> {
    Some(match format {
        RasterFormat::Pot => potential_levels,
        _ if bytes.starts_with(b"#?") => hdr::decode,
        _ if bytes.starts_with(b"GIF8") => gif_file::decode,
        RasterFormat::Tga => tga::decode,
        RasterFormat::Hdr if image::guess_format(bytes).is_err() => hdr::decode,
        _ => return None,
    })
}

/// Whether a PNG file states how its values are encoded (a `gAMA`, `sRGB` or `iCCP` chunk).
fn png_states_gamma(bytes: &[u8]) -> bool {
    let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.read_info().is_ok_and(|reader| {
        let info = reader.info();
        info.gama_chunk.is_some() || info.srgb.is_some() || info.icc_profile.is_some()
    })
}

/// A Fractint continuous potential file as a 16-bit grey raster: each level is the palette
/// index in the left half of the GIF times 256 plus the one in the right half.
fn potential_levels(bytes: &[u8]) -> Result<Raster, String> {
    // Two stored pixels make one height, so twice the usual limit.
    let image = gif_file::stored_indices(bytes, 2 * MAX_PIXELS)?;
    if !image.covers_screen {
        return Err("the image does not cover the whole screen".to_string());
    }
    let (frame_width, frame_height) = (image.width, image.height);
    let width = frame_width / 2;
    if width == 0 {
        return Err(format!(
            "a {frame_width}x{frame_height} image is too small for a potential file"
        ));
    }
    let mut pixels = Vec::with_capacity(width as usize * frame_height as usize);
    for row in image.indices.chunks(frame_width as usize) {
        for column in 0..width as usize {
            let level = u16::from(row[column]) << 8 | u16::from(row[column + width as usize]);
            let value = f32::from(level) / f32::from(u16::MAX);
            pixels.push([value, value, value, 1.0]);
        }
    }
    Ok(Raster {
        width,
        height: frame_height,
        pixels,
        grey: true,
        sixteen_bit: true,
        high_dynamic_range: false,
        alpha: false,
        palette_indices: None,
        encoding: StoredEncoding::AsStored,
    })
}

/// The picture row that an interlaced GIF stores in place `stored` (passes: every 8th row
/// from 0, every 8th from 4, every 4th from 2, every 2nd from 1). POV-Ray reads a `pot`
/// file's rows in stored order (measured: an interlaced file's rows come out permuted).
fn interlaced_row(stored: usize, height: usize) -> usize {
    let mut remaining = stored;
    for (start, step) in [(0, 8), (4, 8), (2, 4), (1, 2)] {
        let in_pass = height.saturating_sub(start).div_ceil(step);
        if remaining < in_pass {
            return start + remaining * step;
        }
        remaining -= in_pass;
    }
    stored
}

/// The palette index of every pixel of a palette PNG (`None` for other PNGs or when the
/// file does not decode to `width` × `height` pixels).
fn png_palette_indices(bytes: &[u8], width: u32, height: u32) -> Option<Vec<u8>> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().ok()?;
    if reader.info().color_type != png::ColorType::Indexed {
        return None;
    }
    let mut buffer = vec![0; reader.output_buffer_size()?];
    let frame = reader.next_frame(&mut buffer).ok()?;
    if frame.color_type != png::ColorType::Indexed || (frame.width, frame.height) != (width, height)
    {
        return None;
    }
    let bits = frame.bit_depth as usize;
    if !matches!(bits, 1 | 2 | 4 | 8) {
        return None;
    }
    let per_byte = 8 / bits;
    let mask = (1u16 << bits) - 1;
    let mut indices = Vec::with_capacity(width as usize * height as usize);
    for row in buffer.chunks(frame.line_size).take(height as usize) {
        for column in 0..width as usize {
            let byte = *row.get(column / per_byte)?;
            let shift = 8 - bits * (column % per_byte + 1);
            indices.push(((u16::from(byte) >> shift) & mask) as u8);
        }
    }
    Some(indices)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_oversized_potential_file_is_refused_before_decoding() {
        // A GIF header for a 65535x65535 image (2-colour palette) and its image descriptor,
        // with no pixel data: refused from the sizes alone.
        let mut bytes = b"GIF89a".to_vec();
        bytes.extend_from_slice(&[0xff, 0xff, 0xff, 0xff, 0x80, 0, 0]);
        bytes.extend_from_slice(&[0, 0, 0, 255, 255, 255]);
        bytes.extend_from_slice(&[0x2c, 0, 0, 0, 0, 0xff, 0xff, 0xff, 0xff, 0]);
        bytes.extend_from_slice(&[2, 0, 0x3b]);
        let error = potential_levels(&bytes).err().unwrap();
        assert!(error.contains("larger than durer reads"), "{error}");
    }

    #[test]
    fn reads_a_png_and_reports_missing_files() {
        let folder = std::env::temp_dir().join(format!("durer-raster-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let path = folder.join("two.png");
        let image = image::RgbImage::from_fn(2, 1, |x, _| image::Rgb([255 * x as u8, 0, 51]));
        image.save(&path).unwrap();
        let raster = load(&path, RasterFormat::Png).unwrap();
        assert_eq!((raster.width, raster.height), (2, 1));
        assert_eq!(raster.pixel(1, 0), [1.0, 0.0, 0.2, 1.0]);
        assert_eq!(raster.pixel(-5, 9), [0.0, 0.0, 0.2, 1.0]);
        assert!(!raster.grey && !raster.sixteen_bit);
        assert!(load(&folder.join("none.png"), RasterFormat::Png).is_err());
        assert!(raster.palette_indices.is_none());
        std::fs::remove_dir_all(&folder).unwrap();
    }

    #[test]
    fn every_test_image_decodes_and_its_truncations_never_panic() {
        let folder = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference/images");
        let formats = [
            ("tga", RasterFormat::Tga),
            ("ppm", RasterFormat::Ppm),
            ("pgm", RasterFormat::Pgm),
            ("hdr", RasterFormat::Hdr),
            ("gif", RasterFormat::Gif),
            ("jpg", RasterFormat::Jpeg),
            ("png", RasterFormat::Png),
        ];
        let mut decoded = 0;
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            let extension = path.extension().and_then(|e| e.to_str()).unwrap_or("");
            let Some(&(_, format)) = formats.iter().find(|(name, _)| *name == extension) else {
                continue;
            };
            let bytes = std::fs::read(&path).unwrap();
            let raster = decode(&bytes, format).unwrap();
            let pixels = raster.width as usize * raster.height as usize;
            assert_eq!(raster.pixels.len(), pixels, "{}", path.display());
            decoded += 1;
            for length in (0..bytes.len()).step_by(5) {
                let _ = decode(&bytes[..length], format);
                let mut damaged = bytes.clone();
                damaged[length] ^= 0xa5;
                let _ = decode(&damaged, format);
            }
        }
        assert!(decoded >= 25, "only {decoded} test images found");
    }

    #[test]
    fn interlaced_gif_rows_are_listed_pass_by_pass() {
        let order: Vec<usize> = (0..16).map(|stored| interlaced_row(stored, 16)).collect();
        assert_eq!(
            order,
            [0, 8, 4, 12, 2, 6, 10, 14, 1, 3, 5, 7, 9, 11, 13, 15]
        );
        let order: Vec<usize> = (0..3).map(|stored| interlaced_row(stored, 3)).collect();
        assert_eq!(order, [0, 2, 1]);
    }

    #[test]
    fn keeps_palette_indices_of_packed_palette_pngs() {
        let folder = std::env::temp_dir().join(format!("durer-palette-{}", std::process::id()));
        std::fs::create_dir_all(&folder).unwrap();
        let path = folder.join("palette.png");
        let mut encoder = png::Encoder::new(std::fs::File::create(&path).unwrap(), 3, 2);
        encoder.set_color(png::ColorType::Indexed);
        encoder.set_depth(png::BitDepth::Four);
        encoder.set_palette((0..16u8).flat_map(|i| [i * 16, 0, 0]).collect::<Vec<u8>>());
        let mut writer = encoder.write_header().unwrap();
        // Rows of three 4-bit indices: 1 2 3 and 15 0 7 (the last nibble is padding).
        writer.write_image_data(&[0x12, 0x30, 0xF0, 0x70]).unwrap();
        writer.finish().unwrap();
        let raster = load(&path, RasterFormat::Png).unwrap();
        assert_eq!(raster.palette_indices, Some(vec![1, 2, 3, 15, 0, 7]));
        assert_eq!(raster.pixel(0, 1)[0], 240.0 / 255.0);
        std::fs::remove_dir_all(&folder).unwrap();
    }
}
