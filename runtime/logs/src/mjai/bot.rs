//! An MJAI bot run as a child process, spoken to over its stdin and stdout in one of the two
//! dialects in use:
//!
//! * [`Dialect::App`] (mjai.app's): each line sent is a JSON array of every event since the last
//!   one, and the bot answers each line with exactly one reaction object (`none` to `start_game`,
//!   `end_kyoku` and `end_game`);
//! * [`Dialect::Stdio`] (Mortal's and mjai-manue's): one event per line, and a reaction only when
//!   the bot can act. Events the seat is only told carry `"can_act": false` (Mortal reads it), so
//!   a bot replies to exactly the events it is asked about. A reply that is an array (akochan's
//!   `[pon, dahai]`) answers this question with its first element and the next ones with the rest.
//!
//! Every read waits at most the timeout; a bot that is late, closes its output, sends a line
//! over [`MAX_LINE`] bytes or garbage gets an error naming it and the tail of its stderr, and the
//! process is killed when the [`Bot`] is dropped.

use std::collections::VecDeque;
use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{sync_channel, Receiver, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::thread;
use std::time::Duration;

use rinshan_engine::env::{Backend, Mode};
use rinshan_engine::Variant;

use super::event::{seat_lists_cut, Event};

/// The longest reply line read; a bot that writes more without a newline has failed.
pub const MAX_LINE: u64 = 1 << 20;
/// How much of a bot's stderr an error quotes.
const STDERR_TAIL: usize = 2000;

/// How a bot expects to be spoken to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dialect {
    /// mjai.app: a JSON array of events per line, one reaction per line.
    App,
    /// Mortal, mjai-manue: one event per line, a reaction only when asked.
    Stdio,
}

impl std::str::FromStr for Dialect {
    type Err = String;
    fn from_str(s: &str) -> Result<Dialect, String> {
        match s {
            "app" | "mjai.app" => Ok(Dialect::App),
            "stdio" | "mortal" => Ok(Dialect::Stdio),
            other => Err(format!("unknown MJAI dialect `{other}` (app or stdio)")),
        }
    }
}

/// Why MJAI bots cannot play some games (each front end words it in its own terms).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unplayable {
    /// The protocol's events and the bots know Tenhou's rules, four players (`red`) or three
    /// (`sanma`), and a bot follows a whole east or half game: other rule sets and single hands
    /// are not theirs.
    Rules,
    /// Each bot follows its game's state after every step, which the GPU backend keeps on the
    /// device.
    Backend,
}

/// Whether MJAI bots can play games of these rules on this backend.
pub fn check_games(variant: Variant, mode: Mode, backend: Backend) -> Result<(), Unplayable> {
    if !matches!(variant, Variant::Red | Variant::Sanma) || mode == Mode::Single {
        return Err(Unplayable::Rules);
    }
    if backend != Backend::Cpu {
        return Err(Unplayable::Backend);
    }
    Ok(())
}

/// A wait given in seconds (`--mjai-timeout`, `mjai_timeout=`): only a positive, finite number is one.
pub fn wait(seconds: f64) -> Option<Duration> {
    Duration::try_from_secs_f64(seconds).ok().filter(|d| !d.is_zero())
}

/// How to run a bot.
#[derive(Debug, Clone)]
pub struct BotSpec {
    /// The command line, run by `sh -c` with the bot's seat id (0-3, from East 1's dealer)
    /// appended, as mjai.app and Mortal take it.
    pub command: String,
    /// Its dialect.
    pub dialect: Dialect,
    /// The longest wait for a reply.
    pub timeout: Duration,
    /// The longest wait for the first reply (a bot may load a network first).
    pub startup: Duration,
}

/// A running bot.
pub struct Bot {
    child: Child,
    stdin: Option<ChildStdin>,
    lines: Receiver<Result<String, String>>,
    stderr: Arc<Mutex<VecDeque<u8>>>,
    dialect: Dialect,
    timeout: Duration,
    startup: Option<Duration>,
    /// Reactions of an array reply still to be used (Stdio).
    queued: VecDeque<Event>,
    /// Players at the table: a three-player game's events list three seats.
    seats: usize,
}

impl Drop for Bot {
    fn drop(&mut self) {
        drop(self.stdin.take());
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

impl Bot {
    /// Starts the bot of MJAI seat `seat` at a table of `seats` players.
    pub fn spawn(spec: &BotSpec, seat: u8, seats: usize) -> Result<Bot, String> {
        let mut child = Command::new("sh")
            .arg("-c")
            .arg(format!("exec {} {seat}", spec.command))
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(|e| format!("cannot start `{}`: {e}", spec.command))?;
        let (Some(stdin), Some(stdout), Some(mut err)) = (child.stdin.take(), child.stdout.take(), child.stderr.take())
        else {
            return Err("the bot's pipes were not opened".into());
        };
        let (send, lines) = sync_channel(16);
        thread::spawn(move || {
            let mut out = BufReader::new(stdout);
            loop {
                let mut line = Vec::new();
                let got = out.by_ref().take(MAX_LINE).read_until(b'\n', &mut line);
                let msg = match got {
                    Ok(0) => Err("the bot closed its output (it exited or crashed)".to_string()),
                    Err(e) => Err(format!("reading the bot's output: {e}")),
                    Ok(_) if line.last() != Some(&b'\n') && line.len() as u64 >= MAX_LINE => {
                        Err(format!("the bot wrote a line over {MAX_LINE} bytes"))
                    }
                    Ok(_) => Ok(String::from_utf8_lossy(&line).trim().to_string()),
                };
                let end = msg.is_err();
                if send.send(msg).is_err() || end {
                    return;
                }
            }
        });
        let stderr = Arc::new(Mutex::new(VecDeque::new()));
        let tail = Arc::clone(&stderr);
        thread::spawn(move || {
            let mut buf = [0u8; 4096];
            while let Ok(n @ 1..) = err.read(&mut buf) {
                if let Ok(mut t) = tail.lock() {
                    t.extend(&buf[..n]);
                    let extra = t.len().saturating_sub(STDERR_TAIL);
                    t.drain(..extra);
                }
            }
        });
        Ok(Bot {
            child,
            stdin: Some(stdin),
            lines,
            stderr,
            dialect: spec.dialect,
            timeout: spec.timeout,
            startup: Some(spec.startup.max(spec.timeout)),
            queued: VecDeque::new(),
            seats,
        })
    }

    /// The last of what the bot wrote to stderr.
    pub fn stderr_tail(&self) -> String {
        let t = self.stderr.lock().map(|t| t.iter().copied().collect::<Vec<u8>>());
        String::from_utf8_lossy(&t.unwrap_or_default()).trim().to_string()
    }

    fn failed(&mut self, what: String) -> String {
        // Give a crashing bot a moment to finish its message.
        thread::sleep(Duration::from_millis(50));
        let tail = self.stderr_tail();
        if tail.is_empty() {
            what
        } else {
            format!("{what}; its stderr ends: {tail}")
        }
    }

    fn write(&mut self, text: &str) -> Result<(), String> {
        let Some(stdin) = self.stdin.as_mut() else {
            return Err("the bot's input is closed".into());
        };
        let sent = stdin.write_all(text.as_bytes()).and_then(|()| stdin.flush());
        sent.map_err(|e| format!("writing to the bot: {e}"))
    }

    fn read(&mut self) -> Result<String, String> {
        let wait = self.startup.take().unwrap_or(self.timeout);
        match self.lines.recv_timeout(wait) {
            Ok(line) => line,
            Err(RecvTimeoutError::Timeout) => Err(format!("no reply within {:.1} s", wait.as_secs_f64())),
            Err(RecvTimeoutError::Disconnected) => Err("the bot's output is closed".into()),
        }
    }

    fn value(&self, event: &Event) -> serde_json::Value {
        seat_lists_cut(serde_json::to_value(event).unwrap_or_default(), self.seats)
    }

    fn json(&self, event: &Event, can_act: bool) -> String {
        let mut v = self.value(event);
        if let (false, Some(map)) = (can_act, v.as_object_mut()) {
            map.insert("can_act".into(), false.into());
        }
        v.to_string()
    }

    /// Sends `events` as updates the bot does not answer (Stdio).
    fn tell(&mut self, events: &[Event]) -> Result<(), String> {
        let mut text = String::new();
        for e in events {
            text.push_str(&self.json(e, false));
            text.push('\n');
        }
        self.write(&text).map_err(|e| self.failed(e))
    }

    /// Sends `events`, the last of which the bot can act on, and returns its reaction.
    pub fn ask(&mut self, events: &[Event]) -> Result<Event, String> {
        self.exchange(events).map_err(|e| self.failed(e))
    }

    fn exchange(&mut self, events: &[Event]) -> Result<Event, String> {
        let text = match self.dialect {
            Dialect::App => {
                let list: Vec<serde_json::Value> = events.iter().map(|e| self.value(e)).collect();
                format!("{}\n", serde_json::Value::Array(list))
            }
            Dialect::Stdio => {
                let mut text = String::new();
                for (i, e) in events.iter().enumerate() {
                    text.push_str(&self.json(e, i + 1 == events.len()));
                    text.push('\n');
                }
                text
            }
        };
        self.write(&text)?;
        if let Some(next) = self.queued.pop_front() {
            return Ok(next);
        }
        let line = self.read()?;
        let reply: serde_json::Value =
            serde_json::from_str(&line).map_err(|e| format!("the reply is not JSON ({e}): {}", clip(&line)))?;
        let mut reactions = match reply {
            serde_json::Value::Array(items) if self.dialect == Dialect::Stdio && !items.is_empty() => items,
            other => vec![other],
        }
        .into_iter()
        .map(|v| {
            serde_json::from_value::<Event>(v)
                .map_err(|e| format!("the reply is not a reaction ({e}): {}", clip(&line)))
        })
        .collect::<Result<VecDeque<Event>, String>>()?;
        let first = reactions.pop_front().ok_or("an empty reply")?;
        self.queued = reactions;
        Ok(first)
    }

    /// Sends `events` to a bot that must acknowledge them (App: `end_kyoku`, `end_game`, the
    /// first `start_game`); the reply is read and not judged.
    pub fn acknowledge(&mut self, events: &[Event]) -> Result<(), String> {
        match self.dialect {
            Dialect::App => self.exchange(events).map(drop).map_err(|e| self.failed(e)),
            Dialect::Stdio => self.tell(events),
        }
    }
}

fn clip(line: &str) -> String {
    let mut s: String = line.chars().take(200).collect();
    if s.len() < line.len() {
        s.push('…');
    }
    s
}
