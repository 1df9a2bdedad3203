//! "Adding a register is one table entry": a copy of the table with one more
//! register (the example of docs/register-map.md) yields the register-file
//! RTL (Verilator-lint clean), the accessors and the docs for it, and the
//! `pl_top` harness needs nothing (it binds only the AXI port and the pins).
use std::path::PathBuf;
use std::process::Command;

use regmap::{self, Access, Block, Hw, Invalid, Register, BLOCKS};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The example entry: PWM/gates, offset 0x024, a clamped 12-bit setting.
const TRIM: Register = Register {
    name: "TRIM",
    offset: 0x024,
    access: Access::Rw,
    width: 12,
    reset: 100,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::Clamp { min: 10, max: 4000 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Example register.",
};

/// The table with `TRIM` appended to the PWM block.
fn table_with_trim() -> Vec<&'static Block> {
    BLOCKS
        .iter()
        .map(|b| {
            if b.name != "PWM" {
                return *b;
            }
            let mut regs: Vec<&'static Register> = b.registers.to_vec();
            regs.push(&TRIM);
            let block = Block {
                registers: Box::leak(regs.into_boxed_slice()),
                ..**b
            };
            &*Box::leak(Box::new(block))
        })
        .collect()
}

#[test]
fn the_register_file_gets_storage_decode_rule_read_and_a_port() {
    let v = regmap_gen::rtl::pl_regs(&table_with_trim());
    let base = regmap_gen::rtl::pl_regs(&BLOCKS);
    for line in [
        "    output wire  [11:0] trim_o",
        "    reg  [11:0] trim_q;",
        "            hit_trim_q <= wr_i && wr_addr_i == 15'h3024;",
        "    wire w_trim = hit_trim_q;",
        "    wire [31:0] n_trim = clamp(merge({20'd0, trim_q}, wr_data_q, wr_strb_q), \
         32'h0000000a, 32'h00000fa0);",
        "            trim_q <= 12'h64;",
        "            if (w_trim) trim_q <= n_trim[11:0];",
        "                15'h3024: rd_pwm_q <= {20'd0, trim_q};  // TRIM",
        "    assign trim_o = trim_q;",
    ] {
        assert!(v.contains(line), "missing in the generated RTL: {line}");
        assert!(!base.contains(line), "already in the real map: {line}");
    }
    assert!(v.contains("| w_trim"), "a write to TRIM must answer OKAY");

    // The generated file is Verilator -Wall clean as its own top.
    let dir = std::env::temp_dir().join(format!("regmap-gen-add-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("pl_regs.v");
    std::fs::write(&file, &v).unwrap();
    // Also with its formal properties, which now cover TRIM too.
    assert!(v.contains("            if ($past(!w_trim)) assert (trim_q == $past(trim_q));"));
    assert!(v.contains(
        "            assert ({20'd0, trim_q} >= 32'h0000000a && {20'd0, trim_q} <= 32'h00000fa0);"
    ));
    for defs in [None, Some("-DFORMAL")] {
        let out = Command::new("verilator")
            .args(["--lint-only", "-Wall", "--top-module", "pl_regs"])
            .args(defs)
            .arg(root().join("pl-bitstream-src/lint.vlt"))
            .arg(&file)
            .output()
            .expect("verilator not found (run scripts/setup)");
        assert!(
            out.status.success(),
            "verilator -Wall {defs:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_accessors_header_and_docs_name_it() {
    let t = table_with_trim();
    let rust = regmap_gen::rust::rust(&t);
    for item in [
        "pub struct Trim;",
        "pub const ADDR: usize = 0x43C03024;",
        "pub const DEF: &'static Register = &regmap::TRIM;",
        "pub struct TrimValue(u32);",
        "pub const RESET: Self = Self(0x64);",
        "pub const fn with_value(self, v: u32) -> Self {",
        "Self((self.0 & !0xFFF) | (v & 0xFFF))",
        "clamps the written word to 10..=4000",
    ] {
        assert!(rust.contains(item), "missing in the accessors: {item}");
    }
    let vh = regmap_gen::verilog(&t);
    assert!(vh.contains("localparam [14:0] RM_TRIM_ADDR = 15'h3024;"));
    let md = regmap_gen::markdown(&t);
    assert!(md.contains("| `0x024` | `0x43C03024` | `TRIM` | RW | 12 | `0x64` (100) |"));
}

/// Whether `text` has an identifier starting with `prefix`.
fn has_ident_prefix(text: &str, prefix: &str) -> bool {
    text.match_indices(prefix).any(|(i, _)| {
        !text[..i]
            .chars()
            .next_back()
            .is_some_and(|c| c.is_ascii_alphanumeric() || c == '_')
    })
}

#[test]
fn the_pl_top_harness_binds_no_register() {
    assert!(has_ident_prefix("x = trim_o;", "trim_"));
    assert!(!has_ident_prefix("x = strim_o;", "trim_"));
    for path in [
        "pl-bitstream-src/sim/csrc/pl_top_shim.cpp",
        "pl-bitstream-src/sim/src/pl_top.rs",
    ] {
        let text = std::fs::read_to_string(root().join(path)).unwrap();
        for b in table_with_trim() {
            for r in b.registers {
                let signal = format!("{}_", r.name.to_ascii_lowercase());
                assert!(
                    !has_ident_prefix(&text, &signal) && !text.contains(&format!("RM_{}", r.name)),
                    "{path} names register {} ({signal})",
                    r.name
                );
            }
        }
    }
    // Registers reach the harness as AXI addresses from the table.
    assert_eq!(regmap::PWM.addr(&TRIM) - regmap::BASE_ADDR, 0x3024);
}
