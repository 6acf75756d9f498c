//! The file policy: which files a scene may read and write.
//!
//! Modelled on POV-Ray for Unix's I/O restrictions (`povray.conf`, manual section 1.4): a
//! security level (`none`, `read-only`, `restricted`) and a list of permitted folders, each
//! for reading or for reading and writing, with or without its subfolders (`read=DIR`,
//! `read*=DIR`, `read+write=DIR`, `read+write*=DIR`). Every way a scene touches a file asks
//! [`FilePolicy::check`] first: `#include`, `#fopen` (`read`, `write`, `append`), images,
//! fonts, density files, `file_exists`. The path is resolved before the check (symbolic
//! links followed and `..` removed, for a file that does not exist yet through its nearest
//! existing folder), so a link inside a permitted folder cannot lead outside it.
//!
//! durer's default (see `docs/limits.md`) is `restricted` with the scene's folder and the
//! output image's folder readable and writable (with subfolders) and the include folders
//! readable; `--allow-read`, `--allow-write` and `--file-policy FILE` (a `povray.conf`)
//! widen it. Unlike POV-Ray, durer does not read a `povray.conf` by itself, so a scene is
//! treated the same on every machine.

use std::fmt;
use std::path::{Component, Path, PathBuf};

/// POV-Ray's `[File I/O Security]` level.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Security {
    /// No restriction beyond the file system's.
    None,
    /// Any file may be read; writing needs a `read+write` folder.
    ReadOnly,
    /// Reading needs a permitted folder, writing a `read+write` one.
    Restricted,
}

impl Security {
    /// The word `povray.conf` uses.
    pub fn word(self) -> &'static str {
        match self {
            Security::None => "none",
            Security::ReadOnly => "read-only",
            Security::Restricted => "restricted",
        }
    }
}

/// What a scene wants to do with a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    Read,
    Write,
}

impl Access {
    fn word(self) -> &'static str {
        match self {
            Access::Read => "read",
            Access::Write => "write",
        }
    }
}

/// How far a grant reaches from its path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reach {
    /// The files directly in the folder (`read=DIR`).
    Folder,
    /// The folder and all its subfolders (`read*=DIR`).
    Tree,
    /// One file (the command line's `Include_Header`).
    File,
}

/// One permitted path.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Grant {
    /// The resolved path.
    pub path: PathBuf,
    /// Writing is allowed too.
    pub write: bool,
    pub reach: Reach,
    /// Where the grant comes from ("the scene's folder", "--allow-read", a conf file line).
    pub origin: String,
}

impl Grant {
    fn covers(&self, resolved: &Path) -> bool {
        match self.reach {
            Reach::Tree => resolved.starts_with(&self.path),
            Reach::Folder => resolved.parent() == Some(self.path.as_path()),
            Reach::File => resolved == self.path,
        }
    }
}

/// A refused access, for the diagnostic.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// The path as resolved (links followed).
    pub resolved: PathBuf,
    pub access: Access,
    /// The folders that would have allowed it, one line each.
    pub permitted: Vec<String>,
}

impl Refusal {
    /// The help text: what is permitted and how to widen it.
    pub fn help(&self) -> String {
        let flag = match self.access {
            Access::Read => "--allow-read",
            Access::Write => "--allow-write",
        };
        let mut text = format!(
            "the file policy lets scenes {} only in: {}",
            self.access.word(),
            if self.permitted.is_empty() {
                "(no folder)".to_string()
            } else {
                self.permitted.join(", ")
            }
        );
        text.push_str(&format!(
            "; to allow it give {flag} {} (or a povray.conf with --file-policy)",
            self.resolved.parent().unwrap_or(Path::new("/")).display()
        ));
        text
    }
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the file policy does not allow scenes to {} `{}`",
            self.access.word(),
            self.resolved.display()
        )
    }
}

/// The security level and the permitted paths.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FilePolicy {
    security: Security,
    grants: Vec<Grant>,
}

impl Default for FilePolicy {
    /// `restricted` with nothing permitted yet (the evaluator adds the scene's folders).
    fn default() -> Self {
        FilePolicy {
            security: Security::Restricted,
            grants: Vec::new(),
        }
    }
}

impl FilePolicy {
    /// A policy that allows everything the file system allows (POV-Ray's `none`).
    pub fn unrestricted() -> FilePolicy {
        FilePolicy {
            security: Security::None,
            grants: Vec::new(),
        }
    }

    pub fn security(&self) -> Security {
        self.security
    }

    pub fn set_security(&mut self, security: Security) {
        self.security = security;
    }

    pub fn grants(&self) -> &[Grant] {
        &self.grants
    }

    /// Permits `path` (resolved now) for reading, or reading and writing.
    pub fn allow(&mut self, path: &Path, write: bool, reach: Reach, origin: impl Into<String>) {
        let grant = Grant {
            path: resolve(path),
            write,
            reach,
            origin: origin.into(),
        };
        if !self.grants.contains(&grant) {
            self.grants.push(grant);
        }
    }

    /// Permits a library folder for reading (with subfolders) and the targets of the
    /// symbolic links directly in it: an installed include folder links its fonts from the
    /// system's font folder (`timrom.ttf -> ../../fonts/truetype/povray/timrom.ttf`). Only
    /// for read-only folders: a scene cannot create links there, while a link in a writable
    /// folder (the scene's) may have been planted to lead out, and is not trusted.
    pub fn allow_library(&mut self, folder: &Path, origin: &str) {
        self.allow(folder, false, Reach::Tree, origin);
        let Ok(entries) = std::fs::read_dir(folder) else {
            return;
        };
        for entry in entries.flatten() {
            let is_link = entry.file_type().is_ok_and(|t| t.is_symlink());
            if is_link {
                let target = resolve(&entry.path());
                if target.is_file() {
                    self.allow(&target, false, Reach::File, format!("a link in {origin}"));
                }
            }
        }
    }

    /// Checks an access; on success returns the resolved path, which is the one to open.
    pub fn check(&self, path: &Path, access: Access) -> Result<PathBuf, Refusal> {
        let resolved = resolve(path);
        let allowed = match (self.security, access) {
            (Security::None, _) | (Security::ReadOnly, Access::Read) => true,
            _ => self
                .grants
                .iter()
                .any(|g| (g.write || access == Access::Read) && g.covers(&resolved)),
        };
        if allowed {
            return Ok(resolved);
        }
        let permitted = self
            .grants
            .iter()
            .filter(|g| g.write || access == Access::Read)
            .map(|g| {
                let suffix = match g.reach {
                    Reach::Tree => " and its subfolders",
                    Reach::Folder | Reach::File => "",
                };
                format!("{}{suffix} ({})", g.path.display(), g.origin)
            })
            .collect();
        Err(Refusal {
            resolved,
            access,
            permitted,
        })
    }

    /// Whether `path` may be read.
    pub fn may_read(&self, path: &Path) -> bool {
        self.check(path, Access::Read).is_ok()
    }

    /// Reads a `povray.conf` (POV-Ray for Unix's format): its security level replaces this
    /// policy's and its permitted paths are added. Relative paths are resolved against
    /// `current_folder` (POV-Ray: the current folder), `%INSTALLDIR%` is `install_folder`
    /// and `%HOME%` is `home`. Errors name the line.
    pub fn read_conf(
        &mut self,
        text: &str,
        name: &str,
        current_folder: &Path,
        install_folder: &Path,
        home: Option<&Path>,
    ) -> Result<(), String> {
        let mut section = String::new();
        for (index, raw) in text.lines().enumerate() {
            let line_number = index + 1;
            let line = strip_comment(raw).trim();
            if line.is_empty() {
                continue;
            }
            let at = || format!("{name}:{line_number}");
            if let Some(rest) = line.strip_prefix('[') {
                let Some(title) = rest.strip_suffix(']') else {
                    return Err(format!("{}: a section title must end with `]`", at()));
                };
                section = title.trim().to_ascii_lowercase();
                continue;
            }
            match section.as_str() {
                "file i/o security" => {
                    self.security = match line.to_ascii_lowercase().as_str() {
                        "none" => Security::None,
                        "read-only" => Security::ReadOnly,
                        "restricted" => Security::Restricted,
                        other => {
                            return Err(format!(
                                "{}: expected `none`, `read-only` or `restricted`, found `{other}`",
                                at()
                            ))
                        }
                    }
                }
                // durer runs no shell commands; the section is accepted and has no effect.
                "shellout security" => {}
                "permitted paths" => {
                    let Some((key, value)) = line.split_once('=') else {
                        return Err(format!(
                            "{}: expected `read=DIR`, `read*=DIR`, `read+write=DIR` or \
                             `read+write*=DIR`",
                            at()
                        ));
                    };
                    let key = key.trim().to_ascii_lowercase();
                    let (write, reach) = match key.as_str() {
                        "read" => (false, Reach::Folder),
                        "read*" => (false, Reach::Tree),
                        "read+write" => (true, Reach::Folder),
                        "read+write*" => (true, Reach::Tree),
                        other => {
                            return Err(format!(
                                "{}: expected `read`, `read*`, `read+write` or `read+write*`, \
                                 found `{other}`",
                                at()
                            ))
                        }
                    };
                    let mut folder = unquote(value.trim()).to_string();
                    folder = folder.replace("%INSTALLDIR%", &install_folder.to_string_lossy());
                    if folder.contains("%HOME%") {
                        let Some(home) = home else {
                            return Err(format!("{}: %HOME% is not set", at()));
                        };
                        folder = folder.replace("%HOME%", &home.to_string_lossy());
                    }
                    let path = current_folder.join(folder);
                    self.allow(&path, write, reach, at());
                }
                "" => return Err(format!("{}: a setting before any [section]", at())),
                other => return Err(format!("{}: unknown section `[{other}]`", at())),
            }
        }
        Ok(())
    }
}

/// A conf line without its `;` comment (outside quotes).
fn strip_comment(line: &str) -> &str {
    let mut quote = None;
    for (i, c) in line.char_indices() {
        match (quote, c) {
            (None, '"' | '\'') => quote = Some(c),
            (Some(q), c) if c == q => quote = None,
            (None, ';') => return &line[..i],
            _ => {}
        }
    }
    line
}

fn unquote(text: &str) -> &str {
    for q in ['"', '\''] {
        if let Some(inner) = text.strip_prefix(q).and_then(|t| t.strip_suffix(q)) {
            return inner;
        }
    }
    text
}

/// How many folders above the scene's folder [`project_folder`] reaches.
pub const PROJECT_LEVELS: usize = 2;

/// The folder a scene may read as its project: [`PROJECT_LEVELS`] folders above the
/// scene's folder (resolved), but never a folder less than two names deep (never `/`,
/// `/home`, `/tmp`, `/usr`), so `/home/me/scene.pov` gets `/home/me` and
/// `/home/me/art/scenes/a/a.pov` gets `/home/me/art`. Published scenes share include files,
/// models and images between sibling folders (`#include "../matrices.inc"`,
/// `"../../models/orion_POV_geom.inc"`), which POV-Ray reads (its default `povray.conf`
/// permits reading all of `%HOME%`); `None` when the scene's folder is itself that shallow.
pub fn project_folder(scene_folder: &Path) -> Option<PathBuf> {
    let folder = resolve(scene_folder);
    let depth = folder
        .components()
        .filter(|c| matches!(c, Component::Normal(_)))
        .count();
    let levels = PROJECT_LEVELS.min(depth.saturating_sub(2));
    if levels == 0 {
        return None;
    }
    folder.ancestors().nth(levels).map(Path::to_path_buf)
}

/// The path with symbolic links followed and `.`/`..` removed. A path that does not exist
/// (a file about to be written) is resolved through its nearest existing ancestor, the rest
/// appended with `..` applied to the names.
pub fn resolve(path: &Path) -> PathBuf {
    let absolute = if path.is_absolute() {
        path.to_path_buf()
    } else {
        std::env::current_dir()
            .unwrap_or_else(|_| PathBuf::from("/"))
            .join(path)
    };
    if let Ok(canonical) = absolute.canonicalize() {
        return canonical;
    }
    let mut existing = absolute.as_path();
    let mut rest = Vec::new();
    while let Some(parent) = existing.parent() {
        if let Some(name) = existing.file_name() {
            rest.push(name.to_os_string());
        } else {
            // `..` or `.` as the last component: keep it for the lexical pass.
            rest.push(existing.components().next_back().map_or_else(
                || std::ffi::OsString::from("."),
                |c| c.as_os_str().to_os_string(),
            ));
        }
        existing = parent;
        if let Ok(canonical) = existing.canonicalize() {
            let mut out = canonical;
            for name in rest.iter().rev() {
                out.push(name);
            }
            return lexical(&out);
        }
    }
    lexical(&absolute)
}

/// `.` and `..` removed without touching the file system.
fn lexical(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for component in path.components() {
        match component {
            Component::ParentDir => {
                out.pop();
            }
            Component::CurDir => {}
            other => out.push(other.as_os_str()),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("durer-policy-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir.canonicalize().unwrap()
    }

    #[test]
    fn project_folder_is_two_levels_up_but_never_shallow() {
        let p = |s: &str| project_folder(Path::new(s)).map(|f| f.display().to_string());
        assert_eq!(
            p("/nonexistent-d/me/art/scenes/a").as_deref(),
            Some("/nonexistent-d/me/art")
        );
        assert_eq!(
            p("/nonexistent-d/me/art").as_deref(),
            Some("/nonexistent-d/me")
        );
        assert_eq!(p("/nonexistent-d/me"), None);
        assert_eq!(p("/nonexistent-d"), None);
        assert_eq!(p("/"), None);
    }

    #[test]
    fn restricted_policy_reads_and_writes_only_in_its_folders() {
        let dir = scratch("basic");
        std::fs::create_dir_all(dir.join("scene/sub")).unwrap();
        std::fs::create_dir_all(dir.join("lib")).unwrap();
        let mut policy = FilePolicy::default();
        policy.allow(&dir.join("scene"), true, Reach::Tree, "scene");
        policy.allow(&dir.join("lib"), false, Reach::Folder, "lib");
        assert!(policy.check(&dir.join("scene/a.inc"), Access::Read).is_ok());
        assert!(policy
            .check(&dir.join("scene/sub/a.txt"), Access::Write)
            .is_ok());
        assert!(policy.check(&dir.join("lib/x.inc"), Access::Read).is_ok());
        assert!(policy.check(&dir.join("lib/x.inc"), Access::Write).is_err());
        assert!(policy
            .check(&dir.join("lib/deeper/x.inc"), Access::Read)
            .is_err());
        assert!(policy
            .check(Path::new("/etc/passwd"), Access::Read)
            .is_err());
        // `..` cannot climb out.
        let climbing = dir.join("scene/../../../../etc/passwd");
        assert!(policy.check(&climbing, Access::Read).is_err());
        let new_climbing = dir.join("scene/nothing/../../outside.txt");
        assert!(policy.check(&new_climbing, Access::Write).is_err());
    }

    #[cfg(unix)]
    #[test]
    fn symbolic_links_are_followed_before_the_check() {
        let dir = scratch("links");
        std::fs::create_dir_all(dir.join("scene")).unwrap();
        std::fs::create_dir_all(dir.join("elsewhere")).unwrap();
        std::fs::write(dir.join("elsewhere/secret"), "s").unwrap();
        std::os::unix::fs::symlink(dir.join("elsewhere/secret"), dir.join("scene/link")).unwrap();
        std::os::unix::fs::symlink(dir.join("elsewhere"), dir.join("scene/folder")).unwrap();
        let mut policy = FilePolicy::default();
        policy.allow(&dir.join("scene"), true, Reach::Tree, "scene");
        let refused = policy
            .check(&dir.join("scene/link"), Access::Read)
            .unwrap_err();
        assert_eq!(refused.resolved, dir.join("elsewhere/secret"));
        assert!(policy
            .check(&dir.join("scene/folder/new"), Access::Write)
            .is_err());
        assert!(refused.help().contains("--allow-read"));
    }

    #[test]
    fn povray_conf_sets_the_level_and_the_folders() {
        let dir = scratch("conf");
        std::fs::create_dir_all(dir.join("install/include/sub")).unwrap();
        std::fs::create_dir_all(dir.join("home")).unwrap();
        std::fs::create_dir_all(dir.join("out")).unwrap();
        let conf = "; comment\n[File I/O Security]\nrestricted ; only these\n\
                    [Shellout Security]\nforbidden\n[Permitted Paths]\n\
                    read* = %INSTALLDIR%/include\nread = \"%HOME%\"\nread+write=out\n";
        let mut policy = FilePolicy::unrestricted();
        policy
            .read_conf(
                conf,
                "test.conf",
                &dir,
                &dir.join("install"),
                Some(&dir.join("home")),
            )
            .unwrap();
        assert_eq!(policy.security(), Security::Restricted);
        assert!(policy.may_read(&dir.join("install/include/sub/x.inc")));
        assert!(policy.may_read(&dir.join("home/x")));
        assert!(!policy.may_read(&dir.join("home/deeper/x")));
        assert!(policy.check(&dir.join("out/x"), Access::Write).is_ok());
        assert!(policy.check(&dir.join("home/x"), Access::Write).is_err());
        let mut read_only = FilePolicy::default();
        read_only
            .read_conf("[File I/O Security]\nread-only\n", "c", &dir, &dir, None)
            .unwrap();
        assert!(read_only.may_read(Path::new("/etc/hostname")));
        assert!(read_only.check(&dir.join("x"), Access::Write).is_err());
        let error = FilePolicy::default()
            .read_conf("[Permitted Paths]\nwrite=/tmp\n", "c", &dir, &dir, None)
            .unwrap_err();
        assert!(error.starts_with("c:2:"), "{error}");
    }
}
