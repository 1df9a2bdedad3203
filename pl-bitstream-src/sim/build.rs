//! Verilates the PL RTL and compiles the C++ shims that expose each model to
//! Rust through `extern "C"` functions.
//!
//! For every top in `TOPS`: `verilator --cc --build` into `$OUT_DIR/obj_<top>`
//! (Verilator's own makefile compiles the model, in parallel), the archive is
//! renamed `libvtop_<top>.a` so that Cargo can link it, and one
//! `libverilated.a` (the runtime) is linked once. The shims in `csrc/` are
//! compiled with the `cc` crate. Cargo reruns this only when an RTL file, a
//! shim or this script changes, so an unchanged tree builds in no time.
use std::env;
use std::path::{Path, PathBuf};
use std::process::Command;

/// (top module, RTL files under `pl-bitstream-src/rtl`, shim under `csrc/`).
const TOPS: &[(&str, &[&str], &str)] = &[
    (
        "gate_driver",
        &["gate_leg.v", "gate_driver.v"],
        "gate_driver_shim.cpp",
    ),
    (
        "pl_top",
        &[
            "pl_top.v",
            "mpdtc_core.v",
            "mpdtc_seq.v",
            "mpdtc_frontend.v",
            "sin_table.vh",
            "axil_slave.v",
            "pl_regs.v",
            "regmap.vh",
            "sync2.v",
            "adc_frontend.v",
            "encoder_qei.v",
            "fault_block.v",
            "pwm_center.v",
            "gate_driver.v",
            "gate_leg.v",
            "mpdcc_core.v",
            "mpdcc_common.v",
            "mpdcc_explorer.v",
            "mpdcc_lane.v",
            "mpdcc_piece.v",
            "mpdcc_pipe.v",
        ],
        "pl_top_shim.cpp",
    ),
    ("mpdtc_core", &["mpdtc_core.v"], "mpdtc_core_shim.cpp"),
    (
        "mpdtc_frontend",
        &["mpdtc_frontend.v", "sin_table.vh"],
        "mpdtc_frontend_shim.cpp",
    ),
    (
        "mpdcc_lane",
        &["mpdcc_lane.v", "mpdcc_piece.v"],
        "mpdcc_lane_shim.cpp",
    ),
    (
        "mpdcc_explorer",
        &[
            "mpdcc_explorer.v",
            "mpdcc_lane.v",
            "mpdcc_piece.v",
            "mpdcc_pipe.v",
        ],
        "mpdcc_explorer_shim.cpp",
    ),
    (
        "mpdcc_core",
        &[
            "mpdcc_core.v",
            "mpdcc_explorer.v",
            "mpdcc_lane.v",
            "mpdcc_piece.v",
            "mpdcc_pipe.v",
        ],
        "mpdcc_core_shim.cpp",
    ),
    // The same core in pl_top's configuration: explorers with shared
    // search lanes, one candidate every MPDCC_CORE_SHARED_II clocks.
    (
        MPDCC_CORE_SHARED,
        &[
            "mpdcc_core.v",
            "mpdcc_explorer.v",
            "mpdcc_lane.v",
            "mpdcc_piece.v",
            "mpdcc_pipe.v",
        ],
        "mpdcc_core_shared_shim.cpp",
    ),
];

/// The Verilated `mpdcc_core` with `II = MPDCC_CORE_SHARED_II` (the model
/// name; its Verilog top is `mpdcc_core`).
const MPDCC_CORE_SHARED: &str = "mpdcc_core_shared";
/// `II` of pl_top's `mpdcc_core` (regmap::MPDCC_II; the bit-exact runs
/// check the cycle count of this II, so a difference fails them).
const MPDCC_CORE_SHARED_II: u32 = 4;

fn run(cmd: &mut Command) {
    let status = cmd
        .status()
        .unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e} (run scripts/setup)"));
    assert!(status.success(), "{cmd:?} failed with {status}");
}

/// Gate-level option: `RTL_SIM_MPDTC_NETLIST=<netlist.v>` (a yosys
/// `write_verilog` of the synthesised `mpdtc_core`, see `scripts/rtl-gatesim`)
/// makes the `mpdtc_core` harness simulate that netlist with yosys' Xilinx
/// cell models instead of the RTL, so the same bit-exact tests check what
/// synthesis produced.
const NETLIST_ENV: &str = "RTL_SIM_MPDTC_NETLIST";
/// Xilinx cell models for the netlist (`cells_sim.v` of the yosys that
/// wrote it; `scripts/rtl-gatesim` sets it).
const CELLS_ENV: &str = "RTL_SIM_XILINX_CELLS";

/// Explorers instantiated in the Verilated `mpdcc_core` (`n_use_i` selects
/// how many a decision uses, so one model serves `--explorers 1..=6`).
const MPDCC_CORE_EXPLORERS: u32 = 6;

fn verilate(rtl: &Path, out: &Path, top: &str, files: &[&str]) -> PathBuf {
    let netlist = (top == "mpdtc_core")
        .then(|| env::var(NETLIST_ENV).ok())
        .flatten();
    let mdir = out.join(format!("obj_{top}"));
    let mut cmd = Command::new("verilator");
    cmd.arg("--cc")
        .arg("--build")
        .args(["-j", "2"])
        .arg("--no-timing")
        .args([
            "--top-module",
            if top == MPDCC_CORE_SHARED {
                "mpdcc_core"
            } else {
                top
            },
        ])
        .args(["--prefix", &format!("V{top}")])
        .arg("--Mdir")
        .arg(&mdir)
        .args(["-CFLAGS", "-fPIC -O1"])
        .args(["-MAKEFLAGS", "OPT_FAST=-O1 OPT_SLOW=-O1 OPT_GLOBAL=-O1"])
        .arg("-Wno-fatal")
        .arg(format!("-I{}", rtl.display()));
    if top == "mpdcc_core" || top == MPDCC_CORE_SHARED {
        // The most explorers of the table; a run uses n_use_i of them.
        cmd.arg(format!("-GN={MPDCC_CORE_EXPLORERS}"));
    }
    if top == MPDCC_CORE_SHARED {
        cmd.arg(format!("-GII={MPDCC_CORE_SHARED_II}"));
    }
    if let Some(n) = netlist {
        // The cell models of the yosys that wrote the netlist: `CELLS_ENV`,
        // else those next to the yosys on PATH (<prefix>/share/yosys).
        let cells = match env::var(CELLS_ENV) {
            Ok(c) => PathBuf::from(c),
            Err(_) => {
                let bin = String::from_utf8(
                    Command::new("sh")
                        .args(["-c", "command -v yosys"])
                        .output()
                        .expect("sh")
                        .stdout,
                )
                .unwrap();
                PathBuf::from(bin.trim())
                    .parent()
                    .and_then(Path::parent)
                    .map(Path::to_path_buf)
                    .expect("yosys not found")
                    .join("share/yosys/xilinx/cells_sim.v")
            }
        };
        println!("cargo:rerun-if-changed={n}");
        println!("cargo:warning=mpdtc_core: simulating the gate-level netlist {n}");
        cmd.args(["-Wno-lint", "-Wno-style"]).arg(n).arg(cells);
    } else {
        for f in files.iter().filter(|f| f.ends_with(".v")) {
            cmd.arg(rtl.join(f));
        }
    }
    run(&mut cmd);
    let lib = out.join(format!("libvtop_{top}.a"));
    std::fs::copy(mdir.join(format!("V{top}__ALL.a")), &lib).expect("copy model archive");
    mdir
}

/// The Verilator runtime (`verilated.o`, `verilated_threads.o`), built once
/// with the flags of Verilator's makefile, as `libverilated.a`.
fn runtime(out: &Path, mdir: &Path, top: &str) {
    let objs = ["verilated.o", "verilated_threads.o"];
    run(Command::new("make")
        .args(["-j", "2", "-s", "-C"])
        .arg(mdir)
        .args(["-f", &format!("V{top}.mk")])
        .arg("OPT_GLOBAL=-O1")
        .arg("VM_USER_CFLAGS=-fPIC")
        .args(objs));
    let lib = out.join("libverilated.a");
    let _ = std::fs::remove_file(&lib);
    run(Command::new("ar")
        .arg("rcs")
        .arg(&lib)
        .args(objs.iter().map(|o| mdir.join(o))));
}

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    let rtl = manifest.join("../rtl");
    let out = PathBuf::from(env::var("OUT_DIR").unwrap());
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed={NETLIST_ENV}");
    println!("cargo:rerun-if-env-changed={CELLS_ENV}");

    let vroot = String::from_utf8(
        Command::new("verilator")
            .arg("--getenv")
            .arg("VERILATOR_ROOT")
            .output()
            .expect("verilator not found (run scripts/setup)")
            .stdout,
    )
    .unwrap();
    let vinc = PathBuf::from(vroot.trim()).join("include");

    let mut shim = cc::Build::new();
    shim.cpp(true)
        .std("c++17")
        .opt_level(1)
        .include(&vinc)
        .include(vinc.join("vltstd"))
        .flag_if_supported("-Wno-unused-parameter");
    let mut models = Vec::new();
    for (top, files, shim_src) in TOPS {
        for f in *files {
            println!("cargo:rerun-if-changed={}", rtl.join(f).display());
        }
        let src = manifest.join("csrc").join(shim_src);
        println!("cargo:rerun-if-changed={}", src.display());
        // The port accessors a core's shim includes (generated from its RTL).
        let ports = manifest.join("csrc").join(format!("{top}_ports.h"));
        if ports.exists() {
            println!("cargo:rerun-if-changed={}", ports.display());
        }
        let mdir = verilate(&rtl, &out, top, files);
        if models.is_empty() {
            runtime(&out, &mdir, top);
        }
        shim.include(&mdir).file(src);
        models.push(*top);
    }
    shim.compile("rtl_shims");
    // Static link order: shims, then models, then the Verilator runtime.
    println!("cargo:rustc-link-search=native={}", out.display());
    for top in models {
        println!("cargo:rustc-link-lib=static=vtop_{top}");
    }
    println!("cargo:rustc-link-lib=static=verilated");
    println!("cargo:rustc-env=RTL_SIM_MPDCC_CORE_SHARED_II={MPDCC_CORE_SHARED_II}");
    println!("cargo:rustc-link-lib=dylib=stdc++");
    println!("cargo:rustc-link-lib=dylib=pthread");
}
