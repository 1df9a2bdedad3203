//! Writes `pl-bitstream-src/rtl/regmap.vh` and `docs/register-map.md` from
//! `drive::regmap` (run from anywhere in the repository).
use std::path::PathBuf;

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    for (path, text) in [
        (
            rtl_sim::regmap_gen::VERILOG_PATH,
            rtl_sim::regmap_gen::verilog(),
        ),
        (
            rtl_sim::regmap_gen::MARKDOWN_PATH,
            rtl_sim::regmap_gen::markdown(),
        ),
    ] {
        let p = root.join(path);
        if let Err(e) = std::fs::write(&p, text) {
            eprintln!("regmap-gen: cannot write {}: {e}", p.display());
            std::process::exit(1);
        }
        println!("regmap-gen: wrote {path}");
    }
}
