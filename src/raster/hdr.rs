//! Radiance HDR (RGBE) files: flat, old-style and new-style run-length encoded scanlines.
//!
//! In: the file's bytes. Out: a [`Raster`] of linear values (rows from the top). Holds: a
//! stored mantissa m with exponent e means (m + ½)·2^(e − 136), measured: POV-Ray gives a
//! stored 192 with exponent 125 as 0.093994, not 0.09375; exponent 0 is black. A bad header
//! or truncated file is an error message, never a panic.

use super::{Raster, StoredEncoding, MAX_PIXELS};

/// Decodes a Radiance HDR file.
pub(super) fn decode(bytes: &[u8]) -> Result<Raster, String> {
    let (width, height, top_first, mut position) = header(bytes)?;
    // Grown row by row as scanlines decode, so a header claiming a huge image costs
    // nothing up front.
    let mut pixels: Vec<[f32; 4]> = Vec::new();
    // A run-length scanline needs at least 8 bytes per 127 pixels: refuse a width the
    // rest of the file cannot hold before allocating a scanline for it.
    if width as usize / 16 > bytes.len() - position {
        return Err(TRUNCATED.to_string());
    }
    let mut scanline = vec![[0u8; 4]; width as usize];
    for _ in 0..height {
        position = read_scanline(bytes, position, &mut scanline)?;
        pixels.extend(scanline.iter().map(|&rgbe| linear(rgbe)));
    }
    if !top_first {
        // Rows were stored from the bottom: swap them end for end in place.
        let row = width as usize;
        let rows = height as usize;
        for low in 0..rows / 2 {
            let high = rows - 1 - low;
            let (front, back) = pixels.split_at_mut(high * row);
            front[low * row..(low + 1) * row].swap_with_slice(&mut back[..row]);
        }
    }
    Ok(Raster {
        width,
        height,
        pixels,
        grey: false,
        sixteen_bit: false,
        high_dynamic_range: true,
        alpha: false,
        palette_indices: None,
        encoding: StoredEncoding::Linear,
    })
}

/// The header: width, height, whether rows are stored from the top, and where the pixels
/// start.
fn header(bytes: &[u8]) -> Result<(u32, u32, bool, usize), String> {
    if !bytes.starts_with(b"#?") {
        return Err("the file does not start with a Radiance `#?` signature".to_string());
    }
    let mut position = 0;
    let mut next_line = || -> Result<&[u8], String> {
        let rest = &bytes[position..];
        let length = rest
            .iter()
            .position(|&byte| byte == b'\n')
            .ok_or("the file ends inside its header")?;
        position += length + 1;
        Ok(&rest[..length])
    };
    loop {
        let line = next_line()?;
        if line.is_empty() {
            break;
        }
        if let Some(format) = line.strip_prefix(b"FORMAT=") {
            if format.trim_ascii() != b"32-bit_rle_rgbe" {
                return Err(format!(
                    "pixel format `{}` is not RGBE",
                    String::from_utf8_lossy(format.trim_ascii())
                ));
            }
        }
    }
    let resolution = String::from_utf8_lossy(next_line()?).into_owned();
    let words: Vec<&str> = resolution.split_whitespace().collect();
    let parse = |word: &str| word.parse::<u32>().ok().filter(|&size| size > 0);
    let (top_first, height, width) = match words.as_slice() {
        ["-Y", height, "+X", width] => (true, parse(height), parse(width)),
        ["+Y", height, "+X", width] => (false, parse(height), parse(width)),
        _ => (true, None, None),
    };
    let (Some(height), Some(width)) = (height, width) else {
        return Err(format!(
            "the resolution line `{resolution}` is not `-Y height +X width`"
        ));
    };
    if u64::from(width) * u64::from(height) > MAX_PIXELS {
        return Err(format!("unsupported image size {width}x{height}"));
    }
    Ok((width, height, top_first, position))
}

const TRUNCATED: &str = "the file ends before its last pixel";

/// Reads one scanline starting at `position` into `scanline`; the position after it.
fn read_scanline(bytes: &[u8], position: usize, scanline: &mut [[u8; 4]]) -> Result<usize, String> {
    let width = scanline.len();
    let start = bytes.get(position..position + 4).ok_or(TRUNCATED)?;
    let new_style =
        (8..0x8000).contains(&width) && start[0] == 2 && start[1] == 2 && start[2] & 0x80 == 0;
    if new_style {
        if usize::from(start[2]) << 8 | usize::from(start[3]) != width {
            return Err("a scanline's length does not match the image width".to_string());
        }
        return read_planes(bytes, position + 4, scanline);
    }
    // Flat pixels, where a pixel 1, 1, 1, n repeats the previous one (n shifted left by 8
    // for every such pixel in a row).
    let mut position = position;
    let mut filled = 0;
    let mut shift = 0;
    while filled < width {
        let pixel = bytes.get(position..position + 4).ok_or(TRUNCATED)?;
        position += 4;
        if pixel[..3] == [1, 1, 1] && filled > 0 {
            let repeat = (usize::from(pixel[3]) << shift).min(width - filled);
            let previous = scanline[filled - 1];
            scanline[filled..filled + repeat].fill(previous);
            filled += repeat;
            shift = (shift + 8).min(24);
        } else {
            scanline[filled] = [pixel[0], pixel[1], pixel[2], pixel[3]];
            filled += 1;
            shift = 0;
        }
    }
    Ok(position)
}

/// A new-style scanline: each of the four byte planes as runs (a count above 128 repeats
/// the next byte count − 128 times) and literals (a count up to 128 copies that many bytes).
fn read_planes(
    bytes: &[u8],
    mut position: usize,
    scanline: &mut [[u8; 4]],
) -> Result<usize, String> {
    for plane in 0..4 {
        let mut filled = 0;
        while filled < scanline.len() {
            let count = usize::from(*bytes.get(position).ok_or(TRUNCATED)?);
            position += 1;
            if count > 128 {
                let value = *bytes.get(position).ok_or(TRUNCATED)?;
                position += 1;
                let repeat = count - 128;
                if filled + repeat > scanline.len() {
                    return Err("a run goes past the end of its scanline".to_string());
                }
                for pixel in &mut scanline[filled..filled + repeat] {
                    pixel[plane] = value;
                }
                filled += repeat;
            } else {
                if count == 0 || filled + count > scanline.len() {
                    return Err("a scanline holds a bad run length".to_string());
                }
                let values = bytes.get(position..position + count).ok_or(TRUNCATED)?;
                position += count;
                for (pixel, &value) in scanline[filled..filled + count].iter_mut().zip(values) {
                    pixel[plane] = value;
                }
                filled += count;
            }
        }
    }
    Ok(position)
}

/// A stored RGBE pixel as linear red, green, blue and an opaque alpha.
fn linear([red, green, blue, exponent]: [u8; 4]) -> [f32; 4] {
    if exponent == 0 {
        return [0.0, 0.0, 0.0, 1.0];
    }
    let scale = 2f32.powi(i32::from(exponent) - 136);
    let channel = |mantissa: u8| (f32::from(mantissa) + 0.5) * scale;
    [channel(red), channel(green), channel(blue), 1.0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_flat_and_run_length_scanlines_alike() {
        let mut flat = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n".to_vec();
        let mut packed = flat.clone();
        for column in 0..8u8 {
            flat.extend_from_slice(&[192, column * 10, 0, 125]);
        }
        packed.extend_from_slice(&[2, 2, 0, 8]);
        packed.extend_from_slice(&[136, 192]);
        packed.extend_from_slice(&[8, 0, 10, 20, 30, 40, 50, 60, 70]);
        packed.extend_from_slice(&[136, 0, 136, 125]);
        let flat = decode(&flat).unwrap();
        let packed = decode(&packed).unwrap();
        assert_eq!(flat.pixels, packed.pixels);
        assert_eq!(flat.pixel(0, 0)[0], 192.5 / 2048.0);
        assert_eq!(flat.pixel(3, 0)[1], 30.5 / 2048.0);
    }

    #[test]
    fn rows_stored_from_the_bottom_are_turned_top_first() {
        let mut file = b"#?RADIANCE\n\n+Y 3 +X 2\n".to_vec();
        for row in 0..3u8 {
            for column in 0..2u8 {
                file.extend_from_slice(&[128 + row * 20 + column, 128, 128, 129]);
            }
        }
        let raster = decode(&file).unwrap();
        let reds: Vec<f32> = raster.pixels.iter().map(|pixel| pixel[0]).collect();
        let stored = |row: u8, column: u8| linear([128 + row * 20 + column, 128, 128, 129])[0];
        let expected = [
            stored(2, 0),
            stored(2, 1),
            stored(1, 0),
            stored(1, 1),
            stored(0, 0),
            stored(0, 1),
        ];
        assert_eq!(reds, expected);
    }

    #[test]
    fn bad_headers_and_truncated_files_are_errors() {
        assert!(decode(b"P6\n").is_err());
        assert!(decode(b"#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n").is_err());
        assert!(decode(b"#?RADIANCE\n\n-Y 1 +Z 1\n").is_err());
        let error = decode(b"#?RADIANCE\n\n-Y 2 +X 1\n\x80\x80\x80\x80")
            .err()
            .unwrap();
        assert_eq!(error, TRUNCATED);
        assert!(decode(b"#?RADIANCE\n\n-Y 1 +X 8\n\x02\x02\x00\x08\xff\x01").is_err());
    }
}
