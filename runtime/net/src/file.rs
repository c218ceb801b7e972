//! A net's safetensors export, read and checked. The file holds the PyTorch state dict's tensors
//! under their names and, in its metadata, the net's shape (`config`), its action names
//! (`actions`) and the observation layout it was trained on; anything that does not fit this
//! engine is refused with the reason, never misread.

use std::collections::HashMap;
use std::path::Path;

use candle_core::{DType, Device, Tensor};
use rinshan_engine::observe::{Form, PLANE_ROWS};
use safetensors::SafeTensors;
use serde_json::Value;

use crate::model::{Linear, TileHead};

/// What the metadata's `format` must say, and the layout versions this reader knows.
const FORMAT: &str = "rinshan-net";
const VERSIONS: [&str; 1] = ["1"];

/// Why a net cannot be read or run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NetError {
    message: String,
}

impl NetError {
    pub(crate) fn new(message: impl Into<String>) -> NetError {
        NetError {
            message: message.into(),
        }
    }
}

impl std::fmt::Display for NetError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for NetError {}

impl From<candle_core::Error> for NetError {
    fn from(e: candle_core::Error) -> NetError {
        NetError::new(format!("the net's forward pass failed: {e}"))
    }
}

/// A policy net: masked logits over its action names, from a seat's observation.
#[derive(Debug)]
pub struct Net {
    /// The action names its logits are indexed by (the red variant's, for the training example's
    /// nets).
    pub actions: Vec<String>,
    /// The analysis form's fields it reads as rows under the planes, in order.
    pub analysis: Vec<&'static str>,
    /// The name it is reported under (the file's stem).
    pub name: String,
    pub(crate) torso: Vec<Linear>,
    pub(crate) head: Linear,
    /// Per input row, its scale (rows, 1).
    pub(crate) row_scale: Tensor,
    pub(crate) scalar_mean: Tensor,
    pub(crate) scalar_std: Tensor,
    pub(crate) tile_head: Option<TileHead>,
}

/// The planes' rows and the scalars of this engine's planes form.
pub(crate) fn planes_shape() -> (usize, usize) {
    let planes = Form::Planes.field("planes").map_or(0, |f| f.shape[0]);
    let scalars = Form::Planes.field("scalars").map_or(0, |f| f.shape[0]);
    (planes, scalars)
}

/// The planes' row that holds the drawn tile, which the tile head reads for `tsumogiri`.
pub(crate) fn drawn_row() -> usize {
    PLANE_ROWS
        .iter()
        .find(|r| r.name == "drawn")
        .map_or(0, |r| r.row as usize)
}

struct Reader<'a> {
    tensors: SafeTensors<'a>,
    path: String,
}

impl Reader<'_> {
    fn error(&self, what: impl std::fmt::Display) -> NetError {
        NetError::new(format!("{}: {what}", self.path))
    }

    /// Tensor `name` as `dtype`, of the shape `shape` (None: any length on that axis).
    fn tensor(&self, name: &str, dtype: DType, shape: &[Option<usize>]) -> Result<Tensor, NetError> {
        use candle_core::safetensors::Load;
        let view = self
            .tensors
            .tensor(name)
            .map_err(|_| self.error(format!("no tensor `{name}`: not a policy net of the training example")))?;
        let fits = view.shape().len() == shape.len()
            && view
                .shape()
                .iter()
                .zip(shape)
                .all(|(&n, want)| want.is_none_or(|w| w == n));
        if !fits {
            let want: Vec<String> = shape.iter().map(|d| d.map_or("_".into(), |d| d.to_string())).collect();
            return Err(self.error(format!(
                "`{name}` has shape {:?}, not ({})",
                view.shape(),
                want.join(", ")
            )));
        }
        let t = view
            .load(&Device::Cpu)
            .map_err(|e| self.error(format!("`{name}`: {e}")))?;
        if t.dtype() != dtype {
            return Err(self.error(format!("`{name}` is {:?}, not {dtype:?}", t.dtype())));
        }
        Ok(t)
    }

    /// The linear layer `name` (`name.weight` (out, in), `name.bias` (out)) from `inputs` to any width.
    fn linear(&self, name: &str, inputs: usize) -> Result<Linear, NetError> {
        let weight = self.tensor(&format!("{name}.weight"), DType::F32, &[None, Some(inputs)])?;
        let out = weight.dims()[0];
        let bias = self.tensor(&format!("{name}.bias"), DType::F32, &[Some(out)])?;
        Ok(Linear::new(&weight, bias)?)
    }
}

fn meta<'a>(path: &str, metadata: &'a HashMap<String, String>, key: &str) -> Result<&'a str, NetError> {
    metadata
        .get(key)
        .map(String::as_str)
        .ok_or_else(|| NetError::new(format!("{path}: the metadata has no `{key}`")))
}

fn json(path: &str, key: &str, text: &str) -> Result<Value, NetError> {
    serde_json::from_str(text).map_err(|e| NetError::new(format!("{path}: metadata `{key}` is not JSON: {e}")))
}

impl Net {
    /// Reads the net exported at `path` (examples/train/export.py).
    pub fn load(path: impl AsRef<Path>) -> Result<Net, NetError> {
        let path = path.as_ref();
        let shown = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| NetError::new(format!("{shown}: {e}")))?;
        let name = path
            .file_stem()
            .map_or("net".into(), |s| s.to_string_lossy().into_owned());
        Net::from_bytes(&bytes, &shown, name)
    }

    /// Reads a net from the bytes of its file; `path` names it in errors, `name` in reports.
    pub fn from_bytes(bytes: &[u8], path: &str, name: String) -> Result<Net, NetError> {
        let not_safetensors =
            |e: safetensors::SafeTensorError| NetError::new(format!("{path}: not a safetensors file ({e})"));
        let (_, header) = SafeTensors::read_metadata(bytes).map_err(not_safetensors)?;
        let empty = HashMap::new();
        let metadata = header.metadata().as_ref().unwrap_or(&empty);
        let format = meta(path, metadata, "format")?;
        let version = meta(path, metadata, "version")?;
        if format != FORMAT || !VERSIONS.contains(&version) {
            return Err(NetError::new(format!(
                "{path}: a `{format}` file of version {version}; this reader takes {FORMAT} version {}",
                VERSIONS.join(", ")
            )));
        }
        let (planes, scalars) = planes_shape();
        for (key, ours) in [("plane_rows", planes), ("scalars", scalars)] {
            let theirs = meta(path, metadata, key)?;
            if theirs != ours.to_string() {
                return Err(NetError::new(format!(
                    "{path}: trained on observations of {theirs} {key}; this engine's have {ours}: export it again from a net trained on this version"
                )));
            }
        }
        let analysis = analysis_rows(
            path,
            &json(path, "analysis_rows", meta(path, metadata, "analysis_rows")?)?,
        )?;
        let actions: Vec<String> = match json(path, "actions", meta(path, metadata, "actions")?)? {
            Value::Array(names) => names.iter().filter_map(|n| n.as_str().map(String::from)).collect(),
            _ => Vec::new(),
        };
        if actions.is_empty() {
            return Err(NetError::new(format!(
                "{path}: metadata `actions` is not a list of action names"
            )));
        }
        let config = json(path, "config", meta(path, metadata, "config")?)?;
        let layers = config["layers"].as_u64().unwrap_or(0) as usize;
        if layers == 0 || config["extra"].as_u64().unwrap_or(0) != 0 {
            return Err(NetError::new(format!(
                "{path}: config {config} is not a policy net's (layers >= 1, no extra inputs)"
            )));
        }
        let tensors = SafeTensors::deserialize(bytes).map_err(not_safetensors)?;
        let r = Reader {
            tensors,
            path: path.to_string(),
        };
        let rows = planes + analysis.len();
        let mut width = rows * 34 + scalars;
        let mut torso = Vec::with_capacity(layers);
        for i in 0..layers {
            // nn.Sequential numbers a Linear and its ReLU: the linear layers are 0, 2, 4 ...
            let layer = r.linear(&format!("torso.{}", 2 * i), width)?;
            width = layer.outputs();
            torso.push(layer);
        }
        let head = r.linear("head", width)?;
        if head.outputs() != actions.len() {
            return Err(r.error(format!("{} logits for {} action names", head.outputs(), actions.len())));
        }
        let tile_head = if config["tile_head"].as_bool().unwrap_or(false) {
            let context = r.linear("tile_context", width)?;
            let first = r.linear("tile_head.0", rows + context.outputs())?;
            let second = r.linear("tile_head.2", first.outputs())?;
            if second.outputs() != 1 {
                return Err(r.error("`tile_head.2` gives more than one score per tile"));
            }
            let a = Some(actions.len());
            let column = r.tensor("discard_column", DType::I64, &[a])?;
            let is_discard = r.tensor("is_discard", DType::F32, &[a])?;
            let columns: Vec<i64> = column.to_vec1()?;
            if columns.iter().any(|&c| !(0..=34).contains(&c)) {
                return Err(r.error("`discard_column` holds a column outside 0..=34"));
            }
            Some(TileHead::new(rows, context, first, second, column, is_discard)?)
        } else {
            None
        };
        Ok(Net {
            name,
            torso,
            head,
            row_scale: r.tensor("row_scale", DType::F32, &[Some(rows), Some(1)])?,
            scalar_mean: r.tensor("scalar_mean", DType::F32, &[Some(scalars)])?,
            scalar_std: r.tensor("scalar_std", DType::F32, &[Some(scalars)])?,
            tile_head,
            actions,
            analysis,
        })
    }

    /// Input rows per decision: the planes' and the analysis rows'.
    pub fn rows(&self) -> usize {
        planes_shape().0 + self.analysis.len()
    }
}

/// The analysis fields named in the metadata, each one of this engine's with 34 values.
fn analysis_rows(path: &str, names: &Value) -> Result<Vec<&'static str>, NetError> {
    let Value::Array(names) = names else {
        return Err(NetError::new(format!("{path}: metadata `analysis_rows` is not a list")));
    };
    names
        .iter()
        .map(|n| {
            let name = n.as_str().unwrap_or_default();
            match Form::Analysis.field(name) {
                Some(f) if f.shape == [34] => Ok(f.name),
                _ => Err(NetError::new(format!(
                    "{path}: the net reads analysis row `{name}`, which this engine's analysis form lacks"
                ))),
            }
        })
        .collect()
}
