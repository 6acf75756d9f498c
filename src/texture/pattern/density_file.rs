//! `density_file df3 "file"`: a voxel grid read from a DF3 file, spread over the unit cube.
//!
//! In: a pattern-space point. Out: the voxel value in [0, 1] (0 outside [0, 1)³). Holds: the
//! grid is read once when the scene is parsed ([`DensityFile::parse`], bounded in size);
//! evaluation is allocation-free.
//!
//! The file: three big-endian 16-bit sizes (x, y, z), then the voxels, x fastest, with 1, 2
//! or 4 big-endian bytes each (the size that the rest of the file divides into), divided by
//! the largest value of that size. Measured against POV-Ray 3.7 (`function { pattern {
//! density_file .. } }` at random points of 8- and 16-bit grids): the voxel of point p is
//! ⌊p · size⌋, the unit cube is half open; `interpolate 1` is trilinear between the voxels
//! at ⌊p · size⌋ and one further, wrapping around at the far faces. `interpolate 2` is
//! POV-Ray's cubic, approximated here by a Catmull-Rom spline over the same wrapped
//! neighbours (within about 0.07 of POV-Ray's values).

/// Largest number of voxels accepted (a 512³ grid).
pub const MAX_VOXELS: usize = 512 * 512 * 512;

/// A voxel grid.
#[derive(Clone, Debug, PartialEq)]
pub struct DensityFile {
    /// Voxels along x, y and z.
    size: [usize; 3],
    /// The values in [0, 1], x fastest, then y, then z.
    values: Vec<f32>,
    /// The file the grid was read from (for writing the scene back), when known.
    pub path: Option<std::path::PathBuf>,
}

impl DensityFile {
    /// Reads a DF3 file's bytes; the error says what is wrong with them.
    pub fn parse(bytes: &[u8]) -> Result<DensityFile, String> {
        let Some(header) = bytes.get(..6) else {
            return Err("the file is shorter than its 6-byte header".into());
        };
        let size =
            [0, 2, 4].map(|at| usize::from(u16::from_be_bytes([header[at], header[at + 1]])));
        let count = size[0] * size[1] * size[2];
        if count == 0 {
            return Err(format!(
                "the grid is empty ({} x {} x {} voxels)",
                size[0], size[1], size[2]
            ));
        }
        if count > MAX_VOXELS {
            return Err(format!(
                "the grid has {count} voxels, more than the {MAX_VOXELS} accepted"
            ));
        }
        let data = &bytes[6..];
        if !data.len().is_multiple_of(count) || !matches!(data.len() / count, 1 | 2 | 4) {
            return Err(format!(
                "{} bytes of voxels do not fit {} x {} x {} voxels of 1, 2 or 4 bytes",
                data.len(),
                size[0],
                size[1],
                size[2]
            ));
        }
        let width = data.len() / count;
        let largest = match width {
            1 => f64::from(u8::MAX),
            2 => f64::from(u16::MAX),
            _ => f64::from(u32::MAX),
        };
        let values = data
            .chunks_exact(width)
            .map(|chunk| {
                let raw = chunk
                    .iter()
                    .fold(0u32, |acc, &byte| (acc << 8) | u32::from(byte));
                (f64::from(raw) / largest) as f32
            })
            .collect();
        Ok(DensityFile {
            size,
            values,
            path: None,
        })
    }

    /// The value at a pattern-space point with `interpolation` 0 (nearest voxel), 1
    /// (trilinear) or 2 (cubic).
    pub fn value(&self, point: glam::DVec3, interpolation: u8) -> f64 {
        let p = point.to_array();
        if !p.iter().all(|c| (0.0..1.0).contains(c)) {
            return 0.0;
        }
        let mut cell = [0usize; 3];
        let mut fraction = [0.0; 3];
        for axis in 0..3 {
            let scaled = p[axis] * self.size[axis] as f64;
            let index = (scaled.floor() as usize).min(self.size[axis] - 1);
            cell[axis] = index;
            fraction[axis] = scaled - index as f64;
        }
        match interpolation {
            0 => self.voxel(cell, [0; 3]),
            1 => self.blend(cell, &fraction.map(|t| [1.0 - t, t]), 0),
            _ => self.blend(cell, &fraction.map(catmull_rom), -1),
        }
    }

    /// The weighted sum of the voxels around `cell`: weight `weights[axis][n]` for the
    /// voxel `first + n` steps along each axis (wrapping around the grid).
    fn blend<const N: usize>(
        &self,
        cell: [usize; 3],
        weights: &[[f64; N]; 3],
        first: isize,
    ) -> f64 {
        let mut sum = 0.0;
        for (k, wz) in weights[2].iter().enumerate() {
            for (j, wy) in weights[1].iter().enumerate() {
                for (i, wx) in weights[0].iter().enumerate() {
                    let offset = [i, j, k].map(|n| n as isize + first);
                    sum += wx * wy * wz * self.voxel(cell, offset);
                }
            }
        }
        sum
    }

    /// The voxel `offset` steps from `cell`, wrapping around the grid.
    fn voxel(&self, cell: [usize; 3], offset: [isize; 3]) -> f64 {
        let mut index = [0usize; 3];
        for axis in 0..3 {
            let size = self.size[axis] as isize;
            index[axis] = (cell[axis] as isize + offset[axis]).rem_euclid(size) as usize;
        }
        let flat = index[0] + self.size[0] * (index[1] + self.size[1] * index[2]);
        self.values.get(flat).map_or(0.0, |&value| f64::from(value))
    }
}

/// Catmull-Rom weights of the voxels at offsets −1, 0, 1, 2 for a fraction `t`.
fn catmull_rom(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        (-t3 + 2.0 * t2 - t) / 2.0,
        (3.0 * t3 - 5.0 * t2 + 2.0) / 2.0,
        (-3.0 * t3 + 4.0 * t2 + t) / 2.0,
        (t3 - t2) / 2.0,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    /// A 4 x 3 x 5 grid of 8-bit voxels with values 0, 1, 2, ... (POV-Ray's probes used
    /// random values; the rules are the same).
    fn grid() -> DensityFile {
        let mut bytes = vec![0, 4, 0, 3, 0, 5];
        bytes.extend((0..60u8).map(|v| v * 4));
        DensityFile::parse(&bytes).unwrap()
    }

    #[test]
    fn nearest_voxel_and_half_open_cube() {
        let grid = grid();
        // Voxel (1, 0, 0) holds 4/255.
        assert_eq!(
            grid.value(DVec3::new(0.25, 0.0, 0.0), 0),
            f64::from(4.0f32 / 255.0)
        );
        assert_eq!(grid.value(DVec3::new(0.2499, 0.0, 0.0), 0), 0.0);
        assert_eq!(grid.value(DVec3::ONE, 0), 0.0);
        assert_eq!(grid.value(DVec3::new(-0.01, 0.5, 0.5), 2), 0.0);
    }

    #[test]
    fn trilinear_wraps_at_the_far_face() {
        let grid = grid();
        // Half way between voxel x = 3 (12/255) and, wrapped, x = 0 (0) on the first row.
        let mid = grid.value(DVec3::new(0.875, 0.0, 0.0), 1);
        assert!((mid - f64::from(12.0f32 / 255.0) / 2.0).abs() < 1e-9);
    }

    #[test]
    fn bad_files_are_refused() {
        assert!(DensityFile::parse(&[0, 1]).unwrap_err().contains("header"));
        assert!(DensityFile::parse(&[0, 0, 0, 1, 0, 1])
            .unwrap_err()
            .contains("empty"));
        assert!(DensityFile::parse(&[0, 2, 0, 1, 0, 1, 9, 9, 9])
            .unwrap_err()
            .contains("do not fit"));
        assert!(DensityFile::parse(&[255, 255, 255, 255, 0, 1])
            .unwrap_err()
            .contains("more than"));
    }
}
