//! `--lib DIR` (repeatable): subprograms in other files (issue 11, spec/dialects.md §3.6).
//!
//! The folders are listed once, up front (at most [`MAX_FILES`] entries each, else the run is
//! refused with the reason); files are read only when a call needs them. `O1234` is found
//! as a file named `O1234` / `O01234` with or without an NC extension (`.nc .cnc .tap .ngc
//! .iso .txt .gcode`, any case); failing that, as the file whose first program number is
//! 1234 (every other file is read once for that, at most [`MAX_SCAN_BYTES`] in all).
//!
//! A Haas `M98 (path)` names a file relative to the main program's folder
//! ([`Folders::home`]); a path that leaves it (absolute, a drive, `..`) is refused.
//!
//! Each file read gets a byte range of its own after the main file's (its spans are
//! shifted into it, `gcode::Program::shift_spans`), so a diagnostic or a segment made by a
//! subprogram names its own file and line: [`Folders::place`].

use crate::diag::Source;
use gcode::Program;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

/// The extensions of program files (see [`is_program_file`]).
const NC_EXTENSIONS: [&str; 7] = ["nc", "cnc", "tap", "ngc", "iso", "txt", "gcode"];
/// Most entries one `--lib` folder may hold: more is not a folder of subprograms.
const MAX_FILES: usize = 10_000;
/// Most bytes read in all to find programs by their first program number.
const MAX_SCAN_BYTES: u64 = 256 * 1024 * 1024;
/// Largest library file read, bytes (as for the main program).
const MAX_FILE_BYTES: u64 = 64 * 1024 * 1024;

/// The `--lib` folders of one run.
pub(crate) struct Folders {
    /// Program files, in folder order then name order.
    files: Vec<PathBuf>,
    /// The main program's folder, where `M98 (path)` looks.
    home: PathBuf,
    /// How the files are read: as the main program (macro B, decimal comma).
    read: gcode::ReadOptions,
    state: Mutex<State>,
}

#[derive(Default)]
struct State {
    /// Files read so far, with the byte offset their spans start at.
    read: Vec<(PathBuf, usize, Source, Arc<Program>)>,
    /// First program number → file, once built (the fallback lookup).
    by_first_number: Option<HashMap<u32, PathBuf>>,
    /// Where the next file's byte range starts.
    next_base: usize,
}

impl Folders {
    /// List the folders. `main_len`: the main file's length (library ranges start after it);
    /// `home`: the main program's folder.
    pub(crate) fn scan(
        dirs: &[PathBuf],
        home: &Path,
        main_len: usize,
        read: gcode::ReadOptions,
    ) -> Result<Self, String> {
        let mut files = vec![];
        for dir in dirs {
            let entries = std::fs::read_dir(dir)
                .map_err(|e| format!("cannot read --lib folder {}: {e}", dir.display()))?;
            let mut found = vec![];
            for (n, e) in entries.flatten().enumerate() {
                if n >= MAX_FILES {
                    return Err(format!(
                        "--lib folder {} holds more than {MAX_FILES} entries: not a folder of subprograms",
                        dir.display()
                    ));
                }
                let p = e.path();
                if p.is_file() && is_program_file(&p) {
                    found.push(p);
                }
            }
            found.sort();
            files.extend(found);
        }
        Ok(Self {
            files,
            home: home.to_path_buf(),
            read,
            state: Mutex::new(State {
                next_base: main_len + 1,
                ..State::default()
            }),
        })
    }

    /// The file and its 1-based line and column for a span's byte offset, when the offset
    /// lies in a library file (`None`: the main file).
    pub(crate) fn place(&self, offset: usize) -> Option<(Source, usize)> {
        let state = self.state.lock().ok()?;
        state
            .read
            .iter()
            .rev()
            .find(|(_, base, ..)| offset >= *base)
            .map(|(_, base, src, _)| {
                (
                    Source {
                        name: src.name.clone(),
                        text: src.text.clone(),
                    },
                    offset - base,
                )
            })
    }

    fn load(&self, state: &mut State, path: &Path) -> Result<Arc<Program>, String> {
        if let Some((.., p)) = state.read.iter().find(|(f, ..)| f == path) {
            return Ok(Arc::clone(p));
        }
        let text = read(path)?;
        let base = file_base(state.next_base, text.len()).ok_or_else(|| {
            format!(
                "{}: the main program and the --lib files read for it pass 4 GiB of text, more than one run reads",
                path.display()
            )
        })?;
        let text: Arc<str> = text.into();
        let mut program = gcode::parse_shared(Arc::clone(&text), self.read).map_err(|e| {
            format!(
                "{}:{}:{}: {}",
                path.display(),
                e.span.line,
                e.span.column,
                e.message
            )
        })?;
        program.shift_spans(base);
        state.next_base = base as usize + text.len() + 1;
        let program = Arc::new(program);
        let name = path.display().to_string();
        state.read.push((
            path.to_path_buf(),
            base as usize,
            Source { name, text },
            Arc::clone(&program),
        ));
        Ok(program)
    }

    /// First program number → file, for every file (read once).
    fn first_numbers(&self, state: &mut State) -> Result<(), String> {
        if state.by_first_number.is_some() {
            return Ok(());
        }
        let mut map = HashMap::new();
        let mut bytes = 0;
        for f in &self.files {
            bytes += std::fs::metadata(f).map(|m| m.len()).unwrap_or(0);
            if bytes > MAX_SCAN_BYTES {
                return Err(format!(
                    "the --lib folders hold more than {} MB of programs to search",
                    MAX_SCAN_BYTES / (1024 * 1024)
                ));
            }
            // A file that does not read or parse simply has no number here.
            if let Some(n) = read(f)
                .ok()
                .and_then(|t| gcode::parse_with(&t, self.read).ok())
                .and_then(|p| p.programs.iter().find_map(|s| s.number))
            {
                map.entry(n).or_insert_with(|| f.clone());
            }
        }
        state.by_first_number = Some(map);
        Ok(())
    }
}

impl expander::Library for Folders {
    fn find(&self, number: u32) -> Result<Option<Arc<Program>>, String> {
        let mut state = self
            .state
            .lock()
            .map_err(|_| "library lock poisoned".to_string())?;
        if let Some(f) = self
            .files
            .iter()
            .find(|f| number_in_name(f) == Some(number))
        {
            return self.load(&mut state, f).map(Some);
        }
        self.first_numbers(&mut state)?;
        let path = state
            .by_first_number
            .as_ref()
            .and_then(|m| m.get(&number))
            .cloned();
        match path {
            Some(f) => self.load(&mut state, &f).map(Some),
            None => Ok(None),
        }
    }

    fn has_folders(&self) -> bool {
        !self.files.is_empty()
    }

    fn file(&self, path: &str) -> Result<Arc<Program>, String> {
        let full = self.home.join(inside(path)?);
        if !full.is_file() {
            return Err(format!(
                "no file {} (the path is read from the main program's folder)",
                full.display()
            ));
        }
        let mut state = self
            .state
            .lock()
            .map_err(|_| "library lock poisoned".to_string())?;
        self.load(&mut state, &full)
    }
}

/// An `M98 (path)` as a path inside the main program's folder: `/` or `\` separate folders;
/// an empty path, an absolute one, a drive (`C:`) or a `..` is refused with the reason.
fn inside(path: &str) -> Result<PathBuf, String> {
    if path.is_empty() {
        return Err("the comment after M98 names no file".into());
    }
    if path.starts_with(['/', '\\']) || path.contains(':') {
        return Err("an absolute path: give the path from the main program's folder".into());
    }
    let mut rel = PathBuf::new();
    for part in path.split(['/', '\\']) {
        match part.trim() {
            "" | "." => {}
            ".." => {
                return Err("the path leaves the main program's folder ('..')".into());
            }
            p => rel.push(p),
        }
    }
    if rel.as_os_str().is_empty() {
        return Err("the comment after M98 names no file".into());
    }
    Ok(rel)
}

/// Where a file of `len` bytes starts in the run's byte range, if all of it stays within
/// `u32` (the offsets of [`gcode::Span`]).
fn file_base(next_base: usize, len: usize) -> Option<u32> {
    let base = u32::try_from(next_base).ok()?;
    base.checked_add(u32::try_from(len).ok()?)?;
    Some(base)
}

/// A program file by its name: an NC extension, or a program number (`O1234`, `O01234`,
/// with or without an NC extension: how DNC software and controls name their files).
pub(crate) fn is_program_file(p: &Path) -> bool {
    is_nc(p) || number_in_name(p).is_some()
}

fn is_nc(p: &Path) -> bool {
    p.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| NC_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
}

/// The program number a file name gives: `O1234`, `o01234.nc`, `O1234.TAP` → 1234.
fn number_in_name(p: &Path) -> Option<u32> {
    let name = p.file_name()?.to_str()?;
    let stem = match name.rsplit_once('.') {
        Some((stem, _)) if is_nc(p) => stem,
        Some(_) => return None,
        None => name,
    };
    let digits = stem.strip_prefix(['O', 'o'])?;
    if digits.is_empty() || digits.len() > 8 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    digits.parse().ok().filter(|&n| n > 0)
}

/// A library file's text (size-bounded, decoded like the main program).
fn read(path: &Path) -> Result<String, String> {
    let len = std::fs::metadata(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?
        .len();
    if len > MAX_FILE_BYTES {
        return Err(format!(
            "{} is larger than {} MB",
            path.display(),
            MAX_FILE_BYTES >> 20
        ));
    }
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    // decoded as the main program is (UTF-8, else the encoding detected)
    gcode::decode(&bytes, None).map(|d| d.text).map_err(|e| {
        format!(
            "{} is not a text NC file (byte {} is no {} character)",
            path.display(),
            e.offset,
            e.encoding.name()
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_ranges_stay_within_span_offsets() {
        assert_eq!(file_base(10, 5), Some(10));
        let max = u32::MAX as usize;
        assert_eq!(file_base(max - 5, 5), Some(u32::MAX - 5));
        assert_eq!(file_base(max - 5, 6), None);
        assert_eq!(file_base(max + 1, 0), None);
    }

    #[test]
    fn numbers_in_file_names() {
        for (name, n) in [
            ("O1234", Some(1234)),
            ("o01234.nc", Some(1234)),
            ("O1001.TAP", Some(1001)),
            ("O1234.pdf", None),
            ("part.nc", None),
            ("O0.nc", None),
            ("Oabc.nc", None),
        ] {
            assert_eq!(number_in_name(Path::new(name)), n, "{name}");
        }
    }

    #[test]
    fn m98_paths_stay_in_the_main_folder() {
        assert_eq!(inside("sub.nc"), Ok(PathBuf::from("sub.nc")));
        assert_eq!(
            inside("subs/O00101.nc"),
            Ok(PathBuf::from("subs/O00101.nc"))
        );
        assert_eq!(
            inside("subs\\./O00101.nc"),
            Ok(PathBuf::from("subs/O00101.nc"))
        );
        for bad in [
            "",
            "/etc/passwd",
            "\\x.nc",
            "C:/x.nc",
            "../x.nc",
            "a/../../x.nc",
            "./",
        ] {
            assert!(inside(bad).is_err(), "{bad}");
        }
    }
}
