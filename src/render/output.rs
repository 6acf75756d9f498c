//! Writing the rendered image as a PNG file, atomically.
//!
//! In: an [`Image`] and a path. Out: an 8-bit RGB PNG at that path, carrying the same `gAMA`
//! (1/2.2) and `sRGB` chunks POV-Ray 3.7 writes. Holds: the file appears complete or not at
//! all: the data goes to a temporary file in the same folder, which is then renamed over the
//! target, so a failed write never destroys an existing image.

use super::Image;
use image::codecs::png::PngEncoder;
use image::{ExtendedColorType, ImageEncoder};
use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Distinguishes temporary files of concurrent writes from one process.
static TEMPORARY_COUNTER: AtomicU64 = AtomicU64::new(0);

/// Writes `image` as a PNG to `path` via a temporary file and a rename.
pub fn write_png_atomic(path: &Path, image: &Image) -> io::Result<()> {
    let bytes = encode_png(image)?;
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
    let result = write_then_rename(&temporary, path, &bytes);
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

/// The PNG file contents for `image`.
pub fn encode_png(image: &Image) -> io::Result<Vec<u8>> {
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
    let mut encoded = Vec::new();
    PngEncoder::new(&mut encoded)
        .write_image(
            image.pixels.as_flattened(),
            image.width,
            image.height,
            ExtendedColorType::Rgb8,
        )
        .map_err(io::Error::other)?;
    Ok(with_colour_space_chunks(encoded))
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

    fn small_image() -> Image {
        Image {
            width: 2,
            height: 1,
            pixels: vec![[255, 0, 0], [0, 128, 255]],
        }
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
        let broken = Image {
            width: 3,
            height: 3,
            pixels: vec![[0; 3]; 2],
        };
        assert!(write_png_atomic(&old, &broken).is_err());
        assert_eq!(fs::read(&old).unwrap(), b"old image");

        // A folder that does not exist fails without creating anything.
        let missing = folder.join("missing").join("out.png");
        assert!(write_png_atomic(&missing, &small_image()).is_err());
        fs::remove_dir_all(&folder).unwrap();
    }
}
