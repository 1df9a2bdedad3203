//! The port accessors of the Verilated cores (`mpdcc_core`, `mpdcc_explorer`,
//! `mpdcc_lane`, `mpdtc_core`), generated from the port lists of their RTL
//! files: per input a setter masked to the port's width, per output a getter
//! sign-extended when the port is signed, ports wider than 64 bits as 32-bit
//! words (least significant first), and for the ports that pack equal lanes
//! ([`LANES`]: several words of one format side by side, lane `k` in bits
//! `[k w +: w]`) per-lane accessors and the lane count. The shims in
//! `pl-bitstream-src/sim/csrc/` include them, so no width, lane or port list
//! is written in a shim.
use std::fmt::Write;

/// Direction of a port.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dir {
    /// `input`.
    In,
    /// `output`.
    Out,
}

/// One port of a module's ANSI port list.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RtlPort {
    /// Direction.
    pub dir: Dir,
    /// Declared `signed`.
    pub signed: bool,
    /// Bits (`[msb:lsb]` with constant bounds, 1 without a range).
    pub width: u32,
    /// Port name.
    pub name: String,
}

/// The cores: (module, its RTL file's text, repository-relative path of the
/// generated header).
pub const CORES: &[(&str, &str, &str)] = &[
    (
        "mpdcc_core",
        include_str!("../../rtl/mpdcc_core.v"),
        "pl-bitstream-src/sim/csrc/mpdcc_core_ports.h",
    ),
    (
        "mpdcc_explorer",
        include_str!("../../rtl/mpdcc_explorer.v"),
        "pl-bitstream-src/sim/csrc/mpdcc_explorer_ports.h",
    ),
    (
        "mpdcc_lane",
        include_str!("../../rtl/mpdcc_lane.v"),
        "pl-bitstream-src/sim/csrc/mpdcc_lane_ports.h",
    ),
    (
        "mpdtc_core",
        include_str!("../../rtl/mpdtc_core.v"),
        "pl-bitstream-src/sim/csrc/mpdtc_core_ports.h",
    ),
];

/// Ports made of equal lanes, lane `k` in bits `[k w +: w]` of the port
/// (the RTL's `// 7 x Q2.13`-style comments): (module, port, lane width `w`,
/// lanes signed). The port's width must be a multiple of `w` (checked when
/// the headers are generated).
pub const LANES: &[(&str, &str, u32, bool)] = &[
    ("mpdcc_core", "s_prev_i", 3, false),
    ("mpdcc_core", "v_ph_i", 16, true),
    ("mpdcc_core", "bnd_i", 16, true),
    ("mpdcc_core", "s_o", 3, false),
    ("mpdcc_explorer", "s_i", 3, false),
    ("mpdcc_explorer", "s_prev_i", 3, false),
    ("mpdcc_explorer", "e0_i", 16, true),
    ("mpdcc_explorer", "bnd_i", 16, true),
    ("mpdcc_explorer", "dn_i", 16, true),
    ("mpdcc_explorer", "dn1_i", 16, true),
    ("mpdcc_explorer", "pn_i", 32, true),
    ("mpdcc_explorer", "pph_i", 32, true),
    ("mpdcc_explorer", "v_ph_i", 16, true),
    ("mpdcc_explorer", "s_o", 3, false),
    ("mpdcc_explorer", "d0_o", 16, true),
    ("mpdtc_core", "p_w2_i", 18, true),
    ("mpdtc_core", "i2_d_o", 25, true),
    ("mpdtc_core", "i2_q_o", 25, true),
    ("mpdtc_core", "err_o", 25, true),
    ("mpdtc_core", "cost2_o", 48, true),
];

/// Per-lane accessors of port `p` with lanes of `lw` bits: `_LANES`, a
/// setter of lane `k` (masked to the lane) for inputs, a getter (sign-extended
/// for signed lanes) for outputs.
fn lane_accessors(
    s: &mut String,
    module: &str,
    p: &RtlPort,
    lw: u32,
    signed: bool,
) -> Result<(), String> {
    let (n, v) = (&p.name, format!("V{module}"));
    if lw == 0 || lw > 64 || p.width % lw != 0 {
        return Err(format!(
            "{module}.{n}: {} bits are not lanes of {lw} bits",
            p.width
        ));
    }
    let lanes = p.width / lw;
    let mask = if lw == 64 { u64::MAX } else { (1u64 << lw) - 1 };
    let _ = writeln!(
        s,
        "// {n}: {lanes} lanes of {lw} bits{}, lane k in [{lw} k +: {lw}]\n\
         static const int {module}_{n}_LANES = {lanes};",
        if signed { " (signed)" } else { "" }
    );
    let wide = p.width > 64;
    match p.dir {
        Dir::In if wide => {
            let _ = writeln!(
                s,
                "static inline void {module}_set_{n}_lane({v}* t, int k, int64_t x) {{\n    \
                 for (int i = 0; i < {lw}; i++) {{\n        \
                 const int b = {lw} * k + i;\n        \
                 const uint32_t bit = 1u << (b % 32);\n        \
                 if (((uint64_t)x >> i) & 1u) t->{n}[b / 32] |= bit;\n        \
                 else t->{n}[b / 32] &= ~bit;\n    \
                 }}\n}}"
            );
        }
        Dir::In => {
            let _ = writeln!(
                s,
                "static inline void {module}_set_{n}_lane({v}* t, int k, int64_t x) {{\n    \
                 const uint64_t m = 0x{mask:x}ULL << ({lw} * k);\n    \
                 t->{n} = ((uint64_t)t->{n} & ~m) | (((uint64_t)x << ({lw} * k)) & m);\n}}"
            );
        }
        Dir::Out => {
            let raw = if wide {
                format!(
                    "uint64_t r = 0;\n    \
                     for (int i = 0; i < {lw}; i++) {{\n        \
                     const int b = {lw} * k + i;\n        \
                     r |= (uint64_t)((t->{n}[b / 32] >> (b % 32)) & 1u) << i;\n    \
                     }}"
                )
            } else {
                format!("const uint64_t r = ((uint64_t)t->{n} >> ({lw} * k)) & 0x{mask:x}ULL;")
            };
            let ret = if signed && lw < 64 {
                format!(
                    "const uint64_t m = 1ULL << {};\n    return (int64_t)((r ^ m) - m);",
                    lw - 1
                )
            } else {
                "return (int64_t)r;".to_string()
            };
            let _ = writeln!(
                s,
                "static inline int64_t {module}_get_{n}_lane(const {v}* t, int k) {{\n    {raw}\n    {ret}\n}}"
            );
        }
    }
    Ok(())
}

/// Text without `//` and `/* */` comments.
fn strip_comments(src: &str) -> String {
    let mut out = String::with_capacity(src.len());
    let mut rest = src;
    while !rest.is_empty() {
        if let Some(r) = rest.strip_prefix("//") {
            rest = r.find('\n').map_or("", |i| &r[i..]);
        } else if let Some(r) = rest.strip_prefix("/*") {
            rest = r.find("*/").map_or("", |i| &r[i + 2..]);
        } else {
            let c = rest.chars().next().unwrap_or(' ');
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    out
}

/// The ports of `module` in `src` (an ANSI-style header, constant ranges).
pub fn ports(src: &str, module: &str) -> Result<Vec<RtlPort>, String> {
    let text = strip_comments(src);
    let start = text
        .split_inclusive(char::is_whitespace)
        .scan(0, |pos, w| {
            let at = *pos;
            *pos += w.len();
            Some((at, w))
        })
        .zip(text.split_inclusive(char::is_whitespace).skip(1))
        .find(|((_, w), next)| w.trim() == "module" && next.trim_start().starts_with(module))
        .map(|((at, _), _)| at)
        .ok_or_else(|| format!("no `module {module}`"))?;
    let mut rest = &text[start + "module".len()..];
    rest = rest
        .trim_start()
        .strip_prefix(module)
        .ok_or("module name")?
        .trim_start();
    // Skip a parameter list `#( ... )`.
    if let Some(r) = rest.strip_prefix('#') {
        let r = r.trim_start();
        let mut depth = 0;
        let mut end = None;
        for (i, c) in r.char_indices() {
            match c {
                '(' => depth += 1,
                ')' => {
                    depth -= 1;
                    if depth == 0 {
                        end = Some(i);
                        break;
                    }
                }
                _ => {}
            }
        }
        rest = r[end.ok_or("unclosed parameter list")? + 1..].trim_start();
    }
    let body = rest.strip_prefix('(').ok_or("no port list")?;
    let body = &body[..body.find(");").ok_or("unclosed port list")?];
    let mut out = Vec::new();
    for decl in body.split(',') {
        let mut words = decl.split_whitespace().peekable();
        let dir = match words.next() {
            Some("input") => Dir::In,
            Some("output") => Dir::Out,
            Some(w) => {
                return Err(format!(
                    "{module}: `{w}` is not a direction (non-ANSI port?)"
                ))
            }
            None => continue,
        };
        let mut signed = false;
        let mut range = String::new();
        let mut name = None;
        for w in words {
            match w {
                "wire" | "reg" => {}
                "signed" => signed = true,
                _ if w.starts_with('[') || !range.is_empty() && !range.contains(']') => {
                    range.push_str(w);
                    // `[7:0]name` written without a space.
                    if let Some(i) = range.find(']') {
                        let tail = range[i + 1..].to_string();
                        range.truncate(i + 1);
                        if !tail.is_empty() {
                            name = Some(tail);
                        }
                    }
                }
                _ => name = Some(w.to_string()),
            }
        }
        let width = if range.is_empty() {
            1
        } else {
            let inner = range.trim_start_matches('[').trim_end_matches(']');
            let (m, l) = inner
                .split_once(':')
                .ok_or(format!("{module}: range {range}"))?;
            let m: u32 = m
                .trim()
                .parse()
                .map_err(|_| format!("{module}: range {range} is not constant"))?;
            let l: u32 = l
                .trim()
                .parse()
                .map_err(|_| format!("{module}: range {range} is not constant"))?;
            m.abs_diff(l) + 1
        };
        let name = name.ok_or(format!("{module}: a port without a name"))?;
        out.push(RtlPort {
            dir,
            signed,
            width,
            name,
        });
    }
    Ok(out)
}

/// The C++ header of `module`'s port accessors.
pub fn header(module: &str, ports: &[RtlPort]) -> String {
    let v = format!("V{module}");
    let mut s = format!(
        "// Generated from pl-bitstream-src/rtl/{module}.v (its port list) by `cargo run -p\n\
         // regmap-gen`; do not edit (a test fails when this file is stale).\n\
         //\n\
         // Setters mask to the port's width; getters of signed ports sign-extend;\n\
         // ports wider than 64 bits go as 32-bit words, least significant first.\n\
         #pragma once\n\
         #include <cstdint>\n\n\
         #include \"{v}.h\"\n\n"
    );
    for p in ports {
        let n = &p.name;
        let w = p.width;
        let sign = if p.signed { "signed " } else { "" };
        let _ = writeln!(
            s,
            "// {} {sign}[{}:0] {n}",
            if p.dir == Dir::In { "input" } else { "output" },
            w - 1
        );
        let words = w.div_ceil(32);
        let top_mask = if w % 32 == 0 {
            0xFFFF_FFFFu32
        } else {
            (1u32 << (w % 32)) - 1
        };
        match (p.dir, w > 64) {
            (Dir::In, false) => {
                let mask = if w == 64 { u64::MAX } else { (1u64 << w) - 1 };
                let _ = writeln!(
                    s,
                    "static inline void {module}_set_{n}({v}* t, int64_t x) {{\n    \
                     t->{n} = (uint64_t)x & 0x{mask:x}ULL;\n}}"
                );
            }
            (Dir::In, true) => {
                let _ = writeln!(
                    s,
                    "static inline void {module}_set_{n}({v}* t, const uint32_t* w) {{\n    \
                     for (int k = 0; k < {words}; k++) t->{n}[k] = w[k];\n    \
                     t->{n}[{}] &= 0x{top_mask:x}u;\n}}",
                    words - 1
                );
            }
            (Dir::Out, false) if p.signed && w < 64 => {
                let _ = writeln!(
                    s,
                    "static inline int64_t {module}_get_{n}(const {v}* t) {{\n    \
                     const uint64_t m = 1ULL << {};\n    \
                     return (int64_t)((((uint64_t)t->{n} & 0x{:x}ULL) ^ m) - m);\n}}",
                    w - 1,
                    (1u64 << w) - 1
                );
            }
            (Dir::Out, false) => {
                let ty = if p.signed { "int64_t" } else { "uint64_t" };
                let _ = writeln!(
                    s,
                    "static inline {ty} {module}_get_{n}(const {v}* t) {{ return ({ty})t->{n}; }}"
                );
            }
            (Dir::Out, true) => {
                let _ = writeln!(
                    s,
                    "static inline void {module}_get_{n}(const {v}* t, uint32_t* w) {{\n    \
                     for (int k = 0; k < {words}; k++) w[k] = t->{n}[k];\n}}"
                );
            }
        }
        if let Some(&(_, _, lw, signed)) = LANES.iter().find(|l| l.0 == module && l.1 == *n) {
            lane_accessors(&mut s, module, p, lw, signed).unwrap_or_else(|e| panic!("{e}"));
        }
    }
    s
}

/// Every generated header: (path, contents).
pub fn files() -> Vec<(&'static str, String)> {
    CORES
        .iter()
        .map(|&(m, src, path)| {
            let p = ports(src, m).unwrap_or_else(|e| panic!("{m}: {e}"));
            (path, header(m, &p))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_a_header_with_parameters_signed_ranges_and_comments() {
        let src =
            "`default_nettype none\n// module fake\nmodule m #(\n  parameter integer N = 2\n) (\n\
                   input wire clk_i, // clock\n  input  wire signed [17:0] a_i,\n\
                   /* x */ output reg [ 2:0] b_o,\n  output wire [111:0]c_o\n);\nendmodule\n";
        let p = ports(src, "m").unwrap();
        let got: Vec<_> = p
            .iter()
            .map(|p| (p.dir, p.signed, p.width, p.name.as_str()))
            .collect();
        assert_eq!(
            got,
            [
                (Dir::In, false, 1, "clk_i"),
                (Dir::In, true, 18, "a_i"),
                (Dir::Out, false, 3, "b_o"),
                (Dir::Out, false, 112, "c_o"),
            ]
        );
        let h = header("m", &p);
        assert!(h.contains("t->a_i = (uint64_t)x & 0x3ffffULL;"), "{h}");
        assert!(
            h.contains("static inline void m_get_c_o(const Vm* t, uint32_t* w)"),
            "{h}"
        );
    }

    /// Every lane entry names a port of its core whose width it divides;
    /// the generated accessors address lane k at bit `w k`.
    #[test]
    fn lanes_divide_their_ports() {
        for &(m, port, lw, _) in LANES {
            let (_, src, _) = CORES.iter().find(|c| c.0 == m).expect("core");
            let p = ports(src, m).unwrap();
            let p = p
                .iter()
                .find(|p| p.name == port)
                .unwrap_or_else(|| panic!("{m}.{port}"));
            assert_eq!(p.width % lw, 0, "{m}.{port}");
        }
        let p = RtlPort {
            dir: Dir::Out,
            signed: false,
            width: 200,
            name: "x_o".into(),
        };
        let mut s = String::new();
        lane_accessors(&mut s, "m", &p, 25, true).unwrap();
        assert!(s.contains("static const int m_x_o_LANES = 8;"), "{s}");
        assert!(
            s.contains("const int b = 25 * k + i;") && s.contains("1ULL << 24"),
            "{s}"
        );
        assert!(lane_accessors(&mut s, "m", &p, 24, true).is_err());
        let p = RtlPort {
            dir: Dir::In,
            signed: false,
            width: 9,
            name: "s_i".into(),
        };
        let mut s = String::new();
        lane_accessors(&mut s, "m", &p, 3, false).unwrap();
        assert!(s.contains("const uint64_t m = 0x7ULL << (3 * k);"), "{s}");
    }

    #[test]
    fn every_core_has_ports() {
        for &(m, src, _) in CORES {
            let p = ports(src, m).unwrap();
            assert!(
                p.iter().any(|p| p.name == "clk_i" && p.dir == Dir::In),
                "{m}"
            );
            assert!(p.iter().any(|p| p.dir == Dir::Out), "{m}");
        }
        // Widths read from the RTL, against the formats documented for them.
        let (_, src, _) = CORES[3];
        let p = ports(src, "mpdtc_core").unwrap();
        let i_d = p.iter().find(|p| p.name == "i_d_i").unwrap();
        assert_eq!((i_d.signed, i_d.width), (true, 25)); // sQ8.16
        let cos = p.iter().find(|p| p.name == "cos0_i").unwrap();
        assert_eq!((cos.signed, cos.width), (true, 18)); // sQ1.16
    }
}
