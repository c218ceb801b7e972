//! Kernel functions mapped over a batch of game states on the CPU.

use rayon::prelude::*;

use crate::generated::kernel;
use crate::observe::TableView;

/// `out[i] = f(states[i], args[i])` over the batch, in parallel unless `serial`.
pub(crate) fn each<T: bytemuck::Pod + Send>(
    out: &mut [u32],
    sts: &[kernel::GameState],
    args: &[u32],
    serial: bool,
    f: fn(kernel::GameState, u32) -> T,
) {
    // A zero-sized item per env: the vector allocates nothing.
    rows(
        out,
        sts,
        args,
        &mut vec![(); sts.len()],
        serial,
        |o: &mut T, s, a, _| *o = f(*s, a),
    );
}

/// `f(&mut state, arg, view, &mut out[i])` over the batch, in parallel unless `serial`, for a
/// writer that fills its record in place and reads each state's [`TableView`], brought up to that
/// state's log first with the `parts` the writer reads. The kernel takes states as `&mut`: it gets
/// a copy of each.
pub(crate) fn each_followed<T: bytemuck::Pod + Send>(
    out: &mut [u32],
    sts: &[kernel::GameState],
    args: &[u32],
    tables: &mut [TableView],
    parts: u8,
    serial: bool,
    f: impl Fn(&mut kernel::GameState, u32, &TableView, &mut T) + Sync + Send,
) {
    rows(out, sts, args, tables, serial, |o: &mut T, s, a, t: &mut TableView| {
        t.follow(s, parts);
        f(&mut { *s }, a, t, o);
    });
}

/// `one(record i, state i, arg i, item i)` over the batch, in parallel unless `serial`.
fn rows<T: bytemuck::Pod + Send, X: Send>(
    out: &mut [u32],
    sts: &[kernel::GameState],
    args: &[u32],
    items: &mut [X],
    serial: bool,
    one: impl Fn(&mut T, &kernel::GameState, u32, &mut X) + Sync + Send,
) {
    let outs: &mut [T] = bytemuck::cast_slice_mut(out);
    let one = |(((o, s), a), x): (((&mut T, &kernel::GameState), &u32), &mut X)| one(o, s, *a, x);
    if serial {
        outs.iter_mut().zip(sts).zip(args).zip(items.iter_mut()).for_each(one);
    } else {
        outs.par_iter_mut()
            .zip(sts.par_iter())
            .zip(args.par_iter())
            .zip(items.par_iter_mut())
            .with_min_len(8)
            .for_each(one);
    }
}
