//! The generated register-map files are up to date with `regmap`.
use std::path::PathBuf;

#[test]
fn generated_files_are_current() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let files = regmap_gen::files(&regmap::BLOCKS);
    assert!(files.len() >= 3);
    for (path, want) in files {
        let got = std::fs::read_to_string(root.join(path)).unwrap_or_default();
        assert!(
            got == want,
            "{path} is stale: run `cargo run -p regmap-gen` and commit it"
        );
    }
}
