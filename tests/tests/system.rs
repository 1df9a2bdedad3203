//! The system tests, one module per file of this directory, in one test
//! binary: one compilation and one link instead of one per file (the test
//! stage builds on an empty target directory; docs/ARCHITECTURE.md, "Tests
//! and their budget"). A test is `<module>::<name>`: run one file's tests
//! with `cargo test -p system-tests --test system <module>::`. cargo-nextest
//! runs every test in its own process, as before.
mod agreement;
mod bringup;
mod calibration;
mod capture;
mod config;
mod config_file;
mod config_writes;
mod console;
mod control_irq;
mod cosim;
mod drive;
mod fault_matrix;
mod faults;
mod flash;
mod motion;
mod mpdcc;
mod pl_faults;
mod sensor_check;
mod storm;
mod telemetry;

/// Every `.rs` file of a directory of tests built as one binary is a
/// module of its root file (`autotests = false` in their Cargo.toml: a
/// file left out would never run).
#[test]
fn every_test_file_is_a_module_of_its_binary() {
    let ws = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut missing = Vec::new();
    for (dir, root) in [
        ("tests/tests", "system"),
        ("pl-bitstream-src/sim/tests", "rtl"),
        ("firmware/simpl/tests", "host"),
    ] {
        let dir = ws.join(dir);
        let text = std::fs::read_to_string(dir.join(format!("{root}.rs"))).unwrap();
        for e in std::fs::read_dir(&dir).unwrap() {
            let name = e.unwrap().file_name().into_string().unwrap();
            if let Some(m) = name.strip_suffix(".rs") {
                if m != root && !text.lines().any(|l| l == format!("mod {m};")) {
                    missing.push(dir.join(name));
                }
            }
        }
    }
    assert!(
        missing.is_empty(),
        "not a module of its test binary: {missing:?}"
    );
}
