//! The MPDCC core's table for N = 1..6 explorers (`scripts/mpdcc-table`,
//! run by `scripts/bench rtl-mpdcc`; too long for `scripts/test`): what it
//! wrote to docs/mpdcc-rtl-table.md must be complete and agree with the
//! design, and README.md must carry the same rows.
//! - every N synthesised (LUT, FF, DSP48E1, BRAM36 are numbers);
//! - the paper column is Table II, the measured cycles are the pipelined
//!   core's count for 216 candidates (`cycles::pipelined_core_cycles`);
//! - DSP48E1 = 4 shared multipliers of the common terms + 12 per explorer
//!   (the multipliers written in `mpdcc_common.v` and `mpdcc_explorer.v`),
//!   so at most 32 at N = 2;
//! - LUT and FF grow with every explorer added.
use models::mpdcc::cycles::{pipelined_core_cycles, PAPER_TABLE2};

const CANDIDATES: u32 = 216;

fn repo_file(rel: &str) -> String {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// The table's lines that start with `| <digit>`.
fn rows(text: &str) -> Vec<&str> {
    text.lines()
        .filter(|l| l.starts_with("| ") && l[2..].starts_with(|c: char| c.is_ascii_digit()))
        .collect()
}

fn cells(row: &str) -> Vec<&str> {
    row.trim_matches('|').split('|').map(str::trim).collect()
}

fn number(cell: &str, what: &str, row: &str) -> f64 {
    cell.parse()
        .unwrap_or_else(|_| panic!("{what} is not a number ({cell:?}) in {row:?}"))
}

#[test]
fn mpdcc_table_is_complete_and_agrees_with_the_design() {
    let doc = repo_file("docs/mpdcc-rtl-table.md");
    let rs = rows(&doc);
    assert_eq!(rs.len(), 6, "{doc}");
    let mut last = (0.0, 0.0);
    for (k, row) in rs.iter().enumerate() {
        let n = k as u32 + 1;
        let c = cells(row);
        assert_eq!(c.len(), 8, "{row}");
        assert_eq!(c[0], n.to_string(), "{row}");
        assert_eq!(c[1], PAPER_TABLE2[k].to_string(), "{row}");
        assert_eq!(
            c[2],
            pipelined_core_cycles(n, CANDIDATES).to_string(),
            "{row}"
        );
        let lut = number(c[3], "LUT", row);
        let ff = number(c[4], "FF", row);
        let dsp = number(c[5], "DSP48E1", row);
        number(c[6], "BRAM36", row);
        assert_eq!(dsp, f64::from(4 + 12 * n), "{row}");
        assert!(lut > last.0 && ff > last.1, "{row}");
        last = (lut, ff);
        // the utilisation column follows from LUT and FF
        let want = format!(
            "{:.0} % / {:.0} %",
            100.0 * lut / 53200.0,
            100.0 * ff / 106400.0
        );
        assert_eq!(c[7], want, "{row}");
    }
    let n2 = cells(rs[1]);
    assert!(number(n2[5], "DSP48E1", rs[1]) <= 32.0);
    let readme = repo_file("README.md");
    let begin = readme
        .find("<!-- mpdcc-rtl-table begin -->")
        .expect("README marker");
    let end = readme
        .find("<!-- mpdcc-rtl-table end -->")
        .expect("README marker");
    assert_eq!(
        rows(&readme[begin..end]),
        rs,
        "README and docs/mpdcc-rtl-table.md differ"
    );
}
