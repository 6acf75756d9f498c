//! The pipeline's direction, enforced: every `crate::` import in `src/` must run down the
//! layer table below, and no two sibling modules anywhere may import each other (directly
//! or round a circle), except the circles named in [`ALLOWED_CIRCLES`].
//!
//! The table is the one place the layer order is written; `docs/architecture.md` draws it.
//! A module is placed in the layer of its first path segment (`texture::pattern::warp` is in
//! `texture`). Imports are read from the source text: `use` trees (groups, renames, globs,
//! `self`, `super`, child modules) and paths written in code (`crate::a::b`, `super::c`),
//! with comments and string literals skipped. The binary (`main.rs`, `cli/`) sits above
//! every layer and is not checked.
//!
//! `cargo test --test integration architecture -- --nocapture` prints the layer graph.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// The layers, bottom first, each with the layers it may import. A layer may name only
/// layers above it in this list (so the table itself has no circle).
const LAYERS: &[(&str, &[&str])] = &[
    // Leaves: hashing, colours and transforms, diagnostics.
    ("hash", &[]),
    ("math", &[]),
    ("diag", &[]),
    // Which files scenes may read and write (povray.conf's I/O restrictions).
    ("file_policy", &[]),
    // The named, adjustable limits.
    ("limits", &[]),
    // POV-Ray's noise, image file readers, bounding boxes and the BVH.
    ("noise", &["math"]),
    ("raster", &["math"]),
    ("accel", &["math"]),
    // The recursive appearance family: patterns, functions, pigments, normals, finishes.
    ("texture", &["hash", "math", "noise", "raster"]),
    // The evaluated scene: plain data.
    ("scene", &["hash", "math", "noise", "raster", "texture"]),
    // The evaluated scene written back as flat SDL.
    ("expand", &["math", "noise", "raster", "texture", "scene"]),
    // Render objects: shapes, CSG, materials, the world.
    (
        "geometry",
        &[
            "hash", "math", "noise", "raster", "accel", "texture", "scene",
        ],
    ),
    // Light transport.
    (
        "render",
        &[
            "hash", "math", "noise", "raster", "accel", "texture", "scene", "geometry",
        ],
    ),
    // Source text to AST.
    ("syntax", &["diag", "hash"]),
    // AST to scene (it builds geometry for `trace`, `inside` and the object pattern).
    (
        "eval",
        &[
            "hash",
            "math",
            "diag",
            "noise",
            "raster",
            "accel",
            "texture",
            "scene",
            "geometry",
            "syntax",
            "file_policy",
            "limits",
        ],
    ),
    // Diagnostics drawn as miette reports, at the edge.
    ("report", &["diag", "syntax"]),
    // Fuzzer entry points: one scene text through the whole pipeline.
    (
        "fuzzing",
        &[
            "diag", "syntax", "eval", "geometry", "render", "report", "limits",
        ],
    ),
];

/// Sibling circles allowed, each with its reason.
const ALLOWED_CIRCLES: &[(&[&str], &str)] = &[
    (
        &["texture::function", "texture::pattern", "texture::pigment"],
        "the language's own recursion: a pattern may be a function or a pigment, a function may \
         be a pattern or a pigment, a pigment is made of patterns",
    ),
    (
        &[
            "expand::appearance",
            "expand::functions",
            "expand::patterns",
        ],
        "the same recursion, written back: a pigment is written with its pattern, a pattern \
         may be a function or a pigment, a function may be a pattern or a pigment",
    ),
];

/// One crate-internal import: from the module whose file holds it to the deepest module
/// its path names, with the file for messages.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Import {
    from: Vec<String>,
    to: Vec<String>,
    file: String,
}

/// The module path of a file under `src/` (`texture/pattern/mod.rs` is `texture::pattern`).
fn module_path(relative: &str) -> Vec<String> {
    let mut parts: Vec<String> = relative.split('/').map(str::to_string).collect();
    let file = parts.pop().unwrap_or_default();
    let stem = file.trim_end_matches(".rs");
    if stem != "mod" && stem != "lib" {
        parts.push(stem.to_string());
    }
    parts
}

/// The text with comments replaced by spaces and string and char literals emptied, so
/// that only code is searched for paths.
fn code_only(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let at = |i: usize, s: &str| {
        s.chars()
            .enumerate()
            .all(|(k, c)| chars.get(i + k) == Some(&c))
    };
    while i < chars.len() {
        if at(i, "//") {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
            continue;
        }
        if at(i, "/*") {
            let mut depth = 0;
            while i < chars.len() {
                if at(i, "/*") {
                    depth += 1;
                    i += 2;
                } else if at(i, "*/") {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
            out.push(' ');
            continue;
        }
        let word_before = i > 0 && (chars[i - 1].is_alphanumeric() || chars[i - 1] == '_');
        if chars[i] == 'r' && !word_before && (at(i + 1, "\"") || at(i + 1, "#")) {
            let mut j = i + 1;
            let mut hashes = 0;
            while chars.get(j) == Some(&'#') {
                hashes += 1;
                j += 1;
            }
            if chars.get(j) == Some(&'"') {
                j += 1;
                while j < chars.len() {
                    if chars[j] == '"' && (1..=hashes).all(|k| chars.get(j + k) == Some(&'#')) {
                        j += 1 + hashes;
                        break;
                    }
                    j += 1;
                }
                out.push_str("\"\"");
                i = j;
                continue;
            }
        }
        if chars[i] == '"' {
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                if chars[i] == '\\' {
                    i += 1;
                }
                i += 1;
            }
            i += 1;
            out.push_str("\"\"");
            continue;
        }
        if chars[i] == '\'' {
            if chars.get(i + 1) == Some(&'\\') {
                let mut j = i + 2;
                while j < chars.len() && chars[j] != '\'' {
                    j += 1;
                }
                i = j + 1;
                out.push_str("' '");
                continue;
            }
            if chars.get(i + 2) == Some(&'\'') {
                i += 3;
                out.push_str("' '");
                continue;
            }
        }
        out.push(chars[i]);
        i += 1;
    }
    out
}

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// Reads one use tree starting at `chars[*i]` and appends every path it names.
fn read_use_tree(chars: &[char], i: &mut usize, prefix: Vec<String>, paths: &mut Vec<Vec<String>>) {
    let mut path = prefix;
    let skip_space = |i: &mut usize| {
        while *i < chars.len() && chars[*i].is_whitespace() {
            *i += 1;
        }
    };
    loop {
        skip_space(i);
        match chars.get(*i) {
            None => break,
            Some('{') => {
                *i += 1;
                loop {
                    while *i < chars.len() && (chars[*i].is_whitespace() || chars[*i] == ',') {
                        *i += 1;
                    }
                    match chars.get(*i) {
                        None => return,
                        Some('}') => {
                            *i += 1;
                            return;
                        }
                        Some(_) => {
                            let before = *i;
                            read_use_tree(chars, i, path.clone(), paths);
                            if *i == before {
                                *i += 1;
                            }
                        }
                    }
                }
            }
            Some('*') => {
                *i += 1;
                break;
            }
            Some(_) => {}
        }
        let start = *i;
        while *i < chars.len() && is_word(chars[*i]) {
            *i += 1;
        }
        if start == *i {
            break;
        }
        let word: String = chars[start..*i].iter().collect();
        if word != "self" {
            path.push(word);
        }
        skip_space(i);
        if chars.get(*i) == Some(&':') && chars.get(*i + 1) == Some(&':') {
            *i += 2;
            continue;
        }
        // `NAME as ALIAS`: the alias names nothing in the crate.
        let rename = chars[*i..].starts_with(&['a', 's'])
            && chars.get(*i + 2).is_some_and(|c| c.is_whitespace());
        if rename {
            *i += 2;
            skip_space(i);
            while *i < chars.len() && is_word(chars[*i]) {
                *i += 1;
            }
        }
        break;
    }
    paths.push(path);
}

/// Every path a file's code names: use trees and `crate::`/`super::`/`self::` paths.
fn written_paths(text: &str) -> Vec<Vec<String>> {
    let chars: Vec<char> = code_only(text).chars().collect();
    let mut paths = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let starts_word = is_word(chars[i])
            && (i == 0 || !(is_word(chars[i - 1]) || chars[i - 1] == ':' || chars[i - 1] == '#'));
        if !starts_word {
            i += 1;
            continue;
        }
        let start = i;
        while i < chars.len() && is_word(chars[i]) {
            i += 1;
        }
        let word: String = chars[start..i].iter().collect();
        let followed_by_path = chars.get(i) == Some(&':') && chars.get(i + 1) == Some(&':');
        if word == "use" && chars.get(i).is_some_and(|c| c.is_whitespace()) {
            read_use_tree(&chars, &mut i, Vec::new(), &mut paths);
        } else if matches!(word.as_str(), "crate" | "super" | "self") && followed_by_path {
            let mut path = vec![word];
            while chars.get(i) == Some(&':') && chars.get(i + 1) == Some(&':') {
                i += 2;
                let segment_start = i;
                while i < chars.len() && is_word(chars[i]) {
                    i += 1;
                }
                if segment_start == i {
                    break;
                }
                path.push(chars[segment_start..i].iter().collect());
            }
            paths.push(path);
        }
    }
    paths
}

/// The crate-internal imports of a set of files (path under `src/`, text).
fn imports(files: &[(String, String)]) -> (BTreeSet<Vec<String>>, Vec<Import>) {
    let modules: BTreeSet<Vec<String>> = files.iter().map(|(path, _)| module_path(path)).collect();
    let mut found = Vec::new();
    for (path, text) in files {
        let here = module_path(path);
        for written in written_paths(text) {
            let mut segments = written.into_iter().peekable();
            let mut base = match segments.peek().map(String::as_str) {
                Some("crate") => {
                    segments.next();
                    Vec::new()
                }
                Some("super") => {
                    let mut base = here.clone();
                    while segments.peek().map(String::as_str) == Some("super") {
                        segments.next();
                        base.pop();
                    }
                    base
                }
                Some("self") => {
                    segments.next();
                    here.clone()
                }
                Some(first) => {
                    // `use child::Item` names a child module; anything else is another crate.
                    let mut child = here.clone();
                    child.push(first.to_string());
                    if !modules.contains(&child) {
                        continue;
                    }
                    here.clone()
                }
                None => continue,
            };
            let mut deepest = base.clone();
            for segment in segments {
                base.push(segment);
                if modules.contains(&base) {
                    deepest = base.clone();
                }
            }
            if !deepest.is_empty() && deepest != here {
                found.push(Import {
                    from: here.clone(),
                    to: deepest,
                    file: path.clone(),
                });
            }
        }
    }
    found.sort();
    found.dedup();
    (modules, found)
}

/// Imports that leave their layer for one the table does not allow, and modules in no layer.
fn layer_violations(modules: &BTreeSet<Vec<String>>, imports: &[Import]) -> Vec<String> {
    let allowed: BTreeMap<&str, &[&str]> = LAYERS.iter().copied().collect();
    let mut problems = Vec::new();
    let top_level: BTreeSet<&str> = modules
        .iter()
        .filter_map(|m| m.first().map(String::as_str))
        .collect();
    for layer in top_level {
        if !allowed.contains_key(layer) {
            problems.push(format!(
                "module `{layer}` is in no layer: add it to LAYERS in tests/integration/architecture.rs"
            ));
        }
    }
    for import in imports {
        let (from, to) = (import.from[0].as_str(), import.to[0].as_str());
        if from == to {
            continue;
        }
        if !allowed.get(from).is_some_and(|may| may.contains(&to)) {
            problems.push(format!(
                "{}: `{}` imports `{}`, but layer `{from}` may not import `{to}`",
                import.file,
                import.from.join("::"),
                import.to.join("::"),
            ));
        }
    }
    problems
}

/// The strongly connected groups of more than one node (Tarjan's algorithm).
fn circles(
    nodes: &BTreeSet<String>,
    edges: &BTreeMap<String, BTreeSet<String>>,
) -> Vec<Vec<String>> {
    struct Search<'a> {
        edges: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<String, usize>,
        low: BTreeMap<String, usize>,
        stack: Vec<String>,
        on_stack: BTreeSet<String>,
        found: Vec<Vec<String>>,
    }
    fn visit(node: &str, search: &mut Search) {
        let number = search.index.len();
        search.index.insert(node.to_string(), number);
        search.low.insert(node.to_string(), number);
        search.stack.push(node.to_string());
        search.on_stack.insert(node.to_string());
        let next: Vec<String> = search
            .edges
            .get(node)
            .into_iter()
            .flatten()
            .cloned()
            .collect();
        for other in next {
            if !search.index.contains_key(&other) {
                visit(&other, search);
                let low = search.low[node].min(search.low[&other]);
                search.low.insert(node.to_string(), low);
            } else if search.on_stack.contains(&other) {
                let low = search.low[node].min(search.index[&other]);
                search.low.insert(node.to_string(), low);
            }
        }
        if search.low[node] == search.index[node] {
            let mut group = Vec::new();
            while let Some(member) = search.stack.pop() {
                search.on_stack.remove(&member);
                let done = member == node;
                group.push(member);
                if done {
                    break;
                }
            }
            if group.len() > 1 {
                group.sort();
                search.found.push(group);
            }
        }
    }
    let mut search = Search {
        edges,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        found: Vec::new(),
    };
    for node in nodes {
        if !search.index.contains_key(node) {
            visit(node, &mut search);
        }
    }
    search.found
}

/// Circles between the direct children of every module (imports lifted to the children
/// they pass through), at every depth, and between layers.
fn sibling_circles(modules: &BTreeSet<Vec<String>>, imports: &[Import]) -> Vec<Vec<String>> {
    let mut parents: BTreeSet<Vec<String>> = BTreeSet::new();
    for module in modules {
        for depth in 0..module.len() {
            parents.insert(module[..depth].to_vec());
        }
    }
    let mut found = Vec::new();
    for parent in parents {
        let depth = parent.len();
        let under = |m: &Vec<String>| m.len() > depth && m[..depth] == parent[..];
        let child = |m: &Vec<String>| m[..=depth].join("::");
        let nodes: BTreeSet<String> = modules.iter().filter(|m| under(m)).map(child).collect();
        let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for import in imports {
            if under(&import.from) && under(&import.to) && import.from[depth] != import.to[depth] {
                edges
                    .entry(child(&import.from))
                    .or_default()
                    .insert(child(&import.to));
            }
        }
        found.extend(circles(&nodes, &edges));
    }
    found
}

/// The circles that [`ALLOWED_CIRCLES`] does not name, as messages naming the imports.
fn circle_violations(modules: &BTreeSet<Vec<String>>, imports: &[Import]) -> Vec<String> {
    sibling_circles(modules, imports)
        .into_iter()
        .filter(|circle| {
            !ALLOWED_CIRCLES.iter().any(|(allowed, _)| {
                allowed
                    .iter()
                    .copied()
                    .eq(circle.iter().map(String::as_str))
            })
        })
        .map(|circle| {
            let members: BTreeSet<&str> = circle.iter().map(String::as_str).collect();
            let inside =
                |m: &[String]| (1..=m.len()).any(|d| members.contains(m[..d].join("::").as_str()));
            let member_of = |m: &[String]| {
                (1..=m.len())
                    .map(|d| m[..d].join("::"))
                    .find(|name| members.contains(name.as_str()))
            };
            let mut through: Vec<String> = imports
                .iter()
                .filter(|i| {
                    inside(&i.from) && inside(&i.to) && member_of(&i.from) != member_of(&i.to)
                })
                .map(|i| {
                    format!(
                        "  {} ({}) -> {}",
                        i.from.join("::"),
                        i.file,
                        i.to.join("::")
                    )
                })
                .collect();
            through.dedup();
            format!(
                "import circle {}:\n{}",
                circle.join(" <-> "),
                through.join("\n")
            )
        })
        .collect()
}

/// Every `.rs` file under `dir` as (path relative to `src/`, text), sorted.
fn source_files(src: &Path, dir: &Path, files: &mut Vec<(String, String)>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .expect("src/ is readable")
        .map(|e| e.expect("directory entry").path())
        .collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            source_files(src, &path, files);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let relative = path
                .strip_prefix(src)
                .expect("under src")
                .to_string_lossy()
                .replace('\\', "/");
            if relative == "main.rs" || relative.starts_with("cli/") {
                continue;
            }
            let text = fs::read_to_string(&path).expect("source is UTF-8");
            files.push((relative, text));
        }
    }
}

fn crate_sources() -> Vec<(String, String)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    source_files(&src, &src, &mut files);
    files
}

#[test]
fn imports_run_down_the_layers_and_siblings_never_import_each_other_round_a_circle() {
    let files = crate_sources();
    let (modules, found) = imports(&files);
    // The reader must see the crate's imports at all (a broken reader passes nothing).
    assert!(found.len() > 500, "only {} imports read", found.len());
    let mut problems = layer_violations(&modules, &found);
    problems.extend(circle_violations(&modules, &found));
    let mut graph: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    for import in &found {
        if import.from[0] != import.to[0] {
            graph
                .entry(&import.from[0])
                .or_default()
                .insert(&import.to[0]);
        }
    }
    for (layer, uses) in &graph {
        println!(
            "{layer} -> {}",
            uses.iter().copied().collect::<Vec<_>>().join(", ")
        );
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn the_layer_table_names_only_lower_layers() {
    for (position, (layer, may_import)) in LAYERS.iter().enumerate() {
        for used in *may_import {
            let lower = LAYERS[..position].iter().any(|(name, _)| name == used);
            assert!(
                lower,
                "layer `{layer}` names `{used}`, which is not below it"
            );
        }
    }
}

#[test]
fn one_module_layout_style() {
    // `name/mod.rs` folders only: no `name.rs` beside a `name/` folder.
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut both = Vec::new();
    for (path, _) in crate_sources() {
        if let Some(stem) = path.strip_suffix(".rs") {
            if !stem.ends_with("mod") && src.join(stem).is_dir() {
                both.push(path);
            }
        }
    }
    assert!(
        both.is_empty(),
        "files beside a folder of the same name: {both:?}"
    );
}

fn files(list: &[(&str, &str)]) -> Vec<(String, String)> {
    list.iter()
        .map(|(path, text)| (path.to_string(), text.to_string()))
        .collect()
}

#[test]
fn an_upward_import_is_reported_with_its_file() {
    let tree = files(&[
        ("lib.rs", "pub mod scene; pub mod render;"),
        (
            "scene/mod.rs",
            "use crate::render::{camera::Ray, Image as Picture};",
        ),
        ("render/mod.rs", "pub mod camera; use crate::scene::Scene;"),
        ("render/camera.rs", ""),
    ]);
    let (modules, found) = imports(&tree);
    let problems = layer_violations(&modules, &found);
    assert_eq!(problems.len(), 2, "{problems:?}");
    let says = |text: &str| problems.iter().any(|p| p.contains(text));
    assert!(says(
        "scene/mod.rs: `scene` imports `render::camera`, but layer `scene` may not"
    ));
    assert!(says(
        "scene/mod.rs: `scene` imports `render`, but layer `scene` may not import `render`"
    ));
}

#[test]
fn a_module_outside_the_table_is_reported() {
    let tree = files(&[("lib.rs", "pub mod gadgets;"), ("gadgets.rs", "")]);
    let (modules, found) = imports(&tree);
    let problems = layer_violations(&modules, &found);
    assert!(
        problems[0].contains("module `gadgets` is in no layer"),
        "{problems:?}"
    );
}

#[test]
fn a_sibling_circle_is_reported_through_super_and_child_paths() {
    let tree = files(&[
        ("render/mod.rs", "mod lights; mod media;"),
        ("render/lights.rs", "use super::media::transmittance;"),
        (
            "render/media.rs",
            "fn f() { crate::render::lights::incoming(); }",
        ),
        ("render/camera.rs", "use super::lights;"),
    ]);
    let (modules, found) = imports(&tree);
    let problems = circle_violations(&modules, &found);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert!(problems[0].starts_with("import circle render::lights <-> render::media"));
    assert!(problems[0].contains("render::media (render/media.rs) -> render::lights"));
}

#[test]
fn comments_strings_and_other_crates_are_not_imports() {
    let tree = files(&[
        ("lib.rs", "pub mod scene; pub mod render;"),
        (
            "scene/mod.rs",
            "// use crate::render::X;\n/* crate::render::Y */\nconst S: &str = \"crate::render::Z\";\n\
             const R: &str = r#\"use crate::render;\"#;\nuse glam::DVec3;\nuse std::{fmt, rc::Rc};",
        ),
        ("render/mod.rs", ""),
    ]);
    let (_, found) = imports(&tree);
    assert!(found.is_empty(), "{found:?}");
}

#[test]
fn nested_use_groups_and_renames_are_read() {
    let paths = written_paths("use crate::{a::{b, c::D as E}, f::*, g::{self, H}};");
    let expected: Vec<Vec<String>> = [
        "crate a b",
        "crate a c D",
        "crate f",
        "crate g",
        "crate g H",
    ]
    .iter()
    .map(|p| p.split(' ').map(str::to_string).collect())
    .collect();
    assert_eq!(paths, expected);
}

#[test]
fn an_allowed_circle_passes_and_only_that_one() {
    let tree = files(&[
        ("texture/mod.rs", ""),
        (
            "texture/pattern.rs",
            "use super::function::F; use super::pigment::P;",
        ),
        ("texture/function.rs", "use super::pattern::Q;"),
        ("texture/pigment.rs", "use super::pattern::R;"),
    ]);
    let (modules, found) = imports(&tree);
    assert!(circle_violations(&modules, &found).is_empty());
    let tree = files(&[
        ("texture/mod.rs", ""),
        ("texture/pattern.rs", "use super::finish::F;"),
        ("texture/finish.rs", "use super::pattern::Q;"),
    ]);
    let (modules, found) = imports(&tree);
    assert_eq!(circle_violations(&modules, &found).len(), 1);
}
