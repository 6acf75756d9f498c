//! GIF files: the first image, its palette and transparent entry.
//!
//! In: the file's bytes. Out: a [`Raster`] with each pixel's palette index. Holds: rows come
//! in the order the file stores them, so an interlaced file's rows stay permuted (measured:
//! POV-Ray shows stored row 1 of a 16-row interlaced GIF as picture row 1, where it belongs
//! to row 8); the transparent entry has alpha 0 (measured: transmit 1).

use super::{interlaced_row, Raster, StoredEncoding, MAX_PIXELS};

/// A GIF file's first image as palette indices, its rows in the order the file stores them.
pub(super) struct StoredIndices {
    pub width: u32,
    pub height: u32,
    /// One palette index per pixel, row by row as stored (an interlaced file's rows permuted).
    pub indices: Vec<u8>,
    /// Red, green, blue bytes per palette entry.
    pub palette: Vec<u8>,
    /// The transparent palette entry, if any.
    pub transparent: Option<u8>,
    /// Whether the image fills the file's whole logical screen.
    pub covers_screen: bool,
}

/// Reads a GIF file's first image as palette indices; an image of no pixels or more than
/// `max_pixels` is an error.
pub(super) fn stored_indices(bytes: &[u8], max_pixels: u64) -> Result<StoredIndices, String> {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options
        .read_info(std::io::Cursor::new(bytes))
        .map_err(|error| error.to_string())?;
    let screen = (u32::from(decoder.width()), u32::from(decoder.height()));
    let frame = decoder
        .next_frame_info()
        .map_err(|error| error.to_string())?
        .ok_or("the file holds no image")?;
    let (width, height) = (u32::from(frame.width), u32::from(frame.height));
    // The decoder puts an interlaced file's rows back in order; POV-Ray does not.
    let interlaced = frame.interlaced;
    let transparent = frame.transparent;
    if width == 0 || height == 0 {
        return Err(format!("unsupported image size {width}x{height}"));
    }
    if u64::from(width) * u64::from(height) > max_pixels {
        return Err(format!(
            "a {width}x{height} image is larger than durer reads"
        ));
    }
    let mut buffer = vec![0; decoder.buffer_size()];
    if buffer.len() != width as usize * height as usize {
        return Err("the image is not one palette index per pixel".to_string());
    }
    decoder
        .read_into_buffer(&mut buffer)
        .map_err(|error| error.to_string())?;
    let palette = decoder
        .palette()
        .map_err(|error| error.to_string())?
        .to_vec();
    let rows: Vec<&[u8]> = buffer.chunks(width as usize).collect();
    let mut indices = Vec::with_capacity(buffer.len());
    for stored in 0..rows.len() {
        let row = if interlaced {
            rows[interlaced_row(stored, rows.len())]
        } else {
            rows[stored]
        };
        indices.extend_from_slice(row);
    }
    Ok(StoredIndices {
        width,
        height,
        indices,
        palette,
        transparent,
        covers_screen: (width, height) == screen,
    })
}

/// Decodes a GIF file's first image.
pub(super) fn decode(bytes: &[u8]) -> Result<Raster, String> {
    let StoredIndices {
        width,
        height,
        indices,
        palette,
        transparent,
        ..
    } = stored_indices(bytes, MAX_PIXELS)?;
    let palette: Vec<[f32; 4]> = palette
        .chunks_exact(3)
        .map(|entry| {
            let level = |value: u8| f32::from(value) / 255.0;
            [level(entry[0]), level(entry[1]), level(entry[2]), 1.0]
        })
        .collect();
    let pixels = indices
        .iter()
        .map(|&index| {
            let mut colour = palette
                .get(usize::from(index))
                .copied()
                .unwrap_or([0.0, 0.0, 0.0, 1.0]);
            if Some(index) == transparent {
                colour[3] = 0.0;
            }
            colour
        })
        .collect();
    Ok(Raster {
        width,
        height,
        pixels,
        grey: false,
        sixteen_bit: false,
        high_dynamic_range: false,
        alpha: transparent.is_some(),
        palette_indices: Some(indices),
        encoding: StoredEncoding::Srgb,
    })
}
