//! Harness of the system tests: boots the release firmware in QEMU (under a
//! timeout: the session kills QEMU when dropped) and talks to its console
//! through `drivectl`'s link, the same code users run.
use drivectl::link::{default_elf, Final, Qemu, Reply, Session};
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

/// Generous: QEMU boots the firmware in well under a second.
pub const TIMEOUT: Duration = Duration::from_secs(20);

/// The release ELF; fails with the command that builds it.
pub fn elf() -> PathBuf {
    let e = default_elf();
    assert!(
        e.is_file(),
        "{} missing: build it first with `cargo fw-build` (scripts/test does)",
        e.display()
    );
    // cargo's dep-info beside the ELF lists every file it was built from
    // (sources, memory.x, the board file; git's HEAD and index, for the
    // version string, left out: `git status` alone rewrites the index).
    let deps = std::fs::read_to_string(e.with_extension("d")).unwrap_or_default();
    let deps = deps.split_once(": ").map_or("", |(_, d)| d);
    assert_fresh(
        &e,
        deps.split_whitespace()
            .filter(|d| !d.contains("/.git/"))
            .map(PathBuf::from),
        "cargo fw-build",
    );
    e
}

/// Workspace root.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// Files under `dir` (recursively) whose name ends in one of `ext`.
fn files(dir: &Path, ext: &[&str], out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let p = e.path();
        if p.is_dir() {
            files(&p, ext, out);
        } else if ext.iter().any(|x| p.to_string_lossy().ends_with(x)) {
            out.push(p);
        }
    }
}

/// Fails (with the command that rebuilds it) when `artifact` is older than
/// one of `sources` (those that exist): a test would otherwise run a stale
/// build (`cargo test -p system-tests` builds neither the firmware nor
/// `pl-cosim`).
fn assert_fresh(artifact: &Path, sources: impl Iterator<Item = PathBuf>, rebuild: &str) {
    let mtime = |p: &Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    let built = mtime(artifact).unwrap_or(SystemTime::UNIX_EPOCH);
    let newer: Vec<PathBuf> = sources
        .filter(|s| mtime(s).is_some_and(|t| t > built))
        .collect();
    assert!(
        newer.is_empty(),
        "{} is older than {} (and {} more source files): rebuild it with `{rebuild}`",
        artifact.display(),
        newer
            .first()
            .map_or(String::new(), |p| p.display().to_string()),
        newer.len().saturating_sub(1)
    );
}

/// `pl-cosim` (the Verilated `pl_top`, the shadow simulated PL): fails when
/// it is older than its RTL, its Rust or C++ sources (a stale one once
/// failed a test far from the cause). `$DRIVE_PL_COSIM` is taken as given.
fn check_pl_cosim() {
    if std::env::var_os("DRIVE_PL_COSIM").is_some() {
        return;
    }
    let exe = drivectl::cosim::pl_cosim_exe().expect("pl-cosim");
    let r = root();
    let sim = r.join("pl-bitstream-src/sim");
    let mut src = vec![sim.join("build.rs")];
    files(&r.join("pl-bitstream-src/rtl"), &[".v", ".vh"], &mut src);
    files(&sim.join("csrc"), &[".cpp", ".h"], &mut src);
    files(&sim.join("src"), &[".rs"], &mut src);
    for c in ["models", "simpl", "regmap"] {
        files(&r.join("firmware").join(c).join("src"), &[".rs"], &mut src);
    }
    // The other binary of the crate is not part of pl-cosim.
    src.retain(|p| !p.ends_with("src/bin/rtl-check.rs"));
    assert_fresh(
        &exe,
        src.into_iter(),
        "cargo build -p rtl-sim --bin pl-cosim --profile test",
    );
}

/// A booted firmware with its console ready; `defmt_raw` captures UART0.
pub fn boot_with(defmt_raw: Option<PathBuf>) -> Session {
    let mut q = Qemu::new(elf());
    q.defmt_raw = defmt_raw;
    Session::spawn_qemu(&q, TIMEOUT).expect("firmware boots to its prompt")
}

pub fn boot() -> Session {
    boot_with(None)
}

/// A booted firmware whose PL is the Verilated `pl_top` behind the
/// co-simulation bridge (`pl-cosim`, built beside the test binaries by
/// `cargo test --workspace`, or `$DRIVE_PL_COSIM`).
pub fn boot_rtl() -> Session {
    check_pl_cosim();
    let mut q = Qemu::new(elf());
    q.pl_rtl = true;
    Session::spawn_qemu(&q, TIMEOUT).expect("firmware boots to its prompt with the bridge")
}

/// A booted firmware whose socketcand server (GEM0, TCP 29536) is
/// forwarded to the returned host port, one picked free per boot so that
/// tests in parallel do not share one; a boot whose port another process
/// took in between is retried on a new one.
pub fn boot_with_can() -> (Session, u16) {
    boot_with_can_on(false)
}

/// [`boot_with_can`] with the Verilated `pl_top` behind the co-simulation
/// bridge (`rtl`) or the simulated PL.
pub fn boot_with_can_on(rtl: bool) -> (Session, u16) {
    if rtl {
        check_pl_cosim();
    }
    let mut last = None;
    for _ in 0..3 {
        let port = drivectl::link::free_tcp_port().expect("a free TCP port");
        let mut q = Qemu::new(elf());
        q.can_port = Some(port);
        q.pl_rtl = rtl;
        match Session::spawn_qemu(&q, TIMEOUT) {
            Ok(s) => return (s, port),
            Err(e) => last = Some(e),
        }
    }
    panic!("firmware boots with GEM0 forwarded: {last:?}");
}

/// A fresh erased QSPI flash image `target/run/tests/<name>.img` (one per
/// test: QEMU locks its image).
pub fn fresh_flash(name: &str) -> PathBuf {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../target/run/tests")
        .join(format!("{name}.img"));
    let _ = std::fs::remove_file(&p);
    drivectl::link::ensure_flash_image(&p).expect("flash image");
    p
}

/// A booted firmware with `flash` as its QSPI flash image.
pub fn boot_with_flash(flash: &std::path::Path) -> Session {
    let mut q = Qemu::new(elf());
    q.flash = Some(flash.to_path_buf());
    Session::spawn_qemu(&q, TIMEOUT).expect("firmware boots to its prompt")
}

/// Sends `line`, returns the reply (panics with the transcript on a
/// protocol error).
pub fn cmd(s: &mut Session, line: &str) -> Reply {
    match s.command(line, TIMEOUT) {
        Ok(r) => r,
        Err(e) => panic!(
            "{line:?}: {e:#}\ntranscript:\n{}",
            String::from_utf8_lossy(&s.transcript)
        ),
    }
}

/// The value after `key: ` in a reply line, up to the next space.
pub fn field<'a>(r: &'a Reply, key: &str) -> Option<&'a str> {
    r.lines
        .iter()
        .find_map(|l| l.strip_prefix(key)?.strip_prefix(": "))
        .and_then(|v| v.split_whitespace().next())
}

/// Asserts that `r` ended in `OK`.
pub fn assert_ok(r: &Reply) {
    assert!(r.is_ok(), "{r:?}");
}

/// Asserts that `r` ended in `ERR <want_code>`.
pub fn assert_err(r: &Reply, want_code: &str) {
    match &r.fin {
        Final::Err { code, .. } => assert_eq!(code, want_code, "{r:?}"),
        Final::Ok => panic!("expected ERR {want_code}, got {r:?}"),
    }
}

/// The number after `key: ` in a reply line (a trailing `,` of a list
/// ignored); panics with the reply when there is none.
pub fn num(r: &Reply, key: &str) -> f64 {
    field(r, key)
        .and_then(|v| v.trim_end_matches(',').parse().ok())
        .unwrap_or_else(|| panic!("no number for {key}: {r:?}"))
}
