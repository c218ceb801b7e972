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
    rows(out, sts, args, serial, |o: &mut T, s, a| *o = f(*s, a));
}

/// `f(&mut state, arg, view, &mut out[i])` over the batch, in parallel unless `serial`, for a
/// writer that fills its record in place and reads each state's [`TableView`], brought up to that
/// state's log first. The kernel takes states as `&mut`: it gets a copy of each.
pub(crate) fn each_followed<T: bytemuck::Pod + Send>(
    out: &mut [u32],
    sts: &[kernel::GameState],
    args: &[u32],
    tables: &mut [TableView],
    serial: bool,
    f: impl Fn(&mut kernel::GameState, u32, &TableView, &mut T) + Sync + Send,
) {
    let outs: &mut [T] = bytemuck::cast_slice_mut(out);
    let one = |(((o, s), a), t): (((&mut T, &kernel::GameState), &u32), &mut TableView)| {
        t.follow(s);
        f(&mut { *s }, *a, t, o);
    };
    if serial {
        outs.iter_mut().zip(sts).zip(args).zip(tables.iter_mut()).for_each(one);
    } else {
        outs.par_iter_mut()
            .zip(sts.par_iter())
            .zip(args.par_iter())
            .zip(tables.par_iter_mut())
            .with_min_len(8)
            .for_each(one);
    }
}

/// `one(record i, state i, arg i)` over the batch, in parallel unless `serial`.
fn rows<T: bytemuck::Pod + Send>(
    out: &mut [u32],
    sts: &[kernel::GameState],
    args: &[u32],
    serial: bool,
    one: impl Fn(&mut T, &kernel::GameState, u32) + Sync + Send,
) {
    let outs: &mut [T] = bytemuck::cast_slice_mut(out);
    let one = |((o, s), a): ((&mut T, &kernel::GameState), &u32)| one(o, s, *a);
    if serial {
        outs.iter_mut().zip(sts).zip(args).for_each(one);
    } else {
        outs.par_iter_mut()
            .zip(sts.par_iter())
            .zip(args.par_iter())
            .with_min_len(8)
            .for_each(one);
    }
}
