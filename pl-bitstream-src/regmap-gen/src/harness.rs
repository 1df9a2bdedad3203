//! The Verilator harness of `pl_top`, generated from
//! `ports::PL_TOP_PORTS`: the C++ shim (`csrc/pl_top_shim.cpp`) and
//! the `#[repr(C)]` structs `PtIn`/`PtOut` it shares with Rust
//! (`rtl_sim::pl_top`). Registers never appear here: the harness reaches them
//! through the AXI port, at addresses from the table.
use std::fmt::Write;

use crate::ports::{Port, PortDir};

/// Repository-relative path of the generated C++ shim.
pub const SHIM_PATH: &str = "pl-bitstream-src/sim/csrc/pl_top_shim.cpp";
/// Repository-relative path of the generated Rust structs.
pub const RUST_PATH: &str = "pl-bitstream-src/sim/src/pl_top_ports.rs";

/// The smallest unsigned word that holds `width` bits: (C, Rust, bits).
fn word(width: u8) -> (&'static str, &'static str, u8) {
    match width {
        0..=8 => ("uint8_t", "u8", 8),
        9..=16 => ("uint16_t", "u16", 16),
        17..=32 => ("uint32_t", "u32", 32),
        _ => ("uint64_t", "u64", 64),
    }
}

fn of(ports: &[Port], dir: PortDir) -> Vec<&Port> {
    ports.iter().filter(|p| p.dir == dir).collect()
}

/// `in->field` masked to the port width (nothing to mask for a full word).
fn masked(p: &Port) -> String {
    let (_, _, bits) = word(p.width);
    if p.width == bits {
        format!("in->{}", p.field)
    } else if p.width <= 32 {
        format!("in->{} & 0x{:x}", p.field, (1u64 << p.width) - 1)
    } else {
        format!("in->{} & 0x{:x}ULL", p.field, (1u64 << p.width) - 1)
    }
}

/// The C++ shim.
pub fn shim(ports: &[Port]) -> String {
    let mut s = String::new();
    s.push_str(
        "// Generated from pl-bitstream-src/regmap-gen/src/ports.rs (PL_TOP_PORTS) by `cargo run -p\n\
         // regmap-gen`; do not edit (a test fails when this file is stale).\n\
         //\n\
         // C ABI around the Verilated pl_top, for rtl-sim (Rust).\n\
         // pt_step applies the inputs with the clock low, settles the combinational\n\
         // logic, copies the outputs as the rising edge will sample them (so a Rust\n\
         // AXI master sees READY exactly as the slave presents it), then gives one\n\
         // rising edge: two evaluations per cycle. Only the simulation-only MPDCC\n\
         // clock gate uses the falling edge, so the clock returns low in the next\n\
         // cycle's first evaluation, with that cycle's inputs. The input-driven\n\
         // logic runs only in that first evaluation and only when an input other\n\
         // than the clock changed (pl_top_clock.h).\n\
         // pt_peek reads the outputs after the edge.\n\
         #include <cstdint>\n\n\
         #include \"Vpl_top.h\"\n\
         #include \"pl_top_clock.h\"\n\
         #include \"verilated.h\"\n\n\
         extern \"C\" {\n\n",
    );
    for (name, dir) in [("PtIn", PortDir::In), ("PtOut", PortDir::Out)] {
        let _ = writeln!(s, "struct {name} {{");
        for p in of(ports, dir) {
            let _ = writeln!(s, "    {} {};", word(p.width).0, p.field);
        }
        s.push_str("};\n\n");
    }
    s.push_str(
        "struct PlTopSim {\n    VerilatedContext ctx;\n    Vpl_top* top;\n};\n\n\
         static void apply(Vpl_top* t, const PtIn* in) {\n",
    );
    for p in of(ports, PortDir::In) {
        let _ = writeln!(s, "    t->{} = {};", p.verilog, masked(p));
    }
    s.push_str("}\n\n// Every input but the clock as `in` would set it.\nstatic bool unchanged(const Vpl_top* t, const PtIn* in) {\n    return true");
    for p in of(ports, PortDir::In) {
        let _ = write!(s, "\n        && t->{} == ({})", p.verilog, masked(p));
    }
    s.push_str(";\n}\n\nstatic void read_out(const Vpl_top* t, PtOut* out) {\n");
    for p in of(ports, PortDir::Out) {
        let _ = writeln!(s, "    out->{} = t->{};", p.field, p.verilog);
    }
    s.push_str(
        "}\n\nvoid* pt_new() {\n    auto* sim = new PlTopSim;\n    \
         sim->top = new Vpl_top(&sim->ctx, \"pl_top\");\n    sim->top->clk_i = 0;\n",
    );
    for p in of(ports, PortDir::In) {
        let _ = writeln!(s, "    sim->top->{} = {};", p.verilog, p.idle);
    }
    s.push_str(
        "    sim->top->eval();\n    return sim;\n}\n\n\
         void pt_step(void* p, const PtIn* in, PtOut* before_edge) {\n    \
         auto* t = static_cast<PlTopSim*>(p)->top;\n    if (unchanged(t, in)) {\n        \
         pl_top_clock::clock(t, 0);\n    } else {\n        apply(t, in);\n        t->clk_i = 0;\n        \
         t->eval();\n    }\n    read_out(t, before_edge);\n    pl_top_clock::clock(t, 1);\n}\n\n\
         void pt_peek(void* p, PtOut* out) { read_out(static_cast<PlTopSim*>(p)->top, out); }\n\n\
         void pt_free(void* p) {\n    auto* sim = static_cast<PlTopSim*>(p);\n    \
         sim->top->final();\n    delete sim->top;\n    delete sim;\n}\n}\n",
    );
    s
}

/// The Rust side: `PtIn`, `PtOut` (C layout shared with the shim) and
/// `PtIn::IDLE`.
pub fn rust(ports: &[Port]) -> String {
    let mut s = String::new();
    s.push_str(
        "// Generated from pl-bitstream-src/regmap-gen/src/ports.rs (PL_TOP_PORTS) by `cargo run -p\n\
         // regmap-gen`; do not edit (a test fails when this file is stale).\n\
         //! The ports of `pl_top` as the harness sees them (C layout shared with\n\
         //! `csrc/pl_top_shim.cpp`); re-exported by [`crate::pl_top`].\n\n\
         /// Inputs of `pl_top` (C layout shared with the shim).\n\
         #[repr(C)]\n\
         #[derive(Debug, Clone, Copy, Default)]\n\
         pub struct PtIn {\n",
    );
    for p in of(ports, PortDir::In) {
        let _ = writeln!(
            s,
            "    /// {}\n    pub {}: {},",
            p.doc,
            p.field,
            word(p.width).1
        );
    }
    s.push_str(
        "}\n\n/// Outputs of `pl_top`.\n#[repr(C)]\n\
         #[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]\npub struct PtOut {\n",
    );
    for p in of(ports, PortDir::Out) {
        let _ = writeln!(
            s,
            "    /// {}\n    pub {}: {},",
            p.doc,
            p.field,
            word(p.width).1
        );
    }
    s.push_str(
        "}\n\nimpl PtIn {\n    /// Every input at its inactive level (reset asserted, the \
         active-low\n    /// fault pin high).\n    pub const IDLE: Self = Self {\n",
    );
    for p in of(ports, PortDir::In) {
        let _ = writeln!(s, "        {}: {},", p.field, p.idle);
    }
    s.push_str("    };\n}\n");
    s
}
