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
mod socketcand;
mod storm;
mod telemetry;
mod torque_steps;

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

/// The modules of a crate's source directory (`*.rs`, a subdirectory as
/// one module) import each other without a circle: a function two modules
/// need lives in one and is used by (or handed to) the other. A module's
/// imports are the `crate::<module>` paths and `use crate::{...}` groups
/// outside comments. `must`: modules the scan has to find (a guard against
/// a scan that finds nothing and passes).
fn assert_no_import_circle(src: &std::path::Path, must: &[&str]) {
    use std::collections::BTreeMap;
    let mut files: Vec<(String, std::path::PathBuf)> = Vec::new();
    for e in std::fs::read_dir(src).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            for f in std::fs::read_dir(&p).unwrap() {
                let f = f.unwrap().path();
                if f.extension().is_some_and(|x| x == "rs") {
                    files.push((p.file_name().unwrap().to_string_lossy().into(), f));
                }
            }
        } else if let Some(m) = p
            .file_stem()
            .filter(|_| p.extension().is_some_and(|x| x == "rs"))
        {
            files.push((m.to_string_lossy().into(), p.clone()));
        }
    }
    let mut deps: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for (m, path) in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let code: String = text
            .lines()
            .map(|l| l.split("//").next().unwrap_or(""))
            .collect::<Vec<_>>()
            .join("\n");
        let d = deps.entry(m.clone()).or_default();
        let mut add = |name: &str| {
            let name: String = name
                .trim()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() && name != *m && !d.contains(&name) {
                d.push(name);
            }
        };
        for (k, _) in code.match_indices("crate::") {
            let rest = &code[k + "crate::".len()..];
            if let Some(group) = rest.strip_prefix('{') {
                let group = &group[..group.find('}').unwrap_or(group.len())];
                group.split(',').for_each(&mut add);
            } else {
                add(rest);
            }
        }
    }
    // Depth-first search for a back edge.
    fn visit(
        m: &str,
        deps: &BTreeMap<String, Vec<String>>,
        path: &mut Vec<String>,
        done: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(i) = path.iter().position(|p| p == m) {
            let mut circle = path[i..].to_vec();
            circle.push(m.to_string());
            return Some(circle);
        }
        if done.iter().any(|d| d == m) {
            return None;
        }
        path.push(m.to_string());
        for d in deps.get(m).into_iter().flatten() {
            if let Some(c) = visit(d, deps, path, done) {
                return Some(c);
            }
        }
        path.pop();
        done.push(m.to_string());
        None
    }
    for m in must {
        assert!(deps.contains_key(*m), "{m} not among {deps:?}");
    }
    let mut done = Vec::new();
    for m in deps.keys() {
        let circle = visit(m, &deps, &mut Vec::new(), &mut done);
        assert!(
            circle.is_none(),
            "{}: import circle: {circle:?}",
            src.display()
        );
    }
}

/// The firmware crate's modules (`ps/` as one).
#[test]
fn firmware_modules_import_each_other_without_a_circle() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../firmware/src");
    assert_no_import_circle(&src, &["app", "control"]);
}

/// `drivectl`'s modules, library and binary (their names differ; `ui/` as
/// one): the console link, the telemetry frames and the co-simulation
/// bridge among them.
#[test]
fn drivectl_modules_import_each_other_without_a_circle() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scripts/drivectl/src");
    assert_no_import_circle(
        &src,
        &["link", "tel", "frames", "cosim", "server", "console"],
    );
}
