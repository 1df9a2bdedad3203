//! `pl_top.v`'s port list is `ports::PL_TOP_PORTS` plus the clock:
//! the generated harness binds every port, with the right direction and
//! width, and nothing else.
use std::path::PathBuf;

use regmap_gen::ports::{PortDir, PL_TOP_PORTS};

/// (name, direction, width) of every port in the ANSI header of `module`.
fn ports_of(verilog: &str, module: &str) -> Vec<(String, PortDir, u8)> {
    // A parameter list `#( ... )` before the ports is skipped.
    let start = verilog
        .find(&format!("module {module} ("))
        .or_else(|| {
            let p = verilog.find(&format!("module {module} #("))?;
            Some(p + verilog[p..].find(") (")?)
        })
        .expect("module header");
    let header = &verilog[start..start + verilog[start..].find(");").expect("end of header")];
    let mut out = Vec::new();
    for line in header.lines().skip(1) {
        let code = line.split("//").next().unwrap_or("").trim();
        let mut words = code.split_whitespace();
        let dir = match words.next() {
            Some("input") => PortDir::In,
            Some("output") => PortDir::Out,
            _ => continue,
        };
        let rest: String = words.filter(|w| *w != "wire" && *w != "reg").collect();
        let (width, name) = match rest.strip_prefix('[') {
            Some(r) => {
                let (range, name) = r.split_once(']').expect("range");
                let msb: u8 = range.split(':').next().unwrap().trim().parse().unwrap();
                (msb + 1, name)
            }
            None => (1, rest.as_str()),
        };
        out.push((name.trim_end_matches(',').to_string(), dir, width));
    }
    out
}

#[test]
fn pl_top_has_exactly_the_table_ports() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../rtl/pl_top.v");
    let v = std::fs::read_to_string(path).unwrap();
    let mut got = ports_of(&v, "pl_top");
    got.sort_by(|a, b| a.0.cmp(&b.0));
    let mut want: Vec<(String, PortDir, u8)> = PL_TOP_PORTS
        .iter()
        .map(|p| (p.verilog.to_string(), p.dir, p.width))
        .chain([("clk_i".to_string(), PortDir::In, 1)])
        .collect();
    want.sort_by(|a, b| a.0.cmp(&b.0));
    assert_eq!(got, want);
}

#[test]
fn the_parser_reads_widths_and_directions() {
    let v = "module m (\n    input  wire        a_i,\n    output wire [35:0] b_o,  // x\n    \
             output reg  [ 2:0] c_o\n);\n";
    assert_eq!(
        ports_of(v, "m"),
        [
            ("a_i".to_string(), PortDir::In, 1),
            ("b_o".to_string(), PortDir::Out, 36),
            ("c_o".to_string(), PortDir::Out, 3),
        ]
    );
}
