//! Generates from the one table, `drive::regmap`, every file that repeats
//! it: `pl-bitstream-src/rtl/regmap.vh`, `docs/register-map.md` and the typed
//! accessors `firmware/drive/src/regs.rs` ([`rust`]). `cargo run -p rtl-sim
//! --bin regmap-gen` writes them; the test `tests/regmap_files.rs` fails when
//! the committed files differ from what this produces.
use std::fmt::Write;

pub mod rust;

/// Every generated file: (repository-relative path, contents) for the
/// table `blocks`.
pub fn files(blocks: &[&Block]) -> Vec<(&'static str, String)> {
    vec![
        (VERILOG_PATH, verilog()),
        (MARKDOWN_PATH, markdown()),
        (rust::RUST_PATH, rust::rust(blocks)),
    ]
}

use drive::regmap::{self, Access, Block, Invalid, Register, BLOCKS};

/// Repository-relative path of the Verilog header.
pub const VERILOG_PATH: &str = "pl-bitstream-src/rtl/regmap.vh";
/// Repository-relative path of the documentation table.
pub const MARKDOWN_PATH: &str = "docs/register-map.md";

fn access(a: Access) -> &'static str {
    match a {
        Access::Rw => "RW",
        Access::Ro => "RO",
        Access::W1c => "W1C",
    }
}

fn invalid(r: &Register) -> String {
    match (r.access, r.invalid) {
        (Access::Ro, _) => "write: SLVERR, ignored".into(),
        (Access::W1c, _) => "write 1 clears".into(),
        (_, Invalid::AllValid) => "all values valid".into(),
        (_, Invalid::Clamp { min, max }) => format!("clamped to {min}..={max}"),
        (_, Invalid::Reject { max }) => format!("> {max} rejected (ERR.BAD_VALUE)"),
    }
}

/// The Verilog header: localparams only, included inside module bodies.
pub fn verilog() -> String {
    let mut s = String::new();
    s.push_str(
        "// Generated from firmware/drive/src/regmap.rs by `cargo run -p rtl-sim --bin\n\
         // regmap-gen`; do not edit (a test fails when this file is stale).\n\
         // Included inside module bodies. RM_<REG>_ADDR: byte address in the\n\
         // 15-bit AXI window (page << 12 | offset); _W: implemented bits;\n\
         // _RESET; _MIN/_MAX: clamp or reject bounds; _<FIELD>_LSB/_W: fields.\n",
    );
    let _ = writeln!(
        s,
        "localparam integer RM_AXI_ADDR_W = {};",
        regmap::AXI_ADDR_BITS
    );
    let _ = writeln!(
        s,
        "localparam [31:0] RM_MODE_OFF = 32'd{};",
        regmap::mode::OFF
    );
    let _ = writeln!(
        s,
        "localparam [31:0] RM_MODE_FOC_PWM = 32'd{};",
        regmap::mode::FOC_PWM
    );
    let _ = writeln!(
        s,
        "localparam [31:0] RM_MODE_MPDTC = 32'd{};",
        regmap::mode::MPDTC
    );
    // Plain RW words of the MPDTC page (inputs and parameters): their
    // implemented-bit masks by word index, for the generic storage in pl_regs.
    s.push_str(
        "\n// Mask of the plain RW registers (all values valid) of the MPDTC page\n\
         // at offsets 0x010..0x084, by word index; 0 elsewhere.\n\
         function automatic [31:0] rm_mpdtc_plain_mask(input [9:0] word);\n\
         \x20   case (word)\n",
    );
    for r in regmap::MPDTC.registers {
        // Words 4..33 (0x010..=0x084): the generic storage of pl_regs; the
        // sequence registers above have their own flops.
        if r.access == Access::Rw
            && r.invalid == Invalid::AllValid
            && (0x10..=0x84).contains(&r.offset)
        {
            let _ = writeln!(
                s,
                "        10'd{}: rm_mpdtc_plain_mask = 32'h{:08x};  // {}",
                r.offset / 4,
                r.mask(),
                r.name
            );
        }
    }
    s.push_str("        default: rm_mpdtc_plain_mask = 32'h00000000;\n    endcase\nendfunction\n");
    for b in BLOCKS {
        let _ = writeln!(s, "\n// Block {} {}: {}", b.index, b.name, b.doc);
        let _ = writeln!(s, "localparam [2:0] RM_BLK_{} = 3'd{};", b.name, b.index);
        for r in b.registers {
            let n = r.name;
            let addr = (b.index as usize) << 12 | r.offset as usize;
            let _ = writeln!(s, "localparam [14:0] RM_{n}_ADDR = 15'h{addr:04x};");
            let _ = writeln!(s, "localparam integer RM_{n}_W = {};", r.width);
            let _ = writeln!(s, "localparam [31:0] RM_{n}_RESET = 32'h{:08x};", r.reset);
            match r.invalid {
                Invalid::AllValid => {}
                Invalid::Clamp { min, max } => {
                    let _ = writeln!(s, "localparam [31:0] RM_{n}_MIN = 32'h{min:08x};");
                    let _ = writeln!(s, "localparam [31:0] RM_{n}_MAX = 32'h{max:08x};");
                }
                Invalid::Reject { max } => {
                    let _ = writeln!(s, "localparam [31:0] RM_{n}_MAX = 32'h{max:08x};");
                }
            }
            for f in r.fields {
                let _ = writeln!(s, "localparam integer RM_{n}_{}_LSB = {};", f.name, f.lsb);
                let _ = writeln!(s, "localparam integer RM_{n}_{}_W = {};", f.name, f.width);
            }
        }
    }
    s
}

/// The documentation table.
pub fn markdown() -> String {
    let mut s = String::new();
    s.push_str("# PL register map\n\n");
    s.push_str(
        "Generated from `firmware/drive/src/regmap.rs` by `cargo run -p rtl-sim --bin \
         regmap-gen`; do not edit.\n\n",
    );
    let _ = writeln!(
        s,
        "AXI4-Lite slave on GP0, base `0x{:08X}`, 32-bit registers, one 4 KiB page per \
         block, PL clock {} MHz (1 cycle = 10 ns).\n",
        regmap::BASE_ADDR,
        regmap::PL_CLOCK_HZ / 1_000_000
    );
    s.push_str(
        "Rules: bits above a register's width read 0. Byte strobes are honoured on RW \
         registers; the merged 32-bit word is then masked to the width (all values valid), \
         clamped as a whole (`clamped`) or compared as a whole (`rejected`: the register \
         keeps its value, the write answers OKAY and sets `ERR.BAD_VALUE`). Reads or writes \
         of unmapped offsets, and writes to RO registers, answer SLVERR, change nothing and \
         set `ERR.BAD_ADDR`. W1C: writing 1 clears a bit unless its condition is still \
         present.\n",
    );
    for b in BLOCKS {
        let _ = writeln!(
            s,
            "\n## Block {} `{}` at `0x{:08X}`\n\n{}\n",
            b.index,
            b.name,
            b.base(),
            b.doc
        );
        if b.registers.is_empty() {
            continue;
        }
        s.push_str(
            "| offset | address | register | access | bits | reset | format | invalid values | description |\n\
             |---|---|---|---|---|---|---|---|---|\n",
        );
        for r in b.registers {
            let mut desc = r.doc.to_string();
            for f in r.fields {
                let bits = if f.width == 1 {
                    format!("{}", f.lsb)
                } else {
                    format!("{}:{}", f.lsb + f.width - 1, f.lsb)
                };
                let _ = write!(desc, "<br>`[{bits}]` {}: {}", f.name, f.doc);
            }
            let _ = writeln!(
                s,
                "| `0x{:03X}` | `0x{:08X}` | `{}` | {} | {} | `0x{:X}` ({}) | {} | {} | {} |",
                r.offset,
                b.addr(r),
                r.name,
                access(r.access),
                r.width,
                r.reset,
                r.reset,
                r.format.replace('|', "\\|"),
                invalid(r),
                desc.replace('|', "\\|")
            );
        }
    }
    s
}
