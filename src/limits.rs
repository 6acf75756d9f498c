//! Named, adjustable limits: how far a scene may go before durer stops it with a
//! diagnostic that names the limit and how to raise it (`--limit NAME=VALUE`).
//!
//! Each limit bounds time, memory or stack that a hostile or runaway scene could otherwise
//! exhaust. The table [`LIMITS`] is the one list of names, defaults and meanings;
//! `docs/limits.md` shows it and `durer render --limit help` prints it.

use std::fmt;

/// Stack size of the thread that evaluates scenes: macro recursion, includes and
/// expressions as deep as the `nesting` limit allows need room.
pub const EVALUATION_STACK_BYTES: usize = 1 << 30;

/// Stack size of each render thread: building and tracing CSG nested as deep as the
/// `nesting` limit allows (20,000) needs about 40 MiB (measured); this leaves room.
pub const RENDER_STACK_BYTES: usize = 256 << 20;

/// The limits in force for one run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Deepest nesting of macro calls, includes, blocks and parentheses.
    pub nesting: u64,
    /// Most iterations of one `#while` or `#for` loop.
    pub iterations: u64,
    /// Most elements of one array.
    pub array_size: u64,
    /// Longest string, in bytes.
    pub string_size: u64,
    /// Most bytes of scene text one text-macro call emits.
    pub macro_text: u64,
    /// Largest file a scene may read (scene, include, data file), in bytes.
    pub file_size: u64,
    /// Most objects (shapes, CSG nodes and object copies) a scene may create.
    pub objects: u64,
    /// Most bytes of mesh data (triangles, vectors, indices) a scene may hold.
    pub geometry_memory: u64,
    /// Largest image, in pixels (width times height).
    pub pixels: u64,
    /// Most render threads.
    pub threads: u64,
    /// Most steps the parser may take on one file (bounds the time of pathological text).
    pub parse_steps: u64,
}

impl Default for Limits {
    fn default() -> Self {
        let mut limits = Limits {
            nesting: 0,
            iterations: 0,
            array_size: 0,
            string_size: 0,
            macro_text: 0,
            file_size: 0,
            objects: 0,
            geometry_memory: 0,
            pixels: 0,
            threads: 0,
            parse_steps: 0,
        };
        for limit in LIMITS {
            *(limit.field)(&mut limits) = limit.default;
        }
        limits
    }
}

/// One named limit: its flag name, default, unit and meaning.
pub struct Limit {
    pub name: &'static str,
    pub default: u64,
    pub meaning: &'static str,
    field: fn(&mut Limits) -> &mut u64,
}

/// Every limit, in the order the documentation lists them.
pub const LIMITS: &[Limit] = &[
    Limit {
        name: "nesting",
        default: 20_000,
        meaning: "deepest nesting of macro calls, includes, blocks (CSG, textures) and \
                  parenthesised expressions",
        field: |l| &mut l.nesting,
    },
    Limit {
        name: "iterations",
        default: 10_000_000,
        meaning: "most iterations of one #while or #for loop (a loop that leaves a value each \
                  time holds them all: 10 million take about 0.5 GB)",
        field: |l| &mut l.iterations,
    },
    Limit {
        name: "array-size",
        default: 16 << 20,
        meaning: "most elements of one array",
        field: |l| &mut l.array_size,
    },
    Limit {
        name: "string-size",
        default: 16 << 20,
        meaning: "longest string a scene may build, in bytes",
        field: |l| &mut l.string_size,
    },
    Limit {
        name: "macro-text",
        default: 64 << 20,
        meaning: "most bytes of scene text one macro call emits when its body runs across \
                  directives (a loop in it that never ends); about 10 bytes of memory each",
        field: |l| &mut l.macro_text,
    },
    Limit {
        name: "file-size",
        default: 1 << 30,
        meaning: "largest scene, include or data file a scene may read, in bytes",
        field: |l| &mut l.file_size,
    },
    Limit {
        name: "objects",
        default: 5_000_000,
        meaning: "most objects (shapes, CSG nodes, object copies) one scene may create",
        field: |l| &mut l.objects,
    },
    Limit {
        name: "geometry-memory",
        default: 8 << 30,
        meaning: "most bytes of mesh data (triangles, mesh2 vectors and indices) one scene \
                  may hold",
        field: |l| &mut l.geometry_memory,
    },
    Limit {
        name: "pixels",
        default: 40_000_000,
        meaning: "largest image, width times height (about 100 bytes of memory per pixel)",
        field: |l| &mut l.pixels,
    },
    Limit {
        name: "threads",
        default: 512,
        meaning: "most render threads (--threads, +WT)",
        field: |l| &mut l.threads,
    },
    Limit {
        name: "parse-steps",
        default: 50_000_000,
        meaning: "parser steps allowed for one file, plus 400 per byte of it (bounds the \
                  time of text that makes the grammar backtrack)",
        field: |l| &mut l.parse_steps,
    },
];

/// A `--limit` that could not be applied.
#[derive(Debug, PartialEq, Eq)]
pub struct BadLimit(pub String);

impl fmt::Display for BadLimit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl Limits {
    /// Applies `NAME=VALUE` (`objects=10000000`, `pixels=100e6`, `nesting=50000`).
    pub fn set(&mut self, assignment: &str) -> Result<(), BadLimit> {
        let names = || LIMITS.iter().map(|l| l.name).collect::<Vec<_>>().join(", ");
        let Some((name, value)) = assignment.split_once('=') else {
            return Err(BadLimit(format!(
                "--limit `{assignment}`: expected NAME=VALUE, NAME one of {}",
                names()
            )));
        };
        let name = name.trim().replace('_', "-").to_ascii_lowercase();
        let Some(limit) = LIMITS.iter().find(|l| l.name == name) else {
            return Err(BadLimit(format!(
                "--limit: no limit named `{name}`; the limits are {}",
                names()
            )));
        };
        let value = value.trim().replace('_', "");
        let number = value
            .parse::<u64>()
            .ok()
            .or_else(|| {
                value
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite() && *v >= 0.0 && v.fract() == 0.0 && *v < 1.8e19)
                    .map(|v| v as u64)
            })
            .filter(|v| *v >= 1);
        let Some(number) = number else {
            return Err(BadLimit(format!(
                "--limit {name}: expected a whole number of at least 1, found `{value}`"
            )));
        };
        *(limit.field)(self) = number;
        Ok(())
    }

    /// The help line of a diagnostic for a limit that was hit.
    pub fn raise_hint(name: &str, value: u64) -> String {
        format!(
            "this is the `{name}` limit ({value}); raise it with --limit {name}={}",
            value.saturating_mul(10)
        )
    }
}

/// The table as text, for `--limit help`.
pub fn table() -> String {
    let mut out = String::from("limits (set with --limit NAME=VALUE):\n");
    for limit in LIMITS {
        out.push_str(&format!(
            "  {:<12} {:>12}  {}\n",
            limit.name, limit.default, limit.meaning
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn limits_are_set_by_name() {
        let mut limits = Limits::default();
        assert_eq!(limits.nesting, 20_000);
        limits.set("objects=123").unwrap();
        limits.set("string_size = 1e6").unwrap();
        limits.set("PIXELS=1_000").unwrap();
        assert_eq!(limits.objects, 123);
        assert_eq!(limits.string_size, 1_000_000);
        assert_eq!(limits.pixels, 1000);
        assert!(limits.set("objects=0").is_err());
        assert!(limits.set("objects=-4").is_err());
        assert!(limits.set("objects=1.5").is_err());
        assert!(limits.set("colours=5").unwrap_err().0.contains("nesting"));
        assert!(limits.set("objects").is_err());
        assert!(table().contains("parse-steps"));
    }
}
