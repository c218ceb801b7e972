//! Finished games on disk: each game's Tenhou log is written to the data directory when the game
//! ends (to a temporary name, then renamed, so a crash leaves no half-written log), and the replay
//! page lists them after a restart. A kill loses at most the games still in play. The folder is
//! kept within a count and a size (the oldest go first), and one network may have only so many
//! games saved an hour. A saved game's name is its time and a random number of its own: it is no
//! handle to the game while the server still holds it.

use std::collections::{HashMap, VecDeque};
use std::net::IpAddr;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

use serde::Serialize;

use super::store::Limits;

/// The folder of saved games (`<data dir>/games`).
#[derive(Debug, Clone)]
pub struct Archive {
    dir: PathBuf,
    budget: Budget,
    kept: Arc<Mutex<Option<Kept>>>,
}

/// How much the folder may hold, and how fast one network may add to it.
#[derive(Debug, Clone, Copy)]
struct Budget {
    games: usize,
    bytes: u64,
    per_network_hour: usize,
}

/// What the folder holds, oldest first (read from the folder at the first use), and when each
/// network last saved.
#[derive(Debug, Default)]
struct Kept {
    games: VecDeque<Saved>,
    bytes: u64,
    saves: HashMap<IpAddr, VecDeque<Instant>>,
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

/// A name the archive writes: `<seconds>-<number>.json`, digits and one dash. Anything else
/// (a path, `..`) names no saved game.
fn is_saved_name(name: &str) -> bool {
    let Some(stem) = name.strip_suffix(".json") else {
        return false;
    };
    let mut parts = stem.split('-');
    let digits = |p: Option<&str>| p.is_some_and(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()));
    digits(parts.next()) && digits(parts.next()) && parts.next().is_none()
}

const HOUR: Duration = Duration::from_secs(3600);

impl Archive {
    /// The archive in `data_dir` (its `games` folder is made when the first game is saved), kept
    /// within `limits`' budget.
    pub fn new(data_dir: &Path, limits: &Limits) -> Archive {
        Archive {
            dir: data_dir.join("games"),
            budget: Budget {
                games: limits.saved_games.max(1),
                bytes: limits.saved_bytes,
                per_network_hour: limits.saves_per_network_hour,
            },
            kept: Arc::default(),
        }
    }

    fn kept(&self) -> MutexGuard<'_, Option<Kept>> {
        let mut kept = self.kept.lock().unwrap_or_else(|p| p.into_inner());
        if kept.is_none() {
            let games: VecDeque<Saved> = self.scan().into_iter().rev().collect();
            let bytes = games.iter().map(|g| g.bytes).sum();
            *kept = Some(Kept {
                games,
                bytes,
                saves: HashMap::new(),
            });
        }
        kept
    }

    /// Writes a log for a game played from `network`; returns its name. Refused once that
    /// network has saved its share this hour; the oldest games are deleted past the budget.
    pub fn save(&self, network: IpAddr, log: &str) -> std::io::Result<String> {
        {
            let mut guard = self.kept();
            let kept = guard.get_or_insert_with(Kept::default);
            let now = Instant::now();
            kept.saves.retain(|_, times| {
                while times.front().is_some_and(|t| now.duration_since(*t) >= HOUR) {
                    times.pop_front();
                }
                !times.is_empty()
            });
            let times = kept.saves.entry(network).or_default();
            if times.len() >= self.budget.per_network_hour {
                return Err(std::io::Error::other(format!(
                    "your network saved {} games in the last hour, as many as it may",
                    times.len()
                )));
            }
            times.push_back(now);
        }
        std::fs::create_dir_all(&self.dir)?;
        let secs = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
        let number = getrandom::u64().map_err(|e| std::io::Error::other(e.to_string()))? >> 11;
        let name = format!("{secs}-{number}.json");
        let tmp = self.dir.join(format!(".{name}.tmp"));
        std::fs::write(&tmp, log)?;
        let path = self.dir.join(&name);
        std::fs::rename(&tmp, &path)?;
        // The listing after a restart reads the file's time: the index holds the same.
        let written = std::fs::metadata(&path)
            .and_then(|m| m.modified())
            .ok()
            .and_then(|t| t.duration_since(UNIX_EPOCH).ok())
            .map_or(secs, |d| d.as_secs());
        let mut guard = self.kept();
        let kept = guard.get_or_insert_with(Kept::default);
        kept.bytes += log.len() as u64;
        kept.games.push_back(Saved {
            name: name.clone(),
            written,
            bytes: log.len() as u64,
        });
        while kept.games.len() > 1 && (kept.games.len() > self.budget.games || kept.bytes > self.budget.bytes) {
            let Some(old) = kept.games.pop_front() else { break };
            kept.bytes -= old.bytes;
            // Already gone (someone cleaned the folder) is as good as deleted.
            let _ = std::fs::remove_file(self.dir.join(&old.name));
        }
        Ok(name)
    }

    /// The saved games in the folder, newest first.
    fn scan(&self) -> Vec<Saved> {
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

    /// The saved games, newest first.
    pub fn list(&self) -> Vec<Saved> {
        let guard = self.kept();
        guard
            .as_ref()
            .map_or_else(Vec::new, |k| k.games.iter().rev().cloned().collect())
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

    fn folder(what: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rinshan-archive-{what}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    const HOME: IpAddr = IpAddr::V4(std::net::Ipv4Addr::LOCALHOST);

    #[test]
    fn saved_games_are_listed_and_read_back() {
        let dir = folder("list");
        let a = Archive::new(&dir, &Limits::default());
        assert!(a.list().is_empty(), "no folder yet: nothing saved");
        let name = a.save(HOME, "{\"log\": []}").expect("saved");
        assert_eq!(a.read(&name).as_deref(), Some("{\"log\": []}"));
        let listed = a.list();
        assert_eq!(listed.len(), 1);
        assert_eq!((listed[0].name.as_str(), listed[0].bytes), (name.as_str(), 11));
        // A fresh archive over the same folder (a restarted server) sees it too.
        assert_eq!(Archive::new(&dir, &Limits::default()).list(), listed);
        assert_eq!(a.read("../games/x.json"), None);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn the_folder_keeps_its_budget_and_each_network_its_share() {
        let dir = folder("budget");
        let limits = Limits {
            saved_games: 3,
            saved_bytes: 1000,
            saves_per_network_hour: 5,
            ..Limits::default()
        };
        let a = Archive::new(&dir, &limits);
        let names: Vec<String> = (0..5)
            .map(|k| a.save(HOME, &format!("{{\"game\": {k}}}")).expect("saved"))
            .collect();
        // The two oldest went, from the folder too.
        let listed: Vec<String> = a.list().into_iter().map(|s| s.name).collect();
        assert_eq!(listed.len(), 3);
        for old in &names[..2] {
            assert!(!listed.contains(old) && a.read(old).is_none(), "{old} was kept");
        }
        assert_eq!(std::fs::read_dir(dir.join("games")).expect("a folder").count(), 3);
        // The network has had its five this hour; another network has not.
        let refused = a.save(HOME, "{}").expect_err("past the share");
        assert!(refused.to_string().contains("5 games in the last hour"), "{refused}");
        a.save("10.9.9.9".parse().expect("an address"), "{}")
            .expect("another network");
        // Past the size, the oldest go however few there are.
        let big = a
            .save("10.9.8.9".parse().expect("an address"), &"x".repeat(999))
            .expect("saved");
        assert_eq!(a.list().into_iter().map(|s| s.name).collect::<Vec<_>>(), vec![big]);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
