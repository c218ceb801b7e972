//! A batch of decisions as the net reads them: per decision the planes with the analysis rows
//! under them (as counts, scaled by the net), the scalars, the drawn tile's column and the legal
//! actions in the net's action order.

use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::observe::{field_values, record, Dtype, Form};
use rinshan_engine::Variant;

use crate::file::{drawn_row, planes_shape, NetError};

/// One decision's observation as the net reads it: the planes form's rows and then the analysis
/// form's fields named, a signed field shifted up by one so that "none" (-1) is 0 (as the
/// training example's `rows`), and the scalars.
#[derive(Debug, Clone)]
pub struct Decision {
    rows: Vec<f32>,
    scalars: Vec<f32>,
}

impl Decision {
    /// The decision of the player to move in `state`.
    pub fn of(variant: Variant, state: &GameState, analysis: &[&str]) -> Decision {
        let planes = record(variant, Form::Planes, state, 4);
        let extra = if analysis.is_empty() {
            Vec::new()
        } else {
            record(variant, Form::Analysis, state, 4)
        };
        let mut rows: Vec<f32> = field_values(Form::Planes, &planes, "planes")
            .into_iter()
            .map(|v| v as f32)
            .collect();
        for name in analysis {
            let shift = match Form::Analysis.field(name).map(|f| f.dtype) {
                Some(Dtype::I8 | Dtype::I16) => 1,
                _ => 0,
            };
            rows.extend(
                field_values(Form::Analysis, &extra, name)
                    .into_iter()
                    .map(|v| (v + shift) as f32),
            );
        }
        let scalars = field_values(Form::Planes, &planes, "scalars")
            .into_iter()
            .map(|v| v as f32)
            .collect();
        Decision { rows, scalars }
    }
}

/// Decisions for one forward pass.
#[derive(Debug, Clone, Default)]
pub struct Inputs {
    rows: usize,
    actions: usize,
    planes: Vec<f32>,
    /// The same values tile by tile (34 x rows per decision): the tile head reads each tile's
    /// column, and a transpose on the host is cheaper than candle's strided copy.
    columns: Vec<f32>,
    scalars: Vec<f32>,
    drawn: Vec<u32>,
    masks: Vec<bool>,
}

impl Inputs {
    /// An empty batch of decisions with `analysis` rows under the planes, for a net of `actions`
    /// logits.
    pub fn new(analysis: usize, actions: usize) -> Inputs {
        Inputs {
            rows: planes_shape().0 + analysis,
            actions,
            ..Inputs::default()
        }
    }

    /// Adds a decision made by [`Decision::of`].
    pub fn push_decision(&mut self, d: &Decision, legal: impl Fn(usize) -> bool) {
        // The engine's own records have the layout `Net::load` checked.
        let _ = self.push(&d.rows, &d.scalars, legal);
    }

    /// Adds a decision from its rows (rows x 34 counts, row-major) and scalars (raw values).
    pub fn push(&mut self, rows: &[f32], scalars: &[f32], legal: impl Fn(usize) -> bool) -> Result<(), NetError> {
        let want = planes_shape().1;
        if rows.len() != self.rows * 34 || scalars.len() != want {
            return Err(NetError::new(format!(
                "a decision of {} row values and {} scalars; the net reads {} x 34 and {want}",
                rows.len(),
                scalars.len(),
                self.rows
            )));
        }
        let d = drawn_row() * 34;
        // The first column of the largest count, as PyTorch's argmax (column 0 when none is drawn;
        // the tile head's `tsumogiri` score is then never legal to play).
        let drawn = rows.get(d..d + 34).map_or(0, |row| {
            row.iter()
                .enumerate()
                .fold(0, |best, (i, &v)| if v > row[best] { i } else { best })
        });
        self.planes.extend_from_slice(rows);
        for t in 0..34 {
            self.columns.extend(rows.iter().skip(t).step_by(34));
        }
        self.scalars.extend_from_slice(scalars);
        self.drawn.push(drawn as u32);
        self.masks.extend((0..self.actions).map(legal));
        Ok(())
    }

    /// Decisions held.
    pub fn len(&self) -> usize {
        self.drawn.len()
    }

    /// Whether it holds no decision.
    pub fn is_empty(&self) -> bool {
        self.drawn.is_empty()
    }

    /// Empties it for the next batch, keeping its memory.
    pub fn clear(&mut self) {
        self.planes.clear();
        self.columns.clear();
        self.scalars.clear();
        self.drawn.clear();
        self.masks.clear();
    }

    pub(crate) fn rows(&self) -> usize {
        self.rows
    }

    pub(crate) fn actions(&self) -> usize {
        self.actions
    }

    pub(crate) fn planes(&self) -> &[f32] {
        &self.planes
    }

    pub(crate) fn columns(&self) -> &[f32] {
        &self.columns
    }

    pub(crate) fn scalars(&self) -> &[f32] {
        &self.scalars
    }

    pub(crate) fn drawn(&self) -> &[u32] {
        &self.drawn
    }

    pub(crate) fn masks(&self) -> &[bool] {
        &self.masks
    }
}
