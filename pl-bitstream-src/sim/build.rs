//! Verilates the PL RTL and compiles the C++ shims that expose each model to
//! Rust through `extern "C"` functions.
//!
//! For every top in `TOPS`: `verilator --cc --build` into `$OUT_DIR/obj_<top>`
//! (Verilator's own makefile compiles the model, in parallel), the archive is
//! renamed `libvtop_<top>.a` so that Cargo can link it, and one
//! `libverilated.a` (the runtime) is linked once. The shims in `csrc/` are
//! compiled with the `cc` crate. Cargo reruns this only when an RTL file, a
//! shim or this script changes, so an unchanged tree builds in no time.
//!
//! Each Verilated model is also kept under `<target>/verilated/<top>-<key>`,
//! `<key>` a hash of its RTL files' contents, its options and the Verilator
//! version: the profiles and commands that run this script with their own
//! `OUT_DIR` (`cargo clippy`, `cargo test`, `cargo build --release`) and an
//! edit that leaves a model's files alone reuse it instead of compiling it
//! again.
use std::collections::hash_map::DefaultHasher;
use std::env;
use std::hash::{Hash, Hasher};
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
            "capture_buf.v",
            "ctrl_irq.v",
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
            "mpdcc_common.v",
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
            "mpdcc_common.v",
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

/// Gate-level option: `RTL_SIM_NETLIST_<MODEL>=<netlist.v>` (`<MODEL>` the
/// model's name in upper case: `MPDTC_CORE`, `MPDTC_FRONTEND`,
/// `MPDCC_CORE_SHARED`), a yosys `write_verilog` of that top synthesised for
/// the xc7 (see `scripts/rtl-gatesim`), makes the model's harness simulate
/// that netlist with yosys' Xilinx cell models instead of the RTL, so the
/// same bit-exact checks (`rtl-check`, the tests) check what synthesis
/// produced.
fn netlist_env(top: &str) -> String {
    format!("RTL_SIM_NETLIST_{}", top.to_uppercase())
}
/// C++ optimisation of a netlist's model: -O1 for the per-cycle code
/// (Verilator's `OPT_FAST` files), none for the rest (`OPT_SLOW`: the
/// constructors and the initial settling of thousands of cell instances,
/// the larger part of the generated code). For the `mpdtc_frontend`
/// netlist (2,398 cells) this builds in 38 s of CPU instead of 37 s at -O0
/// throughout, and its 20,000 vectors take about 3 s of CPU instead of 34 s
/// (docs/rtl.md, "Gate level").
const NETLIST_OPT: &str = "OPT_FAST=-O1 OPT_SLOW=-O0 OPT_GLOBAL=-O0";
/// The models that can run a netlist.
const NETLIST_TOPS: [&str; 3] = ["mpdtc_core", "mpdtc_frontend", MPDCC_CORE_SHARED];
/// Xilinx cell models for the netlist (`cells_sim.v` of the yosys that
/// wrote it; `scripts/rtl-gatesim` sets it).
const CELLS_ENV: &str = "RTL_SIM_XILINX_CELLS";
/// `<dir>`: the cache of Verilated RTL models to use instead of
/// `<target>/verilated` (`scripts/rtl-gatesim` builds in its own target
/// directory and shares the RTL models of the main one).
const CACHE_ENV: &str = "RTL_SIM_VERILATED_CACHE";

/// Explorers instantiated in the Verilated `mpdcc_core` (`n_use_i` selects
/// how many a decision uses, so one model serves `--explorers 1..=6`).
const MPDCC_CORE_EXPLORERS: u32 = 6;

/// C++ optimisation of a model's per-cycle code (Verilator's `OPT_FAST`
/// files; the `OPT_SLOW` constructors stay at -O1). `pl_top` runs millions
/// of cycles in the co-simulation, where -O2 takes about 5 % less CPU per
/// cycle (docs/speed.md); the cores' checks are short and keep the quicker
/// -O1 build.
fn opt_fast(top: &str) -> &'static str {
    if top == "pl_top" {
        "-O2"
    } else {
        "-O1"
    }
}

/// Verilog defines of a model. `pl_top`: `SIM_MPDCC_CLOCK_GATE`, the MPDCC
/// core clocked only in reset and while a decision runs (`pl_top.v`), so the
/// co-simulation does not evaluate the idle core on every edge (about half
/// of `pl_top`'s evaluation time, docs/speed.md); `SIM_MPDTC_CLOCK_GATE`,
/// the same for the MPDTC core (busy 39 of about 1,564 cycles a period);
/// `SIM_REGS_CLOCK_GATE`, the register file clocked only around its bus
/// accesses (about 20 of 1,564 cycles a period in the co-simulation);
/// `SIM_FE_CLOCK_GATE`, the MPDTC front end clocked only in reset, at a
/// start and for 16 edges after either (one start a period).
fn defines(top: &str) -> &'static [&'static str] {
    if top == "pl_top" {
        &[
            "+define+SIM_MPDCC_CLOCK_GATE",
            "+define+SIM_MPDTC_CLOCK_GATE",
            "+define+SIM_REGS_CLOCK_GATE",
            "+define+SIM_FE_CLOCK_GATE",
        ]
    } else {
        &[]
    }
}

fn verilate(rtl: &Path, out: &Path, top: &str, files: &[&str]) -> PathBuf {
    let netlist = NETLIST_TOPS
        .contains(&top)
        .then(|| env::var(netlist_env(top)).ok())
        .flatten()
        .map(|n| (PathBuf::from(n), xilinx_cells()));
    // The cached model, when there is a target directory (a netlist's
    // model under its own key: the netlist's and cell models' contents).
    let cached = cache_root(out).map(|root| match &netlist {
        None => root.join(format!("{top}-{:016x}", model_key(rtl, top, files))),
        Some((n, cells)) => root.join(format!("{top}-gl-{:016x}", netlist_key(top, n, cells))),
    });
    if let Some(dir) = cached.as_ref().filter(|d| d.join(DONE).exists()) {
        copy_model(out, dir, top);
        return dir.clone();
    }
    // Built in a fresh directory, moved into the cache when complete.
    let mdir = match &cached {
        Some(dir) => dir.with_extension(format!("tmp{}", std::process::id())),
        None => out.join(format!("obj_{top}")),
    };
    if cached.is_some() {
        let _ = std::fs::remove_dir_all(&mdir);
        std::fs::create_dir_all(&mdir).expect("create the model directory");
    }
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
        .args([
            "-MAKEFLAGS",
            &if netlist.is_some() {
                NETLIST_OPT.to_string()
            } else {
                format!("OPT_FAST={} OPT_SLOW=-O1 OPT_GLOBAL=-O1", opt_fast(top))
            },
        ])
        .arg("-Wno-fatal")
        .args(defines(top))
        .arg(format!("-I{}", rtl.display()));
    if (top == "mpdcc_core" || top == MPDCC_CORE_SHARED) && netlist.is_none() {
        // The most explorers of the table; a run uses n_use_i of them (a
        // netlist has its parameters fixed by synthesis).
        cmd.arg(format!("-GN={MPDCC_CORE_EXPLORERS}"));
    }
    if top == MPDCC_CORE_SHARED && netlist.is_none() {
        cmd.arg(format!("-GII={MPDCC_CORE_SHARED_II}"));
    }
    if let Some((n, cells)) = &netlist {
        // the cell models too: their contents are in the model's key, but
        // without this a changed cells_sim.v kept the old model
        println!("cargo:rerun-if-changed={}", n.display());
        println!("cargo:rerun-if-changed={}", cells.display());
        println!(
            "cargo:warning={top}: simulating the gate-level netlist {}",
            n.display()
        );
        cmd.args(["-Wno-lint", "-Wno-style"]).arg(n).arg(cells);
    } else {
        for f in files.iter().filter(|f| f.ends_with(".v")) {
            cmd.arg(rtl.join(f));
        }
    }
    run(&mut cmd);
    let Some(dir) = cached else {
        copy_model(out, &mdir, top);
        return mdir;
    };
    // The Verilator runtime is built in the first model's directory.
    if top == TOPS[0].0 {
        runtime_objs(&mdir, top);
    }
    std::fs::write(mdir.join(DONE), "").expect("mark the model complete");
    // Another build may have stored the same model meanwhile: keep theirs.
    if std::fs::rename(&mdir, &dir).is_err() {
        let _ = std::fs::remove_dir_all(&mdir);
    }
    copy_model(out, &dir, top);
    dir
}

/// `csrc/pl_top_clock.h` gives `pl_top` clock edges without Verilator's
/// input-driven ("ico") region, recomputing only the wires of that region
/// that read `clk_i`: the simulation-only clock gates (MPDCC, MPDTC, register
/// file, MPDTC front end). Fails the build
/// when the generated region reads `clk_i` anywhere else (a new clock-driven
/// wire would go stale there).
fn check_input_region(mdir: &Path) {
    let gates_src = [
        "pl_top__DOT__mc_clk = ((IData)(vlSelf->clk_i)",
        "pl_top__DOT__mt_clk = ((IData)(vlSelf->clk_i)",
        "pl_top__DOT__rg_clk = ((IData)(vlSelf->clk_i)",
        "pl_top__DOT__fe_clk = ((IData)(vlSelf->clk_i)",
    ];
    let (mut reads, mut gates) = (0, 0);
    for entry in std::fs::read_dir(mdir).expect("read the pl_top model directory") {
        let path = entry.expect("model directory entry").path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if !(name.starts_with("Vpl_top___024root__DepSet_") && name.ends_with(".cpp")) {
            continue;
        }
        let text = std::fs::read_to_string(&path).expect("read a generated file");
        let mut inside = false;
        for line in text.lines() {
            if !inside {
                inside = line.contains("___ico_sequent") && line.trim_end().ends_with('{');
                continue;
            }
            if line == "}" {
                inside = false;
                continue;
            }
            reads += line.matches("vlSelf->clk_i").count();
            gates += gates_src.iter().filter(|g| line.contains(*g)).count();
        }
    }
    assert!(
        reads == gates_src.len() && gates == gates_src.len(),
        "pl_top's input-driven region reads clk_i {reads} times, in the clock gates {gates} \
         times: csrc/pl_top_clock.h assumes the gates alone (once each)"
    );
}

/// Marks a complete model directory in the cache.
const DONE: &str = "complete";

/// `<target>/verilated`: `OUT_DIR` is `<target>/<profile>/build/<pkg>/out`,
/// recognised by the profile directory's `.fingerprint` (`None` if that is
/// not so: then nothing is cached). Not by `<target>/CACHEDIR.TAG`: cargo
/// writes that only into a target directory it creates itself, and
/// `scripts/setup` creates `target/` first (its venvs), so on a fresh clone
/// every profile and the gate-level build Verilated every model again.
fn cache_root(out: &Path) -> Option<PathBuf> {
    if let Ok(dir) = env::var(CACHE_ENV) {
        return Some(PathBuf::from(dir));
    }
    let mut up = out.ancestors().skip(2);
    let (build, profile, target) = (up.next()?, up.next()?, up.next()?);
    (build.file_name() == Some("build".as_ref()) && profile.join(".fingerprint").is_dir())
        .then(|| target.join("verilated"))
}

/// The cache key of a model: its name, options, RTL file contents and the
/// Verilator version.
fn model_key(rtl: &Path, top: &str, files: &[&str]) -> u64 {
    let mut h = DefaultHasher::new();
    (top, opt_fast(top), MPDCC_CORE_EXPLORERS, KEY_VERSION).hash(&mut h);
    // Hashed only where there are some: the other models keep their keys.
    if !defines(top).is_empty() {
        defines(top).hash(&mut h);
    }
    for f in files {
        f.hash(&mut h);
        std::fs::read(rtl.join(f))
            .unwrap_or_else(|e| panic!("{}: {e}", rtl.join(f).display()))
            .hash(&mut h);
    }
    verilator_version().hash(&mut h);
    h.finish()
}

/// The cell models for a netlist (`cells_sim.v` of the yosys that wrote
/// it): `CELLS_ENV`, else those next to the yosys on PATH
/// (<prefix>/share/yosys).
fn xilinx_cells() -> PathBuf {
    if let Ok(c) = env::var(CELLS_ENV) {
        return PathBuf::from(c);
    }
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

/// The cache key of a netlist's model: its name, options, the netlist's
/// and the cell models' contents and the Verilator version.
fn netlist_key(top: &str, netlist: &Path, cells: &Path) -> u64 {
    let mut h = DefaultHasher::new();
    (top, NETLIST_OPT, KEY_VERSION).hash(&mut h);
    for f in [netlist, cells] {
        std::fs::read(f)
            .unwrap_or_else(|e| panic!("{}: {e}", f.display()))
            .hash(&mut h);
    }
    verilator_version().hash(&mut h);
    h.finish()
}

fn verilator_version() -> Vec<u8> {
    Command::new("verilator")
        .arg("--version")
        .output()
        .expect("verilator not found (run scripts/setup)")
        .stdout
}

/// Bumped when the way a model is built changes (options not in the key).
const KEY_VERSION: u32 = 1;

fn copy_model(out: &Path, mdir: &Path, top: &str) {
    let lib = out.join(format!("libvtop_{top}.a"));
    std::fs::copy(mdir.join(format!("V{top}__ALL.a")), &lib).expect("copy model archive");
}

/// The Verilator runtime (`verilated.o`, `verilated_threads.o`), built once
/// with the flags of Verilator's makefile, as `libverilated.a`.
fn runtime(out: &Path, mdir: &Path, top: &str) {
    runtime_objs(mdir, top);
    let lib = out.join("libverilated.a");
    let _ = std::fs::remove_file(&lib);
    run(Command::new("ar")
        .arg("rcs")
        .arg(&lib)
        .args(RUNTIME_OBJS.iter().map(|o| mdir.join(o))));
}

const RUNTIME_OBJS: [&str; 2] = ["verilated.o", "verilated_threads.o"];

/// Compiles the runtime's objects in a model's directory (nothing to do
/// when they are there).
fn runtime_objs(mdir: &Path, top: &str) {
    let objs = RUNTIME_OBJS;
    run(Command::new("make")
        .args(["-j", "2", "-s", "-C"])
        .arg(mdir)
        .args(["-f", &format!("V{top}.mk")])
        .arg("OPT_GLOBAL=-O1")
        .arg("VM_USER_CFLAGS=-fPIC")
        .args(objs));
}

/// Models Verilated at a time by `prebuild`.
const PARALLEL_MODELS: usize = 2;

/// Verilates the models into the cache `PARALLEL_MODELS` at a time before
/// the loop of `main` takes them from it: Verilator's front end runs on
/// one core and a model's last large file compiles alone, so one model at
/// a time left a core idle for much of a fresh clone's first build.
/// Nothing to do without a cache (then `main` builds them one by one).
fn prebuild(rtl: &Path, out: &Path) {
    if cache_root(out).is_none() {
        return;
    }
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..PARALLEL_MODELS {
            s.spawn(|| {
                while let Some((top, files, _)) =
                    TOPS.get(next.fetch_add(1, std::sync::atomic::Ordering::Relaxed))
                {
                    verilate(rtl, out, top, files);
                }
            });
        }
    });
}

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    let rtl = manifest.join("../rtl");
    let out = PathBuf::from(env::var("OUT_DIR").unwrap());
    println!("cargo:rerun-if-changed=build.rs");
    for top in NETLIST_TOPS {
        println!("cargo:rerun-if-env-changed={}", netlist_env(top));
    }
    println!("cargo:rerun-if-env-changed={CACHE_ENV}");
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
    // `pl_top`'s shim runs Verilator's trigger loop twice a PL cycle in the
    // co-simulation (`csrc/pl_top_clock.h`): at -O2 its small trigger-vector
    // methods are inlined (at -O1 they were calls, about a fifth of
    // `pl-cosim`'s instructions, docs/speed.md).
    let mut pl_top_shim = shim.clone();
    pl_top_shim.opt_level(2);
    prebuild(&rtl, &out);
    let mut models = Vec::new();
    for (top, files, shim_src) in TOPS {
        for f in *files {
            println!("cargo:rerun-if-changed={}", rtl.join(f).display());
        }
        let src = manifest.join("csrc").join(shim_src);
        println!("cargo:rerun-if-changed={}", src.display());
        if *top == "pl_top" {
            println!(
                "cargo:rerun-if-changed={}",
                manifest.join("csrc/pl_top_clock.h").display()
            );
        }
        // The port accessors a core's shim includes (generated from its RTL).
        let ports = manifest.join("csrc").join(format!("{top}_ports.h"));
        if ports.exists() {
            println!("cargo:rerun-if-changed={}", ports.display());
        }
        let mdir = verilate(&rtl, &out, top, files);
        if *top == "pl_top" {
            check_input_region(&mdir);
        }
        if models.is_empty() {
            runtime(&out, &mdir, top);
        }
        shim.include(&mdir);
        if *top == "pl_top" {
            pl_top_shim.include(&mdir).file(src);
        } else {
            shim.file(src);
        }
        models.push(*top);
    }
    shim.compile("rtl_shims");
    pl_top_shim.compile("rtl_shim_pl_top");
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
