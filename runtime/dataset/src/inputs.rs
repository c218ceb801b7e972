//! The logs a dataset is built from: files, folders (searched recursively), glob patterns and tar
//! archives (plain or gzipped), visited in one fixed order so that the same inputs always make
//! the same shards.

use std::io::Read;
use std::path::{Path, PathBuf};

use flate2::read::GzDecoder;
use rinshan_logs::tenhou::log::LOG_EXTENSIONS;

/// The most bytes one log may hold (as stored; `rinshan_logs` caps what a gzipped one unpacks
/// to): a hanchan is under 200 KB, so anything near this is not a log.
const MAX_LOG_BYTES: u64 = 64 << 20;

/// One place logs come from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Source {
    /// One log file.
    File(PathBuf),
    /// A tar archive of logs (`.tar`, `.tar.gz`, `.tgz`).
    Tar(PathBuf),
}

/// One log to read: its name (the path; `archive.tar:member` inside an archive) and where its
/// bytes are.
#[derive(Debug)]
pub struct Unit {
    /// The name the dataset's manifest and messages use.
    pub name: String,
    /// The bytes, or why they could not be had.
    pub body: Body,
}

/// Where a [`Unit`]'s bytes are.
#[derive(Debug)]
pub enum Body {
    /// A file, read when the unit is processed (in parallel).
    File(PathBuf),
    /// Bytes already read (an archive member: archives are read in order).
    Bytes(Vec<u8>),
    /// The input could not be read (a broken archive): the reason.
    Unreadable(String),
}

impl Unit {
    /// The log's bytes.
    pub fn bytes(&self) -> Result<std::borrow::Cow<'_, [u8]>, String> {
        match &self.body {
            Body::File(path) => {
                let file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", self.name))?;
                let mut out = Vec::new();
                file.take(MAX_LOG_BYTES + 1)
                    .read_to_end(&mut out)
                    .map_err(|e| format!("{}: {e}", self.name))?;
                if out.len() as u64 > MAX_LOG_BYTES {
                    return Err(format!("{}: larger than {} MiB", self.name, MAX_LOG_BYTES >> 20));
                }
                Ok(out.into())
            }
            Body::Bytes(b) => Ok(b.as_slice().into()),
            Body::Unreadable(reason) => Err(reason.clone()),
        }
    }
}

fn lower_name(path: &Path) -> String {
    path.file_name()
        .map(|n| n.to_string_lossy().to_lowercase())
        .unwrap_or_default()
}

/// The names of tar archives of logs (plain or gzipped).
pub const ARCHIVE_EXTENSIONS: [&str; 3] = [".tar", ".tar.gz", ".tgz"];

fn is_tar(path: &Path) -> bool {
    let name = lower_name(path);
    ARCHIVE_EXTENSIONS.iter().any(|e| name.ends_with(e))
}

fn is_log(name: &str) -> bool {
    let name = name.to_lowercase();
    LOG_EXTENSIONS.iter().any(|e| name.ends_with(e))
}

fn source_of(path: PathBuf) -> Source {
    if is_tar(&path) {
        Source::Tar(path)
    } else {
        Source::File(path)
    }
}

/// Log files and archives under `dir`, recursively, sorted by path.
fn walk(dir: &Path, out: &mut Vec<Source>) -> Result<(), String> {
    let io = |e: std::io::Error| format!("{}: {e}", dir.display());
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(io)?
        .map(|e| e.map(|e| e.path()))
        .collect::<Result<_, _>>()
        .map_err(io)?;
    entries.sort();
    for path in entries {
        if path.is_dir() {
            walk(&path, out)?;
        } else if is_tar(&path) || is_log(&lower_name(&path)) {
            out.push(source_of(path));
        }
    }
    Ok(())
}

/// The sources `inputs` name, in order: a file as given (a tar archive by its name), a folder's
/// log files and archives recursively sorted by path, a glob pattern's matches sorted.
pub fn sources(inputs: &[String]) -> Result<Vec<Source>, String> {
    let mut out = Vec::new();
    for input in inputs {
        let path = PathBuf::from(input);
        let mut paths = Vec::new();
        if path.exists() {
            paths.push(path);
        } else if input.contains(['*', '?', '[']) {
            let matches = glob::glob(input).map_err(|e| format!("{input}: not a glob pattern: {e}"))?;
            for m in matches {
                paths.push(m.map_err(|e| format!("{input}: {e}"))?);
            }
            if paths.is_empty() {
                return Err(format!("{input}: the pattern matches nothing"));
            }
            paths.sort();
        } else {
            return Err(format!("{input}: no such file or folder"));
        }
        for path in paths {
            if path.is_dir() {
                let before = out.len();
                walk(&path, &mut out)?;
                if out.len() == before {
                    return Err(format!(
                        "{}: the folder has no log files ({}, or tar archives)",
                        path.display(),
                        LOG_EXTENSIONS.join(", ")
                    ));
                }
            } else {
                out.push(source_of(path));
            }
        }
    }
    Ok(out)
}

/// The number of logs `sources` hold, when it is known without reading them (no archives).
pub fn count(sources: &[Source]) -> Option<u64> {
    sources
        .iter()
        .all(|s| matches!(s, Source::File(_)))
        .then_some(sources.len() as u64)
}

/// Calls `each` with every log of `sources` in order; archives are read here, member by member.
/// A broken archive gives one [`Body::Unreadable`] unit and its remaining members are not read.
pub fn for_each_unit(sources: &[Source], each: &mut dyn FnMut(Unit) -> Result<(), String>) -> Result<(), String> {
    for source in sources {
        match source {
            Source::File(path) => each(Unit {
                name: path.display().to_string(),
                body: Body::File(path.clone()),
            })?,
            Source::Tar(path) => read_tar(path, each)?,
        }
    }
    Ok(())
}

fn read_tar(path: &Path, each: &mut dyn FnMut(Unit) -> Result<(), String>) -> Result<(), String> {
    let name = path.display().to_string();
    let broken = |reason: String| Unit {
        name: name.clone(),
        body: Body::Unreadable(format!("{name}: {reason}")),
    };
    let file = match std::fs::File::open(path) {
        Ok(f) => f,
        Err(e) => return each(broken(e.to_string())),
    };
    let lower = lower_name(path);
    let reader: Box<dyn Read> = if lower.ends_with(".tar") {
        Box::new(std::io::BufReader::new(file))
    } else {
        Box::new(GzDecoder::new(std::io::BufReader::new(file)))
    };
    let mut archive = tar::Archive::new(reader);
    let entries = match archive.entries() {
        Ok(e) => e,
        Err(e) => return each(broken(format!("not a readable tar archive: {e}"))),
    };
    for (index, entry) in entries.enumerate() {
        let mut entry = match entry {
            Ok(e) => e,
            Err(e) => return each(broken(format!("entry {index}: not a readable tar entry: {e}"))),
        };
        if !entry.header().entry_type().is_file() {
            continue;
        }
        let member = match entry.path() {
            Ok(p) => p.display().to_string(),
            Err(e) => return each(broken(format!("entry {index}: unreadable name: {e}"))),
        };
        if !is_log(&member) {
            continue;
        }
        let unit_name = format!("{name}:{member}");
        let size = entry.size();
        let mut bytes = Vec::new();
        let body = match (&mut entry).take(MAX_LOG_BYTES + 1).read_to_end(&mut bytes) {
            Ok(_) if bytes.len() as u64 > MAX_LOG_BYTES => {
                Body::Unreadable(format!("{unit_name}: larger than {} MiB", MAX_LOG_BYTES >> 20))
            }
            // A member cut short reads as fewer bytes, not as an error.
            Ok(n) if (n as u64) < size => {
                return each(broken(format!(
                    "{member}: the archive breaks off ({n} of its {size} bytes)"
                )))
            }
            Ok(_) => Body::Bytes(bytes),
            Err(e) => return each(broken(format!("{member}: the archive breaks off: {e}"))),
        };
        each(Unit { name: unit_name, body })?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tar_of(members: &[(&str, &[u8])]) -> Vec<u8> {
        let mut builder = tar::Builder::new(Vec::new());
        for (name, bytes) in members {
            let mut header = tar::Header::new_gnu();
            header.set_size(bytes.len() as u64);
            header.set_mode(0o644);
            header.set_cksum();
            builder.append_data(&mut header, name, *bytes).unwrap();
        }
        builder.into_inner().unwrap()
    }

    fn names(sources: &[Source]) -> Vec<(String, Result<Vec<u8>, String>)> {
        let mut out = Vec::new();
        for_each_unit(sources, &mut |u| {
            out.push((u.name.clone(), u.bytes().map(|b| b.to_vec())));
            Ok(())
        })
        .unwrap();
        out
    }

    #[test]
    fn folders_globs_and_archives_are_visited_in_one_order() {
        let dir = std::env::temp_dir().join(format!("rinshan-inputs-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("b")).unwrap();
        std::fs::write(dir.join("b/2.json"), "x").unwrap();
        std::fs::write(dir.join("1.mjson"), "y").unwrap();
        std::fs::write(dir.join("notes.txt"), "z").unwrap();
        let tar = tar_of(&[("z/1.xml", b"<a/>"), ("readme", b"no"), ("z/0.json", b"j")]);
        std::fs::write(dir.join("a.tar"), &tar).unwrap();
        let folder = sources(&[dir.display().to_string()]).unwrap();
        let got: Vec<String> = names(&folder).into_iter().map(|(n, _)| n).collect();
        let d = dir.display();
        assert_eq!(
            got,
            vec![
                format!("{d}/1.mjson"),
                format!("{d}/a.tar:z/1.xml"),
                format!("{d}/a.tar:z/0.json"),
                format!("{d}/b/2.json"),
            ]
        );
        assert_eq!(count(&folder), None);
        let globbed = sources(&[format!("{d}/*.mjson"), format!("{d}/b/*")]).unwrap();
        assert_eq!(count(&globbed), Some(2));
        assert!(sources(&[format!("{d}/*.nothing")])
            .unwrap_err()
            .contains("matches nothing"));
        assert!(sources(&[format!("{d}/missing.json")])
            .unwrap_err()
            .contains("no such file"));
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn a_broken_archive_is_one_unreadable_input_after_its_good_members() {
        let dir = std::env::temp_dir().join(format!("rinshan-tar-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let mut tar = tar_of(&[("0.json", b"first"), ("1.json", &[7u8; 3000])]);
        tar.truncate(512 + 512 + 512 + 100);
        let path = dir.join("cut.tar");
        std::fs::write(&path, &tar).unwrap();
        let got = names(&[Source::Tar(path.clone())]);
        assert_eq!(got.len(), 2, "{got:?}");
        assert_eq!(got[0].1.as_deref().unwrap(), b"first");
        let reason = got[1].1.as_ref().unwrap_err();
        assert!(reason.contains("cut.tar") && reason.contains("1.json"), "{reason}");
        std::fs::write(&path, b"not a tar at all, but long enough to be read as a header?").unwrap();
        let got = names(&[Source::Tar(path)]);
        assert!(got.len() == 1 && got[0].1.is_err(), "{got:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
