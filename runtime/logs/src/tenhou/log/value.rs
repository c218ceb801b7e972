//! Reading plain JSON values of a log, with messages that quote the value.

use serde_json::Value;

/// A JSON value for messages, cut short when long (a whole round would drown the message).
pub(super) fn show(v: &Value) -> String {
    const MAX: usize = 60;
    let text = v.to_string();
    match text.char_indices().nth(MAX) {
        Some((cut, _)) => format!("{}...", &text[..cut]),
        None => text,
    }
}

/// `N` integers that fit an i32.
pub(super) fn numbers<const N: usize>(v: &Value) -> Result<[i32; N], String> {
    let items = v
        .as_array()
        .ok_or_else(|| format!("{} is not a list of {N} integers", show(v)))?;
    if items.len() != N {
        return Err(format!(
            "{} has {} entries, expected {N} integers",
            show(v),
            items.len()
        ));
    }
    let mut out = [0; N];
    for (slot, item) in out.iter_mut().zip(items) {
        let n = item.as_i64().and_then(|n| i32::try_from(n).ok());
        *slot = n.ok_or_else(|| format!("{} in {} is not an integer", show(item), show(v)))?;
    }
    Ok(out)
}
