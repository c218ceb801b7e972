//! Kernel subset -> WGSL translator.
