//! Generates from the one table, `regmap`, every file that repeats
//! it: the Verilog header `pl-bitstream-src/rtl/regmap.vh`, the register file
//! `pl-bitstream-src/rtl/pl_regs.v` ([`rtl`]), `docs/register-map.md` and the
//! typed accessors `firmware/regmap/src/regs.rs` ([`rust`]); and from the
//! port list [`ports::PL_TOP_PORTS`] the `pl_top` Verilator harness
//! ([`harness`]); from the RTL's own port lists the port accessors of the
//! Verilated cores ([`core_ports`]). `cargo run -p
//! regmap-gen` writes them; the test `tests/regmap_files.rs` fails when
//! the committed files differ from what this produces.
use std::fmt::Write;

pub mod core_ports;
pub mod harness;
pub mod ports;
pub mod rtl;
pub mod rust;
pub mod trig;

/// Every generated file: (repository-relative path, contents) for the
/// table `blocks`.
pub fn files(blocks: &[&Block]) -> Vec<(&'static str, String)> {
    vec![
        (VERILOG_PATH, verilog(blocks)),
        (rtl::PL_REGS_PATH, rtl::pl_regs(blocks)),
        (MARKDOWN_PATH, markdown(blocks)),
        (rust::RUST_PATH, rust::rust(blocks)),
        (harness::SHIM_PATH, harness::shim(ports::PL_TOP_PORTS)),
        (harness::RUST_PATH, harness::rust(ports::PL_TOP_PORTS)),
        (trig::SIN_TABLE_PATH, trig::sin_table()),
    ]
    .into_iter()
    .chain(core_ports::files())
    .collect()
}

use regmap::{self, Access, Block, Invalid, Register};

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
pub fn verilog(blocks: &[&Block]) -> String {
    let mut s = String::new();
    s.push_str(
        "// Generated from firmware/regmap/src/lib.rs by `cargo run -p regmap-gen`;\n\
         // do not edit (a test fails when this file is stale).\n\
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
    for b in blocks {
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

/// The part of the docs that explains the generated files and how to add
/// a register.
const HOW_TO: &str = r#"
## What is generated from the table

`cargo run -p regmap-gen` writes, from `firmware/regmap/src/lib.rs`:

| file | contents |
|---|---|
| `pl-bitstream-src/rtl/pl_regs.v` | the whole AXI4-Lite register file behind `axil_slave`: storage, address decode, byte strobes, each register's write rule, W1C, SLVERR for RO and unmapped offsets, `ERR`, the read mux, one port per field |
| `pl-bitstream-src/rtl/regmap.vh` | Verilog localparams (`RM_<REG>_ADDR`, `_W`, `_RESET`, bounds, field positions, `RM_MODE_*`) for hand-written RTL |
| `firmware/regmap/src/regs.rs` | typed accessors `regmap::regs` over `regmap::bus::RegisterBus` |
| `docs/register-map.md` | this page |
| `pl-bitstream-src/sim/csrc/pl_top_shim.cpp`, `pl-bitstream-src/sim/src/pl_top_ports.rs` | the `pl_top` Verilator harness (C++ shim, `PtIn`/`PtOut`), from the port list `regmap_gen::ports::PL_TOP_PORTS` (a test checks `pl_top.v`'s ports against it) |
| `pl-bitstream-src/sim/csrc/<core>_ports.h` for `mpdcc_core`, `mpdcc_explorer`, `mpdcc_lane`, `mpdtc_core` | from the port list of the core's own RTL file (not the table): a setter per input masked to its width, a getter per output sign-extended when signed, and for the ports that pack equal lanes (`core_ports::LANES`, e.g. `bnd_i` = 7 x 16 bits) per-lane setters/getters and the lane count; the cores' shims use them and pack no bits by hand |

`cargo test -p regmap-gen` fails when a committed file differs from what the
generator writes. The hand-written RTL holds only the cores and their wiring
in `pl_top.v`.

Ports of `pl_regs` (the table's `hw` column, `regmap::Hw`), named
`<register>[_<field>]` in lower case, one per field (a register without
fields is one port):

| access, `hw` | ports |
|---|---|
| RW, `Plain` | output `_o` per field: the stored bits |
| RW, `HwClear` | as `Plain`, and input `_hw_clr_i`: holds the register at 0, wins over a write (`GATE_CTRL` while a fault is latched) |
| RW, `Strobe` | output `_we_o` only: one cycle per write (`HEARTBEAT`, `MPDTC_START`); the value is stored for read-back |
| RO, `Plain` | input `_i` per field, read as is |
| RO, `Const` | none: reads the reset value (`ID`, `VERSION`, `MPDTC_LATENCY`) |
| W1C, `Plain` | input `_i` per field (the flags live in the core) and output `_clr_o` per field (the ones written, one cycle) |
| W1C, `Errors` | none: the register file's own `ERR` |

Typed access from Rust (`regmap::regs`): one module per block, per register
a zero-sized type named after it in camel case with `ADDR`, `DEF` (the
table entry) and the accesses its type allows (RW `read`/`write`/`modify`,
RO `read`, W1C `read`/`write`), and a value type `<Name>Value` with a getter
and a `with_*` setter per field (`bool` for one bit, else `u32` masked to
the field; a register without fields has the one field `value`):

```rust
use regmap::regs::pwm::{DeadTime, DeadTimeValue, GateCtrl};
DeadTime::write(&mut bus, DeadTimeValue::ZERO.with_value(100))?; // 1 us
GateCtrl::modify(&mut bus, |v| v.with_gate_en(true))?;
let on = GateCtrl::read(&mut bus)?.gate_en();
```

## Adding a register

One table entry: write the `Register` constant next to its block's others in
`firmware/regmap/src/lib.rs` and list it in the block's `registers`
(increasing offset), for example a clamped 12-bit setting of the PWM block:

```rust
/// PWM/gates: example setting.
pub const TRIM: Register = Register {
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
```

Then `cargo run -p regmap-gen` regenerates the files: `pl_regs` gets
`trim_q`, its decode, the clamp, the read-mux entry and the port
`output wire [11:0] trim_o`; `regmap::regs::pwm::Trim` and `TrimValue`
appear; this page gets the row. What stays by hand is the core that uses the
value: connect `.trim_o(...)` in `pl_top.v` (Verilator warns about an
unconnected port). The `pl_top` harness (`rtl-sim`, generated from
`PL_TOP_PORTS`) binds only the AXI port and the pins, so it needs nothing. Bump `VERSION` when the map changes. The
test `tests/add_register.rs` of `regmap-gen` does exactly this on a copy of
the table and checks the RTL (Verilator -Wall), the accessors and this page.
"#;

/// The documentation table.
pub fn markdown(blocks: &[&Block]) -> String {
    let mut s = String::new();
    s.push_str("# PL register map\n\n");
    s.push_str(
        "Generated from `firmware/regmap/src/lib.rs` by `cargo run -p regmap-gen`; do not \
         edit.\n\n",
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
    s.push_str(HOW_TO);
    for b in blocks {
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
            "| offset | address | register | access | bits | reset | format | invalid values | description | `pl_regs` ports |\n\
             |---|---|---|---|---|---|---|---|---|---|\n",
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
                "| `0x{:03X}` | `0x{:08X}` | `{}` | {} | {} | `0x{:X}` ({}) | {} | {} | {} | {} |",
                r.offset,
                b.addr(r),
                r.name,
                access(r.access),
                r.width,
                r.reset,
                r.reset,
                r.format.replace('|', "\\|"),
                invalid(r),
                desc.replace('|', "\\|"),
                rtl::port_list(r)
            );
        }
    }
    s
}
