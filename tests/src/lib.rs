//! Harness of the system tests: boots the release firmware in QEMU (under a
//! timeout: the session kills QEMU when dropped) and talks to its console
//! through `drivectl`'s link, the same code users run.
use drivectl::link::{default_elf, Final, Qemu, Reply, Session};
use std::path::PathBuf;
use std::time::Duration;

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
    e
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
    let mut q = Qemu::new(elf());
    q.pl_rtl = true;
    Session::spawn_qemu(&q, TIMEOUT).expect("firmware boots to its prompt with the bridge")
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
