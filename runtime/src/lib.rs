//! rinshan runtime
