//! Nets of random weights in the export's layout: what tests and timings play when the point is
//! the machinery (reading, the forward pass, seating), not the play. Trained nets come from
//! examples/train/export.py.

use std::collections::HashMap;

use rinshan_engine::env::action_names;
use rinshan_engine::random::Rng;
use rinshan_engine::{Tile, Variant};
use safetensors::tensor::{Dtype, TensorView};
use serde_json::json;

use crate::file::planes_shape;

/// The shape of a random net (the training example's `Net` arguments).
#[derive(Debug, Clone, Copy)]
pub struct Shape {
    /// Width of the torso's layers.
    pub hidden: usize,
    /// Torso layers.
    pub layers: usize,
    /// Whether it reads the analysis rows (`discard_shanten`, `discard_ukeire`, `improving`).
    pub analysis: bool,
    /// Whether it has the tile head, and its width.
    pub tile_hidden: Option<usize>,
    /// Whether its actions are every variant's (red's, then three players' `kita`), as the
    /// training example's nets are, or red's alone, as nets saved before kita joined them.
    pub kita: bool,
}

impl Default for Shape {
    fn default() -> Shape {
        Shape {
            hidden: 64,
            layers: 2,
            analysis: true,
            tile_hidden: Some(16),
            kita: true,
        }
    }
}

impl Shape {
    /// The default shape in red's actions alone: a net saved before kita joined the layout.
    pub fn red_only() -> Shape {
        Shape {
            kita: false,
            ..Shape::default()
        }
    }
}

/// The analysis rows the training example's nets read.
const ANALYSIS: [&str; 3] = ["discard_shanten", "discard_ukeire", "improving"];

/// Per action name, the column its tile head score comes from: a discard's tile type (a red five
/// is its type's five), 34 for `tsumogiri` (the drawn tile), -1 for the rest. The discards are
/// recognised by the names the engine gives them ([`action_names`]).
pub fn discard_column(name: &str) -> i64 {
    if name == "tsumogiri" {
        return 34;
    }
    (0..=u8::MAX)
        .filter_map(Tile::from_value)
        .find(|t| name.strip_prefix("discard_") == Some(t.to_string().as_str()))
        .map_or(-1, |t| t.kind().index() as i64)
}

/// The bytes of a safetensors file of a net of `shape` with random weights (seeded by `seed`),
/// indexed by red's actions and, with `shape.kita`, those only other variants have after them.
pub fn net_file(shape: Shape, seed: u64) -> Vec<u8> {
    let mut rng = Rng::new(seed);
    let mut uniform = |n: usize, bound: f32| -> Vec<f32> {
        (0..n)
            .map(|_| ((rng.next_u64() >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0) * bound)
            .collect()
    };
    let mut actions = action_names(Variant::Red);
    if shape.kita {
        for name in Variant::ALL.iter().flat_map(|&v| action_names(v)) {
            if !actions.contains(&name) {
                actions.push(name);
            }
        }
    }
    let (planes, scalars) = planes_shape();
    let analysis: &[&str] = if shape.analysis { &ANALYSIS } else { &[] };
    let rows = planes + analysis.len();
    let mut tensors: Vec<(String, Vec<usize>, Vec<f32>)> = Vec::new();
    let mut linear = |tensors: &mut Vec<(String, Vec<usize>, Vec<f32>)>, name: &str, inputs: usize, outputs: usize| {
        // PyTorch's default initialisation: uniform within 1/sqrt(fan-in).
        let bound = 1.0 / (inputs as f32).sqrt();
        tensors.push((
            format!("{name}.weight"),
            vec![outputs, inputs],
            uniform(inputs * outputs, bound),
        ));
        tensors.push((format!("{name}.bias"), vec![outputs], uniform(outputs, bound)));
    };
    let mut width = rows * 34 + scalars;
    for i in 0..shape.layers {
        linear(&mut tensors, &format!("torso.{}", 2 * i), width, shape.hidden);
        width = shape.hidden;
    }
    linear(&mut tensors, "head", width, actions.len());
    if let Some(th) = shape.tile_hidden {
        linear(&mut tensors, "tile_context", width, 32);
        linear(&mut tensors, "tile_head.0", rows + 32, th);
        linear(&mut tensors, "tile_head.2", th, 1);
    }
    let mut stats = Rng::new(seed ^ 0x5ca1a5);
    let mean: Vec<f32> = (0..scalars).map(|_| stats.below(2000) as f32 / 100.0).collect();
    let std: Vec<f32> = (0..scalars).map(|_| 0.5 + stats.below(1000) as f32 / 100.0).collect();
    tensors.push(("scalar_mean".into(), vec![scalars], mean));
    tensors.push(("scalar_std".into(), vec![scalars], std));
    let scale: Vec<f32> = (0..rows).map(|r| if r < planes { 0.25 } else { 1.0 / 16.0 }).collect();
    tensors.push(("row_scale".into(), vec![rows, 1], scale));
    let columns: Vec<i64> = actions.iter().map(|a| discard_column(a)).collect();
    if shape.tile_hidden.is_some() {
        let is_discard = columns.iter().map(|&c| f32::from(u8::from(c >= 0))).collect();
        tensors.push(("is_discard".into(), vec![actions.len()], is_discard));
    }
    let mut bytes: Vec<(String, Vec<usize>, Dtype, Vec<u8>)> = tensors
        .into_iter()
        .map(|(name, shape, v)| (name, shape, Dtype::F32, bytemuck::cast_slice(&v).to_vec()))
        .collect();
    if shape.tile_hidden.is_some() {
        let clamped: Vec<i64> = columns.iter().map(|&c| c.max(0)).collect();
        bytes.push((
            "discard_column".into(),
            vec![actions.len()],
            Dtype::I64,
            bytemuck::cast_slice(&clamped).to_vec(),
        ));
    }
    let config = json!({
        "num_actions": actions.len(),
        "hidden": shape.hidden,
        "layers": shape.layers,
        "analysis": shape.analysis,
        "extra": 0,
        "tile_head": shape.tile_hidden.is_some(),
        "tile_hidden": shape.tile_hidden.unwrap_or(64),
    });
    let metadata = HashMap::from([
        ("format".to_string(), "rinshan-net".to_string()),
        ("version".to_string(), "1".to_string()),
        ("config".to_string(), config.to_string()),
        ("actions".to_string(), json!(actions).to_string()),
        ("plane_rows".to_string(), planes.to_string()),
        ("scalars".to_string(), scalars.to_string()),
        ("analysis_rows".to_string(), json!(analysis).to_string()),
    ]);
    let views: Vec<(String, TensorView<'_>)> = bytes
        .iter()
        .filter_map(|(name, shape, dtype, data)| {
            Some((name.clone(), TensorView::new(*dtype, shape.clone(), data).ok()?))
        })
        .collect();
    safetensors::serialize(views, Some(metadata)).unwrap_or_default()
}
