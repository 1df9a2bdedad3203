//! `boardgen`: generate and check the files derived from the board files.
//!
//!   boardgen gen                      write boards/<name>.xdc, -ps7.tcl, -pins.md
//!   boardgen check                    pins vs board_top ports, generated files fresh
//!   boardgen bd-check --facts FILE [--board NAME]
//!                                     block design recorded by scripts/vivado/stub-run.tcl
//!                                     vs the ps_bd stand-in, register map and board file
//!   boardgen standin --fsbl F --bit B [--board NAME]
//!                                     stand-in FSBL ELF and bitstream for bootgen tests
//!   boardgen boot-check --image BOOT.BIN --fsbl F --firmware ELF
//!                                     partition order and content of a boot image
//! `--root DIR` (any command) selects the repository (default: this checkout).
use boardgen::{board_names, check, generated, image, load_board, top_ports};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const USAGE: &str = "usage: boardgen gen | check | bd-check --facts FILE [--board NAME] | standin --fsbl F --bit B [--board NAME] | \
boot-check --image BOOT.BIN --fsbl F --firmware ELF   [--root DIR]";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("boardgen: {e}");
            ExitCode::FAILURE
        }
    }
}

/// `--key value` options after the command.
fn options(args: &[String], allowed: &[&str]) -> Result<Vec<(String, String)>, String> {
    let mut out = Vec::new();
    let mut it = args.iter();
    while let Some(k) = it.next() {
        if k == "-h" || k == "--help" {
            return Err(USAGE.into());
        }
        if !allowed.contains(&k.as_str()) && k != "--root" {
            return Err(format!("unknown option `{k}`\n{USAGE}"));
        }
        let v = it.next().ok_or_else(|| format!("`{k}` needs a value"))?;
        out.push((k.clone(), v.clone()));
    }
    Ok(out)
}

fn get<'a>(opts: &'a [(String, String)], key: &str) -> Option<&'a str> {
    opts.iter()
        .rev()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
}

fn need<'a>(opts: &'a [(String, String)], key: &str) -> Result<&'a str, String> {
    get(opts, key).ok_or_else(|| format!("missing `{key}`\n{USAGE}"))
}

fn read(p: &str) -> Result<Vec<u8>, String> {
    std::fs::read(p).map_err(|e| format!("{p}: {e}"))
}

fn write(p: &Path, data: &[u8]) -> Result<(), String> {
    std::fs::write(p, data).map_err(|e| format!("{}: {e}", p.display()))
}

fn run(args: &[String]) -> Result<(), String> {
    let Some((cmd, rest)) = args.split_first() else {
        return Err(USAGE.into());
    };
    let allowed: &[&str] = match cmd.as_str() {
        "gen" | "check" => &[],
        "standin" => &["--fsbl", "--bit", "--board"],
        "bd-check" => &["--facts", "--board"],
        "boot-check" => &["--image", "--fsbl", "--firmware"],
        "-h" | "--help" | "help" => {
            println!("{USAGE}");
            return Ok(());
        }
        other => return Err(format!("unknown command `{other}`\n{USAGE}")),
    };
    let opts = options(rest, allowed)?;
    let root = get(&opts, "--root")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("../.."));
    match cmd.as_str() {
        "gen" => {
            let ports = top_ports(&root)?;
            for name in board_names(&root)? {
                let b = load_board(&root, &name)?;
                for (path, text) in generated(&b, &ports) {
                    write(&root.join(&path), text.as_bytes())?;
                    println!("boardgen: wrote {}", path.display());
                }
            }
            Ok(())
        }
        "check" => {
            let ports = top_ports(&root)?;
            let mut problems = Vec::new();
            let names = board_names(&root)?;
            for name in &names {
                let b = load_board(&root, name)?;
                for p in check::port_problems(&b, &ports) {
                    problems.push(format!("boards/{name}.toml: {p}"));
                }
                for (path, text) in generated(&b, &ports) {
                    let on_disk = std::fs::read_to_string(root.join(&path)).unwrap_or_default();
                    if on_disk != text {
                        problems.push(format!(
                            "{} is stale or missing: run `cargo run -p boardgen -- gen`",
                            path.display()
                        ));
                    }
                }
                let pl = ports.iter().filter(|p| !check::is_ps_port(&p.name)).count();
                println!(
                    "boardgen: {name}: {} pins on the {pl} PL ports of {} ({} PS ports left to the PS7)",
                    b.pins.len(),
                    boardgen::TOP_MODULE,
                    ports.len() - pl
                );
            }
            if problems.is_empty() {
                println!(
                    "boardgen: {} board file(s) consistent with {}, generated files fresh",
                    names.len(),
                    boardgen::TOP_FILE
                );
                Ok(())
            } else {
                Err(problems.join("\n"))
            }
        }
        "bd-check" => {
            let b = load_board(&root, get(&opts, "--board").unwrap_or("zedboard"))?;
            let facts = String::from_utf8_lossy(&read(need(&opts, "--facts")?)?).into_owned();
            let stub_path = root.join(boardgen::bd::PS_BD_STUB);
            let src = std::fs::read_to_string(&stub_path)
                .map_err(|e| format!("{}: {e}", stub_path.display()))?;
            let stub = boardgen::verilog::module_ports(&src, "ps_bd").map_err(|e| e.0)?;
            let problems = boardgen::bd::problems(&facts, &stub, &b);
            if !problems.is_empty() {
                return Err(problems.join("\n"));
            }
            println!(
                "boardgen: block design: {} ports as in {}, PL window 0x{:08X}, FCLK0 {} MHz",
                stub.len(),
                boardgen::bd::PS_BD_STUB,
                regmap::BASE_ADDR,
                boardgen::gen::mhz(regmap::PL_CLOCK_HZ)
            );
            Ok(())
        }
        "standin" => {
            let name = get(&opts, "--board").unwrap_or("zedboard");
            let b = load_board(&root, name)?;
            // A stand-in FSBL in OCM at 0x0, as the real one.
            write(
                Path::new(need(&opts, "--fsbl")?),
                &image::standin_elf(0, 64),
            )?;
            write(
                Path::new(need(&opts, "--bit")?),
                &image::standin_bit(boardgen::TOP_MODULE, &b.board.part),
            )?;
            Ok(())
        }
        "boot-check" => {
            let img = read(need(&opts, "--image")?)?;
            let fsbl = read(need(&opts, "--fsbl")?)?;
            let fw = read(need(&opts, "--firmware")?)?;
            let parts = image::read_boot_image(&img).map_err(|e| e.0)?;
            for (i, p) in parts.iter().enumerate() {
                println!(
                    "boardgen: partition {i}: {:<14} {:?} load {:#010x} exec {:#010x} {} bytes",
                    p.name,
                    p.dest,
                    p.load,
                    p.exec,
                    p.data.len()
                );
            }
            image::check_boot_order(&parts, &fsbl, &fw).map_err(|e| e.0)?;
            println!("boardgen: boot image order FSBL, bitstream, firmware: ok");
            Ok(())
        }
        _ => unreachable!("commands are matched above"),
    }
}
