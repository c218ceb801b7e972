//! Translates rinshan's "kernel subset" of Rust into one WGSL module and validates it with
//! naga.
//!
//! Kernel sources are ordinary Rust (they also compile natively) restricted to what maps
//! directly onto WGSL. Anything outside the subset is rejected with a located [`Error`]
//! saying what to write instead.
//!
//! - Items: `const`, `struct` (named fields) and `fn`; attributes `derive`, `doc`, `allow`,
//!   `inline`, `repr` are ignored. Items are emitted in source order.
//! - Types: `u32`, `i32`, `f32`, `bool`, `[T; N]`, kernel structs, and `&mut T` parameters
//!   (`ptr<function, T>`). `usize` only as the type of a const (array lengths) and in
//!   `a[i as usize]`, where the cast is dropped.
//! - Statements: `let` / `let mut` (type from the annotation or the value), assignment and
//!   compound assignment, `if`/`else`, `while`, `loop`, `for i in a..b` / `a..=b`, `match` on
//!   u32/i32 literals and consts (a WGSL `switch`; `break` in an arm still leaves the loop),
//!   `break`, `continue`, `return`, tail expressions.
//! - Expressions: literals, arithmetic/bit/comparison/logical operators, `as` between
//!   u32/i32/f32 (and from bool), field access, indexing, struct and array literals,
//!   `[v; N]`, calls, `if`/`else` with simple branches (WGSL `select`), the methods `min`,
//!   `max`, `count_ones`, `trailing_zeros`, `leading_zeros`, `wrapping_add/sub/mul`, `abs`,
//!   `clone`, the consts `u32::MAX/MIN`, `i32::MAX/MIN`, and the `table(i)` intrinsic
//!   (reads the `tables` storage buffer).
//!
//! - Entry points ([`translate_entry_points`]): [`Entry`] maps `input[i]` to `output[i]` with
//!   `fn(In) -> Out`; [`UpdateEntry`] updates `state[i]` in place with `fn(&mut State, Arg)`.
//!
//! Code generation choices (see the modules for why): consts holding arrays become
//! `var<private>`, parameters and `let`s holding arrays are kept in `var`s, Rust names that
//! are WGSL reserved words get a `_` suffix, shadowed locals get `_1`, `_2`... suffixes.

mod diag;
mod entry;
mod items;
mod lower;
mod names;
mod shared;
mod types;
mod validate;

pub use diag::Error;
pub use shared::shared_files;
pub use validate::{validate, validate_with_info};

use diag::Diag;
use items::{Decl, Program};

/// A kernel source file; `path` is only used in error messages.
#[derive(Debug, Clone)]
pub struct Source {
    pub path: String,
    pub text: String,
}

/// One compute entry point: `name` runs `function(input) -> output` once per element of the
/// input array. See [`translate`] for the binding layout.
#[derive(Debug, Clone)]
pub struct Entry {
    pub name: String,
    pub function: String,
    pub input: String,
    pub output: String,
}

/// An entry that updates records in place: `fn function(state: &mut State, arg: Arg)`.
///
/// `name` runs once per element of the state array, with the argument at the same index,
/// and writes the updated state back. `state` and `arg` name kernel structs or `u32`/`i32`/
/// `f32`; both must be host-shareable (no `bool` anywhere inside).
#[derive(Debug, Clone)]
pub struct UpdateEntry {
    pub name: String,
    pub function: String,
    pub state: String,
    pub arg: String,
    /// Where this is false the entry leaves the record alone without copying it in and out.
    pub guard: Option<Guard>,
}

/// When an update entry has work: `function(state.field)`, a kernel `fn(u32) -> bool` of one
/// `u32` field of the state, read straight from the storage buffer. The entry's function must
/// leave the state unchanged wherever it is false (one pass of a step that runs as several,
/// which most records skip).
#[derive(Debug, Clone)]
pub struct Guard {
    pub field: String,
    pub function: String,
}

/// An entry that reads a record with an argument: `fn function(state: State, arg: Arg) -> Out`.
///
/// `name` runs once per element of the output array: `output[i] = function(state[i], arg[i])`
/// (an observation of game `i` for the seat in `arg[i]`). All three must be host-shareable.
#[derive(Debug, Clone)]
pub struct ReadEntry {
    pub name: String,
    pub function: String,
    pub state: String,
    pub arg: String,
    pub output: String,
}

/// One compute entry point of any kind.
#[derive(Debug, Clone)]
pub enum EntryPoint {
    /// `output[i] = function(input[i])`.
    Map(Entry),
    /// `function(&mut state[i], arg[i])`.
    Update(UpdateEntry),
    /// `output[i] = function(state[i], arg[i])`; takes two binding slots.
    Read(ReadEntry),
}

impl From<Entry> for EntryPoint {
    fn from(e: Entry) -> Self {
        EntryPoint::Map(e)
    }
}

impl From<UpdateEntry> for EntryPoint {
    fn from(e: UpdateEntry) -> Self {
        EntryPoint::Update(e)
    }
}

/// An update entry as a plain table row: `(name, function, state, arg, guard)`, the guard as
/// `(field, function)`.
pub type UpdateTable = (
    &'static str,
    &'static str,
    &'static str,
    &'static str,
    Option<(&'static str, &'static str)>,
);

/// The entry points of a module from plain tables, map entries first, then update entries, then
/// read entries (the binding order): `(name, function, input, output)`, `(name, function, state,
/// arg, guard)` with the guard as `(field, function)`, and `(name, function, state, arg, output)`.
pub fn entry_points(
    map: &[(&str, &str, &str, &str)],
    update: &[UpdateTable],
    read: &[(&str, &str, &str, &str, &str)],
) -> Vec<EntryPoint> {
    let maps = map.iter().map(|(name, function, input, output)| {
        EntryPoint::Map(Entry {
            name: name.to_string(),
            function: function.to_string(),
            input: input.to_string(),
            output: output.to_string(),
        })
    });
    let updates = update.iter().map(|(name, function, state, arg, guard)| {
        EntryPoint::Update(UpdateEntry {
            name: name.to_string(),
            function: function.to_string(),
            state: state.to_string(),
            arg: arg.to_string(),
            guard: guard.map(|(field, function)| Guard {
                field: field.to_string(),
                function: function.to_string(),
            }),
        })
    });
    let reads = read.iter().map(|(name, function, state, arg, output)| {
        EntryPoint::Read(ReadEntry {
            name: name.to_string(),
            function: function.to_string(),
            state: state.to_string(),
            arg: arg.to_string(),
            output: output.to_string(),
        })
    });
    maps.chain(updates).chain(reads).collect()
}

impl EntryPoint {
    /// The WGSL entry point name.
    pub fn name(&self) -> &str {
        match self {
            EntryPoint::Map(e) => &e.name,
            EntryPoint::Update(e) => &e.name,
            EntryPoint::Read(e) => &e.name,
        }
    }

    /// Binding slots taken (two bindings each): a read entry needs three bindings, so two slots.
    pub fn slots(&self) -> usize {
        match self {
            EntryPoint::Read(_) => 2,
            _ => 1,
        }
    }
}

/// Translate all sources into one WGSL module with one compute entry point per `Entry`, and
/// validate it.
///
/// Binding layout: `tables` (the `table(i)` intrinsic) at group 0 binding 0; the k-th entry's
/// input at binding `1 + 2k` and output at binding `2 + 2k`.
pub fn translate(sources: &[Source], entries: &[Entry]) -> Result<String, Error> {
    let entries: Vec<EntryPoint> = entries.iter().cloned().map(EntryPoint::Map).collect();
    translate_entry_points(sources, &entries)
}

/// Like [`translate`], for a mix of entry kinds. Entries take binding slots in order (a `Read`
/// entry two, the others one); the entry at slot k binds `1 + 2k` and `2 + 2k`: a `Map` entry
/// its input (read) and output (read-write) arrays, an `Update` entry its state (read-write)
/// and argument (read) arrays, a `Read` entry its state and argument (read) and, at `3 + 2k`,
/// its output (read-write).
pub fn translate_entry_points(sources: &[Source], entries: &[EntryPoint]) -> Result<String, Error> {
    let mut files = Vec::new();
    for src in sources {
        let file = syn::parse_file(&src.text)
            .map_err(|e| Diag { file: &src.path }.at(e.span(), format!("syntax error: {e}")))?;
        files.push(file);
    }
    let paths: Vec<&str> = sources.iter().map(|s| s.path.as_str()).collect();
    let prog = Program::collect(paths, &files)?;

    let mut out = String::new();
    out.push_str("// Generated by rinshan-shaders-gen from the kernel sources");
    for s in sources {
        out.push_str(&format!(" {}", s.path));
    }
    out.push_str(". Do not edit.\n\n");
    out.push_str(entry::TABLES_DECL);
    for decl in &prog.order {
        out.push('\n');
        match decl {
            Decl::Struct(name) => out.push_str(&lower::lower_struct(&prog, name)),
            Decl::Const(name) => out.push_str(&lower::lower_const(&prog, name)?),
            Decl::Fn(name) => out.push_str(&lower::lower_fn(&prog, name)?),
        }
    }
    let fallback = Diag {
        file: sources.first().map_or("<no sources>", |s| s.path.as_str()),
    };
    let mut entry_names = std::collections::HashSet::new();
    let mut k = 0;
    for e in entries {
        if !entry_names.insert(e.name()) {
            return Err(fallback.whole_file(format!("two entries are named `{}`", e.name())));
        }
        out.push('\n');
        out.push_str(&match e {
            EntryPoint::Map(e) => entry::lower_entry(&prog, k, e, fallback)?,
            EntryPoint::Update(e) => entry::lower_update_entry(&prog, k, e, fallback)?,
            EntryPoint::Read(e) => entry::lower_read_entry(&prog, k, e, fallback)?,
        });
        k += e.slots();
    }
    if let Err(msg) = validate(&out) {
        // A bug in the translator rather than in the kernel: report it with the WGSL.
        return Err(fallback.whole_file(format!(
            "internal error: generated WGSL does not validate:\n{msg}\n--- WGSL ---\n{out}"
        )));
    }
    Ok(out)
}
