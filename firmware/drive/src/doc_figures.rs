//! Figures the README and the docs repeat from the code, read from the
//! files themselves so that a change on either side fails here.
use crate::config::PARAMS;
use crate::console::PlKind;
use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

fn read(rel: &str) -> String {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// Every `` `pl: ...` `` a document quotes, without the `pl: `.
fn quoted_pl_lines(text: &str) -> Vec<String> {
    text.split("`pl: ")
        .skip(1)
        .map(|s| s.split('`').next().unwrap().to_string())
        .collect()
}

/// The `pl:` lines quoted in the README and the board guide are the ones
/// the firmware prints (`status` and the boot banner share
/// [`PlKind`]'s `Display`); a version is quoted as `vX.Y` or
/// `v<major>.<minor>`.
#[test]
fn quoted_pl_lines_are_the_firmwares() {
    let printed = [
        PlKind::Simulated,
        PlKind::Absent,
        PlKind::RtlCosim,
        PlKind::Bitstream(0x0003_0007),
    ]
    .map(|k| k.to_string());
    assert_eq!(printed[3], "bitstream v3.7");
    let mut seen = 0;
    for doc in ["README.md", "docs/board.md"] {
        for q in quoted_pl_lines(&read(doc)) {
            let q = q
                .replace("vX.Y", "v3.7")
                .replace("v<major>.<minor>", "v3.7");
            assert!(printed.contains(&q), "{doc}: `pl: {q}` is not printed");
            seen += 1;
        }
    }
    assert!(seen >= 2, "{seen}");
    // The `status` reply table lists every form.
    let readme = read("README.md");
    let row = readme
        .lines()
        .find(|l| l.starts_with("| `pl` |"))
        .expect("the `pl` row of the status table");
    for p in &printed[..3] {
        assert!(row.contains(&format!("`{p}`")), "{row}: {p}");
    }
    assert!(row.contains("`bitstream vX.Y`"), "{row}");
}

/// The flash layout's parameter count and the README's parameter table
/// follow the configuration table.
#[test]
fn readme_parameters_follow_the_config_table() {
    let readme = read("README.md");
    let row = readme
        .lines()
        .find(|l| l.contains("number of parameters n ("))
        .expect("flash layout row");
    let n: usize = row
        .split("number of parameters n (")
        .nth(1)
        .and_then(|s| s.split(')').next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("{row}"));
    assert_eq!(n, PARAMS.len(), "{row}");
    // Every parameter has a row (some rows name several).
    for p in PARAMS.iter() {
        let name = format!("`{}`", p.name);
        assert!(
            readme
                .lines()
                .any(|l| l.starts_with("| `") && l.split(" | ").next().unwrap().contains(&name)),
            "{name} has no row in the README's parameter table"
        );
    }
}

/// A number with an SI unit as the docs write it (`100 MHz`, `125 kbit/s`).
fn si_value(s: &str) -> u32 {
    let (num, unit) = s.trim().split_once(' ').unwrap_or_else(|| panic!("{s}"));
    let scale = match unit.chars().next() {
        Some('M') => 1_000_000,
        Some('k') => 1_000,
        _ => 1,
    };
    num.parse::<u32>().unwrap_or_else(|_| panic!("{s}")) * scale
}

/// The bit-timing table of the board guide's CAN section is what
/// `can::timing::bit_timing` computes.
#[test]
fn board_guide_can_bit_timings_are_the_drivers() {
    let guide = read("docs/board.md");
    let mut rows = 0;
    for line in guide
        .lines()
        .filter(|l| l.contains("Hz | ") && l.contains("bit/s | "))
    {
        let c: Vec<&str> = line.trim_matches('|').split(" | ").map(str::trim).collect();
        let t = crate::can::timing::bit_timing(si_value(c[0]), si_value(c[1])).unwrap();
        let quanta = format!(
            "{} (1 + {} + {}), SJW {}",
            t.quanta_per_bit(),
            t.tseg1_quanta,
            t.tseg2_quanta,
            t.sjw_quanta
        );
        let sp = t.sample_point_permille();
        let sp = if sp % 10 == 0 {
            format!("{} %", sp / 10)
        } else {
            format!("{}.{} %", sp / 10, sp % 10)
        };
        let want = [
            t.prescaler.to_string(),
            quanta,
            sp,
            t.brpr().to_string(),
            format!("`{:#X}`", t.btr()).replace("0X", "0x"),
        ];
        assert_eq!(c[2..], want, "{line}");
        rows += 1;
    }
    assert_eq!(rows, 3);
}
