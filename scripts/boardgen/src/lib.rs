//! Board files of the predictive servo drive (`boards/<name>.toml`) and
//! everything derived from them: the XDC, the PS7 configuration and the pin
//! table (generated, stale-checked), the consistency of the pins with the
//! real top-level port list (`pl-bitstream-src/board/board_top.v`), the
//! firmware's clock constants, and checks of a `BOOT.BIN`.
pub mod bd;
pub mod board;
pub mod check;
pub mod gen;
pub mod image;
pub mod verilog;

pub use board::{Board, BoardError};

use std::path::{Path, PathBuf};

/// Path of the top level whose ports the board files constrain.
pub const TOP_FILE: &str = "pl-bitstream-src/board/board_top.v";
/// Its module name.
pub const TOP_MODULE: &str = "board_top";

/// The generated files of a board, relative to the repository root, each
/// with its content.
pub fn generated(board: &Board, ports: &[verilog::Port]) -> Vec<(PathBuf, String)> {
    let n = &board.board.name;
    vec![
        (
            Path::new("boards").join(format!("{n}.xdc")),
            gen::xdc(board, ports),
        ),
        (
            Path::new("boards").join(format!("{n}-ps7.tcl")),
            gen::ps7_tcl(board),
        ),
        (
            Path::new("boards").join(format!("{n}-pins.md")),
            gen::pins_md(board),
        ),
    ]
}

/// Reads `boards/<name>.toml` under `root`; the file stem must match
/// `board.name`.
pub fn load_board(root: &Path, name: &str) -> Result<Board, String> {
    let path = root.join("boards").join(format!("{name}.toml"));
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let b = Board::parse(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    if b.board.name != name {
        return Err(format!(
            "{}: board.name is `{}`, the file is `{name}.toml`",
            path.display(),
            b.board.name
        ));
    }
    Ok(b)
}

/// Names of every board file under `root/boards`.
pub fn board_names(root: &Path) -> Result<Vec<String>, String> {
    let dir = root.join("boards");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok())
        .filter_map(|e| {
            let p = e.path();
            (p.extension()? == "toml").then(|| p.file_stem()?.to_str().map(String::from))?
        })
        .collect();
    names.sort();
    Ok(names)
}

/// The ports of board_top under `root`.
pub fn top_ports(root: &Path) -> Result<Vec<verilog::Port>, String> {
    let path = root.join(TOP_FILE);
    let src = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    verilog::module_ports(&src, TOP_MODULE).map_err(|e| format!("{}: {e}", path.display()))
}
