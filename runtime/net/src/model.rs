//! The forward pass: the training example's `Net` (examples/train/common.py), op for op. The
//! torso is an MLP over the scaled planes and the normalised scalars; the tile head adds to each
//! discard's logit a score from its own tile's column of the planes and the position's context.

use candle_core::{DType, Device, Tensor};

use crate::file::{planes_shape, Net, NetError};
use crate::inputs::Inputs;

/// What a masked-out action's logit is set to (the training example's `MASKED`).
pub const MASKED: f32 = -1e9;

/// `x W^T + b`, with `W^T` kept contiguous for the matrix product.
#[derive(Debug)]
pub(crate) struct Linear {
    weight_t: Tensor,
    bias: Tensor,
}

impl Linear {
    pub(crate) fn new(weight: &Tensor, bias: Tensor) -> candle_core::Result<Linear> {
        Ok(Linear {
            weight_t: weight.t()?.contiguous()?,
            bias,
        })
    }

    pub(crate) fn outputs(&self) -> usize {
        self.bias.dims()[0]
    }

    fn forward(&self, x: &Tensor) -> candle_core::Result<Tensor> {
        x.matmul(&self.weight_t)?.broadcast_add(&self.bias)
    }
}

/// The tile head: its first layer split into the column half and the context half, which the
/// training example computes the same way (once per position for the context).
#[derive(Debug)]
pub(crate) struct TileHead {
    context: Linear,
    /// The first layer's weights on a tile's column (rows, hidden) and on the context (32, hidden).
    column_t: Tensor,
    context_t: Tensor,
    first_bias: Tensor,
    second: Linear,
    /// Per action, the column (0..=34: 34 is the drawn tile's) its score is read from.
    discard_column: Tensor,
    is_discard: Tensor,
}

impl TileHead {
    pub(crate) fn new(
        rows: usize,
        context: Linear,
        first: Linear,
        second: Linear,
        discard_column: Tensor,
        is_discard: Tensor,
    ) -> candle_core::Result<TileHead> {
        let n = first.weight_t.dims()[0];
        Ok(TileHead {
            column_t: first.weight_t.narrow(0, 0, rows)?.contiguous()?,
            context_t: first.weight_t.narrow(0, rows, n - rows)?.contiguous()?,
            first_bias: first.bias,
            context,
            second,
            discard_column,
            is_discard,
        })
    }

    /// Per position and action, the score added to the logit: (n, actions).
    /// `columns`: each tile's column of the scaled rows, (n * 34, rows).
    fn scores(&self, columns: &Tensor, g: &Tensor, drawn: &Tensor) -> candle_core::Result<Tensor> {
        let (n, tiles) = (g.dims()[0], 34);
        let context = self
            .context
            .forward(g)?
            .matmul(&self.context_t)?
            .broadcast_add(&self.first_bias)?;
        let columns = columns.matmul(&self.column_t)?;
        let hidden = columns
            .reshape((n, tiles, ()))?
            .broadcast_add(&context.unsqueeze(1)?)?
            .relu()?;
        let per_tile = self
            .second
            .forward(&hidden.reshape((n * tiles, ()))?)?
            .reshape((n, tiles))?;
        let per_tile = Tensor::cat(&[&per_tile, &per_tile.gather(drawn, 1)?], 1)?;
        per_tile
            .index_select(&self.discard_column, 1)?
            .broadcast_mul(&self.is_discard)
    }
}

impl Net {
    /// The logits of each decision in `inputs` over the net's actions, `MASKED` where the mask
    /// says an action is not legal: (n, actions), row-major.
    pub fn logits(&self, inputs: &Inputs) -> Result<Vec<f32>, NetError> {
        let n = inputs.len();
        let (rows, scalars) = (self.rows(), planes_shape().1);
        if inputs.rows() != rows || inputs.actions() != self.actions.len() {
            return Err(NetError::new(format!(
                "inputs of {} rows and {} actions for a net of {rows} and {}",
                inputs.rows(),
                inputs.actions(),
                self.actions.len()
            )));
        }
        if n == 0 {
            return Ok(Vec::new());
        }
        let cpu = &Device::Cpu;
        let planes = Tensor::from_slice(inputs.planes(), (n, rows, 34), cpu)?;
        let x = planes.broadcast_mul(&self.row_scale)?;
        let s = Tensor::from_slice(inputs.scalars(), (n, scalars), cpu)?
            .broadcast_sub(&self.scalar_mean)?
            .broadcast_div(&self.scalar_std)?;
        let mut g = Tensor::cat(&[&x.reshape((n, rows * 34))?, &s], 1)?;
        for layer in &self.torso {
            g = layer.forward(&g)?.relu()?;
        }
        let mut logits = self.head.forward(&g)?;
        if let Some(tile) = &self.tile_head {
            let drawn = Tensor::from_slice(inputs.drawn(), (n, 1), cpu)?.to_dtype(DType::I64)?;
            let columns = Tensor::from_slice(inputs.columns(), (n * 34, rows), cpu)?
                .broadcast_mul(&self.row_scale.reshape(rows)?)?;
            logits = (logits + tile.scores(&columns, &g, &drawn)?)?;
        }
        let mut out = logits.flatten_all()?.to_vec1::<f32>()?;
        let actions = self.actions.len();
        for (row, legal) in out.chunks_mut(actions).zip(inputs.masks().chunks(actions)) {
            for (l, &ok) in row.iter_mut().zip(legal) {
                if !ok {
                    *l = MASKED;
                }
            }
        }
        Ok(out)
    }

    /// Per decision of `inputs`, the net action with the highest logit among the legal ones (the
    /// first on a tie, as PyTorch's argmax); `None` where none is legal.
    pub fn greedy(&self, inputs: &Inputs) -> Result<Vec<Option<usize>>, NetError> {
        let logits = self.logits(inputs)?;
        let actions = self.actions.len();
        Ok(logits
            .chunks(actions)
            .zip(inputs.masks().chunks(actions))
            .map(|(row, legal)| {
                let mut best: Option<usize> = None;
                for (a, &l) in row.iter().enumerate() {
                    if legal[a] && best.is_none_or(|b| l > row[b]) {
                        best = Some(a);
                    }
                }
                best
            })
            .collect())
    }
}
