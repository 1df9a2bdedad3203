//! The MPDCC core's table for N = 1..6 explorers in both datapaths
//! (`scripts/mpdcc-table`, run by `scripts/bench rtl-mpdcc`; too long for
//! `scripts/test`): what it wrote to docs/mpdcc-rtl-table.md must agree with
//! the design, and README.md must carry the same rows.
//! - twelve rows: II = 1 and II = `regmap::MPDCC_II`, N = 1..6 each;
//! - the paper column is Table II, the measured cycles are the pipelined
//!   core's count for 216 candidates (`cycles::pipelined_core_cycles_ii`);
//! - a synthesised row: DSP48E1 = 4 shared multipliers of the common terms +
//!   12 per explorer (the multipliers written in `mpdcc_common.v` and
//!   `mpdcc_explorer.v`), an estimated delay, the share column follows from
//!   LUT, LUTRAM and FF,
//!   and LUT and FF grow with every explorer added (same II); a row not
//!   synthesised says so in every resource column.
use models::mpdcc::cycles::{pipelined_core_cycles_ii, PAPER_TABLE2};

const CANDIDATES: u32 = 216;
const NS: &str = "not synthesised";

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
fn mpdcc_table_agrees_with_the_design() {
    let doc = repo_file("docs/mpdcc-rtl-table.md");
    let rs = rows(&doc);
    assert_eq!(rs.len(), 12, "{doc}");
    for (block, ii) in [1, regmap::MPDCC_II].into_iter().enumerate() {
        let mut last: Option<(f64, f64)> = None;
        for k in 0..6 {
            let row = rs[6 * block + k];
            let n = k as u32 + 1;
            let c = cells(row);
            assert_eq!(c.len(), 11, "{row}");
            assert_eq!(c[0], ii.to_string(), "{row}");
            assert_eq!(c[1], n.to_string(), "{row}");
            assert_eq!(c[2], PAPER_TABLE2[k].to_string(), "{row}");
            assert_eq!(
                c[3],
                pipelined_core_cycles_ii(n, ii, CANDIDATES).to_string(),
                "{row}"
            );
            if c[4] == NS {
                assert!(c[5..10].iter().all(|&x| x == NS) && c[10] == "?", "{row}");
                continue;
            }
            let lut = number(c[4], "LUT", row);
            let lutram = number(c[5], "LUTRAM", row);
            let ff = number(c[6], "FF", row);
            let dsp = number(c[7], "DSP48E1", row);
            number(c[8], "BRAM36", row);
            assert!(number(c[9], "delay", row) > 0.0, "{row}");
            assert_eq!(dsp, f64::from(4 + 12 * n), "{row}");
            if let Some((l, f)) = last {
                assert!(lut > l && ff > f, "{row}");
            }
            last = Some((lut, ff));
            let want = format!(
                "{:.0} % / {:.0} %",
                100.0 * (lut + lutram) / 53200.0,
                100.0 * ff / 106400.0
            );
            assert_eq!(c[10], want, "{row}");
        }
    }
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
