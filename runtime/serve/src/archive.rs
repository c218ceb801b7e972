//! Finished games on disk: each game's Tenhou log is written to the data directory when the game
//! ends (to a temporary name, then renamed, so a crash leaves no half-written log), and the replay
//! page lists them after a restart. A kill loses at most the games still in play.

use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use serde::Serialize;

/// The folder of saved games (`<data dir>/games`).
#[derive(Debug, Clone)]
pub struct Archive {
    dir: PathBuf,
}

/// One saved game as the replay page lists it.
#[derive(Debug, Clone, Serialize, PartialEq, Eq)]
pub struct Saved {
    /// Its file name, which names it in `GET /api/saved/{name}`.
    pub name: String,
    /// Seconds since 1970 when it was written.
    pub written: u64,
    /// Size in bytes.
    pub bytes: u64,
}

/// A name the archive writes: `<seconds>-<game id>.json`, digits and one dash. Anything else
/// (a path, `..`) names no saved game.
fn is_saved_name(name: &str) -> bool {
    let Some(stem) = name.strip_suffix(".json") else {
        return false;
    };
    let mut parts = stem.split('-');
    let digits = |p: Option<&str>| p.is_some_and(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()));
    digits(parts.next()) && digits(parts.next()) && parts.next().is_none()
}

impl Archive {
    /// The archive in `data_dir` (its `games` folder is made when the first game is saved).
    pub fn new(data_dir: &Path) -> Archive {
        Archive {
            dir: data_dir.join("games"),
        }
    }

    /// Writes game `id`'s log; returns its name.
    pub fn save(&self, id: u64, log: &str) -> std::io::Result<String> {
        std::fs::create_dir_all(&self.dir)?;
        let now = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
        let name = format!("{now}-{id}.json");
        let tmp = self.dir.join(format!(".{name}.tmp"));
        std::fs::write(&tmp, log)?;
        std::fs::rename(&tmp, self.dir.join(&name))?;
        Ok(name)
    }

    /// The saved games, newest first.
    pub fn list(&self) -> Vec<Saved> {
        let Ok(entries) = std::fs::read_dir(&self.dir) else {
            return Vec::new();
        };
        let mut out: Vec<Saved> = entries
            .flatten()
            .filter_map(|e| {
                let name = e.file_name().into_string().ok().filter(|n| is_saved_name(n))?;
                let meta = e.metadata().ok()?;
                let written = meta.modified().ok()?.duration_since(UNIX_EPOCH).ok()?.as_secs();
                Some(Saved {
                    name,
                    written,
                    bytes: meta.len(),
                })
            })
            .collect();
        out.sort_by(|a, b| (b.written, &b.name).cmp(&(a.written, &a.name)));
        out
    }

    /// The log of the saved game `name`, if there is one.
    pub fn read(&self, name: &str) -> Option<String> {
        if !is_saved_name(name) {
            return None;
        }
        std::fs::read_to_string(self.dir.join(name)).ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_names_it_writes_are_read() {
        for good in ["1700000000-42.json", "0-0.json"] {
            assert!(is_saved_name(good), "{good}");
        }
        for bad in [
            "../x.json",
            "1-2",
            "1-2.txt",
            "a-2.json",
            "1-2-3.json",
            "-2.json",
            "/etc/passwd",
            ".1-2.json.tmp",
        ] {
            assert!(!is_saved_name(bad), "{bad}");
        }
    }

    #[test]
    fn saved_games_are_listed_and_read_back() {
        let dir = std::env::temp_dir().join(format!("rinshan-archive-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let a = Archive::new(&dir);
        assert!(a.list().is_empty(), "no folder yet: nothing saved");
        let name = a.save(7, "{\"log\": []}").expect("saved");
        assert_eq!(a.read(&name).as_deref(), Some("{\"log\": []}"));
        let listed = a.list();
        assert_eq!(listed.len(), 1);
        assert_eq!((listed[0].name.as_str(), listed[0].bytes), (name.as_str(), 11));
        // A fresh archive over the same folder (a restarted server) sees it too.
        assert_eq!(Archive::new(&dir).list(), listed);
        assert_eq!(a.read("../games/x.json"), None);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
