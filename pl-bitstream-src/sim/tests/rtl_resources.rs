//! The resource tables that `scripts/rtl-synth` and `scripts/mpdcc-table`
//! generate: one Yosys for all of them, `pl_top` (with the MPDCC core)
//! within 60 % of the xc7z020's LUTs (31,920, LUTRAM counted) and 50 % of
//! its flip-flops (53,200) with a delay estimate, and the README's `pl_top`
//! figures equal to the generated ones.

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
#[ignore = "until `scripts/rtl-synth pl_top` has run on the current build (over an hour)"]
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
#[ignore = "until `scripts/rtl-synth pl_top` has run with the Yosys of scripts/yosys"]
fn one_yosys_for_every_resource_table() {
    let a = repo_file("docs/rtl-resources-pl-top.md");
    let b = repo_file("docs/mpdcc-rtl-table.md");
    assert_eq!(yosys_of(&a), yosys_of(&b));
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
