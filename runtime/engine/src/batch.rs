//! Kernel functions mapped over a batch of game states on the CPU.

use rayon::prelude::*;

use crate::generated::kernel;

/// `out[i] = f(states[i], args[i])` over the batch, in parallel unless `serial`.
pub(crate) fn each<T: bytemuck::Pod + Send>(
    out: &mut [u32],
    sts: &[kernel::GameState],
    args: &[u32],
    serial: bool,
    f: fn(kernel::GameState, u32) -> T,
) {
    let outs: &mut [T] = bytemuck::cast_slice_mut(out);
    let one = |((o, s), a): ((&mut T, &kernel::GameState), &u32)| *o = f(*s, *a);
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
