//! The sine table of the PL front end, `pl-bitstream-src/rtl/sin_table.vh`,
//! from `drive::pmsm::frontend_fixed::sin_entry` (one source for the RTL
//! and its Rust model).
use drive::pmsm::frontend_fixed::{sin_entry, SIN_BITS, SIN_N};
use std::fmt::Write;

/// Repository-relative path of the table.
pub const SIN_TABLE_PATH: &str = "pl-bitstream-src/rtl/sin_table.vh";

/// The Verilog function `sin_lut(i)`, included inside `mpdtc_frontend`.
pub fn sin_table() -> String {
    let mut s = String::new();
    s.push_str(
        "// Generated from drive::pmsm::frontend_fixed by `cargo run -p regmap-gen`;\n\
         // do not edit (a test fails when this file is stale).\n\
         // sin_lut(i) = round(2^16 sin(2 pi i / 1024)), COEF (sQ1.16).\n",
    );
    let _ = writeln!(
        s,
        "function automatic signed [17:0] sin_lut(input [{}:0] i);",
        SIN_BITS - 1
    );
    s.push_str("    case (i)\n");
    for i in 0..SIN_N {
        let v = sin_entry(i);
        let lit = if v < 0 {
            format!("-18'sd{}", -v)
        } else {
            format!("18'sd{v}")
        };
        let _ = writeln!(s, "        {SIN_BITS}'d{i}: sin_lut = {lit};");
    }
    s.push_str("    endcase\nendfunction\n");
    s
}
