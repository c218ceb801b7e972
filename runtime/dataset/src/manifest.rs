//! A dataset's `manifest.json`: the field schema of every array (taken from the observation's one
//! field table), the options it was made with, and per shard the inputs it covers, the games kept
//! and the logs skipped with their reasons. A shard is listed only once it is whole: the list is
//! what a resumed run skips.

use std::path::Path;

use rinshan_engine::env::action_names;
use rinshan_engine::observe::Form;
use serde::{Deserialize, Serialize};

use crate::record::Options;
use crate::shard::{GAME_ARRAYS, ROW_ARRAYS, SEARCH_ARRAYS};

/// What the manifest says the folder is.
pub const FORMAT: &str = "rinshan-dataset";
/// The layout's version: a reader refuses others.
pub const VERSION: u32 = 1;
/// The manifest's file name.
pub const FILE: &str = "manifest.json";

/// One field of an observation record.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct FieldSchema {
    /// The key.
    pub name: String,
    /// Byte offset in the record.
    pub offset: usize,
    /// numpy's dtype name.
    pub dtype: String,
    /// Shape.
    pub shape: Vec<usize>,
    /// Meaning and units.
    pub doc: String,
}

/// An observation form's record layout.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct FormSchema {
    /// The form (`planes`, `tokens`, `analysis`): also its array's file name.
    pub name: String,
    /// Bytes per record (the array is uint8 `[rows, bytes]`).
    pub bytes: usize,
    /// Its fields.
    pub fields: Vec<FieldSchema>,
}

/// An array of each shard besides the observations.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ArraySchema {
    /// File name without `.npy`.
    pub name: String,
    /// numpy's dtype name.
    pub dtype: String,
    /// `row` (one per decision) or `game` (one per kept game).
    pub per: String,
}

/// A log left out, and why.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Skip {
    /// The log's name.
    pub input: String,
    /// Why, with file and position where known.
    pub reason: String,
}

/// A log left out because an earlier input holds the same game (see [`crate::same`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Duplicate {
    /// The log's name.
    pub input: String,
    /// The earlier input whose rows hold the game (or whose skip says why it has none).
    pub same_as: String,
}

/// One finished shard.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct ShardRecord {
    /// Its folder.
    pub name: String,
    /// Decisions it holds.
    pub rows: u64,
    /// Every input it covers, in order (a resumed run checks it sees the same).
    pub inputs: Vec<String>,
    /// The games kept, in order: a row's `game` indexes this list, `scores` and `ranks`.
    pub games: Vec<String>,
    /// The inputs left out, other than duplicates.
    pub skipped: Vec<Skip>,
    /// The inputs left out as the same game as an earlier input: each input is a game, a skip or
    /// a duplicate. Absent when none (and in manifests written before duplicates were told).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub duplicates: Vec<Duplicate>,
}

/// The options as written.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct OptionsRecord {
    /// Whose decisions (`all`, `seats 0,2`, `players NAME,...`).
    pub seats: String,
    /// Decisions with one legal action kept.
    pub forced: bool,
    /// Inputs per shard.
    pub inputs_per_shard: usize,
    /// The look-ahead that labelled the rows (absent when none did).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub search: Option<String>,
}

/// The whole manifest.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Manifest {
    /// Always [`FORMAT`].
    pub format: String,
    /// Always [`VERSION`].
    pub version: u32,
    /// The rules the logs were replayed in.
    pub variant: String,
    /// The action ids' names (the mask's width is their number).
    pub actions: Vec<String>,
    /// The observation forms, each an array `<form>.npy`.
    pub forms: Vec<FormSchema>,
    /// The other arrays.
    pub arrays: Vec<ArraySchema>,
    /// What was asked for.
    pub options: OptionsRecord,
    /// The finished shards, in order.
    pub shards: Vec<ShardRecord>,
}

impl Manifest {
    /// An empty manifest for `options`.
    pub fn new(options: &Options, inputs_per_shard: usize) -> Manifest {
        let forms = options
            .forms
            .iter()
            .map(|&form| FormSchema {
                name: form.name().into(),
                bytes: form.bytes(),
                fields: form
                    .fields()
                    .iter()
                    .map(|f| FieldSchema {
                        name: f.name.into(),
                        offset: f.offset,
                        dtype: f.dtype.name().into(),
                        shape: f.shape.to_vec(),
                        doc: f.doc.into(),
                    })
                    .collect(),
            })
            .collect();
        let labels: &[(&str, &str)] = if options.search.is_some() { &SEARCH_ARRAYS } else { &[] };
        let arrays = ROW_ARRAYS
            .iter()
            .chain(labels)
            .map(|(n, d)| (n, d, "row"))
            .chain(GAME_ARRAYS.iter().map(|(n, d)| (n, d, "game")))
            .map(|(n, d, per)| ArraySchema {
                name: n.to_string(),
                dtype: d.to_string(),
                per: per.into(),
            })
            .collect();
        Manifest {
            format: FORMAT.into(),
            version: VERSION,
            variant: options.variant.to_string(),
            actions: action_names(options.variant),
            forms,
            arrays,
            options: OptionsRecord {
                seats: options.seats.describe(),
                forced: options.forced,
                inputs_per_shard,
                search: options.search.clone(),
            },
            shards: Vec::new(),
        }
    }

    /// Whether `other` describes the same kind of rows (all but the shards).
    pub fn same_layout(&self, other: &Manifest) -> bool {
        self.format == other.format
            && self.version == other.version
            && self.variant == other.variant
            && self.actions == other.actions
            && self.forms == other.forms
            && self.arrays == other.arrays
            && self.options == other.options
    }

    /// Reads `dir`'s manifest; `None` when there is none.
    pub fn load(dir: &Path) -> Result<Option<Manifest>, String> {
        let path = dir.join(FILE);
        match std::fs::read_to_string(&path) {
            Ok(text) => serde_json::from_str(&text)
                .map(Some)
                .map_err(|e| format!("{}: not a dataset manifest: {e}", path.display())),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(format!("{}: {e}", path.display())),
        }
    }

    /// Writes it to `dir` whole or not at all (a temporary file renamed over the old one).
    pub fn save(&self, dir: &Path) -> Result<(), String> {
        let path = dir.join(FILE);
        let partial = dir.join(format!(".{FILE}.partial"));
        let io = |e: std::io::Error| format!("{}: {e}", path.display());
        let text = serde_json::to_string_pretty(self).map_err(|e| e.to_string())?;
        std::fs::write(&partial, text + "\n").map_err(io)?;
        std::fs::rename(&partial, &path).map_err(io)
    }
}

/// The forms a dataset may hold: what a seat sees.
pub fn check_forms(forms: &[Form]) -> Result<(), String> {
    if forms.contains(&Form::Oracle) {
        return Err("a dataset row holds what its seat saw: the oracle is not one of its forms".into());
    }
    Ok(())
}
