//! Outputs are written whole or not at all, and never over a file that is not ours.
//!
//! Every report of a run is first written to an unnamed file in its target folder
//! (`O_TMPFILE`: a killed process leaves nothing behind) and flushed to disk; only when all
//! of them are written are they linked under a temporary name and renamed into place, one
//! after the other, and the folder is synced. A failure before that point leaves every old
//! report untouched. Where the file system has no unnamed files, a named temporary file in
//! the same folder (removed on failure) takes its place.

use rustix::fs::{AtFlags, Mode, OFlags, CWD};
use std::fs::File;
use std::io::Write;
use std::os::fd::AsFd;
use std::path::{Path, PathBuf};

/// A report written to disk but not yet visible under its name.
#[derive(Debug)]
pub(crate) struct Staged {
    target: PathBuf,
    body: Body,
}

#[derive(Debug)]
enum Body {
    /// An `O_TMPFILE` file, linked at commit time.
    Unnamed(File),
    /// A named temporary file (file systems without `O_TMPFILE`).
    Named(tempfile::NamedTempFile),
}

/// Why `path` may not be written: it is one of the `inputs`, or exists and is not a
/// regular file (a FIFO, device, folder or symbolic link is never replaced).
fn refuse(path: &Path, inputs: &[PathBuf]) -> Option<String> {
    let meta = std::fs::symlink_metadata(path).ok()?;
    let kind = meta.file_type();
    if kind.is_symlink() {
        return Some(format!(
            "{} is a symbolic link: latsim does not write through links",
            path.display()
        ));
    }
    if !kind.is_file() {
        return Some(format!(
            "{} exists and is not a regular file (a folder, FIFO or device)",
            path.display()
        ));
    }
    let canon = |p: &Path| std::fs::canonicalize(p).ok();
    let target = canon(path);
    inputs
        .iter()
        .any(|i| canon(i).is_some() && canon(i) == target)
        .then(|| format!("refusing to overwrite the input file {}", path.display()))
}

fn folder_of(path: &Path) -> PathBuf {
    match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Write `bytes` for `path` to disk without making them visible yet.
pub(crate) fn stage(path: &Path, bytes: &[u8], inputs: &[PathBuf]) -> Result<Staged, String> {
    if let Some(why) = refuse(path, inputs) {
        return Err(why);
    }
    let dir = folder_of(path);
    std::fs::create_dir_all(&dir)
        .map_err(|e| format!("cannot create folder {}: {e}", dir.display()))?;
    let failed = |e: std::io::Error| format!("cannot write {}: {e}", path.display());
    let unnamed = rustix::fs::openat(
        CWD,
        &dir,
        OFlags::TMPFILE | OFlags::WRONLY | OFlags::CLOEXEC,
        Mode::from_raw_mode(0o644),
    );
    let body = match unnamed {
        Ok(fd) => {
            let mut file = File::from(fd);
            file.write_all(bytes)
                .and_then(|()| file.sync_all())
                .map_err(failed)?;
            Body::Unnamed(file)
        }
        Err(_) => {
            let mut tmp = tempfile::Builder::new()
                .prefix(".latsim-")
                .tempfile_in(&dir)
                .map_err(|e| format!("cannot write in {}: {e}", dir.display()))?;
            tmp.write_all(bytes)
                .and_then(|()| tmp.as_file().sync_all())
                .map_err(failed)?;
            // A temporary file is private (0600); a report is an ordinary file.
            use std::os::unix::fs::PermissionsExt;
            tmp.as_file()
                .set_permissions(std::fs::Permissions::from_mode(0o644))
                .map_err(failed)?;
            Body::Named(tmp)
        }
    };
    Ok(Staged {
        target: path.to_path_buf(),
        body,
    })
}

/// Make staged reports visible under their names, then sync their folders.
pub(crate) fn commit(staged: Vec<Staged>) -> Result<(), String> {
    let mut folders: Vec<PathBuf> = vec![];
    for s in staged {
        let path = &s.target;
        let failed = |e: &dyn std::fmt::Display| format!("cannot write {}: {e}", path.display());
        let dir = folder_of(path);
        match s.body {
            Body::Unnamed(file) => {
                let name = path
                    .file_name()
                    .map_or_else(|| "report".into(), |n| n.to_string_lossy().into_owned());
                let tmp = dir.join(format!(".{name}.latsim-{}", std::process::id()));
                let _ = std::fs::remove_file(&tmp);
                let proc_path = format!("/proc/self/fd/{}", {
                    use std::os::fd::AsRawFd;
                    file.as_fd().as_raw_fd()
                });
                rustix::fs::linkat(CWD, proc_path.as_str(), CWD, &tmp, AtFlags::SYMLINK_FOLLOW)
                    .map_err(|e| failed(&e))?;
                if let Err(e) = std::fs::rename(&tmp, path) {
                    let _ = std::fs::remove_file(&tmp);
                    return Err(failed(&e));
                }
            }
            Body::Named(tmp) => {
                tmp.persist(path).map_err(|e| failed(&e.error))?;
            }
        }
        if !folders.contains(&dir) {
            folders.push(dir);
        }
    }
    for dir in folders {
        if let Ok(d) = File::open(&dir) {
            let _ = d.sync_all();
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reports_appear_only_at_commit_and_leave_nothing_else() {
        let dir = tempfile::tempdir().unwrap();
        let a = dir.path().join("a.json");
        let b = dir.path().join("a.svg");
        std::fs::write(&a, "old").unwrap();
        let staged = vec![
            stage(&a, b"new", &[]).unwrap(),
            stage(&b, b"<svg/>", &[]).unwrap(),
        ];
        assert_eq!(std::fs::read_to_string(&a).unwrap(), "old");
        assert!(!b.exists());
        commit(staged).unwrap();
        assert_eq!(std::fs::read_to_string(&a).unwrap(), "new");
        assert_eq!(std::fs::read_to_string(&b).unwrap(), "<svg/>");
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().flatten().collect();
        assert_eq!(names.len(), 2);
    }

    #[test]
    fn links_fifos_folders_and_inputs_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.json");
        std::fs::write(&real, "x").unwrap();
        let link = dir.path().join("link.json");
        std::os::unix::fs::symlink(&real, &link).unwrap();
        assert!(stage(&link, b"y", &[])
            .unwrap_err()
            .contains("symbolic link"));
        assert!(stage(dir.path(), b"y", &[])
            .unwrap_err()
            .contains("not a regular file"));
        assert!(stage(&real, b"y", std::slice::from_ref(&real))
            .unwrap_err()
            .contains("input"));
        assert!(stage(Path::new("/dev/null"), b"y", &[]).is_err());
        assert_eq!(std::fs::read_to_string(&real).unwrap(), "x");
    }
}
