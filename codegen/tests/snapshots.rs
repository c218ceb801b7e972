//! Reviewed snapshots of the generated code: a change to the spec or the emitter shows up as a
//! diff to review (`cargo insta review`). Insta never writes snapshots under CI.

use crate::common::*;
use rinshan_codegen::generate;

#[test]
fn red_kernel_rust() {
    insta::assert_snapshot!(generate(&load_real("red")).kernel_rust);
}

#[test]
fn red_host_rust() {
    insta::assert_snapshot!(generate(&load_real("red")).host_rust);
}

#[test]
fn no_red_kernel_rust() {
    insta::assert_snapshot!(generate(&load_real("no_red")).kernel_rust);
}

#[test]
fn no_red_host_rust() {
    insta::assert_snapshot!(generate(&load_real("no_red")).host_rust);
}
