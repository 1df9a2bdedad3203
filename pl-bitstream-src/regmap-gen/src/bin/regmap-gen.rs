//! Writes every file generated from `regmap` (see
//! `regmap_gen::files`; run from anywhere in the repository).
use std::path::PathBuf;

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    for (path, text) in regmap_gen::files(&regmap::BLOCKS) {
        let p = root.join(path);
        if let Err(e) = std::fs::write(&p, text) {
            eprintln!("regmap-gen: cannot write {}: {e}", p.display());
            std::process::exit(1);
        }
        println!("regmap-gen: wrote {path}");
    }
}
