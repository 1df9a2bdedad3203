//! The typed register accessors of `regmap::regs`, generated from the table.
//!
//! Per block a module (`regs::pwm`), per register a zero-sized type named
//! after the register in camel case (`regs::pwm::DeadTime`) with its
//! absolute `ADDR`, its table entry `DEF` and the accesses its type allows
//! (RW: `read`, `write`, `modify`; RO: `read`; W1C: `read`, `write`), and a
//! value type (`DeadTimeValue`) with one getter and one `with_*` setter per
//! field (a register without fields has one field, `value`, over its
//! implemented bits). Every access goes through `regmap::bus::RegisterBus`.
use std::fmt::Write;

use regmap::{Access, Block, Invalid, Register};

/// Repository-relative path of the generated Rust module.
pub const RUST_PATH: &str = "firmware/regmap/src/regs.rs";

/// `DEAD_TIME` -> `DeadTime`.
pub fn camel(name: &str) -> String {
    name.split('_')
        .map(|w| {
            let mut c = w.chars();
            match c.next() {
                Some(f) => f.to_ascii_uppercase().to_string() + &c.as_str().to_ascii_lowercase(),
                None => String::new(),
            }
        })
        .collect()
}

fn rule(r: &Register) -> String {
    match (r.access, r.invalid) {
        (Access::Ro, _) => "read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`".into(),
        (Access::W1c, _) => {
            "write 1 to clear (a bit whose condition is still present stays set)".into()
        }
        (_, Invalid::AllValid) => "every value of the implemented bits is valid; \
                                  bits above the width are dropped"
            .into(),
        (_, Invalid::Clamp { min, max }) => format!(
            "the hardware clamps the written word to {min}..={max} \
             (so a value wider than the field is clamped, not wrapped)"
        ),
        (_, Invalid::Reject { max }) => format!(
            "the hardware rejects a word above {max}: the register keeps its value \
             and `ERR.BAD_VALUE` is set"
        ),
    }
}

fn access_name(a: Access) -> &'static str {
    match a {
        Access::Rw => "RW",
        Access::Ro => "RO",
        Access::W1c => "W1C",
    }
}

/// One line of doc text: the table's strings are single-line already.
fn doc_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

struct F {
    name: String,
    lsb: u8,
    width: u8,
    doc: String,
}

fn fields(r: &Register) -> Vec<F> {
    if r.fields.is_empty() {
        vec![F {
            name: "value".into(),
            lsb: 0,
            width: r.width,
            doc: format!("The whole register ({}).", doc_line(r.format)),
        }]
    } else {
        r.fields
            .iter()
            .map(|f| F {
                name: f.name.to_ascii_lowercase(),
                lsb: f.lsb,
                width: f.width,
                doc: doc_line(f.doc),
            })
            .collect()
    }
}

/// A register without fields whose format is two's complement (it starts
/// with "signed", says "two's complement" or names an `sQm.n` format) also
/// gets `value_i32`/`with_value_i32`.
fn signed(r: &Register) -> bool {
    r.fields.is_empty()
        && r.width < 32
        && (r.format.starts_with("signed")
            || r.format.contains("two's complement")
            || r.format.split_whitespace().any(|w| w.starts_with("sQ")))
}

fn mask(width: u8) -> u32 {
    if width >= 32 {
        u32::MAX
    } else {
        (1 << width) - 1
    }
}

fn register(s: &mut String, b: &Block, r: &Register) {
    let ty = camel(r.name);
    let val = format!("{ty}Value");
    let addr = b.addr(r);
    let _ = writeln!(
        s,
        "\n    /// `{}.{}` at `0x{addr:08X}` ({}, {} bits, reset `0x{:X}`): {}\n    ///\n    \
         /// Format: {}. Writes: {}.",
        b.name,
        r.name,
        access_name(r.access),
        r.width,
        r.reset,
        doc_line(r.doc),
        doc_line(r.format),
        rule(r)
    );
    let _ = writeln!(s, "    #[derive(Debug, Clone, Copy, PartialEq, Eq)]");
    let _ = writeln!(s, "    pub struct {ty};");
    let _ = writeln!(s, "\n    impl {ty} {{");
    let _ = writeln!(s, "        /// Absolute byte address.");
    let _ = writeln!(s, "        pub const ADDR: usize = 0x{addr:08X};");
    let _ = writeln!(s, "        /// The table entry.");
    let _ = writeln!(
        s,
        "        pub const DEF: &'static Register = &regmap::{};",
        r.name
    );
    let sig = format!(
        "        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<{val}, BusError> {{"
    );
    let sig = if sig.len() > 100 {
        format!(
            "        pub fn read<B: RegisterBus + ?Sized>(\n            bus: &mut B,\n        \
             ) -> Result<{val}, BusError> {{"
        )
    } else {
        sig
    };
    let _ = writeln!(
        s,
        "\n        /// Reads the register.\n{sig}\n            \
         bus.read(Self::ADDR).map({val})\n        }}"
    );
    if r.access != Access::Ro {
        let what = if r.access == Access::W1c {
            "Writes `value`: every 1 bit clears that flag"
        } else {
            "Writes `value` (one store)"
        };
        let _ = writeln!(
            s,
            "\n        /// {what}.\n        \
             pub fn write<B: RegisterBus + ?Sized>(\n            bus: &mut B,\n            value: {val},\n        ) -> Result<(), BusError> {{\n            \
             bus.write(Self::ADDR, value.0)\n        }}"
        );
    }
    if r.access == Access::Rw {
        let _ = writeln!(
            s,
            "\n        /// Reads, applies `f`, writes the result back (not atomic).\n        \
             pub fn modify<B: RegisterBus + ?Sized>(\n            bus: &mut B,\n            \
             f: impl FnOnce({val}) -> {val},\n        ) -> Result<(), BusError> {{\n            \
             let v = Self::read(bus)?;\n            Self::write(bus, f(v))\n        }}"
        );
    }
    let _ = writeln!(s, "    }}");

    let _ = writeln!(
        s,
        "\n    /// A value of [`{ty}`]; bits above bit {} are 0 when read.",
        r.width.saturating_sub(1)
    );
    let _ = writeln!(s, "    #[derive(Debug, Clone, Copy, PartialEq, Eq)]");
    let _ = writeln!(s, "    pub struct {val}(u32);");
    let _ = writeln!(s, "\n    impl {val} {{");
    let _ = writeln!(
        s,
        "        /// The value after reset.\n        pub const RESET: Self = Self(0x{:X});",
        r.reset
    );
    let _ = writeln!(
        s,
        "        /// All zeros.\n        pub const ZERO: Self = Self(0);\n\n        \
         /// From the raw 32-bit word.\n        \
         pub const fn from_bits(bits: u32) -> Self {{\n            Self(bits)\n        }}\n\n        \
         /// The raw 32-bit word.\n        \
         pub const fn bits(self) -> u32 {{\n            self.0\n        }}"
    );
    for f in fields(r) {
        let m = mask(f.width);
        let (bits, ty) = if f.width == 1 {
            (format!("bit {}", f.lsb), "bool")
        } else {
            (
                format!("bits {}:{}, {} bits", f.lsb + f.width - 1, f.lsb, f.width),
                "u32",
            )
        };
        let up = f.name.to_ascii_uppercase();
        let shr = if f.lsb == 0 {
            "self.0".to_string()
        } else {
            format!("(self.0 >> {})", f.lsb)
        };
        let (get, set) = if f.width == 1 {
            (
                format!("{shr} & 1 != 0"),
                if f.lsb == 0 {
                    "Self((self.0 & !1) | v as u32)".to_string()
                } else {
                    format!(
                        "Self((self.0 & !(1 << {l})) | ((v as u32) << {l}))",
                        l = f.lsb
                    )
                },
            )
        } else if f.width == 32 {
            ("self.0".to_string(), "Self(v)".to_string())
        } else if f.lsb == 0 {
            (
                format!("self.0 & 0x{m:X}"),
                format!("Self((self.0 & !0x{m:X}) | (v & 0x{m:X}))"),
            )
        } else {
            (
                format!("{shr} & 0x{m:X}"),
                format!(
                    "Self((self.0 & !(0x{m:X} << {l})) | ((v & 0x{m:X}) << {l}))",
                    l = f.lsb
                ),
            )
        };
        let dropped = if f.width == 1 || f.width == 32 {
            String::new()
        } else {
            format!(
                " to the low {} bits of `v` (higher bits are dropped)",
                f.width
            )
        };
        let _ = writeln!(
            s,
            "\n        /// `{up}` ({bits}): {doc}\n        \
             pub const fn {n}(self) -> {ty} {{\n            {get}\n        }}\n\n        \
             /// Sets `{up}` ({bits}){dropped}.\n        \
             pub const fn with_{n}(self, v: {ty}) -> Self {{\n            {set}\n        }}",
            doc = f.doc,
            n = f.name,
        );
    }
    if signed(r) {
        let m = mask(r.width);
        let sh = 32 - u32::from(r.width);
        let get = if sh == 0 {
            "self.0 as i32".to_string()
        } else {
            format!("((self.0 << {sh}) as i32) >> {sh}")
        };
        let _ = writeln!(
            s,
            "\n        /// `VALUE` as a two's-complement number: bit {top} sign-extended.\n        \
             pub const fn value_i32(self) -> i32 {{\n            {get}\n        }}\n\n        \
             /// Sets `VALUE` to `v` in two's complement, its low {w} bits (higher bits are dropped).\n        \
             pub const fn with_value_i32(self, v: i32) -> Self {{\n            \
             Self((self.0 & !0x{m:X}) | (v as u32 & 0x{m:X}))\n        }}",
            top = r.width - 1,
            w = r.width,
        );
    }
    let _ = writeln!(s, "    }}");
    let _ = writeln!(
        s,
        "\n    impl Default for {val} {{\n        fn default() -> Self {{\n            Self::RESET\n        }}\n    }}"
    );
}

/// The generated `regs.rs` for `blocks`.
pub fn rust(blocks: &[&Block]) -> String {
    let mut s = String::new();
    s.push_str(
        "// Generated from firmware/regmap/src/lib.rs by `cargo run -p regmap-gen`;\n\
         // do not edit (a test fails when this file is stale).\n\
         //! Typed access to the PL registers, one module per block.\n\
         //!\n\
         //! Per register a zero-sized type (`regs::pwm::DeadTime`, the table name in\n\
         //! camel case) with its absolute `ADDR`, its table entry `DEF`, and the\n\
         //! accesses its type allows: RW `read`/`write`/`modify`, RO `read`, W1C\n\
         //! `read`/`write` (no `modify`: writing back what was read would clear every\n\
         //! set flag). Its value type (`DeadTimeValue`) has a getter and a `with_*`\n\
         //! setter per field (`bool` for one bit, else `u32` masked to the field's\n\
         //! width); a register without fields has one field, `value`, and when its\n\
         //! format is two's complement also `value_i32`/`with_value_i32` (sign-\n\
         //! extended read, write masked to the register's width). What the\n\
         //! hardware does with an out-of-range word (mask, clamp, reject) is in each\n\
         //! register's doc. Every access is one whole-word `RegisterBus` access:\n\
         //!\n\
         //! ```\n\
         //! # use regmap::bus::{BusError, RegisterBus};\n\
         //! # struct Bus(u32);\n\
         //! # impl RegisterBus for Bus {\n\
         //! #     fn read(&mut self, _: usize) -> Result<u32, BusError> { Ok(self.0) }\n\
         //! #     fn write(&mut self, _: usize, v: u32) -> Result<(), BusError> { self.0 = v; Ok(()) }\n\
         //! # }\n\
         //! use regmap::regs::pwm::{DeadTime, DeadTimeValue, GateCtrl};\n\
         //! let mut bus = Bus(0);\n\
         //! DeadTime::write(&mut bus, DeadTimeValue::ZERO.with_value(100))?;\n\
         //! GateCtrl::modify(&mut bus, |v| v.with_gate_en(true))?;\n\
         //! assert!(GateCtrl::read(&mut bus)?.gate_en());\n\
         //! # Ok::<(), BusError>(())\n\
         //! ```\n\n\
         use crate as regmap;\n\
         use crate::bus::{BusError, RegisterBus};\n\
         use crate::Register;\n",
    );
    for b in blocks {
        let _ = writeln!(
            s,
            "\n/// Block {} `{}` at `0x{:08X}`: {}",
            b.index,
            b.name,
            b.base(),
            doc_line(b.doc)
        );
        let _ = writeln!(s, "pub mod {} {{", b.name.to_ascii_lowercase());
        if !b.registers.is_empty() {
            let _ = writeln!(s, "    use super::*;");
        }
        let _ = writeln!(
            s,
            "\n    /// Absolute address of the block.\n    pub const BASE: usize = 0x{:08X};",
            b.base()
        );
        for r in b.registers {
            register(&mut s, b, r);
        }
        let _ = writeln!(s, "}}");
    }
    s
}
