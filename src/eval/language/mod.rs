//! The language runtime: values, scopes, item streams and directives, macros, expressions,
//! built-in functions, data files and the call trace.
//!
//! In: parsed items (from `syntax`). Out: values ([`value::Value`]) and a stream of items
//! with every directive run and macro expanded. Holds: knows nothing of cameras, lights or
//! objects except as values; a block expression becomes a value through the one hook
//! [`crate::eval::Evaluator::eval_block`], which scene assembly provides.

pub(crate) mod argument_directives;
pub(crate) mod builtins;
pub(crate) mod c_format;
pub(crate) mod datetime;
pub(crate) mod expr;
pub(crate) mod files;
pub(crate) mod function_compiler;
pub(crate) mod literals;
pub(crate) mod macros;
pub(crate) mod reading;
pub(crate) mod scopes;
pub(crate) mod splines;
pub mod standard_names;
pub(crate) mod stream;
pub(crate) mod token_macro;
pub(crate) mod value;

use super::{EvalOptions, EvalResult};
use crate::diag::{suggest_name, Diagnostic, FileId, SourceMap, Span, TraceEntry};
use crate::file_policy::{Access, FilePolicy, Reach, Refusal};
use crate::hash::FastHash;
use crate::syntax::ast::Item;
use crate::syntax::symbol::Symbol;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;
use std::sync::Arc;
use stream::Stream;
use value::Value;

/// durer's own small standard library, used when an include file is found nowhere else
/// (for example on a machine without POV-Ray installed).
pub(crate) const EMBEDDED_INCLUDES: &[(&str, &str)] = &[
    ("colors.inc", include_str!("stdlib/colors.inc")),
    ("consts.inc", include_str!("stdlib/consts.inc")),
    ("finish.inc", include_str!("stdlib/finish.inc")),
    ("glass.inc", include_str!("stdlib/glass.inc")),
    ("glass_old.inc", include_str!("stdlib/glass_old.inc")),
    ("golds.inc", include_str!("stdlib/golds.inc")),
    ("metals.inc", include_str!("stdlib/metals.inc")),
    ("skies.inc", include_str!("stdlib/skies.inc")),
    ("textures.inc", include_str!("stdlib/textures.inc")),
    ("woodmaps.inc", include_str!("stdlib/woodmaps.inc")),
    ("woods.inc", include_str!("stdlib/woods.inc")),
    ("stones.inc", include_str!("stdlib/stones.inc")),
    ("stones1.inc", include_str!("stdlib/stones1.inc")),
    ("stones2.inc", include_str!("stdlib/stones2.inc")),
    ("functions.inc", include_str!("stdlib/functions.inc")),
    ("math.inc", include_str!("stdlib/math.inc")),
    ("transforms.inc", include_str!("stdlib/transforms.inc")),
    ("strings.inc", include_str!("stdlib/strings.inc")),
    ("rand.inc", include_str!("stdlib/rand.inc")),
    ("arrays.inc", include_str!("stdlib/arrays.inc")),
    ("shapes.inc", include_str!("stdlib/shapes.inc")),
    ("shapes_old.inc", include_str!("stdlib/shapes_old.inc")),
    ("shapes2.inc", include_str!("stdlib/shapes2.inc")),
    ("shapesq.inc", include_str!("stdlib/shapesq.inc")),
    ("ior.inc", include_str!("stdlib/ior.inc")),
    ("debug.inc", include_str!("stdlib/debug.inc")),
    ("stdinc.inc", include_str!("stdlib/stdinc.inc")),
    ("stdcam.inc", include_str!("stdlib/stdcam.inc")),
    ("sunpos.inc", include_str!("stdlib/sunpos.inc")),
    ("screen.inc", include_str!("stdlib/screen.inc")),
    ("stage1.inc", include_str!("stdlib/stage1.inc")),
    ("stoneold.inc", include_str!("stdlib/stoneold.inc")),
    ("stars.inc", include_str!("stdlib/stars.inc")),
    ("rad_def.inc", include_str!("stdlib/rad_def.inc")),
    ("logo.inc", include_str!("stdlib/logo.inc")),
    ("chars.inc", include_str!("stdlib/chars.inc")),
    ("shapes3.inc", include_str!("stdlib/shapes3.inc")),
    ("makegrass.inc", include_str!("stdlib/makegrass.inc")),
    ("meshmaker.inc", include_str!("stdlib/meshmaker.inc")),
];

/// POV-Ray's include folders, searched after the scene's and `-L` ones.
const INSTALLED_INCLUDE_FOLDERS: [&str; 2] = [
    "/usr/share/povray-3.7/include",
    "/usr/local/share/povray-3.7/include",
];

/// A file not found on the search path: the folders searched, and the first candidate the
/// file policy refused.
#[derive(Debug, Default)]
pub(crate) struct Missing {
    pub(crate) searched: Vec<PathBuf>,
    pub(crate) refused: Option<Refusal>,
}

/// Folder name under which embedded include files appear in diagnostics.
pub(crate) const EMBEDDED_FOLDER: &str = "<durer standard library>";

/// What an entry of the live call trace entered.
#[derive(Clone, Debug)]
pub(crate) enum Entering {
    /// A call of the named macro.
    Macro(Symbol),
    /// An include of the named file.
    File(Rc<str>),
}

/// One entry of the live call trace: kept cheap (no text is formatted per macro call) and
/// turned into a [`TraceEntry`] only when a diagnostic needs it.
#[derive(Clone, Debug)]
pub(crate) struct Entered {
    pub(crate) what: Entering,
    /// Where it was entered from.
    pub(crate) span: Span,
}

impl Entered {
    pub(crate) fn to_trace(&self) -> TraceEntry {
        let what = match &self.what {
            Entering::Macro(name) => format!("macro `{name}`"),
            Entering::File(name) => format!("file `{name}`"),
        };
        TraceEntry {
            what,
            span: self.span,
        }
    }
}

/// One symbol table: the global one, an include file's or a macro call's.
pub(crate) type Scope = HashMap<Symbol, Value, FastHash>;

/// The language runtime's state: what a scene file's evaluation knows apart from the scene
/// it builds.
pub(crate) struct Runtime {
    /// Include paths, image size, clock and the other options from outside.
    options: EvalOptions,
    /// The text of every file read, for diagnostics.
    sources: SourceMap,
    /// The symbol tables: global, then one per include file and macro call.
    scopes: scopes::ScopeStack,
    /// Each file parsed once, by canonical path.
    parsed: HashMap<PathBuf, (FileId, Rc<[Item]>)>,
    /// The scene file's folder (first on the include path; data files live there).
    scene_folder: PathBuf,
    /// The scene file's name, for `input_file_name`.
    input_file_name: String,
    /// The live call trace: macro calls and includes entered, outermost first.
    trace: Vec<Entered>,
    /// Warnings so far, each distinct message once.
    warnings: Vec<Diagnostic>,
    warned_once: std::collections::HashSet<String>,
    /// Current depth of macro calls, includes and blocks (bounded by the `nesting` limit).
    nesting: usize,
    /// The `#version` in force.
    version: f64,
    /// Whether the scene declared a `#version` at all.
    version_declared: bool,
    /// States of the random streams made by `seed`, indexed by stream number.
    random_streams: Vec<u32>,
    /// Geometry prepared for `trace` and the extent functions, by object address.
    query_worlds: HashMap<usize, (Arc<crate::scene::Object>, Rc<crate::geometry::World>)>,
    /// Data files opened by `#fopen`; closed ones are `None`.
    files: Vec<Option<files::DataFile>>,
    /// Which files the scene may read and write: the options' policy with the scene's
    /// folders added (see `set_main_file`).
    policy: FilePolicy,
    /// Objects created so far, copies included (bounded by the `objects` limit).
    objects_created: u64,
    /// Bytes of mesh data read so far (bounded by the `geometry-memory` limit).
    geometry_bytes: u64,
    /// Text macro bodies parsed once for all calls (see `token_macro`).
    text_macro_cache: token_macro::TextMacroCache,
    /// Running calls with directives among their arguments (see `argument_directives`).
    directive_cursors: Vec<argument_directives::DirectiveCursor>,
    /// Files found on the search path or allowed as data files (images, fonts, density
    /// and `#fopen` files; sources are in `sources`), each once in the order first met
    /// (a scene probing one file in a loop adds it once); `durer watch` watches them.
    data_files_read: std::cell::RefCell<(Vec<PathBuf>, std::collections::HashSet<PathBuf>)>,
}

impl Runtime {
    /// A fresh runtime: empty global scope, nothing read yet, version 3.7.
    pub(crate) fn new(options: EvalOptions) -> Runtime {
        let policy = options.file_policy.clone();
        Runtime {
            data_files_read: Default::default(),
            policy,
            objects_created: 0,
            geometry_bytes: 0,
            options,
            sources: SourceMap::new(),
            scopes: scopes::ScopeStack::new(),
            parsed: HashMap::new(),
            scene_folder: PathBuf::from("."),
            input_file_name: String::new(),
            trace: Vec::new(),
            warnings: Vec::new(),
            warned_once: Default::default(),
            nesting: 0,
            version: 3.7,
            version_declared: false,
            random_streams: Vec::new(),
            query_worlds: HashMap::new(),
            files: Vec::new(),
            text_macro_cache: Default::default(),
            directive_cursors: Vec::new(),
        }
    }

    /// An error at `span` carrying the current macro/include trace.
    pub(crate) fn error(&self, span: Span, message: impl Into<String>) -> Diagnostic {
        let mut d = Diagnostic::error(span, message);
        d.trace = self.trace_for_diagnostic();
        d
    }

    /// Records a warning (each distinct message once).
    pub(crate) fn warn(&mut self, span: Span, message: impl Into<String>) {
        let message = message.into();
        if self.warned_once.insert(message.clone()) {
            let mut d = Diagnostic::warning(span, message);
            d.trace = self.trace_for_diagnostic();
            self.warnings.push(d);
        }
    }

    /// Drops the cached parse of a file the scene is rewriting, so that a later `#include` of
    /// it (strings.inc's `Parse_String`) reads the new text.
    pub(crate) fn forget_parsed(&mut self, path: &Path) {
        let key = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        self.parsed.remove(&key);
    }

    /// Reads and parses a file once; later loads reuse the AST.
    pub(crate) fn load_file(&mut self, path: &Path, from: Option<Span>) -> EvalResult<Rc<[Item]>> {
        let key = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        if let Some((_, items)) = self.parsed.get(&key) {
            return Ok(items.clone());
        }
        let (file, text) = self.read_source(path, from)?;
        let items = crate::syntax::parse(&text, file).map_err(|mut d| {
            d.trace = self.trace_for_diagnostic();
            d
        })?;
        self.parsed.insert(key, (file, items.clone()));
        Ok(items)
    }

    /// The options from outside the scene.
    pub(crate) fn options(&self) -> &EvalOptions {
        &self.options
    }

    /// Parses text that stands for a file of its own (the command line's declarations).
    pub(crate) fn parse_virtual_file(&mut self, name: &str, text: &str) -> EvalResult<Rc<[Item]>> {
        let text: Arc<str> = Arc::from(text);
        let file = self.sources.add(Path::new(name), text.clone());
        crate::syntax::parse(&text, file).map_err(|mut d| {
            d.trace = self.trace_for_diagnostic();
            d
        })
    }

    /// A file's bytes, refusing one larger than the `file-size` limit without reading past
    /// it: a scene cannot make durer load a huge file.
    pub(crate) fn read_file_bytes(&self, path: &Path) -> std::io::Result<Vec<u8>> {
        use std::io::Read;
        let limit = self.options.limits.file_size;
        let mut bytes = Vec::new();
        std::fs::File::open(path)?
            .take(limit.saturating_add(1))
            .read_to_end(&mut bytes)?;
        if bytes.len() as u64 > limit {
            return Err(std::io::Error::other(format!(
                "it is larger than {limit} bytes; {}",
                crate::limits::Limits::raise_hint("file-size", limit)
            )));
        }
        Ok(bytes)
    }

    /// Reads a file (or the embedded file standing for it) and adds it to the sources.
    pub(crate) fn read_source(
        &mut self,
        path: &Path,
        from: Option<Span>,
    ) -> EvalResult<(FileId, Arc<str>)> {
        let embedded = path
            .strip_prefix(EMBEDDED_FOLDER)
            .ok()
            .and_then(|name| EMBEDDED_INCLUDES.iter().find(|(n, _)| Path::new(n) == name))
            .map(|(_, text)| text.as_bytes().to_vec());
        let unsaved = self.options.main_text.clone().filter(|_| from.is_none());
        let bytes = match (unsaved, embedded) {
            (Some(text), _) => Ok(text.as_bytes().to_vec()),
            (None, Some(bytes)) => Ok(bytes),
            (None, None) => match self.policy.check(path, Access::Read) {
                Ok(resolved) => self.read_file_bytes(&resolved),
                Err(refusal) => {
                    let mut d = self.refused(from.unwrap_or_default(), &refusal);
                    if from.is_none() {
                        d.span = Span {
                            file: u32::MAX,
                            start: 0,
                            end: 0,
                        };
                    }
                    return Err(Box::new(d));
                }
            },
        };
        let bytes = bytes.map_err(|e| {
            let span = from.unwrap_or_default();
            let mut d = self
                .error(span, format!("cannot read `{}`: {e}", path.display()))
                .with_code("file-not-found");
            if from.is_none() {
                d.span = Span {
                    file: u32::MAX,
                    start: 0,
                    end: 0,
                };
            }
            Box::new(d)
        })?;
        let text: Arc<str> = Arc::from(String::from_utf8_lossy(&bytes).into_owned());
        let file = self.sources.add(path, text.clone());
        Ok((file, text))
    }

    /// Finds an include file: the scene's folder, `-L` folders, `DURER_INCLUDE_PATH`,
    /// then POV-Ray's installed include folder.
    /// Finds a file on the include search path, or reports `what` (such as "include file")
    /// as not found at `span` with `label`, listing the folders searched.
    pub(crate) fn find_file(
        &self,
        name: &str,
        span: Span,
        what: &str,
        label: &str,
    ) -> EvalResult<PathBuf> {
        self.find_include(name).map_err(|missing| {
            if let Some(refusal) = &missing.refused {
                return self.refused(span, refusal).into();
            }
            let searched: Vec<String> = missing
                .searched
                .iter()
                .map(|f| f.display().to_string())
                .collect();
            self.error(span, format!("cannot find {what} `{name}`"))
                .with_code("file-not-found")
                .with_label(label.to_string())
                .with_help(format!("searched: {}", searched.join(", ")))
                .into()
        })
    }

    /// The diagnostic for an access the file policy refuses.
    pub(crate) fn refused(&self, span: Span, refusal: &Refusal) -> Diagnostic {
        self.error(span, refusal.to_string())
            .with_label("refused by the file policy")
            .with_help(refusal.help())
    }

    /// Checks an access against the file policy; the resolved path is the one to open.
    pub(crate) fn check_access(
        &self,
        path: &Path,
        access: Access,
        span: Span,
    ) -> EvalResult<PathBuf> {
        let resolved = self
            .policy
            .check(path, access)
            .map_err(|refusal| self.refused(span, &refusal))?;
        if access == Access::Read {
            self.note_file_read(&resolved);
        }
        Ok(resolved)
    }

    /// Finds a file on the search path (the scene's folder, `-L` folders,
    /// `DURER_INCLUDE_PATH`, POV-Ray's installed include folder, durer's embedded standard
    /// library). A candidate the file policy refuses is not even probed; when nothing is
    /// found, the refusal is reported rather than "not found".
    pub(crate) fn find_include(&self, name: &str) -> Result<PathBuf, Missing> {
        let found = self.search_include(name);
        if let Ok(path) = &found {
            if !path.starts_with(EMBEDDED_FOLDER) {
                self.note_file_read(path);
            }
        }
        found
    }

    fn note_file_read(&self, path: &Path) {
        let mut files = self.data_files_read.borrow_mut();
        if files.1.insert(path.to_path_buf()) {
            files.0.push(path.to_path_buf());
        }
    }

    fn search_include(&self, name: &str) -> Result<PathBuf, Missing> {
        let direct = Path::new(name);
        if direct.is_absolute() {
            return match self.policy.check(direct, Access::Read) {
                Ok(_) if direct.is_file() => Ok(direct.to_path_buf()),
                Ok(_) => Err(Missing::default()),
                Err(refusal) => Err(Missing {
                    searched: vec![],
                    refused: Some(refusal),
                }),
            };
        }
        let folders = self.search_folders();
        let mut refused = None;
        for folder in &folders {
            let candidate = folder.join(name);
            match self.policy.check(&candidate, Access::Read) {
                Ok(_) if candidate.is_file() => return Ok(candidate),
                Ok(_) => {}
                Err(refusal) => {
                    refused.get_or_insert(refusal);
                }
            }
        }
        if EMBEDDED_INCLUDES.iter().any(|(n, _)| *n == name) {
            return Ok(Path::new(EMBEDDED_FOLDER).join(name));
        }
        Err(Missing {
            searched: folders,
            refused,
        })
    }

    /// The folders searched for include files, images and fonts, in order.
    fn search_folders(&self) -> Vec<PathBuf> {
        let mut folders = vec![self.scene_folder.clone()];
        folders.extend(self.options.include_paths.iter().cloned());
        if let Some(paths) = std::env::var_os("DURER_INCLUDE_PATH") {
            folders.extend(std::env::split_paths(&paths));
        }
        if self.options.search_installed_povray {
            for installed in INSTALLED_INCLUDE_FOLDERS {
                folders.push(PathBuf::from(installed));
            }
        }
        folders
    }

    /// The file `#include "name"` reads: the name as written, then, for a name without an
    /// extension, with `.inc` added, as povray tries (not `.pov`: measured).
    pub(crate) fn find_included(&self, name: &str, span: Span) -> EvalResult<PathBuf> {
        let found = self.find_file(name, span, "include file", "included here");
        match found {
            Err(error) if Path::new(name).extension().is_none() => {
                self.find_include(&format!("{name}.inc")).map_err(|_| error)
            }
            found => found,
        }
    }

    /// Runs `#include`: parses the file once and streams its items in a new local scope.
    pub(crate) fn include(
        &mut self,
        name: &str,
        span: Span,
        stream: &mut Stream,
    ) -> EvalResult<()> {
        let path = self.find_included(name, span)?;
        self.enter_nesting(span)?;
        self.trace.push(Entered {
            what: Entering::File(Rc::from(name)),
            span,
        });
        let items = match self.load_file(&path, Some(span)) {
            Ok(items) => items,
            Err(e) => {
                self.trace.pop();
                self.nesting -= 1;
                return Err(e);
            }
        };
        self.scopes.push(Scope::default());
        stream.push_include(items);
        Ok(())
    }

    /// Stops evaluation once the caller's deadline ([`EvalOptions::deadline`]) has passed:
    /// checked on every loop iteration, macro call and include.
    pub(crate) fn check_deadline(&self, span: Span) -> EvalResult<()> {
        match self.options.deadline {
            Some(deadline) if std::time::Instant::now() >= deadline => Err(self
                .error(span, "evaluation stopped: it ran past its time budget")
                .with_code("time-budget")
                .with_label("still running here")
                .with_help("a loop that never ends or a very long computation")
                .into()),
            _ => Ok(()),
        }
    }

    /// Counts `count` objects created (a shape, a CSG node, or every node of a copied
    /// tree); past the `objects` limit evaluation stops, before memory runs out.
    pub(crate) fn count_objects(&mut self, count: u64, span: Span) -> EvalResult<()> {
        self.objects_created = self.objects_created.saturating_add(count);
        let limit = self.options.limits.objects;
        if self.objects_created > limit {
            return Err(self
                .error(span, format!("the scene creates more than {limit} objects"))
                .with_label("this object is one too many")
                .with_help(format!(
                    "copies count too (`object {{ O }}` copies all of O); a loop that never \
                     ends can cause this; {}",
                    crate::limits::Limits::raise_hint("objects", limit)
                ))
                .into());
        }
        Ok(())
    }

    /// Counts `bytes` of mesh data (triangles, vertex, normal and uv vectors, face
    /// indices); past the `geometry-memory` limit evaluation stops before memory runs out.
    pub(crate) fn count_geometry(&mut self, bytes: u64, span: Span) -> EvalResult<()> {
        self.geometry_bytes = self.geometry_bytes.saturating_add(bytes);
        let limit = self.options.limits.geometry_memory;
        if self.geometry_bytes > limit {
            return Err(self
                .error(
                    span,
                    format!("the scene's meshes need more than {limit} bytes"),
                )
                .with_label("this mesh element is one too many")
                .with_help(format!(
                    "a loop generating triangles or vectors may not end; {}",
                    crate::limits::Limits::raise_hint("geometry-memory", limit)
                ))
                .into());
        }
        Ok(())
    }

    pub(crate) fn enter_nesting(&mut self, span: Span) -> EvalResult<()> {
        self.check_deadline(span)?;
        let limit = self.options.limits.nesting;
        if self.nesting as u64 >= limit {
            return Err(self
                .error(span, format!("nesting deeper than {limit} levels"))
                .with_label("this call, include or block goes too deep")
                .with_help(format!(
                    "a recursive macro probably never reaches its base case; {}",
                    crate::limits::Limits::raise_hint("nesting", limit)
                ))
                .into());
        }
        self.nesting += 1;
        Ok(())
    }

    /// The call trace for a diagnostic, innermost first.
    pub(crate) fn trace_for_diagnostic(&self) -> Vec<TraceEntry> {
        self.trace.iter().rev().map(Entered::to_trace).collect()
    }

    /// Looks an identifier up, innermost scope first, following references.
    #[inline]
    pub(crate) fn lookup(&self, name: Symbol) -> Option<&Value> {
        match self.scopes.innermost_binding(name)?.1 {
            Value::Reference { scope, name } => self.lookup_from(*scope, *name),
            other => Some(other),
        }
    }

    /// Looks an identifier up in scope `top` and the scopes outside it, following references.
    pub(crate) fn lookup_from(&self, top: usize, name: Symbol) -> Option<&Value> {
        let (mut top, mut name) = (top, name);
        loop {
            let (index, value) = self.scopes.binding_at_or_below(name, top)?;
            match value {
                Value::Reference {
                    scope,
                    name: target,
                } if *scope < index => {
                    top = *scope;
                    name = *target;
                }
                Value::Reference { .. } => return None,
                other => return Some(other),
            }
        }
    }

    /// Where `#declare name` writes: the innermost existing version (following references),
    /// or the global scope for a new name.
    pub(crate) fn declare_slot(&self, name: Symbol) -> (usize, Symbol) {
        self.slot_from(self.scopes.len() - 1, name)
    }

    /// Where `#local name` writes: the innermost scope, except that a macro parameter passed
    /// an identifier writes through to the caller's variable, as in POV-Ray.
    pub(crate) fn local_slot(&self, name: Symbol) -> (usize, Symbol) {
        let innermost = self.scopes.len() - 1;
        match self.scopes.get(innermost, name) {
            Some(Value::Reference {
                scope,
                name: target,
            }) if *scope < innermost => self.slot_from(*scope, *target),
            _ => (innermost, name),
        }
    }

    /// The innermost existing version of `name` in scope `top` or outside it, following
    /// references; the global scope when there is none.
    fn slot_from(&self, top: usize, name: Symbol) -> (usize, Symbol) {
        let mut top = top;
        let mut name = name;
        loop {
            match self.scopes.binding_at_or_below(name, top) {
                Some((i, value)) => match value {
                    Value::Reference {
                        scope,
                        name: target,
                    } if *scope < i => {
                        top = *scope;
                        name = *target;
                    }
                    _ => return (i, name),
                },
                None => return (0, name),
            }
        }
    }

    /// An "undefined identifier" error with a did-you-mean over visible names and keywords.
    pub(crate) fn undefined(&self, name: &str, span: Span) -> Diagnostic {
        let mut d = self
            .error(span, format!("undefined identifier `{name}`"))
            .with_label("not declared");
        if let Some(standard) = standard_names::standard_name(name) {
            return d.with_help(format!(
                "`{name}` is declared in the standard include file `{}`: add \
                 `#include \"{}\"` before using it",
                standard.file, standard.include
            ));
        }
        if builtins::FUNCTIONS.contains(&name) {
            return self
                .error(span, format!("`{name}` needs parentheses"))
                .with_label("a built-in function, called without `(`")
                .with_help(format!(
                    "built-in functions take their arguments in parentheses: `{name}(...)`"
                ));
        }
        let visible = self.scopes.names();
        let keywords = crate::syntax::keywords::ALL.iter().copied();
        if let Some(similar) = suggest_name(name, visible.chain(keywords)) {
            d = d.with_help(format!("did you mean `{similar}`?"));
        }
        d
    }

    pub(crate) fn set_version(&mut self, version: f64) {
        if !self.version_declared {
            self.version_declared = true;
        }
        self.version = version;
    }

    /// Records the scene file: its folder starts the include path, its name is
    /// `input_file_name`.
    pub(crate) fn set_main_file(&mut self, path: &Path) {
        self.scene_folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
        self.policy
            .allow(&self.scene_folder, true, Reach::Tree, "the scene's folder");
        if let Some(project) = crate::file_policy::project_folder(&self.scene_folder) {
            self.policy.allow(
                &project,
                false,
                Reach::Tree,
                "the scene's project: two folders up, read only",
            );
        }
        if let Some(output) = &self.options.output_folder {
            self.policy
                .allow(output, true, Reach::Tree, "the output image's folder");
        }
        for folder in &self.options.include_paths {
            self.policy.allow_library(folder, "an include folder");
        }
        if let Some(paths) = std::env::var_os("DURER_INCLUDE_PATH") {
            for folder in std::env::split_paths(&paths) {
                self.policy.allow_library(&folder, "DURER_INCLUDE_PATH");
            }
        }
        if self.options.search_installed_povray {
            for folder in INSTALLED_INCLUDE_FOLDERS {
                self.policy
                    .allow_library(Path::new(folder), "POV-Ray's include folder");
            }
        }
        if let Some(header) = &self.options.include_header {
            self.policy.allow(
                header,
                false,
                Reach::File,
                "the command line's Include_Header",
            );
        }
        self.input_file_name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
    }

    /// Finds an image file as POV-Ray does: the name as written, then, for a name without
    /// an extension, the name with each of the format's extensions (`png "wood"` reads
    /// `wood.png`). The error is the one for the name as written, naming what was tried.
    pub(crate) fn find_image(
        &self,
        name: &str,
        span: Span,
        what: &str,
        format: crate::raster::RasterFormat,
    ) -> EvalResult<PathBuf> {
        let found = self.find_file(name, span, what, "no such file");
        if found.is_ok() || Path::new(name).extension().is_some() {
            return found;
        }
        for extension in format.extensions() {
            if let Ok(path) = self.find_include(&format!("{name}.{extension}")) {
                return Ok(path);
            }
        }
        found.map_err(|mut error| {
            let tried: Vec<String> = format
                .extensions()
                .iter()
                .map(|e| format!("`{name}.{e}`"))
                .collect();
            error.help = Some(format!(
                "{}; also tried {}",
                error.help.take().unwrap_or_default(),
                tried.join(", ")
            ));
            error
        })
    }

    /// Leaves a level entered with [`Runtime::enter_nesting`].
    pub(crate) fn leave_nesting(&mut self) {
        self.nesting -= 1;
    }

    /// The `#version` in force, and whether the scene declared one.
    pub(crate) fn version(&self) -> (f64, bool) {
        (self.version, self.version_declared)
    }

    /// The warnings so far, handed over once evaluation ends.
    pub(crate) fn take_warnings(&mut self) -> Vec<Diagnostic> {
        std::mem::take(&mut self.warnings)
    }

    /// The text of every file read, for showing diagnostics.
    pub(crate) fn into_sources(self) -> SourceMap {
        self.sources
    }

    /// The files read so far: sources (not durer's embedded ones), then data files, each
    /// once.
    pub(crate) fn files_read(&self) -> Vec<PathBuf> {
        let mut seen = std::collections::HashSet::new();
        self.sources
            .paths()
            .filter(|p| !p.starts_with(EMBEDDED_FOLDER))
            .map(Path::to_path_buf)
            .chain(self.data_files_read.borrow().0.iter().cloned())
            .filter(|p| seen.insert(p.clone()))
            .collect()
    }
}
