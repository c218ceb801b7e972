//! naga parse + validation of emitted WGSL.

use naga::valid::{Capabilities, ValidationFlags, Validator};

/// Parse + validate WGSL with naga; `Err` carries naga's message with the WGSL location.
pub fn validate(wgsl: &str) -> Result<naga::Module, String> {
    validate_with_info(wgsl).map(|(module, _)| module)
}

/// Like [`validate`], but also returns the analysis backends need.
pub fn validate_with_info(wgsl: &str) -> Result<(naga::Module, naga::valid::ModuleInfo), String> {
    let module = naga::front::wgsl::parse_str(wgsl).map_err(|e| e.emit_to_string(wgsl))?;
    let info = Validator::new(ValidationFlags::all(), Capabilities::default())
        .validate(&module)
        .map_err(|e| e.emit_to_string(wgsl))?;
    Ok((module, info))
}
