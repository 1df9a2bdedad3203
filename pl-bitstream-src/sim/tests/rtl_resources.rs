//! The resource tables that `scripts/rtl-synth` and `scripts/mpdcc-table`
//! generate: one Yosys for all of them, `pl_top` (with the MPDCC core)
//! within 60 % of the xc7z020's LUTs (31,920, LUTRAM counted) and 50 % of
//! its flip-flops (53,200) with a delay estimate, every estimated
//! register-to-register delay within 8 ns (100 MHz with 2 ns of margin),
//! and the README's tables equal to the generated ones.

fn repo_file(rel: &str) -> String {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(rel);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// "Yosys X.Y" named in a generated table's header.
fn yosys_of(doc: &str) -> &str {
    let at = doc.find("(Yosys ").expect("the Yosys is named");
    let rest = &doc[at + 1..];
    &rest[..rest.find(')').expect("(Yosys X.Y)")]
}

/// The cells of the row of `top`.
fn row<'a>(doc: &'a str, top: &str) -> Vec<&'a str> {
    let l = doc
        .lines()
        .find(|l| l.starts_with(&format!("| `{top}` |")))
        .unwrap_or_else(|| panic!("no row {top}"));
    l.trim_matches('|').split('|').map(str::trim).collect()
}

fn num(cell: &str) -> f64 {
    cell.parse()
        .unwrap_or_else(|_| panic!("not a number: {cell:?}"))
}

#[test]
fn pl_top_fits_the_xc7z020_with_margin() {
    let doc = repo_file("docs/rtl-resources-pl-top.md");
    let c = row(&doc, "pl_top");
    // | top | LUT | LUTRAM | FF | DSP48E1 | BRAM36 | CARRY4 | MUXF7/8 | delay | cells | share |
    assert_eq!(c.len(), 11, "{c:?}");
    let (lut, lutram, ff) = (num(c[1]), num(c[2]), num(c[3]));
    assert!(lut + lutram <= 31920.0, "{c:?}");
    assert!(ff <= 53200.0, "{c:?}");
    assert!(num(c[8]) > 0.0, "delay estimate: {c:?}");
}

#[test]
fn one_yosys_for_every_resource_table() {
    let a = repo_file("docs/rtl-resources-pl-top.md");
    for doc in ["docs/mpdcc-rtl-table.md", "docs/rtl-resources.md"] {
        let b = repo_file(doc);
        assert_eq!(yosys_of(&a), yosys_of(&b), "{doc}");
    }
    assert!(yosys_of(&a).starts_with("Yosys 0.70"), "{}", yosys_of(&a));
}

#[test]
fn readme_carries_the_generated_pl_top_figures() {
    let doc = repo_file("docs/rtl-resources-pl-top.md");
    let c = row(&doc, "pl_top");
    let readme = repo_file("README.md");
    let begin = readme
        .find("<!-- pl-top-resources begin -->")
        .expect("README marker");
    let end = readme
        .find("<!-- pl-top-resources end -->")
        .expect("README marker");
    let block = &readme[begin..end];
    let l = block
        .lines()
        .find(|l| l.starts_with("| `pl_top` |"))
        .expect("pl_top row in the README");
    let r: Vec<&str> = l.trim_matches('|').split('|').map(str::trim).collect();
    assert_eq!(r, c, "README and docs/rtl-resources-pl-top.md differ");
}

/// The table rows (lines starting with `|`, header included) of `text`.
fn table_rows(text: &str) -> Vec<&str> {
    text.lines().filter(|l| l.starts_with('|')).collect()
}

/// The README block between `<!-- name begin -->` and `<!-- name end -->`.
fn readme_block<'a>(readme: &'a str, name: &str) -> &'a str {
    let b = format!("<!-- {name} begin -->");
    let e = format!("<!-- {name} end -->");
    let begin = readme
        .find(&b)
        .unwrap_or_else(|| panic!("README marker {b}"));
    let end = readme
        .find(&e)
        .unwrap_or_else(|| panic!("README marker {e}"));
    &readme[begin + b.len()..end]
}

#[test]
fn readme_tables_are_the_generated_ones() {
    let readme = repo_file("README.md");
    for (block, doc) in [
        ("pl-top-resources", "docs/rtl-resources-pl-top.md"),
        ("rtl-resources", "docs/rtl-resources.md"),
        ("mpdcc-rtl-table", "docs/mpdcc-rtl-table.md"),
    ] {
        let d = repo_file(doc);
        assert_eq!(
            table_rows(readme_block(&readme, block)),
            table_rows(&d),
            "README block {block} and {doc} differ"
        );
    }
}

/// The rows of `doc` whose estimated worst register-to-register delay (the
/// column "delay (ns, est.)") exceeds 8 ns; rows without a number (not
/// synthesised) are skipped, a table without the column fails.
fn rows_over_8_ns(doc: &str) -> Vec<String> {
    let d = repo_file(doc);
    let rows = table_rows(&d);
    let head: Vec<&str> = rows[0]
        .trim_matches('|')
        .split('|')
        .map(str::trim)
        .collect();
    let Some(col) = head.iter().position(|h| *h == "delay (ns, est.)") else {
        panic!("{doc}: no delay column in {head:?}")
    };
    let mut over = Vec::new();
    for r in &rows[2..] {
        let c: Vec<&str> = r.trim_matches('|').split('|').map(str::trim).collect();
        if let Ok(ns) = c[col].parse::<f64>() {
            assert!(ns > 0.0, "{doc}: {r}");
            if ns > 8.0 {
                over.push(format!("{doc}: {r}"));
            }
        }
    }
    over
}

/// Every synthesised module of `scripts/rtl-synth` (the PL's blocks and
/// the MPDTC cores) has an estimated worst register-to-register delay of
/// at most 8 ns.
#[test]
fn every_module_within_8_ns() {
    let over = rows_over_8_ns("docs/rtl-resources.md");
    assert!(over.is_empty(), "{over:#?}");
}

/// `pl_top`'s paths that end outside the MPDCC core (the line
/// `scripts/rtl-synth pl_top` writes below its row): at most 8 ns.
#[test]
fn pl_top_without_the_mpdcc_core_within_8_ns() {
    let doc = repo_file("docs/rtl-resources-pl-top.md");
    let key = "pl_top without mpdcc_core's own paths (end points outside it): ";
    let l = doc
        .lines()
        .find(|l| l.starts_with(key))
        .expect("the line of the paths outside the MPDCC core");
    let ns = num(l[key.len()..].split(' ').next().expect("a delay"));
    assert!(ns > 0.0 && ns <= 8.0, "{l}");
}

/// The MPDCC core's table (`scripts/mpdcc-table`): every row, N = 1..6 in
/// both datapaths, synthesised and within 8 ns. Before the candidate
/// counters stepped through tables, each explorer added one increment to
/// the chain that made the clock's candidates (8.8 to 19.3 ns at N =
/// 2..6); stepping a counter in place put its explorer's fan-out on the
/// step (8.09 ns at II = 1, N = 3), and rounding then saturating on the
/// rounded sum put an add and a compare in series (8.18 ns at N = 5 and 6).
#[test]
fn mpdcc_within_8_ns() {
    let d = repo_file("docs/mpdcc-rtl-table.md");
    let rows = table_rows(&d);
    let delay = |r: &str| -> Option<f64> {
        let c: Vec<&str> = r.trim_matches('|').split('|').map(str::trim).collect();
        c[9].parse::<f64>().ok()
    };
    let mut seen = 0;
    for r in &rows[2..] {
        let ns = delay(r).unwrap_or_else(|| panic!("not synthesised: {r}"));
        assert!(ns > 0.0 && ns <= 8.0, "{r}");
        seen += 1;
    }
    assert_eq!(seen, 12, "the rows II = 1 and 4, N = 1..6");
}

/// The same for the whole `pl_top` (composed with the MPDCC core's
/// netlist: `scripts/rtl-synth pl_top` after `scripts/mpdcc-table 4:1`).
#[test]
fn pl_top_within_8_ns() {
    let over = rows_over_8_ns("docs/rtl-resources-pl-top.md");
    assert!(over.is_empty(), "{over:#?}");
}
