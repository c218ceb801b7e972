//! Compute entry points and their bindings.
//!
//! Binding layout (group 0):
//! - binding 0: `tables`, read-only `array<u32>`, shared by all entries (the `table(i)`
//!   intrinsic), always declared;
//! - the k-th `Entry` (0-based) gets its input array at binding `1 + 2k` and its output
//!   array at binding `2 + 2k`. The runtime builds one pipeline per entry point, so with one
//!   entry per module (the usual case) this is bindings 1 and 2.
//! - the k-th `UpdateEntry` gets its read-write state array at binding `1 + 2k` and its
//!   read-only argument array at binding `2 + 2k`; one invocation per state record copies the
//!   record into a function-scope `var`, passes a pointer to it with the matching argument,
//!   and writes it back (a `ptr<storage>` cannot be passed to a kernel function that takes
//!   `ptr<function, T>`, so the copy is what makes `&mut State` work in place). With a guard,
//!   a record whose guard is false is left alone before that copy.
//! - a `ReadEntry` takes two slots, k and k + 1: its read-only state array at binding `1 + 2k`,
//!   its read-only argument array at `2 + 2k` and its output array at `3 + 2k` (`4 + 2k` stays
//!   unused), so the entries around it keep the two-binding layout.

use crate::diag::{Diag, Error, Result};
use crate::items::Program;
use crate::names::wgsl_ident;
use crate::types::Ty;
use crate::{Entry, ReadEntry, UpdateEntry};

pub(crate) const TABLES_DECL: &str = "@group(0) @binding(0) var<storage, read> tables: array<u32>;\n";

/// Reports an entry's problem at its function's name when that exists.
fn entry_error<'p>(prog: &'p Program, function: &'p str, fallback: Diag<'p>) -> impl Fn(String) -> Error + 'p {
    move |msg: String| match prog.fns.get(function) {
        Some(f) => prog.diag(f.file).node(&f.item.sig.ident, msg),
        None => fallback.whole_file(msg),
    }
}

/// Checks the entry point's name and the module-scope names it declares.
fn check_names(prog: &Program, name: &str, suffixes: &[&str], bad: &impl Fn(String) -> Error) -> Result<()> {
    if !is_plain_ident(name) || wgsl_ident(name) != *name {
        return Err(bad(format!(
            "entry point name `{name}` is not usable as a WGSL identifier"
        )));
    }
    let globals = std::iter::once(name.to_string()).chain(suffixes.iter().map(|s| format!("{name}{s}")));
    for global in globals {
        if prog.module_names.contains(&global) {
            return Err(bad(format!(
                "entry point `{name}` needs the name `{global}`, which the kernel sources already use; rename one"
            )));
        }
    }
    Ok(())
}

pub(crate) fn lower_entry(prog: &Program, k: usize, entry: &Entry, fallback: Diag) -> Result<String> {
    let bad = entry_error(prog, &entry.function, fallback);
    let name = &entry.name;
    check_names(prog, name, &["_in", "_out"], &bad)?;
    let Some(f) = prog.fns.get(&entry.function) else {
        return Err(fallback.whole_file(format!(
            "entry `{name}`: function `{}` is not defined in the kernel sources",
            entry.function
        )));
    };
    let input = Ty::Struct(entry.input.clone());
    let output = Ty::Struct(entry.output.clone());
    if f.params.len() != 1 || f.params[0].ty != input || f.ret != output {
        return Err(bad(format!(
            "entry `{name}` needs `fn {}(input: {}) -> {}`",
            entry.function, entry.input, entry.output
        )));
    }
    for ty in [&input, &output] {
        host_shareable(prog, ty).map_err(|why| {
            bad(format!(
                "entry `{name}`: `{}` cannot live in a storage buffer: {why}",
                ty.rust()
            ))
        })?;
    }
    let (bin, bout) = (1 + 2 * k, 2 + 2 * k);
    let input_w = input.wgsl();
    let output_w = output.wgsl();
    let func = wgsl_ident(&entry.function);
    Ok(format!(
        "@group(0) @binding({bin}) var<storage, read> {name}_in: array<{input_w}>;\n\
         @group(0) @binding({bout}) var<storage, read_write> {name}_out: array<{output_w}>;\n\
         \n\
         @compute @workgroup_size(64)\n\
         fn {name}(@builtin(global_invocation_id) gid: vec3<u32>) {{\n    \
             let i = gid.x;\n    \
             if (i >= arrayLength(&{name}_in)) {{ return; }}\n    \
             {name}_out[i] = {func}({name}_in[i]);\n\
         }}\n"
    ))
}

pub(crate) fn lower_update_entry(prog: &Program, k: usize, entry: &UpdateEntry, fallback: Diag) -> Result<String> {
    let bad = entry_error(prog, &entry.function, fallback);
    let name = &entry.name;
    check_names(prog, name, &["_state", "_arg"], &bad)?;
    let Some(f) = prog.fns.get(&entry.function) else {
        return Err(fallback.whole_file(format!(
            "entry `{name}`: function `{}` is not defined in the kernel sources",
            entry.function
        )));
    };
    let state = entry_ty(&entry.state);
    let arg = entry_ty(&entry.arg);
    let wanted = || {
        bad(format!(
            "entry `{name}` needs `fn {}(state: &mut {}, arg: {})` with no return value",
            entry.function, entry.state, entry.arg
        ))
    };
    if f.params.len() != 2 || f.ret != Ty::Unit {
        return Err(wanted());
    }
    if f.params[0].ty != Ty::Ptr(Box::new(state.clone())) || f.params[1].ty != arg {
        return Err(wanted());
    }
    for ty in [&state, &arg] {
        host_shareable(prog, ty).map_err(|why| {
            bad(format!(
                "entry `{name}`: `{}` cannot live in a storage buffer: {why}",
                ty.rust()
            ))
        })?;
    }
    let func = wgsl_ident(&entry.function);
    // The wrapper's locals must not hide the functions it calls.
    let guard_fn = entry.guard.as_ref().map(|g| wgsl_ident(&g.function));
    let calls = |n: &str| func == n || guard_fn.as_deref() == Some(n);
    let local = if calls("state") { "state_1" } else { "state" };
    let index = if calls("i") { "i_1" } else { "i" };
    let guard = match (&entry.guard, &guard_fn) {
        (Some(g), Some(guard_fn)) => {
            check_guard(prog, &entry.state, g, &bad)?;
            let field = wgsl_ident(&g.field);
            format!("if (!{guard_fn}({name}_state[{index}].{field})) {{ return; }}\n    ")
        }
        _ => String::new(),
    };
    let (bstate, barg) = (1 + 2 * k, 2 + 2 * k);
    let state_w = state.wgsl();
    let arg_w = arg.wgsl();
    Ok(format!(
        "@group(0) @binding({bstate}) var<storage, read_write> {name}_state: array<{state_w}>;\n\
         @group(0) @binding({barg}) var<storage, read> {name}_arg: array<{arg_w}>;\n\
         \n\
         @compute @workgroup_size(64)\n\
         fn {name}(@builtin(global_invocation_id) gid: vec3<u32>) {{\n    \
             let {index} = gid.x;\n    \
             if ({index} >= arrayLength(&{name}_state)) {{ return; }}\n    \
             {guard}\
             var {local} = {name}_state[{index}];\n    \
             {func}(&{local}, {name}_arg[{index}]);\n    \
             {name}_state[{index}] = {local};\n\
         }}\n"
    ))
}

/// A guard's function is a kernel `fn(u32) -> bool` and its field a `u32` field of the state.
fn check_guard(prog: &Program, state: &str, guard: &crate::Guard, bad: &impl Fn(String) -> Error) -> Result<()> {
    let (field, function) = (&guard.field, &guard.function);
    let is_u32_field = prog
        .structs
        .get(state)
        .is_some_and(|s| s.fields.iter().any(|(name, ty)| name == field && *ty == Ty::U32));
    if !is_u32_field {
        return Err(bad(format!(
            "the guard reads `{state}.{field}`, which is not a `u32` field of `{state}`"
        )));
    }
    let right = prog
        .fns
        .get(function)
        .is_some_and(|f| f.params.len() == 1 && f.params[0].ty == Ty::U32 && f.ret == Ty::Bool);
    if !right {
        return Err(bad(format!(
            "the guard needs `fn {function}({field}: u32) -> bool` in the kernel sources"
        )));
    }
    Ok(())
}

pub(crate) fn lower_read_entry(prog: &Program, k: usize, entry: &ReadEntry, fallback: Diag) -> Result<String> {
    let bad = entry_error(prog, &entry.function, fallback);
    let name = &entry.name;
    check_names(prog, name, &["_state", "_arg", "_out"], &bad)?;
    let Some(f) = prog.fns.get(&entry.function) else {
        return Err(fallback.whole_file(format!(
            "entry `{name}`: function `{}` is not defined in the kernel sources",
            entry.function
        )));
    };
    let state = entry_ty(&entry.state);
    let arg = entry_ty(&entry.arg);
    let output = entry_ty(&entry.output);
    if f.params.len() != 2 || f.params[0].ty != state || f.params[1].ty != arg || f.ret != output {
        return Err(bad(format!(
            "entry `{name}` needs `fn {}(state: {}, arg: {}) -> {}`",
            entry.function, entry.state, entry.arg, entry.output
        )));
    }
    for ty in [&state, &arg, &output] {
        host_shareable(prog, ty).map_err(|why| {
            bad(format!(
                "entry `{name}`: `{}` cannot live in a storage buffer: {why}",
                ty.rust()
            ))
        })?;
    }
    let func = wgsl_ident(&entry.function);
    let index = if func == "i" { "i_1" } else { "i" };
    let (bstate, barg, bout) = (1 + 2 * k, 2 + 2 * k, 3 + 2 * k);
    let (state_w, arg_w, out_w) = (state.wgsl(), arg.wgsl(), output.wgsl());
    Ok(format!(
        "@group(0) @binding({bstate}) var<storage, read> {name}_state: array<{state_w}>;\n\
         @group(0) @binding({barg}) var<storage, read> {name}_arg: array<{arg_w}>;\n\
         @group(0) @binding({bout}) var<storage, read_write> {name}_out: array<{out_w}>;\n\
         \n\
         @compute @workgroup_size(64)\n\
         fn {name}(@builtin(global_invocation_id) gid: vec3<u32>) {{\n    \
             let {index} = gid.x;\n    \
             if ({index} >= arrayLength(&{name}_out)) {{ return; }}\n    \
             {name}_out[{index}] = {func}({name}_state[{index}], {name}_arg[{index}]);\n\
         }}\n"
    ))
}

/// An update entry's state or argument type: a 4-byte scalar or a kernel struct.
fn entry_ty(name: &str) -> Ty {
    match name {
        "u32" => Ty::U32,
        "i32" => Ty::I32,
        "f32" => Ty::F32,
        "bool" => Ty::Bool,
        _ => Ty::Struct(name.to_string()),
    }
}

fn is_plain_ident(s: &str) -> bool {
    let mut chars = s.chars();
    chars.next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Entry structs (and scalars) are uploaded as `#[repr(C)]` bytemuck values: only 4-byte scalars
/// and arrays of them, which lay out identically in WGSL storage buffers.
fn host_shareable(prog: &Program, ty: &Ty) -> std::result::Result<(), String> {
    match ty {
        Ty::U32 | Ty::I32 | Ty::F32 => Ok(()),
        Ty::Bool => Err("`bool` has no defined memory layout; use a u32 (0 or 1)".into()),
        Ty::Array(elem, _) => host_shareable(prog, elem),
        Ty::Struct(s) => match prog.structs.get(s) {
            Some(def) => def.fields.iter().try_for_each(|(_, t)| host_shareable(prog, t)),
            None => Err(format!("`{s}` is not a struct defined in the kernel sources")),
        },
        _ => Err(format!("`{}` is not allowed", ty.rust())),
    }
}
