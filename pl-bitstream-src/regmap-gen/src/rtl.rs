//! The PL register file `pl-bitstream-src/rtl/pl_regs.v`, generated from the
//! table: storage, address decode, byte strobes, each register's
//! invalid-value rule, W1C, read-only and unmapped accesses, the read mux and
//! one port per field to the cores ([`regmap::Hw`] says which).
use std::fmt::Write;

use regmap::{Access, Block, Hw, Invalid, Register, AXI_ADDR_BITS};

/// Repository-relative path of the generated register file.
pub const PL_REGS_PATH: &str = "pl-bitstream-src/rtl/pl_regs.v";

/// One port of a register towards its core.
struct Port {
    output: bool,
    width: u8,
    name: String,
}

/// A field as the RTL sees it: the register's fields, or the whole
/// register when it has none. `suffix` is `""` or `_<field>`.
struct Slice {
    suffix: String,
    lsb: u8,
    width: u8,
}

fn slices(r: &Register) -> Vec<Slice> {
    if r.fields.is_empty() {
        vec![Slice {
            suffix: String::new(),
            lsb: 0,
            width: r.width,
        }]
    } else {
        r.fields
            .iter()
            .map(|f| Slice {
                suffix: format!("_{}", f.name.to_ascii_lowercase()),
                lsb: f.lsb,
                width: f.width,
            })
            .collect()
    }
}

fn lc(r: &Register) -> String {
    r.name.to_ascii_lowercase()
}

/// Whether the register file stores the register.
fn stored(r: &Register) -> bool {
    r.access == Access::Rw || r.hw == Hw::Errors
}

/// The ports of `r` (see `Hw`).
fn ports(r: &Register) -> Vec<Port> {
    let n = lc(r);
    let mut p = Vec::new();
    let each = |p: &mut Vec<Port>, output: bool, tail: &str| {
        for s in slices(r) {
            p.push(Port {
                output,
                width: s.width,
                name: format!("{n}{}{tail}", s.suffix),
            });
        }
    };
    match (r.access, r.hw) {
        (Access::Rw, Hw::Strobe) => p.push(Port {
            output: true,
            width: 1,
            name: format!("{n}_we_o"),
        }),
        (Access::Rw, hw) => {
            each(&mut p, true, "_o");
            if hw == Hw::HwClear {
                p.push(Port {
                    output: false,
                    width: 1,
                    name: format!("{n}_hw_clr_i"),
                });
            }
        }
        (Access::Ro, Hw::Const) | (Access::W1c, Hw::Errors) => {}
        (Access::Ro, _) => each(&mut p, false, "_i"),
        (Access::W1c, _) => {
            each(&mut p, false, "_i");
            each(&mut p, true, "_clr_o");
        }
    }
    p
}

/// The ports of `r` for the docs: `` `name_o` [w] `` separated by `<br>`,
/// or "none".
pub fn port_list(r: &Register) -> String {
    let p = ports(r);
    if p.is_empty() {
        return "none".into();
    }
    p.iter()
        .map(|p| {
            if p.width == 1 {
                format!("`{}`", p.name)
            } else {
                format!("`{}` [{}]", p.name, p.width)
            }
        })
        .collect::<Vec<_>>()
        .join("<br>")
}

fn range(width: u8) -> String {
    if width == 1 {
        String::new()
    } else {
        format!("[{}:0]", width - 1)
    }
}

/// `{pad, parts...}` of `width` bits from (lsb, width, expr) parts.
fn concat(width: u8, mut parts: Vec<(u8, u8, String)>) -> String {
    parts.sort_by_key(|p| std::cmp::Reverse(p.0));
    let mut items = Vec::new();
    let mut top = width;
    for (lsb, w, e) in parts {
        let end = lsb + w;
        if end < top {
            items.push(format!("{}'d0", top - end));
        }
        items.push(e);
        top = lsb;
    }
    if top > 0 {
        items.push(format!("{top}'d0"));
    }
    if items.len() == 1 {
        items.pop().unwrap_or_default()
    } else {
        format!("{{{}}}", items.join(", "))
    }
}

fn bits(v: &str, lsb: u8, width: u8) -> String {
    if width == 1 {
        format!("{v}[{lsb}]")
    } else {
        format!("{v}[{}:{lsb}]", lsb + width - 1)
    }
}

/// The value read back: 32 bits.
fn read_expr(r: &Register) -> String {
    let n = lc(r);
    if r.hw == Hw::Const {
        return format!("32'h{:08x}", r.reset);
    }
    if stored(r) {
        return concat(32, vec![(0, r.width, format!("{n}_q"))]);
    }
    concat(
        32,
        slices(r)
            .into_iter()
            .map(|s| (s.lsb, s.width, format!("{n}{}_i", s.suffix)))
            .collect(),
    )
}

/// The merged (byte strobes) and ruled (clamp) 32-bit word a write leaves.
fn next_expr(r: &Register) -> String {
    let n = lc(r);
    if r.access == Access::W1c {
        return "merge(32'd0, wr_data_q, wr_strb_q)".into();
    }
    let old = concat(32, vec![(0, r.width, format!("{n}_q"))]);
    let m = format!("merge({old}, wr_data_q, wr_strb_q)");
    match r.invalid {
        Invalid::Clamp { min, max } => format!("clamp({m}, 32'h{min:08x}, 32'h{max:08x})"),
        _ => m,
    }
}

/// The AXI window address of `r`: a Verilog literal.
fn addr(b: &Block, r: &Register) -> String {
    format!(
        "{AXI_ADDR_BITS}'h{:04x}",
        (b.index as usize) << 12 | r.offset as usize
    )
}

/// The generated `pl_regs.v` for `blocks`: self-contained (literals, the
/// register names in the expressions and comments).
pub fn pl_regs(blocks: &[&Block]) -> String {
    let regs: Vec<(&Block, &Register)> = blocks
        .iter()
        .flat_map(|b| b.registers.iter().map(move |r| (*b, *r)))
        .collect();
    let aw = AXI_ADDR_BITS;
    let mut s = String::new();
    s.push_str(
        "// Generated from firmware/regmap/src/lib.rs by `cargo run -p regmap-gen`;\n\
         // do not edit (a test fails when this file is stale).\n\
         //\n\
         // pl_regs: the PL register file behind axil_slave. Register-bus side:\n\
         // wr_i/rd_i are one-cycle strobes; a write takes effect and wr_err_o\n\
         // answers it the cycle after wr_i; rd_err_o is combinational and\n\
         // rd_data_o answers rd_i the next cycle. Write rules (as the table's\n\
         // Register::apply_write): byte strobes merge into the current value,\n\
         // then the 32-bit word is masked to the width (all valid), clamped as a\n\
         // whole to the table's bounds, or rejected (above the bound: the\n\
         // register keeps its value and ERR.BAD_VALUE is set).\n\
         // Unmapped offsets, and writes to RO registers, answer SLVERR and set\n\
         // ERR.BAD_ADDR. W1C flags clear on a written 1.\n\
         //\n\
         // Ports towards the cores, one per field (a register without fields is\n\
         // one port), named <register>[_<field>] in lower case: RW fields are\n\
         // outputs _o of the stored bits; RO fields are inputs _i; W1C flags kept\n\
         // in a core are inputs _i with a one-cycle output _clr_o of the written\n\
         // ones; a strobe register gives only _we_o (one cycle per write); a\n\
         // register the hardware can clear has an input _hw_clr_i that holds it at\n\
         // 0 and wins over a write. RO constants and ERR have no port.\n\
         `default_nettype none\n\nmodule pl_regs (\n",
    );
    let _ = writeln!(
        s,
        "    input  wire        clk_i,\n    input  wire        rst_i,\n    \
         // register bus\n    input  wire        wr_i,\n    input  wire [{a}:0] wr_addr_i,\n    \
         input  wire [31:0] wr_data_i,\n    input  wire [ 3:0] wr_strb_i,\n    \
         output wire        wr_err_o,\n    input  wire        rd_i,\n    \
         input  wire [{a}:0] rd_addr_i,\n    output reg  [31:0] rd_data_o,\n    \
         output reg         rd_err_o{}",
        if regs.iter().any(|(_, r)| !ports(r).is_empty()) {
            ","
        } else {
            ""
        },
        a = aw - 1
    );
    let mut all: Vec<(String, Port)> = Vec::new();
    for b in blocks {
        for r in b.registers {
            for p in ports(r) {
                all.push((b.name.to_string(), p));
            }
        }
    }
    let mut last_block = String::new();
    for (i, (blk, p)) in all.iter().enumerate() {
        if *blk != last_block {
            let _ = writeln!(s, "    // block {blk}");
            last_block.clone_from(blk);
        }
        let dir = if p.output { "output" } else { "input " };
        let r = range(p.width);
        let sep = if i + 1 == all.len() { "" } else { "," };
        let _ = writeln!(s, "    {dir} wire {r:>7} {}{sep}", p.name);
    }
    s.push_str(");\n\n");
    s.push_str(
        "    // Byte-strobe merge of a write over the current (zero-extended) value,\n\
         \x20   // as one mask (a per-byte loop costs the Verilated model about a quarter\n\
         \x20   // of its time: every register's merge is evaluated on every clock).\n\
         \x20   function automatic [31:0] merge(input [31:0] old, input [31:0] data, input [3:0] strb);\n\
         \x20       reg [31:0] m;\n\
         \x20       begin\n\
         \x20           m = {{8{strb[3]}}, {8{strb[2]}}, {8{strb[1]}}, {8{strb[0]}}};\n\
         \x20           merge = (data & m) | (old & ~m);\n\
         \x20       end\n\
         \x20   endfunction\n\n\
         \x20   function automatic [31:0] clamp(input [31:0] v, input [31:0] lo, input [31:0] hi);\n\
         \x20       begin\n\
         \x20           if (v < lo) clamp = lo;\n\
         \x20           else if (v > hi) clamp = hi;\n\
         \x20           else clamp = v;\n\
         \x20       end\n\
         \x20   endfunction\n\n",
    );

    s.push_str("    // Storage.\n");
    for (_, r) in regs.iter().filter(|(_, r)| stored(r)) {
        let _ = writeln!(s, "    reg {:>7} {}_q;", range(r.width), lc(r));
    }

    let writable: Vec<&(&Block, &Register)> = regs
        .iter()
        .filter(|(_, r)| r.access != Access::Ro)
        .collect();
    s.push_str(
        "\n    // Write decode stage (one clock each at 100 MHz, docs/rtl.md): every\n    \
         // register's address match is registered with the data and strobes; the\n    \
         // write takes effect, and wr_err_o answers it, the cycle after wr_i.\n    \
         reg        wr_q;\n    reg [31:0] wr_data_q;\n    reg [ 3:0] wr_strb_q;\n",
    );
    for (_, r) in &writable {
        let _ = writeln!(s, "    reg        hit_{}_q;", lc(r));
    }
    s.push_str(
        "    always @(posedge clk_i) begin\n        if (rst_i) begin\n            wr_q      <= 1'b0;\n            \
         wr_data_q <= 32'd0;\n            wr_strb_q <= 4'd0;\n",
    );
    for (_, r) in &writable {
        let _ = writeln!(s, "            hit_{}_q <= 1'b0;", lc(r));
    }
    s.push_str(
        "        end else begin\n            wr_q      <= wr_i;\n            wr_data_q <= wr_data_i;\n            \
         wr_strb_q <= wr_strb_i;\n",
    );
    for (b, r) in &writable {
        let _ = writeln!(
            s,
            "            hit_{}_q <= wr_i && wr_addr_i == {};",
            lc(r),
            addr(b, r)
        );
    }
    s.push_str("        end\n    end\n");
    s.push_str("\n    // Write decode, and the word each write leaves (merged, clamped).\n");
    for (_, r) in &writable {
        let n = lc(r);
        let _ = writeln!(s, "    wire w_{n} = hit_{n}_q;");
        let _ = writeln!(s, "    wire [31:0] n_{n} = {};", next_expr(r));
        if let (Access::Rw, Invalid::Reject { max }) = (r.access, r.invalid) {
            let _ = writeln!(s, "    wire bad_{n} = n_{n} > 32'h{max:08x};");
        }
    }
    let any_ok = if writable.is_empty() {
        "1'b0".to_string()
    } else {
        writable
            .iter()
            .map(|(_, r)| format!("w_{}", lc(r)))
            .collect::<Vec<_>>()
            .chunks(5)
            .map(|c| c.join(" | "))
            .collect::<Vec<_>>()
            .join("\n        | ")
    };
    let _ = writeln!(s, "    wire w_any_ok = {any_ok};");
    let rejected: Vec<String> = regs
        .iter()
        .filter(|(_, r)| r.access == Access::Rw && matches!(r.invalid, Invalid::Reject { .. }))
        .map(|(_, r)| format!("(w_{0} && bad_{0})", lc(r)))
        .collect();
    let _ = writeln!(
        s,
        "    // Access errors of this cycle (set ERR).\n    wire bad_value = {};\n    \
         wire bad_addr = (wr_q && !w_any_ok) || (rd_i && rd_err_o);\n\n    \
         assign wr_err_o = wr_q && !w_any_ok;",
        if rejected.is_empty() {
            "1'b0".to_string()
        } else {
            rejected.join(" || ")
        }
    );

    s.push_str("\n    always @(posedge clk_i) begin\n        if (rst_i) begin\n");
    for (_, r) in regs.iter().filter(|(_, r)| stored(r)) {
        let _ = writeln!(s, "            {}_q <= {}'h{:x};", lc(r), r.width, r.reset);
    }
    s.push_str("        end else begin\n");
    for (_, r) in regs.iter().filter(|(_, r)| stored(r)) {
        let n = lc(r);
        let w = r.width;
        let store = format!("{n}_q <= n_{n}[{}:0];", w - 1);
        match (r.hw, r.invalid) {
            (Hw::Errors, _) => {
                let field = |name: &str| r.fields.iter().find(|f| f.name == name);
                let mut set = Vec::new();
                for (name, e) in [("BAD_VALUE", "bad_value"), ("BAD_ADDR", "bad_addr")] {
                    if let Some(f) = field(name) {
                        set.push((f.lsb, f.width, e.to_string()));
                    }
                }
                let _ = writeln!(
                    s,
                    "            // A flag set in this cycle wins over its clear.\n            \
                     {n}_q <= ({n}_q & ~(w_{n} ? n_{n}[{}:0] : {w}'d0)) | {};",
                    w - 1,
                    concat(w, set)
                );
            }
            (Hw::HwClear, _) => {
                let _ = writeln!(
                    s,
                    "            if ({n}_hw_clr_i) {n}_q <= {w}'d0;\n            else if (w_{n}) {store}"
                );
            }
            (_, Invalid::Reject { .. }) => {
                let _ = writeln!(s, "            if (w_{n} && !bad_{n}) {store}");
            }
            _ => {
                let _ = writeln!(s, "            if (w_{n}) {store}");
            }
        }
    }
    s.push_str("        end\n    end\n\n");

    // Read mux in two stages, each within one clock at 100 MHz
    // (docs/rtl.md, delay model): at the read strobe every page's registers
    // are multiplexed into that page's word register (the other pages' words
    // are 0), the next cycle the addressed page's word is rd_data_o.
    let page_bits = AXI_ADDR_BITS - 12;
    let page_reg = |b: &Block| format!("rd_{}_q", b.name.to_lowercase());
    s.push_str(
        "    // Read mux, two stages (one clock each at 100 MHz, docs/rtl.md): at\n    \
         // the read strobe each page's registers are multiplexed into that page's\n    \
         // word (the other pages' words are 0); the next cycle rd_data_o is the\n    \
         // addressed page's word. rd_err_o is combinational (ERR.BAD_ADDR is set\n    \
         // at the strobe's edge).\n",
    );
    let _ = writeln!(s, "    reg [{}:0] rd_page_q;", page_bits - 1);
    for b in blocks {
        let _ = writeln!(s, "    reg [31:0] {};", page_reg(b));
    }
    s.push_str("    always @(posedge clk_i) begin\n        if (rst_i) begin\n");
    let _ = writeln!(s, "            rd_page_q <= {page_bits}'d0;");
    for b in blocks {
        let _ = writeln!(s, "            {} <= 32'd0;", page_reg(b));
    }
    s.push_str("        end else if (rd_i) begin\n");
    let _ = writeln!(
        s,
        "            rd_page_q <= rd_addr_i[{}:12];",
        AXI_ADDR_BITS - 1
    );
    for b in blocks {
        let _ = writeln!(s, "            {} <= 32'd0;", page_reg(b));
    }
    s.push_str("            case (rd_addr_i)\n");
    for (b, r) in &regs {
        let _ = writeln!(
            s,
            "                {}: {} <= {};  // {}",
            addr(b, r),
            page_reg(b),
            read_expr(r),
            r.name
        );
    }
    s.push_str("                default: ;\n            endcase\n        end\n    end\n");
    s.push_str("    always @(*) begin\n        case (rd_page_q)\n");
    for b in blocks {
        let _ = writeln!(
            s,
            "            {page_bits}'d{}: rd_data_o = {};",
            b.index,
            page_reg(b)
        );
    }
    s.push_str("            default: rd_data_o = 32'd0;\n        endcase\n    end\n");
    s.push_str("    always @(*) begin\n        case (rd_addr_i)\n");
    let all_addr: Vec<String> = regs.iter().map(|(b, r)| addr(b, r)).collect();
    for c in all_addr.chunks(6) {
        let _ = writeln!(s, "            {}: rd_err_o = 1'b0;", c.join(", "));
    }
    s.push_str("            default: rd_err_o = rd_i;\n        endcase\n    end\n\n");

    s.push_str("    // Fields to the cores.\n");
    for (_, r) in &regs {
        let n = lc(r);
        match (r.access, r.hw) {
            (Access::Rw, Hw::Strobe) => {
                let _ = writeln!(s, "    assign {n}_we_o = w_{n};");
            }
            (Access::Rw, _) => {
                for sl in slices(r) {
                    let v = if sl.width == r.width {
                        format!("{n}_q")
                    } else {
                        bits(&format!("{n}_q"), sl.lsb, sl.width)
                    };
                    let _ = writeln!(s, "    assign {n}{}_o = {v};", sl.suffix);
                }
            }
            (Access::W1c, Hw::Plain) => {
                for sl in slices(r) {
                    let _ = writeln!(
                        s,
                        "    assign {n}{}_clr_o = w_{n} ? {} : {}'d0;",
                        sl.suffix,
                        bits(&format!("n_{n}"), sl.lsb, sl.width),
                        sl.width
                    );
                }
            }
            _ => {}
        }
    }
    formal(&mut s, &regs);
    s.push_str("endmodule\n\n`default_nettype wire\n");
    s
}

/// The register file's own properties (yosys `sat -tempinduct`, see
/// scripts/rtl-formal): every stored register changes only on its write (or
/// its hardware clear), holds a value its write rule allows, and access
/// errors set `ERR`.
fn formal(s: &mut String, regs: &[(&Block, &Register)]) {
    s.push_str(
        "\n`ifdef FORMAL\n    reg f_past_valid = 1'b0;\n    \
         always @(posedge clk_i) f_past_valid <= 1'b1;\n    always @(*) begin\n        \
         if (!f_past_valid) assume (rst_i);\n    end\n    \
         always @(posedge clk_i) begin\n        if (f_past_valid && !$past(rst_i)) begin\n",
    );
    for (_, r) in regs.iter().filter(|(_, r)| stored(r)) {
        let n = lc(r);
        match r.hw {
            Hw::Errors => {
                for (name, e) in [("BAD_VALUE", "bad_value"), ("BAD_ADDR", "bad_addr")] {
                    if let Some(f) = r.fields.iter().find(|f| f.name == name) {
                        let _ = writeln!(
                            s,
                            "            // ERR.{name} is set by its event.\n            \
                             if ($past({e})) assert ({n}_q[{}]);",
                            f.lsb
                        );
                    }
                }
                let _ = writeln!(
                    s,
                    "            // Only a write clears ERR bits.\n            \
                     if ($past(!w_{n})) assert (({n}_q & $past({n}_q)) == $past({n}_q));"
                );
            }
            Hw::HwClear => {
                let _ = writeln!(
                    s,
                    "            // {0}: held at 0 by the hardware, else changed only by a write.\n            \
                     if ($past({n}_hw_clr_i)) assert ({n}_q == {w}'d0);\n            \
                     if ($past(!{n}_hw_clr_i && !w_{n})) assert ({n}_q == $past({n}_q));",
                    r.name,
                    w = r.width
                );
            }
            _ => {
                let _ = writeln!(
                    s,
                    "            // {}: changed only by a write.\n            \
                     if ($past(!w_{n})) assert ({n}_q == $past({n}_q));",
                    r.name
                );
            }
        }
        match r.invalid {
            Invalid::Clamp { min, max } => {
                let q = concat(32, vec![(0, r.width, format!("{n}_q"))]);
                let mut conds = Vec::new();
                if min > 0 {
                    conds.push(format!("{q} >= 32'h{min:08x}"));
                }
                if u64::from(max) < (1u64 << r.width) - 1 {
                    conds.push(format!("{q} <= 32'h{max:08x}"));
                }
                if !conds.is_empty() {
                    let _ = writeln!(
                        s,
                        "            // {}: always inside its clamp range.\n            assert ({});",
                        r.name,
                        conds.join(" && ")
                    );
                }
            }
            Invalid::Reject { max } => {
                let _ = writeln!(
                    s,
                    "            // {}: a rejected value is never stored.\n            \
                     assert ({} <= 32'h{max:08x});",
                    r.name,
                    concat(32, vec![(0, r.width, format!("{n}_q"))])
                );
            }
            Invalid::AllValid => {}
        }
    }
    s.push_str("        end\n    end\n`endif\n");
}
