//! The generated register-map files are up to date with `drive::regmap`.
use std::path::PathBuf;

use rtl_sim::regmap_gen::{markdown, verilog, MARKDOWN_PATH, VERILOG_PATH};

fn check(path: &str, want: String) {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(path);
    let got = std::fs::read_to_string(&p).unwrap_or_default();
    assert!(
        got == want,
        "{path} is stale: run `cargo run -p rtl-sim --bin regmap-gen` and commit it"
    );
}

#[test]
fn verilog_header_is_current() {
    check(VERILOG_PATH, verilog());
}

#[test]
fn markdown_table_is_current() {
    check(MARKDOWN_PATH, markdown());
}
