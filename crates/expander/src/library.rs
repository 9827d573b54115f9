//! Subprograms that live outside the main program's file (`--lib DIR`, spec/dialects.md §3.6,
//! issue 11). The interpreter asks a [`Library`] for an O number it does not find in the
//! file, and for the file a Haas `M98 (path)` names; the CLI implements it over folders. The programs it hands back keep the spans of
//! their own file (the CLI places each file's byte offsets in a range of its own, so a
//! diagnostic or a segment in a subprogram points at that file's line).

use std::sync::Arc;

/// Programs found by number outside the main file.
pub trait Library: Send + Sync {
    /// The parsed file that holds `O<number>`; `Ok(None)` when no library has it, `Err` with
    /// the reason when the file that should hold it cannot be read or parsed.
    fn find(&self, number: u32) -> Result<Option<Arc<gcode::Program>>, String>;

    /// Whether [`Library::find`] searches any folder (`--lib` given); `false` for a library
    /// that only resolves paths.
    fn has_folders(&self) -> bool {
        true
    }

    /// The parsed file a Haas `M98 (path)` names, relative to the main program's folder;
    /// `Err` with the reason when the path leaves that folder or the file cannot be read
    /// or parsed.
    fn file(&self, path: &str) -> Result<Arc<gcode::Program>, String> {
        Err(format!("no folder to look for {path} in"))
    }
}

/// A shared [`Library`] in the interpreter's options (compared by identity).
#[derive(Clone)]
pub struct LibraryRef(pub Arc<dyn Library>);

impl std::fmt::Debug for LibraryRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("LibraryRef(..)")
    }
}

impl PartialEq for LibraryRef {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}
