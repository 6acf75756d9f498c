//! GIF files: the first image, its palette and transparent entry.
//!
//! In: the file's bytes. Out: a [`Raster`] with each pixel's palette index. Holds: rows come
//! in the order the file stores them, so an interlaced file's rows stay permuted (measured:
//! POV-Ray shows stored row 1 of a 16-row interlaced GIF as picture row 1, where it belongs
//! to row 8); the transparent entry has alpha 0 (measured: transmit 1).

use super::{interlaced_row, Raster, StoredEncoding, MAX_PIXELS};

/// Decodes a GIF file's first image.
pub(super) fn decode(bytes: &[u8]) -> Result<Raster, String> {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::Indexed);
    let mut decoder = options
        .read_info(std::io::Cursor::new(bytes))
        .map_err(|error| error.to_string())?;
    let frame = decoder
        .next_frame_info()
        .map_err(|error| error.to_string())?
        .ok_or("the file holds no image")?;
    let (width, height) = (u32::from(frame.width), u32::from(frame.height));
    let interlaced = frame.interlaced;
    let transparent = frame.transparent;
    if width == 0 || height == 0 || u64::from(width) * u64::from(height) > MAX_PIXELS {
        return Err(format!("unsupported image size {width}x{height}"));
    }
    let mut buffer = vec![0; decoder.buffer_size()];
    if buffer.len() != width as usize * height as usize {
        return Err("the image is not one palette index per pixel".to_string());
    }
    decoder
        .read_into_buffer(&mut buffer)
        .map_err(|error| error.to_string())?;
    let palette: Vec<[f32; 4]> = decoder
        .palette()
        .map_err(|error| error.to_string())?
        .chunks_exact(3)
        .map(|entry| {
            let level = |value: u8| f32::from(value) / 255.0;
            [level(entry[0]), level(entry[1]), level(entry[2]), 1.0]
        })
        .collect();
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
