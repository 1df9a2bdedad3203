//! The sine table of the PL front end, `pl-bitstream-src/rtl/sin_table.vh`,
//! from `models::pmsm::frontend_fixed::sin_entry` (one source for the RTL
//! and its Rust model).
use models::pmsm::frontend_fixed::{sin_entry, SIN_N};
use std::fmt::Write;

/// Repository-relative path of the table.
pub const SIN_TABLE_PATH: &str = "pl-bitstream-src/rtl/sin_table.vh";

/// An 18-bit signed Verilog literal.
fn lit18(v: i32) -> String {
    if v < 0 {
        format!("-18'sd{}", -v)
    } else {
        format!("18'sd{v}")
    }
}

/// The initial contents of `mpdtc_frontend`'s table memory `sin_rom`: word
/// `i` = `{T[i + 1] - T[i], T[i]}` (entry and step to the next, so the
/// interpolation needs one read). Plain assignments: a loop over a table
/// function took yosys minutes to evaluate.
pub fn sin_table() -> String {
    let mut s = String::new();
    let _ = write!(
        s,
        "// Generated from models::pmsm::frontend_fixed by `cargo run -p regmap-gen`;\n\
         // do not edit (a test fails when this file is stale).\n\
         // Included in mpdtc_frontend after `reg [35:0] sin_rom[0:{last}]`:\n\
         // word i = {{T[i + 1] - T[i], T[i]}}, T[i] = round(2^16 sin(2 pi i / {SIN_N})),\n\
         // COEF (sQ1.16), T[{SIN_N}] = T[0]; both fields 18-bit two's complement.\n",
        last = SIN_N - 1
    );
    s.push_str("initial begin\n");
    for i in 0..SIN_N {
        let t = sin_entry(i);
        let d = sin_entry(i + 1) - t;
        let _ = writeln!(s, "    sin_rom[{i}] = {{{}, {}}};", lit18(d), lit18(t));
    }
    s.push_str("end\n");
    s
}
