//! Truevision TGA files: colour-mapped (types 1, 9), true colour (2, 10) and grey (3, 11),
//! uncompressed or run-length encoded.
//!
//! In: the file's bytes. Out: a [`Raster`] with rows from the top whatever the file's
//! origin, and the palette index of every pixel of a colour-mapped file. Holds: a truncated
//! or inconsistent file is an error message, never a panic.

use super::{Raster, StoredEncoding, MAX_PIXELS};

/// The fixed header before the image id.
const HEADER_SIZE: usize = 18;

/// Decodes a TGA file.
pub(super) fn decode(bytes: &[u8]) -> Result<Raster, String> {
    let header = bytes
        .get(..HEADER_SIZE)
        .ok_or("the file is shorter than a TGA header")?;
    let word = |at: usize| u16::from_le_bytes([header[at], header[at + 1]]);
    let id_length = usize::from(header[0]);
    let has_colour_map = header[1] == 1;
    let image_type = header[2];
    let (map_first, map_length, map_bits) = (word(3), usize::from(word(5)), header[7]);
    let (width, height) = (u32::from(word(12)), u32::from(word(14)));
    let depth = header[16];
    let descriptor = header[17];
    let run_length = image_type >= 9;
    let kind = match image_type & 7 {
        1 => Kind::Mapped,
        2 => Kind::TrueColour,
        3 => Kind::Grey,
        _ => {
            return Err(format!(
                "TGA image type {image_type} is not one durer reads"
            ))
        }
    };
    if width == 0 || height == 0 || u64::from(width) * u64::from(height) > MAX_PIXELS {
        return Err(format!("unsupported image size {width}x{height}"));
    }
    let pixel_size = match (kind, depth) {
        (Kind::Mapped, 8) | (Kind::Grey, 8) => 1,
        (Kind::TrueColour, 15 | 16) => 2,
        (Kind::TrueColour, 24) => 3,
        (Kind::TrueColour, 32) => 4,
        _ => {
            return Err(format!(
                "a {depth}-bit TGA of type {image_type} is not supported"
            ))
        }
    };
    let mut position = HEADER_SIZE + id_length;
    let mut palette = Vec::new();
    if has_colour_map {
        let entry_size = match map_bits {
            15 | 16 => 2,
            24 => 3,
            32 => 4,
            _ => {
                return Err(format!(
                    "{map_bits}-bit colour map entries are not supported"
                ))
            }
        };
        let end = position + map_length * entry_size;
        let entries = bytes
            .get(position..end)
            .ok_or("the file ends inside its colour map")?;
        palette = entries.chunks(entry_size).map(colour).collect();
        position = end;
    } else if kind == Kind::Mapped {
        return Err("a colour-mapped TGA without a colour map".to_string());
    }
    let count = width as usize * height as usize;
    let stored = pixel_bytes(
        &bytes[position.min(bytes.len())..],
        count,
        pixel_size,
        run_length,
    )?;
    let top_first = descriptor & 0x20 != 0;
    let right_to_left = descriptor & 0x10 != 0;
    let mut pixels = Vec::with_capacity(count);
    let mut palette_indices = (kind == Kind::Mapped).then(|| Vec::with_capacity(count));
    for row in 0..height as usize {
        let stored_row = if top_first {
            row
        } else {
            height as usize - 1 - row
        };
        for column in 0..width as usize {
            let stored_column = if right_to_left {
                width as usize - 1 - column
            } else {
                column
            };
            let at = (stored_row * width as usize + stored_column) * pixel_size;
            let value = &stored[at..at + pixel_size];
            pixels.push(match kind {
                Kind::Grey => {
                    let level = f32::from(value[0]) / 255.0;
                    [level, level, level, 1.0]
                }
                Kind::TrueColour => colour(value),
                Kind::Mapped => {
                    let index = usize::from(value[0]);
                    if let Some(indices) = palette_indices.as_mut() {
                        indices.push(value[0]);
                    }
                    index
                        .checked_sub(usize::from(map_first))
                        .and_then(|entry| palette.get(entry))
                        .copied()
                        .unwrap_or([0.0, 0.0, 0.0, 1.0])
                }
            });
        }
    }
    let alpha = match kind {
        Kind::TrueColour => depth == 32,
        Kind::Mapped => map_bits == 32,
        Kind::Grey => false,
    };
    Ok(Raster {
        width,
        height,
        pixels,
        grey: kind == Kind::Grey,
        sixteen_bit: false,
        high_dynamic_range: false,
        alpha,
        palette_indices,
        encoding: StoredEncoding::Srgb,
    })
}

/// What a TGA's pixel values are.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Mapped,
    TrueColour,
    Grey,
}

/// A stored colour (2 bytes: 5 bits each of blue, green, red; 3: blue, green, red;
/// 4: blue, green, red, alpha) as red, green, blue, alpha in [0, 1].
fn colour(value: &[u8]) -> [f32; 4] {
    let byte = |at: usize| f32::from(value[at]) / 255.0;
    match value.len() {
        2 => {
            let packed = u16::from_le_bytes([value[0], value[1]]);
            let five = |shift: u16| f32::from((packed >> shift) & 31) / 31.0;
            [five(10), five(5), five(0), 1.0]
        }
        3 => [byte(2), byte(1), byte(0), 1.0],
        _ => [byte(2), byte(1), byte(0), byte(3)],
    }
}

/// The `count` stored pixels of `pixel_size` bytes, unpacked from run-length packets when
/// `run_length` (a packet's header: high bit set for a run of one value, the low 7 bits one
/// less than the number of pixels).
fn pixel_bytes(
    data: &[u8],
    count: usize,
    pixel_size: usize,
    run_length: bool,
) -> Result<Vec<u8>, String> {
    let total = count * pixel_size;
    const TRUNCATED: &str = "the file ends before its last pixel";
    if !run_length {
        return data
            .get(..total)
            .map(<[u8]>::to_vec)
            .ok_or(TRUNCATED.to_string());
    }
    // Grown as packets arrive, so a header claiming a huge image costs nothing up front.
    let mut pixels = Vec::new();
    let mut position = 0;
    while pixels.len() < total {
        let header = *data.get(position).ok_or(TRUNCATED)?;
        position += 1;
        let repeat = usize::from(header & 0x7f) + 1;
        let room = (total - pixels.len()) / pixel_size;
        if header & 0x80 != 0 {
            let value = data.get(position..position + pixel_size).ok_or(TRUNCATED)?;
            position += pixel_size;
            for _ in 0..repeat.min(room) {
                pixels.extend_from_slice(value);
            }
        } else {
            let length = repeat * pixel_size;
            let values = data.get(position..position + length).ok_or(TRUNCATED)?;
            position += length;
            pixels.extend_from_slice(&values[..repeat.min(room) * pixel_size]);
        }
    }
    Ok(pixels)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2x2 TGA header of `image_type` and `depth`, bottom row first.
    fn header(image_type: u8, depth: u8, descriptor: u8) -> Vec<u8> {
        let mut bytes = vec![0, 0, image_type, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 0, 2, 0];
        bytes.extend_from_slice(&[depth, descriptor]);
        bytes
    }

    #[test]
    fn reads_true_colour_bottom_row_first_and_run_length_packets() {
        let mut flat = header(2, 24, 0);
        // Bottom row: blue, green; top row: red, white (stored blue, green, red).
        flat.extend_from_slice(&[255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255]);
        let raster = decode(&flat).unwrap();
        assert_eq!(raster.pixel(0, 0), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(raster.pixel(0, 1), [0.0, 0.0, 1.0, 1.0]);
        let mut packed = header(10, 24, 0x20);
        // A run of three reds, then one raw white pixel.
        packed.extend_from_slice(&[0x82, 0, 0, 255, 0x00, 255, 255, 255]);
        let raster = decode(&packed).unwrap();
        assert_eq!(raster.pixel(1, 0), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(raster.pixel(1, 1), [1.0, 1.0, 1.0, 1.0]);
        assert!(!raster.alpha);
    }

    #[test]
    fn keeps_the_palette_index_of_colour_mapped_pixels() {
        let mut bytes = header(1, 8, 0x20);
        bytes[1] = 1;
        bytes[5] = 2;
        bytes[7] = 24;
        bytes.extend_from_slice(&[0, 0, 255, 255, 0, 0]);
        bytes.extend_from_slice(&[1, 0, 0, 1]);
        let raster = decode(&bytes).unwrap();
        assert_eq!(raster.palette_indices, Some(vec![1, 0, 0, 1]));
        assert_eq!(raster.pixel(0, 0), [0.0, 0.0, 1.0, 1.0]);
    }

    #[test]
    fn a_truncated_file_is_an_error() {
        let mut bytes = header(2, 32, 0);
        bytes.extend_from_slice(&[1, 2, 3]);
        assert_eq!(
            decode(&bytes).err().unwrap(),
            "the file ends before its last pixel"
        );
        assert!(decode(&bytes[..10]).is_err());
        let mut packed = header(10, 24, 0);
        packed.push(0x83);
        assert!(decode(&packed).is_err());
    }
}
