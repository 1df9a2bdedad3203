//! Links the bare-metal image (memory.x from the repository root, cortex-a-rt's
//! link.x, defmt.x), records the git hash and build profile for `version`,
//! and writes the board's clock constants (boards/<DRIVE_BOARD>.toml, default
//! zedboard) to $OUT_DIR/board.rs for src/board.rs.
use std::{env, fs, path::PathBuf, process::Command};

fn main() {
    let root = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap()).join("..");
    let out = PathBuf::from(env::var("OUT_DIR").unwrap());

    let git = |args: &[&str]| {
        Command::new("git")
            .args(args)
            .current_dir(&root)
            .output()
            .ok()
            .filter(|o| o.status.success())
            .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
    };
    let hash = git(&["rev-parse", "--short=12", "HEAD"]).unwrap_or_else(|| "unknown".into());
    let dirty = git(&["status", "--porcelain", "--untracked-files=no"])
        .map(|s| !s.is_empty())
        .unwrap_or(false);
    let hash = if dirty { format!("{hash}-dirty") } else { hash };
    println!("cargo:rustc-env=FW_GIT_HASH={hash}");
    println!(
        "cargo:rustc-env=FW_PROFILE={}",
        env::var("PROFILE").unwrap()
    );
    // Re-run when HEAD moves (a commit, a checkout) or the index changes.
    // In a worktree `.git` is a file: ask git where HEAD, the index and the
    // branch's ref live.
    let git_dir = git(&["rev-parse", "--absolute-git-dir"]).map(PathBuf::from);
    let common =
        git(&["rev-parse", "--path-format=absolute", "--git-common-dir"]).map(PathBuf::from);
    let head_ref = git(&["rev-parse", "--symbolic-full-name", "HEAD"]);
    let mut watch: Vec<PathBuf> = Vec::new();
    if let Some(d) = &git_dir {
        watch.extend([d.join("HEAD"), d.join("index")]);
    }
    if let (Some(c), Some(r)) = (&common, &head_ref) {
        watch.extend([c.join(r), c.join("packed-refs")]);
    }
    for f in watch.iter().filter(|f| f.exists()) {
        println!("cargo:rerun-if-changed={}", f.display());
    }

    // The board file is the one source of the PS clocks the firmware assumes.
    let board = env::var("DRIVE_BOARD").unwrap_or_else(|_| "zedboard".into());
    println!("cargo:rerun-if-env-changed=DRIVE_BOARD");
    let board_file = root.join("boards").join(format!("{board}.toml"));
    println!("cargo:rerun-if-changed={}", board_file.display());
    let b =
        boardgen::load_board(&root, &board).unwrap_or_else(|e| panic!("DRIVE_BOARD={board}: {e}"));
    fs::write(out.join("board.rs"), boardgen::gen::firmware_consts(&b)).expect("board.rs");

    if env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("none") {
        fs::copy(root.join("memory.x"), out.join("memory.x")).expect("memory.x");
        println!("cargo:rustc-link-search={}", out.display());
        println!("cargo:rerun-if-changed={}", root.join("memory.x").display());
        println!("cargo:rustc-link-arg-bins=-Tlink.x");
        println!("cargo:rustc-link-arg-bins=-Tdefmt.x");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
