//! Split renders for render farms: `--tile I/N` writes one tile of an even split as a
//! `.tile.png` file: a PNG of the tile (16 bits, to look at) that also holds the exact
//! traced values (f64, lossless) and what render it belongs to; `durer merge OUT TILE...`
//! checks the set and encodes the whole image with the same encoder as a single render,
//! so every output format is byte-identical to it.
//!
//! Tile file: a PNG with a `tEXt` chunk keyed `durer-tile` (`key value` lines: version,
//! size, tile index and count, region, fingerprint, encoding and output options) and
//! private `duRf` chunks whose concatenation is the tile's pixels row by row as
//! little-endian f64 red, green, blue, coverage.

use durer::render::encoding::OutputEncoding;
use durer::render::output::{self, FileFormat, OutputOptions, RenderedImage};
use durer::render::{Region, RenderOptions};
use std::hash::Hasher;
use std::path::Path;

/// `--tile I/N`: a tile index, or `auto` (from the scheduler's environment), and a count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TileSpec {
    pub index: Option<u32>,
    pub count: u32,
}

/// Parses `I/N` or `auto/N`.
pub fn parse_tile(text: &str) -> Result<TileSpec, String> {
    let (i, n) = text
        .split_once('/')
        .ok_or_else(|| "expected I/N or auto/N, such as 3/16".to_string())?;
    let count: u32 = n
        .trim()
        .parse()
        .ok()
        .filter(|&n| (1..=65536).contains(&n))
        .ok_or("N must be a whole number from 1 to 65536")?;
    let index = if i.trim() == "auto" {
        None
    } else {
        let i: u32 = i.trim().parse().map_err(|_| "I must be a whole number")?;
        if i >= count {
            return Err(format!(
                "tile {i} does not exist: tiles are 0 to {}",
                count - 1
            ));
        }
        Some(i)
    };
    Ok(TileSpec { index, count })
}

/// The tile index a scheduler gives: `SLURM_ARRAY_TASK_ID` wins, then
/// `JOB_COMPLETION_INDEX` (Kubernetes Indexed Jobs), then `PARALLEL_SEQ` (GNU parallel,
/// from 1, so minus 1).
pub fn index_from_environment(get: impl Fn(&str) -> Option<String>) -> Result<u32, String> {
    for (name, offset) in [
        ("SLURM_ARRAY_TASK_ID", 0),
        ("JOB_COMPLETION_INDEX", 0),
        ("PARALLEL_SEQ", 1),
    ] {
        if let Some(value) = get(name) {
            return value
                .trim()
                .parse::<u32>()
                .ok()
                .and_then(|v| v.checked_sub(offset))
                .ok_or_else(|| format!("{name}={value} is not a tile number"));
        }
    }
    Err(
        "--tile auto/N needs SLURM_ARRAY_TASK_ID, JOB_COMPLETION_INDEX or PARALLEL_SEQ \
         in the environment"
            .into(),
    )
}

/// Columns and rows of the split of a `width` × `height` image into `count` tiles: the
/// factor pair whose tiles are closest to square (ties: more columns).
pub fn grid(width: u32, height: u32, count: u32) -> (u32, u32) {
    let mut best = (count, 1);
    let mut best_score = f64::INFINITY;
    for columns in 1..=count {
        if !count.is_multiple_of(columns) {
            continue;
        }
        let rows = count / columns;
        let aspect =
            (f64::from(width) / f64::from(columns)) / (f64::from(height) / f64::from(rows));
        let score = aspect.ln().abs();
        if score < best_score - 1e-12 {
            best_score = score;
            best = (columns, rows);
        }
    }
    best
}

/// The pixels of tile `index` of `count` (may be empty when tiles outnumber pixels).
pub fn tile_region(width: u32, height: u32, count: u32, index: u32) -> Region {
    let (columns, rows) = grid(width, height, count);
    let (c, r) = (u64::from(index % columns), u64::from(index / columns));
    let cut = |k: u64, parts: u32, size: u32| (k * u64::from(size) / u64::from(parts)) as u32;
    Region {
        left: cut(c, columns, width),
        right: cut(c + 1, columns, width),
        top: cut(r, rows, height),
        bottom: cut(r + 1, rows, height),
    }
}

/// Fingerprint of a render's inputs: FNV-1a (64 bits) over `parts`, each ended by a 0xff
/// byte; not a security measure, a guard against merging tiles of different renders.
pub fn fingerprint(parts: &[&[u8]]) -> u64 {
    let mut hasher = durer::hash::FastHasher::default();
    for part in parts {
        hasher.write(part);
        hasher.write(&[0xff]);
    }
    hasher.finish()
}

/// One tile of a split render: which, its pixels and the fingerprint of the render.
#[derive(Clone, Debug, PartialEq)]
pub struct TileJob {
    pub index: u32,
    pub count: u32,
    pub region: Region,
    pub fingerprint: u64,
}

impl TileJob {
    /// The tile `spec` names (its index from `environment` for `auto/N`) of a render with
    /// these options; `identity` is what makes the render this render (scene, options).
    pub fn new(
        spec: TileSpec,
        render: &RenderOptions,
        output: &OutputOptions,
        identity: &[u8],
        environment: impl Fn(&str) -> Option<String>,
    ) -> Result<TileJob, String> {
        let index = match spec.index {
            Some(index) => index,
            None => index_from_environment(environment)?,
        };
        if index >= spec.count {
            return Err(format!(
                "tile {index} does not exist: tiles are 0 to {}",
                spec.count - 1
            ));
        }
        let (columns, rows) = grid(render.width, render.height, spec.count);
        if columns > render.width || rows > render.height {
            return Err(format!(
                "{} tiles of a {}x{} image would leave tiles without pixels",
                spec.count, render.width, render.height
            ));
        }
        Ok(TileJob {
            index,
            count: spec.count,
            region: tile_region(render.width, render.height, spec.count, index),
            fingerprint: fingerprint(&[identity, format!("{output:?}").as_bytes()]),
        })
    }

    /// The same tile of one frame of an animation (frames are different renders).
    pub fn for_frame(&self, frame: &impl std::fmt::Debug) -> TileJob {
        TileJob {
            fingerprint: fingerprint(&[
                &self.fingerprint.to_le_bytes(),
                format!("{frame:?}").as_bytes(),
            ]),
            ..self.clone()
        }
    }

    /// The tile file of this tile of `image` (a whole-size render with this tile's region
    /// traced): a PNG of the tile's pixels (16 bits, to look at) carrying in a `tEXt`
    /// chunk `durer-tile` what it is, and in private `duRf` chunks the exact traced values.
    pub fn encode(
        &self,
        image: &RenderedImage,
        options: &OutputOptions,
    ) -> std::io::Result<Vec<u8>> {
        let header = TileHeader {
            width: image.width,
            height: image.height,
            count: self.count,
            index: self.index,
            fingerprint: self.fingerprint,
            encoding: image.encoding,
            options: *options,
        };
        let region = self.region;
        let mut pixels = Vec::new();
        for row in region.top..region.bottom {
            let start = row as usize * image.width as usize;
            pixels.extend_from_slice(
                &image.pixels[start + region.left as usize..start + region.right as usize],
            );
        }
        let preview = RenderedImage {
            width: region.right - region.left,
            height: region.bottom - region.top,
            pixels,
            encoding: image.encoding,
        };
        let png_options = OutputOptions {
            format: FileFormat::Png,
            bits: 16,
            ..*options
        };
        let mut bytes = output::encode(&preview, &png_options)?;
        // The chunks go just before IEND, the last 12 bytes of the PNG.
        let end = bytes.split_off(bytes.len() - 12);
        let mut text = b"durer-tile\0".to_vec();
        text.extend_from_slice(header.text().as_bytes());
        push_chunk(&mut bytes, b"tEXt", &text);
        let mut values = Vec::with_capacity(preview.pixels.len() * 32);
        for pixel in &preview.pixels {
            for value in pixel {
                values.extend_from_slice(&value.to_le_bytes());
            }
        }
        for part in values.chunks(DATA_CHUNK_BYTES) {
            push_chunk(&mut bytes, DATA_CHUNK, part);
        }
        bytes.extend_from_slice(&end);
        Ok(bytes)
    }
}

/// The private chunk type of a tile's exact values: ancillary, private, safe to copy.
const DATA_CHUNK: &[u8; 4] = b"duRf";
/// Most bytes of values in one chunk (PNG allows up to 2^31 - 1).
const DATA_CHUNK_BYTES: usize = 1 << 30;

fn push_chunk(bytes: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    bytes.extend_from_slice(&(data.len() as u32).to_be_bytes());
    let start = bytes.len();
    bytes.extend_from_slice(kind);
    bytes.extend_from_slice(data);
    let crc = crc32fast::hash(&bytes[start..]);
    bytes.extend_from_slice(&crc.to_be_bytes());
}

/// One PNG chunk: its type and data.
type Chunk<'a> = (&'a [u8], &'a [u8]);

/// The chunks of a PNG file, checked (signature, lengths, CRCs).
fn chunks(bytes: &[u8]) -> Result<Vec<Chunk<'_>>, String> {
    const SIGNATURE: &[u8] = b"\x89PNG\r\n\x1a\n";
    let mut rest = bytes
        .strip_prefix(SIGNATURE)
        .ok_or("not a durer tile (not a PNG file)")?;
    let mut found = Vec::new();
    while !rest.is_empty() {
        if rest.len() < 12 {
            return Err("the PNG file is truncated".into());
        }
        let length = u32::from_be_bytes([rest[0], rest[1], rest[2], rest[3]]) as usize;
        if rest.len() - 12 < length {
            return Err("the PNG file is truncated".into());
        }
        let (kind, data) = (&rest[4..8], &rest[8..8 + length]);
        let crc = u32::from_be_bytes(
            rest[8 + length..12 + length]
                .try_into()
                .map_err(|_| "the PNG file is truncated")?,
        );
        if crc32fast::hash(&rest[4..8 + length]) != crc {
            return Err(format!(
                "the PNG file is damaged (bad checksum of a {} chunk)",
                String::from_utf8_lossy(kind)
            ));
        }
        found.push((kind, data));
        rest = &rest[12 + length..];
        if kind == b"IEND" {
            break;
        }
    }
    Ok(found)
}

/// What a tile file says about itself.
#[derive(Clone, Debug, PartialEq)]
pub struct TileHeader {
    pub width: u32,
    pub height: u32,
    pub count: u32,
    pub index: u32,
    pub fingerprint: u64,
    pub encoding: OutputEncoding,
    pub options: OutputOptions,
}

fn format_letter(format: FileFormat) -> char {
    match format {
        FileFormat::Png => 'N',
        FileFormat::Ppm => 'P',
        FileFormat::Tga => 'T',
        FileFormat::TgaCompressed => 'C',
        FileFormat::Bmp => 'B',
        FileFormat::Jpeg => 'J',
        FileFormat::Exr => 'E',
        FileFormat::Hdr => 'H',
    }
}

impl TileHeader {
    /// `key value` lines (floats as their bits in hex, so they come back exactly).
    fn text(&self) -> String {
        let region = tile_region(self.width, self.height, self.count, self.index);
        let encoding = match self.encoding {
            OutputEncoding::Unchanged => "unchanged".to_string(),
            OutputEncoding::Srgb { assumed_gamma } => {
                format!("srgb {:016x}", assumed_gamma.to_bits())
            }
        };
        let file_gamma = self
            .options
            .file_gamma
            .map_or_else(|| "srgb".to_string(), |g| format!("{:016x}", g.to_bits()));
        format!(
            "version 1\nsize {} {}\ntile {} {}\nregion {} {} {} {}\nfingerprint {:016x}\n\
             encoding {encoding}\nformat {}\nbits {}\nalpha {}\njpeg_quality {}\nfile_gamma {file_gamma}\n",
            self.width,
            self.height,
            self.index,
            self.count,
            region.left,
            region.top,
            region.right,
            region.bottom,
            self.fingerprint,
            format_letter(self.options.format),
            self.options.bits,
            u8::from(self.options.alpha),
            self.options.jpeg_quality,
        )
    }

    fn parse(text: &str) -> Result<TileHeader, String> {
        let mut fields = std::collections::HashMap::new();
        for line in text.lines() {
            let (key, value) = line.split_once(' ').ok_or("bad tile header line")?;
            fields.insert(key, value);
        }
        let field = |key: &str| {
            fields
                .get(key)
                .copied()
                .ok_or(format!("the tile header lacks `{key}`"))
        };
        if field("version")? != "1" {
            return Err("a tile of another durer version (tile format 1 expected)".into());
        }
        let numbers = |key: &str| -> Result<Vec<u32>, String> {
            field(key)?
                .split(' ')
                .map(|w| {
                    w.parse()
                        .map_err(|_| format!("bad `{key}` in the tile header"))
                })
                .collect()
        };
        let hex = |text: &str| {
            u64::from_str_radix(text, 16).map_err(|_| "bad number in the tile header".to_string())
        };
        let size = numbers("size")?;
        let tile = numbers("tile")?;
        let region = numbers("region")?;
        let bits = numbers("bits")?;
        if size.len() != 2 || tile.len() != 2 || region.len() != 4 || bits.len() != 1 {
            return Err("bad tile header".into());
        }
        let encoding = match field("encoding")?.split_once(' ') {
            Some(("srgb", bits)) => OutputEncoding::Srgb {
                assumed_gamma: f64::from_bits(hex(bits)?),
            },
            _ if field("encoding")? == "unchanged" => OutputEncoding::Unchanged,
            _ => return Err("bad `encoding` in the tile header".into()),
        };
        let format = field("format")?
            .chars()
            .next()
            .and_then(FileFormat::from_letter)
            .ok_or("bad `format` in the tile header")?;
        let file_gamma = match field("file_gamma")? {
            "srgb" => None,
            bits => Some(f64::from_bits(hex(bits)?)),
        };
        let header = TileHeader {
            width: size[0],
            height: size[1],
            index: tile[0],
            count: tile[1],
            fingerprint: hex(field("fingerprint")?)?,
            encoding,
            options: OutputOptions {
                format,
                bits: bits[0],
                alpha: field("alpha")? == "1",
                jpeg_quality: field("jpeg_quality")?
                    .parse()
                    .map_err(|_| "bad `jpeg_quality` in the tile header")?,
                file_gamma,
            },
        };
        if header.count == 0 || header.index >= header.count {
            return Err("bad tile number in the tile header".into());
        }
        let expected = tile_region(header.width, header.height, header.count, header.index);
        if [expected.left, expected.top, expected.right, expected.bottom] != region[..] {
            return Err("the tile's region does not match its split".into());
        }
        Ok(header)
    }
}

/// Reads a tile file: its header and pixels (those of its region, row by row).
pub fn decode_tile(bytes: &[u8]) -> Result<(TileHeader, Vec<[f64; 4]>), String> {
    let chunks = chunks(bytes)?;
    let text = chunks
        .iter()
        .find_map(|(kind, data)| {
            (*kind == b"tEXt")
                .then(|| data.strip_prefix(b"durer-tile\0"))
                .flatten()
        })
        .ok_or("a PNG file, but not a durer tile (no durer-tile text)")?;
    let header = TileHeader::parse(&String::from_utf8_lossy(text))?;
    let data: Vec<u8> = chunks
        .iter()
        .filter(|(kind, _)| *kind == DATA_CHUNK)
        .flat_map(|(_, data)| data.iter().copied())
        .collect();
    let region = tile_region(header.width, header.height, header.count, header.index);
    let count = (region.right - region.left) as usize * (region.bottom - region.top) as usize;
    if data.len() != count * 32 {
        return Err(format!(
            "the tile holds {} bytes of pixels, {} expected (truncated?)",
            data.len(),
            count * 32
        ));
    }
    let pixels = data
        .chunks_exact(32)
        .map(|p| {
            let v = |k: usize| f64::from_le_bytes(p[k * 8..k * 8 + 8].try_into().unwrap_or([0; 8]));
            [v(0), v(1), v(2), v(3)]
        })
        .collect();
    Ok((header, pixels))
}

/// The tile file name: `base` (from `-o`, or the scene's name plus `-IofN` when there is no
/// `-o`, so that tiles sharing a folder differ) with the frame number, then `.tile.png`.
pub fn tile_file_name(
    base: &str,
    add_split: bool,
    frame: Option<i64>,
    digits: usize,
    (index, count): (u32, u32),
) -> String {
    let base = base.strip_suffix(".tile").unwrap_or(base);
    let frame = frame.map_or_else(String::new, |n| format!("{n:0digits$}"));
    let split = if add_split {
        format!("-{index}of{count}")
    } else {
        String::new()
    };
    format!("{base}{frame}{split}.tile.png")
}

/// Assembles the whole image from tile files' contents; refuses incomplete or mixed sets.
pub fn assemble(
    tiles: &[(String, TileHeader, Vec<[f64; 4]>)],
) -> Result<(RenderedImage, OutputOptions), String> {
    let Some((first_name, first, _)) = tiles.first() else {
        return Err("no tiles given".into());
    };
    let mut seen = vec![None::<&str>; first.count as usize];
    for (name, header, _) in tiles {
        let same = header.width == first.width
            && header.height == first.height
            && header.count == first.count
            && header.fingerprint == first.fingerprint
            && header.encoding == first.encoding
            && header.options == first.options;
        if !same {
            return Err(format!(
                "{name} and {first_name} are tiles of different renders \
                 (size, split or options fingerprint differ)"
            ));
        }
        if let Some(other) = seen[header.index as usize].replace(name) {
            return Err(format!("{name} and {other} are both tile {}", header.index));
        }
    }
    let missing: Vec<String> = seen
        .iter()
        .enumerate()
        .filter(|(_, s)| s.is_none())
        .map(|(i, _)| i.to_string())
        .collect();
    if !missing.is_empty() {
        return Err(format!(
            "tiles missing from the set of {}: {}",
            first.count,
            missing.join(", ")
        ));
    }
    let pixels_limit = durer::limits::Limits::default().pixels;
    if u64::from(first.width) * u64::from(first.height) > pixels_limit {
        return Err(format!(
            "the tiles say the image is {}x{}, larger than the pixels limit ({pixels_limit})",
            first.width, first.height
        ));
    }
    let (width, height) = (first.width as usize, first.height as usize);
    let mut pixels = vec![[0.0, 0.0, 0.0, 1.0]; width * height];
    for (_, header, data) in tiles {
        let region = tile_region(header.width, header.height, header.count, header.index);
        let mut values = data.iter();
        for row in region.top..region.bottom {
            for column in region.left..region.right {
                if let Some(&value) = values.next() {
                    pixels[row as usize * width + column as usize] = value;
                }
            }
        }
    }
    Ok((
        RenderedImage {
            width: first.width,
            height: first.height,
            pixels,
            encoding: first.encoding,
        },
        first.options,
    ))
}

/// `durer merge OUT TILE...`; returns the exit code.
pub fn merge_command(words: &[String]) -> i32 {
    if words.len() < 2 || words.iter().any(|w| w == "--help" || w == "-h") {
        eprintln!(
            "usage: durer merge OUT TILE...\n  checks that the tiles (`.tile.png` files from `durer render --tile I/N`) \
             are all the tiles of one render and writes the whole image to OUT, in the format its \
             extension names (else the render's)"
        );
        return if words.len() < 2 {
            super::EXIT_USAGE
        } else {
            0
        };
    }
    let out = Path::new(&words[0]);
    let mut tiles = Vec::new();
    for name in &words[1..] {
        let decoded = std::fs::read(name)
            .map_err(|e| e.to_string())
            .and_then(|bytes| decode_tile(&bytes));
        match decoded {
            Ok((header, pixels)) => tiles.push((name.clone(), header, pixels)),
            Err(message) => {
                eprintln!("durer: {name}: {message}");
                return super::EXIT_USAGE;
            }
        }
    }
    let (image, mut options) = match assemble(&tiles) {
        Ok(done) => done,
        Err(message) => {
            eprintln!("durer: cannot merge: {message}");
            return super::EXIT_USAGE;
        }
    };
    if let Some(format) = FileFormat::from_extension(out) {
        if format != options.format
            && !(format == FileFormat::Tga && options.format == FileFormat::TgaCompressed)
        {
            options.format = format;
            if !matches!(format, FileFormat::Png | FileFormat::Ppm) {
                options.bits = 8;
            }
        }
    }
    let written =
        output::encode(&image, &options).and_then(|bytes| output::write_atomic(out, &bytes));
    if let Err(error) = written {
        eprintln!("durer: cannot write {}: {error}", out.display());
        return super::EXIT_SCENE_ERROR;
    }
    0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tiles_cover_the_image_once() {
        for (w, h, n) in [(64, 48, 16), (7, 5, 6), (3, 2, 16), (100, 10, 7)] {
            let mut hits = vec![0; (w * h) as usize];
            for i in 0..n {
                let r = tile_region(w, h, n, i);
                for y in r.top..r.bottom {
                    for x in r.left..r.right {
                        hits[(y * w + x) as usize] += 1;
                    }
                }
            }
            assert!(hits.iter().all(|&k| k == 1), "{w}x{h} in {n}");
        }
        assert_eq!(grid(64, 48, 16), (4, 4));
        assert_eq!(grid(640, 100, 4), (4, 1));
    }

    #[test]
    fn tile_index_from_environment() {
        let env = |pairs: &'static [(&'static str, &'static str)]| {
            move |k: &str| {
                pairs
                    .iter()
                    .find(|(n, _)| *n == k)
                    .map(|(_, v)| v.to_string())
            }
        };
        assert_eq!(index_from_environment(env(&[("PARALLEL_SEQ", "1")])), Ok(0));
        assert_eq!(
            index_from_environment(env(&[("PARALLEL_SEQ", "1"), ("SLURM_ARRAY_TASK_ID", "5")])),
            Ok(5)
        );
        assert_eq!(
            index_from_environment(env(&[("JOB_COMPLETION_INDEX", "3")])),
            Ok(3)
        );
        assert!(index_from_environment(env(&[])).is_err());
        assert!(index_from_environment(env(&[("PARALLEL_SEQ", "0")])).is_err());
        assert_eq!(
            parse_tile("auto/4"),
            Ok(TileSpec {
                index: None,
                count: 4
            })
        );
        assert!(parse_tile("4/4").is_err());
    }
}
