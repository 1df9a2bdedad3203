//! The PL register map: the one source of truth.
//!
//! AXI4-Lite on the PS's GP0 port, 32-bit registers, base [`BASE_ADDR`], one
//! 4 KiB page per block ([`BLOCK_SIZE`]) in the order of [`BLOCKS`]. This
//! table is `const` data so that the `no_std` firmware uses it directly; the
//! generator `regmap-gen` (`cargo run -p regmap-gen`) writes from it the
//! register file `pl-bitstream-src/rtl/pl_regs.v` (storage, decode, write
//! rules, read mux, one port per field as [`Hw`] says), the Verilog header
//! `pl-bitstream-src/rtl/regmap.vh`, the typed accessors [`crate::regs`] and
//! `docs/register-map.md`; a test fails when those are stale, and the
//! AXI-Lite tests in `rtl-sim` check the Verilated register file against
//! every entry (reset value, access type, implemented bits, clamping).
//! Adding a register is one entry here plus its `BLOCKS` slot (see
//! docs/register-map.md).
//!
//! Conventions: offsets are bytes within the block, word aligned; bits above
//! [`Register::width`] read 0. Byte strobes are honoured on RW registers; the
//! merged 32-bit word is then stored masked to the width ([`Invalid::AllValid`]),
//! clamped as a whole ([`Invalid::Clamp`]: 5000 written to a 10-bit register
//! with max 1023 stores 1023) or compared as a whole ([`Invalid::Reject`]). Accesses to an
//! unmapped offset, or a write to a read-only register, answer `SLVERR` and
//! set `ERR.BAD_ADDR`. A rejected value ([`Invalid::Reject`]) leaves the
//! register unchanged, answers `OKAY` and sets `ERR.BAD_VALUE`.
//!
//! PL clock: 100 MHz (FCLK0), so one cycle = 10 ns.

mod mpdcc_page;
pub use mpdcc_page::*;

/// Base of the PL register window on GP0.
pub const BASE_ADDR: usize = 0x43C0_0000;
/// Size of one block's page.
pub const BLOCK_SIZE: usize = 0x1000;
/// Address bits of the AXI-Lite slave: 8 pages of 4 KiB.
pub const AXI_ADDR_BITS: u32 = 15;
/// PL clock of the register file and every block, in Hz.
pub const PL_CLOCK_HZ: u32 = 100_000_000;

/// How software may access a register.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Access {
    /// Read-write.
    Rw,
    /// Read-only: writes answer `SLVERR`, set `ERR.BAD_ADDR` and change nothing.
    Ro,
    /// Read, write 1 to clear (a set condition that is still present wins).
    W1c,
}

/// What a write of an out-of-range value does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Invalid {
    /// Every value of the implemented bits is valid.
    AllValid,
    /// The (merged, masked) value is clamped to `min..=max`.
    Clamp {
        /// Smallest stored value.
        min: u32,
        /// Largest stored value.
        max: u32,
    },
    /// A value above `max` is rejected: the register keeps its value and
    /// `ERR.BAD_VALUE` is set.
    Reject {
        /// Largest accepted value.
        max: u32,
    },
}

/// How a register meets the hardware: the ports the generated register
/// file (`pl-bitstream-src/rtl/pl_regs.v`) gives it. Port names are the
/// register name in lower case, then `_<field>` for each field (a register
/// without fields is one port), then the suffix.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Hw {
    /// RW: stored in the register file, each field an output `_o` to its
    /// core. RO: each field an input `_i` from its core. W1C: the flags live
    /// in the core; each field is an input `_i` and a one-cycle output
    /// `_clr_o` (the written ones).
    Plain,
    /// RO: reads its reset value; no port.
    Const,
    /// RW: stored for read-back only; the core gets a one-cycle write strobe
    /// `_we_o` (every write, whatever the value).
    Strobe,
    /// RW as [`Hw::Plain`], and the input `_hw_clr_i` holds the register at
    /// 0 (it wins over a write in the same cycle).
    HwClear,
    /// W1C: the register file's own access-error flags, fields `BAD_VALUE`
    /// and `BAD_ADDR` (see the module doc); no port.
    Errors,
}

/// A bit field of a register.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Field {
    /// Name (upper case, used in Verilog as `RM_<REG>_<FIELD>_LSB/_W`).
    pub name: &'static str,
    /// Lowest bit.
    pub lsb: u8,
    /// Width in bits.
    pub width: u8,
    /// Meaning.
    pub doc: &'static str,
}

/// One 32-bit register.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Register {
    /// Name (upper case, unique over the whole map).
    pub name: &'static str,
    /// Byte offset within the block.
    pub offset: u16,
    /// Access type.
    pub access: Access,
    /// Implemented bits `[width-1:0]`; the others read 0.
    pub width: u8,
    /// Value after reset.
    pub reset: u32,
    /// Number format and unit (Q notation for fixed point).
    pub format: &'static str,
    /// What out-of-range writes do.
    pub invalid: Invalid,
    /// What the PL does with the register besides storing or reading it:
    /// which ports of the generated register file it has.
    pub hw: Hw,
    /// Bit fields (empty: the register is one number).
    pub fields: &'static [Field],
    /// Meaning.
    pub doc: &'static str,
}

impl Register {
    /// Mask of the implemented bits.
    pub const fn mask(&self) -> u32 {
        if self.width >= 32 {
            u32::MAX
        } else {
            (1u32 << self.width) - 1
        }
    }

    /// The value the register holds after software writes `value` (all byte
    /// strobes set) over `old`: `Err` for a rejected value (register keeps
    /// `old`). The RTL implements the same rule; the AXI tests check it.
    pub const fn apply_write(&self, old: u32, value: u32) -> Result<u32, RegError> {
        let v = value & self.mask();
        match self.access {
            Access::Ro => Err(RegError::ReadOnly),
            Access::W1c => Ok(old & !v),
            Access::Rw => match self.invalid {
                Invalid::AllValid => Ok(v),
                // The whole written word is compared, so 5000 clamps to
                // 1023 rather than wrapping to 5000 mod 1024.
                Invalid::Clamp { min, max } => Ok(if value < min {
                    min
                } else if value > max {
                    max
                } else {
                    value
                }),
                Invalid::Reject { max } => {
                    if value > max {
                        Err(RegError::Rejected)
                    } else {
                        Ok(v)
                    }
                }
            },
        }
    }
}

/// Why a register write did not store the written value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RegError {
    /// The register is read-only.
    ReadOnly,
    /// The value is out of range and was rejected.
    Rejected,
}

/// One 4 KiB block.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Block {
    /// Name (upper case).
    pub name: &'static str,
    /// Page index: the block's base is `BASE_ADDR + index * BLOCK_SIZE`.
    pub index: u8,
    /// Meaning.
    pub doc: &'static str,
    /// Registers, by increasing offset.
    pub registers: &'static [&'static Register],
}

impl Block {
    /// Absolute address of the block.
    pub const fn base(&self) -> usize {
        BASE_ADDR + self.index as usize * BLOCK_SIZE
    }
    /// Absolute address of `reg` in this block.
    pub const fn addr(&self, reg: &Register) -> usize {
        self.base() + reg.offset as usize
    }
}

const fn field(name: &'static str, lsb: u8, width: u8, doc: &'static str) -> Field {
    Field {
        name,
        lsb,
        width,
        doc,
    }
}

// ---------------------------------------------------------------- block 0
/// Magic number "PSDR" (predictive servo drive RTL).
pub const ID_VALUE: u32 = 0x5053_4452;
/// Top/ID: identification.
pub const ID: Register = Register {
    name: "ID",
    offset: 0x000,
    access: Access::Ro,
    width: 32,
    reset: ID_VALUE,
    format: "ASCII \"PSDR\"",
    invalid: Invalid::AllValid,
    hw: Hw::Const,
    fields: &[],
    doc: "Identifies the bitstream.",
};
/// Top/ID: register-map version.
pub const VERSION: Register = Register {
    name: "VERSION",
    offset: 0x004,
    access: Access::Ro,
    width: 32,
    reset: 0x0001_0003,
    format: "major.minor, 16 bits each",
    invalid: Invalid::AllValid,
    hw: Hw::Const,
    fields: &[
        field("MINOR", 0, 16, "minor version"),
        field("MAJOR", 16, 16, "major version"),
    ],
    doc: "Version of this register map (bumped when the table changes).",
};
/// Mode values of `CTRL.MODE`.
pub mod mode {
    /// All gates off.
    pub const OFF: u32 = 0;
    /// Gates follow the centre-aligned PWM comparators (PS-side FOC).
    pub const FOC_PWM: u32 = 1;
    /// Gates follow the predictive controller's switching state.
    pub const MPDTC: u32 = 2;
}
/// Top/ID: control.
pub const CTRL: Register = Register {
    name: "CTRL",
    offset: 0x008,
    access: Access::Rw,
    width: 2,
    reset: mode::OFF,
    format: "enum",
    invalid: Invalid::Reject { max: mode::MPDTC },
    hw: Hw::Plain,
    fields: &[field(
        "MODE",
        0,
        2,
        "0 off, 1 FOC-PWM (PWM comparators), 2 MPDTC (mpdtc_core's S[k+1], or \
         PWM.SW_STATE if MPDTC_CTRL.MANUAL); 3 is rejected",
    )],
    doc: "Selects the source of the switching state.",
};
/// Top/ID: status.
pub const STATUS: Register = Register {
    name: "STATUS",
    offset: 0x00C,
    access: Access::Ro,
    width: 4,
    reset: 0,
    format: "bits",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("MODE", 0, 2, "CTRL.MODE"),
        field(
            "GATES_ACTIVE",
            2,
            1,
            "the gate driver is enabled (GATE_EN, mode not off, no fault; in mode MPDTC \
             with MPDTC_CTRL.MANUAL = 0 also the control sequence out of IDLE)",
        ),
        field(
            "FAULT",
            3,
            1,
            "a fault is latched (FAULT.FAULT_STATUS != 0)",
        ),
    ],
    doc: "Summary of the drive state.",
};
/// Top/ID: access errors.
pub const ERR: Register = Register {
    name: "ERR",
    offset: 0x010,
    access: Access::W1c,
    width: 2,
    reset: 0,
    format: "bits, sticky",
    invalid: Invalid::AllValid,
    hw: Hw::Errors,
    fields: &[
        field("BAD_VALUE", 0, 1, "a write was rejected (out of range)"),
        field(
            "BAD_ADDR",
            1,
            1,
            "an access hit an unmapped offset or wrote a read-only register (SLVERR)",
        ),
    ],
    doc: "Sticky access-error flags.",
};
/// Top/ID: watchdog heartbeat.
pub const HEARTBEAT: Register = Register {
    name: "HEARTBEAT",
    offset: 0x014,
    access: Access::Rw,
    width: 32,
    reset: 0,
    format: "any value",
    invalid: Invalid::AllValid,
    hw: Hw::Strobe,
    fields: &[],
    doc: "Every write restarts the watchdog (FAULT.WDG_TIMEOUT); reads back the last value.",
};
/// Top/ID: scratch register (bus tests).
pub const SCRATCH: Register = Register {
    name: "SCRATCH",
    offset: 0x018,
    access: Access::Rw,
    width: 32,
    reset: 0,
    format: "any value",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "No effect; for bus tests.",
};

// ---------------------------------------------------------------- block 3
/// PWM/gates: gate enable. Fixed at offset 0, bit 0, reset 0: the panic
/// handler's one store relies on it.
pub const GATE_CTRL: Register = Register {
    name: "GATE_CTRL",
    offset: 0x000,
    access: Access::Rw,
    width: 1,
    reset: 0,
    format: "bit",
    invalid: Invalid::AllValid,
    hw: Hw::HwClear,
    fields: &[field(
        "GATE_EN",
        0,
        1,
        "1 = gates follow the selected controller, 0 = all gates off (safe \
         state); held at 0 by the hardware while a fault is latched",
    )],
    doc: "Gate enable.",
};
/// `GATE_CTRL.GATE_EN`.
pub const GATE_CTRL_GATE_EN: u32 = 1;
/// Largest dead time, in PL clock cycles (`gate_driver` `DT_W` = 10).
pub const DEAD_TIME_MAX: u32 = 1023;
/// PWM/gates: dead time.
pub const DEAD_TIME: Register = Register {
    name: "DEAD_TIME",
    offset: 0x004,
    access: Access::Rw,
    width: 10,
    reset: 50,
    format: "unsigned, PL clock cycles (10 ns); 0 acts as 1",
    invalid: Invalid::Clamp {
        min: 0,
        max: DEAD_TIME_MAX,
    },
    hw: Hw::Plain,
    fields: &[],
    doc: "Cycles with both gates of a leg off before either turns on (reset 500 ns).",
};
/// PWM/gates: PWM half period.
pub const PWM_PERIOD: Register = Register {
    name: "PWM_PERIOD",
    offset: 0x008,
    access: Access::Rw,
    width: 16,
    reset: 2500,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::Clamp { min: 2, max: 65535 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Up-down counter top: f_pwm = 100 MHz / (2 PWM_PERIOD) (reset 20 kHz). \
          Takes effect at the next counter bottom.",
};
const fn duty(name: &'static str, offset: u16) -> Register {
    Register {
        name,
        offset,
        access: Access::Rw,
        width: 16,
        reset: 1250,
        format: "unsigned, PL clock cycles (compare value)",
        invalid: Invalid::AllValid,
        hw: Hw::Plain,
        fields: &[],
        doc: "Upper switch on while the counter < DUTY (centre aligned): duty = \
              DUTY / PWM_PERIOD; >= PWM_PERIOD is 100 %. Loaded at the counter bottom.",
    }
}
/// PWM/gates: duty of leg a.
pub const DUTY_A: Register = duty("DUTY_A", 0x00C);
/// PWM/gates: duty of leg b.
pub const DUTY_B: Register = duty("DUTY_B", 0x010);
/// PWM/gates: duty of leg c.
pub const DUTY_C: Register = duty("DUTY_C", 0x014);
/// PWM/gates: switching state for the MPDTC mode.
pub const SW_STATE: Register = Register {
    name: "SW_STATE",
    offset: 0x018,
    access: Access::Rw,
    width: 3,
    reset: 0,
    format: "bits SaSbSc (index 4 Sa + 2 Sb + Sc)",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Switching state applied in mode MPDTC when MPDTC_CTRL.MANUAL = 1.",
};
/// PWM/gates: gate outputs.
pub const GATE_STATUS: Register = Register {
    name: "GATE_STATUS",
    offset: 0x01C,
    access: Access::Ro,
    width: 9,
    reset: 0,
    format: "bits, leg a = highest bit of each field",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("HI", 0, 3, "upper gates (a, b, c = bits 2, 1, 0)"),
        field("LO", 3, 3, "lower gates"),
        field(
            "STATE",
            6,
            3,
            "switching state requested by the selected source",
        ),
    ],
    doc: "Gate driver outputs as driven now.",
};
/// PWM/gates: PWM counter.
pub const PWM_COUNT: Register = Register {
    name: "PWM_COUNT",
    offset: 0x020,
    access: Access::Ro,
    width: 17,
    reset: 0,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("COUNT", 0, 16, "up-down counter"),
        field("DOWN", 16, 1, "1 while counting down"),
    ],
    doc: "Centre-aligned PWM counter.",
};

// ---------------------------------------------------------------- block 4
/// ADC: control.
pub const ADC_CTRL: Register = Register {
    name: "ADC_CTRL",
    offset: 0x000,
    access: Access::Rw,
    width: 1,
    reset: 1,
    format: "bit",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[field(
        "ENABLE",
        0,
        1,
        "1 = convert every ADC_PERIOD (on from reset, so the over-current trip works)",
    )],
    doc: "ADC front-end control.",
};
/// ADC: sample period.
pub const ADC_PERIOD: Register = Register {
    name: "ADC_PERIOD",
    offset: 0x004,
    access: Access::Rw,
    width: 16,
    reset: 391,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::Clamp {
        min: 16,
        max: 65535,
    },
    hw: Hw::Plain,
    fields: &[],
    doc: "Cycles between conversion starts: 391 = 255.75 kHz (nearest to the \
          paper's 256 kHz); 2^ADC_AVG_LOG2 samples are averaged (reset 4), so results come at \
          1/2^ADC_AVG_LOG2 of it.",
};
const fn adc_result(name: &'static str, offset: u16) -> Register {
    Register {
        name,
        offset,
        access: Access::Ro,
        width: 16,
        reset: 0,
        format: "signed 12-bit ADC counts sign-extended to 16 bits (Q11.0 of full scale); \
                 floor(sum / 2^ADC_AVG_LOG2)",
        invalid: Invalid::AllValid,
        hw: Hw::Plain,
        fields: &[],
        doc: "Latest average of 2^ADC_AVG_LOG2 samples of this phase current.",
    }
}
/// ADC: phase a current.
pub const ADC_IA: Register = adc_result("ADC_IA", 0x008);
/// ADC: phase b current.
pub const ADC_IB: Register = adc_result("ADC_IB", 0x00C);
/// ADC: phase c current.
pub const ADC_IC: Register = adc_result("ADC_IC", 0x010);
/// ADC: result counter.
pub const ADC_COUNT: Register = Register {
    name: "ADC_COUNT",
    offset: 0x014,
    access: Access::Ro,
    width: 32,
    reset: 0,
    format: "unsigned, wraps",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Averaged results produced since reset.",
};

/// ADC: averaging.
pub const ADC_AVG_LOG2: Register = Register {
    name: "ADC_AVG_LOG2",
    offset: 0x018,
    access: Access::Rw,
    width: 2,
    reset: 2,
    format: "unsigned, log2 of the samples averaged: 0 = 1, 1 = 2, 2 = 4 (3 is rejected)",
    invalid: Invalid::Reject { max: 2 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Samples per averaged result (ADC_IA..IC, ADC_COUNT, the averaged-sample strobe = \
          the MPDTC control-period boundary): control period = ADC_PERIOD x 2^ADC_AVG_LOG2 \
          cycles. Reset 2 (4 samples, 1564 cycles = 63.94 kHz with ADC_PERIOD 391); 1 us = \
          ADC_PERIOD 100 with 0, or 25 with 2.",
};

// ---------------------------------------------------------------- block 5
/// Encoder: counts per revolution.
pub const ENC_CPR: Register = Register {
    name: "ENC_CPR",
    offset: 0x000,
    access: Access::Rw,
    width: 16,
    reset: 4096,
    format: "unsigned, quadrature counts (4 per line) per mechanical revolution",
    invalid: Invalid::Clamp { min: 4, max: 65535 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Position wraps at ENC_CPR.",
};
/// Encoder: position.
pub const ENC_POS: Register = Register {
    name: "ENC_POS",
    offset: 0x004,
    access: Access::Ro,
    width: 16,
    reset: 0,
    format: "unsigned, counts in 0..ENC_CPR-1",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Mechanical position; the index pulse sets it to 0.",
};
/// Encoder: speed.
pub const ENC_SPEED: Register = Register {
    name: "ENC_SPEED",
    offset: 0x008,
    access: Access::Ro,
    width: 16,
    reset: 0,
    format: "signed 16-bit, counts per ENC_WINDOW (saturated)",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Counts moved during the last complete window (positive = A leads B).",
};
/// Encoder: speed window.
pub const ENC_WINDOW: Register = Register {
    name: "ENC_WINDOW",
    offset: 0x00C,
    access: Access::Rw,
    width: 24,
    reset: 100_000,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::Clamp {
        min: 100,
        max: 0x00FF_FFFF,
    },
    hw: Hw::Plain,
    fields: &[],
    doc: "Speed measurement window (reset 1 ms).",
};
/// Encoder: index pulses.
pub const ENC_INDEX: Register = Register {
    name: "ENC_INDEX",
    offset: 0x010,
    access: Access::Ro,
    width: 16,
    reset: 0,
    format: "unsigned, wraps",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Index pulses seen since reset.",
};

// ---------------------------------------------------------------- block 6
/// Fault: latched faults.
pub const FAULT_STATUS: Register = Register {
    name: "FAULT_STATUS",
    offset: 0x000,
    access: Access::W1c,
    width: 3,
    reset: 0,
    format: "bits, latched",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("OVERCURRENT", 0, 1, "|ADC sample| > OC_LIMIT on a phase"),
        field("EXTERNAL", 1, 1, "external fault input asserted"),
        field(
            "WATCHDOG",
            2,
            1,
            "no HEARTBEAT write for WDG_TIMEOUT cycles",
        ),
    ],
    doc: "Any set bit forces all gates off (at the clock edge after the condition) \
          and holds GATE_EN at 0; a bit clears on a written 1 unless its condition \
          is present in that cycle. Then GATE_EN must be written 1 again.",
};
/// Fault: live fault conditions.
pub const FAULT_RAW: Register = Register {
    name: "FAULT_RAW",
    offset: 0x004,
    access: Access::Ro,
    width: 3,
    reset: 0,
    format: "bits, as FAULT_STATUS",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "The fault conditions now, unlatched.",
};
/// Fault: over-current limit.
pub const OC_LIMIT: Register = Register {
    name: "OC_LIMIT",
    offset: 0x008,
    access: Access::Rw,
    width: 11,
    reset: 1800,
    format: "unsigned ADC counts (as ADC_IA)",
    invalid: Invalid::Clamp { min: 0, max: 2047 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Trip when a raw sample's magnitude exceeds it (-2048 always trips).",
};
/// Fault: watchdog timeout.
pub const WDG_TIMEOUT: Register = Register {
    name: "WDG_TIMEOUT",
    offset: 0x00C,
    access: Access::Rw,
    width: 32,
    reset: 10_000_000,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::Clamp {
        min: 1000,
        max: u32::MAX,
    },
    hw: Hw::Plain,
    fields: &[],
    doc: "Cycles without a HEARTBEAT write before the watchdog trips (reset 100 ms).",
};

// ---------------------------------------------------------------- block 1
/// MPDTC: control.
pub const MPDTC_CTRL: Register = Register {
    name: "MPDTC_CTRL",
    offset: 0x000,
    access: Access::Rw,
    width: 3,
    reset: 0b011,
    format: "bits",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field(
            "MANUAL",
            0,
            1,
            "1 = in mode MPDTC the gates follow PWM.SW_STATE, 0 = the control sequence \
             (MPDTC_SEQ_STATUS: alignment, then mpdtc_core's S[k+1] at each control-period \
             boundary) drives them",
        ),
        field(
            "STATE_CLR",
            1,
            1,
            "1 = hold the core's state (S[k], S[k-1], observer, integrator) at zero",
        ),
        field(
            "AUTO",
            2,
            1,
            "1 = autonomous loop: every averaged ADC sample starts the PL front end \
             (mpdtc_frontend: encoder angle, speed, sin/cos, ADC offset/gain, Clarke/Park \
             from the MPDTC_FE_* registers), whose result starts the core in SAMPLE; the PS \
             writes only MPDTC_IN_T_REF and MPDTC_START is ignored. 0 = the PS writes every \
             MPDTC_IN_* and MPDTC_START each period (debug path)",
        ),
    ],
    doc: "Source of the MPDTC switching state, state reset and core-input path (reset: \
          manual, cleared, PS-fed).",
};
/// MPDTC: start.
pub const MPDTC_START: Register = Register {
    name: "MPDTC_START",
    offset: 0x004,
    access: Access::Rw,
    width: 32,
    reset: 0,
    format: "any value",
    invalid: Invalid::AllValid,
    hw: Hw::Strobe,
    fields: &[],
    doc: "While the control sequence is IDLE, every write starts one decision on the \
          MPDTC_IN_* and MPDTC_P_* registers (ignored while the core is busy or STATE_CLR \
          is set). In SAMPLE a write is the PS's hand-shake \"inputs of this period \
          written\": the decision starts once the period's ADC sample is in; writes in \
          INITIAL, MPDTC and PWM are ignored. Reads back the last value.",
};
/// MPDTC: status.
pub const MPDTC_STATUS: Register = Register {
    name: "MPDTC_STATUS",
    offset: 0x008,
    access: Access::Ro,
    width: 32,
    reset: 0,
    format: "bits and a counter",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("BUSY", 0, 1, "a decision is in flight"),
        field("S_NEXT", 1, 3, "S[k+1] of the last decision (bits SaSbSc)"),
        field(
            "DONE_COUNT",
            16,
            16,
            "decisions completed since reset (wraps)",
        ),
    ],
    doc: "Core status; poll DONE_COUNT to see a decision complete.",
};
/// Fixed latency of `mpdtc_core`, clock cycles.
pub const MPDTC_LATENCY_CYCLES: u32 = 11;
/// MPDTC: latency.
pub const MPDTC_LATENCY: Register = Register {
    name: "MPDTC_LATENCY",
    offset: 0x00C,
    access: Access::Ro,
    width: 8,
    reset: MPDTC_LATENCY_CYCLES,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::AllValid,
    hw: Hw::Const,
    fields: &[],
    doc: "Input strobe to S[k+1], fixed; also the initiation interval.",
};
const CUR_FMT: &str = "CUR sQ8.16, two's complement in [24:0], A";
const COEF_FMT: &str = "COEF sQ1.16, two's complement in [17:0]";
const fn mp(
    name: &'static str,
    offset: u16,
    width: u8,
    format: &'static str,
    doc: &'static str,
) -> Register {
    Register {
        name,
        offset,
        access: Access::Rw,
        width,
        reset: 0,
        format,
        invalid: Invalid::AllValid,
        hw: Hw::Plain,
        fields: &[],
        doc,
    }
}
/// MPDTC input: measured i_d.
pub const MPDTC_IN_ID: Register = mp(
    "MPDTC_IN_ID",
    0x010,
    25,
    CUR_FMT,
    "Measured (averaged) i_d.",
);
/// MPDTC input: measured i_q.
pub const MPDTC_IN_IQ: Register = mp(
    "MPDTC_IN_IQ",
    0x014,
    25,
    CUR_FMT,
    "Measured (averaged) i_q.",
);
/// MPDTC input: cos of the angle at the middle of [k-1, k].
pub const MPDTC_IN_COS0: Register = mp(
    "MPDTC_IN_COS0",
    0x018,
    18,
    COEF_FMT,
    "cos, middle of [k-1, k].",
);
/// MPDTC input: sin of the angle at the middle of [k-1, k].
pub const MPDTC_IN_SIN0: Register = mp(
    "MPDTC_IN_SIN0",
    0x01C,
    18,
    COEF_FMT,
    "sin, middle of [k-1, k].",
);
/// MPDTC input: cos, middle of [k, k+1].
pub const MPDTC_IN_COS1: Register = mp(
    "MPDTC_IN_COS1",
    0x020,
    18,
    COEF_FMT,
    "cos, middle of [k, k+1].",
);
/// MPDTC input: sin, middle of [k, k+1].
pub const MPDTC_IN_SIN1: Register = mp(
    "MPDTC_IN_SIN1",
    0x024,
    18,
    COEF_FMT,
    "sin, middle of [k, k+1].",
);
/// MPDTC input: cos, middle of [k+1, k+2].
pub const MPDTC_IN_COS2: Register = mp(
    "MPDTC_IN_COS2",
    0x028,
    18,
    COEF_FMT,
    "cos, middle of [k+1, k+2].",
);
/// MPDTC input: sin, middle of [k+1, k+2].
pub const MPDTC_IN_SIN2: Register = mp(
    "MPDTC_IN_SIN2",
    0x02C,
    18,
    COEF_FMT,
    "sin, middle of [k+1, k+2].",
);
/// MPDTC input: electrical angle step per period.
pub const MPDTC_IN_W_TS: Register = mp(
    "MPDTC_IN_W_TS",
    0x030,
    18,
    "COEF sQ1.16, rad per period",
    "w_e Ts.",
);
/// MPDTC input: torque reference.
pub const MPDTC_IN_T_REF: Register = mp(
    "MPDTC_IN_T_REF",
    0x034,
    18,
    "TRQ sQ3.14, two's complement in [17:0], N m",
    "Torque reference T*.",
);
/// MPDTC parameter a.
pub const MPDTC_P_A: Register = mp("MPDTC_P_A", 0x040, 18, COEF_FMT, "a = 1 - R Ts / L.");
/// MPDTC parameter lambda.
pub const MPDTC_P_LAMBDA: Register = mp(
    "MPDTC_P_LAMBDA",
    0x044,
    18,
    COEF_FMT,
    "Measurement age, periods.",
);
/// MPDTC parameter U0.
pub const MPDTC_P_U0: Register = mp("MPDTC_P_U0", 0x048, 25, CUR_FMT, "U0 = (Ts / L) 2/3 U_dc.");
/// MPDTC parameter U0/2.
pub const MPDTC_P_U0_HALF: Register = mp("MPDTC_P_U0_HALF", 0x04C, 25, CUR_FMT, "U0 / 2.");
/// MPDTC parameter U0 sqrt(3)/2.
pub const MPDTC_P_U0_H: Register = mp("MPDTC_P_U0_H", 0x050, 25, CUR_FMT, "U0 sqrt(3) / 2.");
/// MPDTC parameter psi/L.
pub const MPDTC_P_PSI_L: Register = mp("MPDTC_P_PSI_L", 0x054, 25, CUR_FMT, "psi / L.");
/// MPDTC parameter 1/k_T.
pub const MPDTC_P_KINV_T: Register = mp(
    "MPDTC_P_KINV_T",
    0x058,
    25,
    "KINV sQ8.16, two's complement in [24:0], A/(N m)",
    "1 / k_T.",
);
/// MPDTC parameter band.
pub const MPDTC_P_TOL: Register = mp(
    "MPDTC_P_TOL",
    0x05C,
    24,
    "CUR, non-negative (24 bits: negative values cannot be written)",
    "Band T_tol / k_T.",
);
/// MPDTC parameter integrator gain.
pub const MPDTC_P_K_INT: Register = mp(
    "MPDTC_P_K_INT",
    0x060,
    18,
    COEF_FMT,
    "Integrator gain K Ts.",
);
/// MPDTC parameter integrator clamp.
pub const MPDTC_P_INT_LIM: Register = mp(
    "MPDTC_P_INT_LIM",
    0x064,
    24,
    "CUR, non-negative (24 bits)",
    "Integrator clamp.",
);
/// MPDTC parameter conditional integration.
pub const MPDTC_P_INT_COND: Register = mp(
    "MPDTC_P_INT_COND",
    0x068,
    1,
    "bit",
    "1 = integrate only after a decision with a candidate in the band.",
);
/// MPDTC parameter observer b Kp.
pub const MPDTC_P_KP_O: Register = mp("MPDTC_P_KP_O", 0x06C, 18, COEF_FMT, "Observer b Kp.");
/// MPDTC parameter observer b Kp Ki Ts.
pub const MPDTC_P_KI_O: Register = mp("MPDTC_P_KI_O", 0x070, 18, COEF_FMT, "Observer b Kp Ki Ts.");
/// MPDTC parameter observer clamp.
pub const MPDTC_P_ETA_LIM: Register = mp(
    "MPDTC_P_ETA_LIM",
    0x074,
    24,
    "CUR, non-negative (24 bits)",
    "Observer clamp b eps_max.",
);
const WGT_FMT: &str = "WGT sQ3.14, two's complement in [17:0]";
/// MPDTC weight, 0 transitions.
pub const MPDTC_P_W2_0: Register = mp(
    "MPDTC_P_W2_0",
    0x078,
    18,
    WGT_FMT,
    "Cost weight, 0 transitions.",
);
/// MPDTC weight, 1 transition.
pub const MPDTC_P_W2_1: Register = mp(
    "MPDTC_P_W2_1",
    0x07C,
    18,
    WGT_FMT,
    "Cost weight, 1 transition.",
);
/// MPDTC weight, 2 transitions.
pub const MPDTC_P_W2_2: Register = mp(
    "MPDTC_P_W2_2",
    0x080,
    18,
    WGT_FMT,
    "Cost weight, 2 transitions.",
);
/// MPDTC weight, 3 transitions.
pub const MPDTC_P_W2_3: Register = mp(
    "MPDTC_P_W2_3",
    0x084,
    18,
    WGT_FMT,
    "Cost weight, 3 transitions.",
);
/// MPDTC output: modified reference.
pub const MPDTC_IQ_REF: Register = Register {
    name: "MPDTC_IQ_REF",
    offset: 0x090,
    access: Access::Ro,
    width: 25,
    reset: 0,
    format: CUR_FMT,
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "i_q* of the last decision (telemetry).",
};

/// `MPDTC_SEQ_STATUS.STATE` values: the control sequence of paper 000
/// (section 3), `mpdtc_seq`.
pub mod seq_state {
    /// Gates off; waits for mode MPDTC, GATE_EN, MANUAL = 0, STATE_CLR = 0, no fault.
    pub const IDLE: u32 = 0;
    /// Rotor alignment (chopped alignment vector for MPDTC_ALIGN_TIME cycles).
    pub const INITIAL: u32 = 1;
    /// Waits for the period's averaged ADC sample and the PS's MPDTC_START.
    pub const SAMPLE: u32 = 2;
    /// The core decides (MPDTC_LATENCY_CYCLES = 11 cycles).
    pub const MPDTC: u32 = 3;
    /// S[k+1] waits for the next control-period boundary (ADC average strobe).
    pub const PWM: u32 = 4;
}
/// MPDTC: control-sequence status.
pub const MPDTC_SEQ_STATUS: Register = Register {
    name: "MPDTC_SEQ_STATUS",
    offset: 0x0A0,
    access: Access::Ro,
    width: 32,
    reset: 0,
    format: "enum, bits and counters",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field(
            "STATE",
            0,
            3,
            "0 IDLE, 1 INITIAL (alignment), 2 SAMPLE, 3 MPDTC, 4 PWM (regmap::seq_state)",
        ),
        field(
            "SAMPLED",
            3,
            1,
            "SAMPLE has this period's averaged ADC sample (waits for MPDTC_START)",
        ),
        field(
            "ALIGNED",
            4,
            1,
            "the alignment of the current run finished (MPDTC_ALIGN_POS valid); 0 from IDLE",
        ),
        field(
            "OVERRUNS",
            8,
            8,
            "control-period boundaries that found no S[k+1] ready (in SAMPLE with the \
             sample taken, or in MPDTC): S[k] held one more period (wraps)",
        ),
        field(
            "PERIODS",
            16,
            16,
            "control periods completed: S[k+1] applied at a boundary (wraps)",
        ),
    ],
    doc: "State of the control sequence (mpdtc_seq), active in mode MPDTC with \
          MPDTC_CTRL.MANUAL = 0 and STATE_CLR = 0. Counters keep their values through IDLE.",
};
/// MPDTC: alignment vector.
pub const MPDTC_ALIGN_VEC: Register = Register {
    name: "MPDTC_ALIGN_VEC",
    offset: 0x0A4,
    access: Access::Rw,
    width: 3,
    reset: 0b100,
    format: "bits SaSbSc (index 4 Sa + 2 Sb + Sc)",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Switching state of the rotor alignment (INITIAL): 100 = phase a upper, b and c \
          lower, the voltage vector on the a axis = d axis at angle 0. 000 and 111 are \
          zero vectors (no alignment current).",
};
/// MPDTC: alignment chopper period.
pub const MPDTC_ALIGN_PERIOD: Register = Register {
    name: "MPDTC_ALIGN_PERIOD",
    offset: 0x0A8,
    access: Access::Rw,
    width: 16,
    reset: 5000,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::Clamp { min: 2, max: 65535 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Period P of the alignment chopper (reset 50 us = 20 kHz). Read at every cycle.",
};
/// MPDTC: alignment on-time.
pub const MPDTC_ALIGN_ON: Register = Register {
    name: "MPDTC_ALIGN_ON",
    offset: 0x0AC,
    access: Access::Rw,
    width: 16,
    reset: 250,
    format: "unsigned, PL clock cycles per chopper period",
    invalid: Invalid::Clamp { min: 0, max: 32767 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Cycles with MPDTC_ALIGN_VEC at the start of each chopper period, the zero vector \
          000 for the rest; the hardware caps it at floor(P / 2) (duty <= 50 %, never \
          full time). Reset 250 / 5000 = 5 %: about 0.05 x (2/3 x 48 V) / 0.555 ohm = 2.9 A \
          in phase a for the paper's motor (less the dead time).",
};
/// MPDTC: alignment duration.
pub const MPDTC_ALIGN_TIME: Register = Register {
    name: "MPDTC_ALIGN_TIME",
    offset: 0x0B0,
    access: Access::Rw,
    width: 32,
    reset: 50_000_000,
    format: "unsigned, PL clock cycles",
    invalid: Invalid::Clamp {
        min: 1,
        max: u32::MAX,
    },
    hw: Hw::Plain,
    fields: &[],
    doc: "Duration of INITIAL (rotor alignment), reset 0.5 s.",
};
/// MPDTC: encoder position at the end of the alignment.
pub const MPDTC_ALIGN_POS: Register = Register {
    name: "MPDTC_ALIGN_POS",
    offset: 0x0B4,
    access: Access::Ro,
    width: 16,
    reset: 0,
    format: "unsigned, counts (as ENC_POS)",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "ENC_POS latched when INITIAL ends (rotor d axis on phase a): the angle \
          reference; the PS uses theta_e = (ENC_POS - ALIGN_POS) pp 2 pi / ENC_CPR. \
          The encoder counter itself is not changed.",
};

/// Front end (`mpdtc_frontend`) latency, PL clock cycles: the averaged
/// sample in, the core's inputs out.
pub const MPDTC_FE_LATENCY_CYCLES: u32 = 9;
const FE_OFF_FMT: &str = "signed 16-bit two's complement, ADC counts (range -32768..32767)";
const FE_GAIN_FMT: &str =
    "signed 18-bit two's complement in [17:0], 2^-20 A per ADC count (range +-0.125 A per count)";
const FE_AGE_FMT: &str = "COEF sQ1.16, two's complement in [17:0], control periods (range -2..2)";
const fn fe(
    name: &'static str,
    offset: u16,
    width: u8,
    reset: u32,
    format: &'static str,
    doc: &'static str,
) -> Register {
    Register {
        name,
        offset,
        access: Access::Rw,
        width,
        reset,
        format,
        invalid: Invalid::AllValid,
        hw: Hw::Plain,
        fields: &[],
        doc,
    }
}
/// MPDTC front end: encoder count to electrical angle.
pub const MPDTC_FE_ANG_SCALE: Register = fe(
    "MPDTC_FE_ANG_SCALE",
    0x0B8,
    32,
    7 << 20,
    "unsigned 32-bit, 2^-32 electrical turn per encoder count (range 0..2^32-1)",
    "round(pole_pairs 2^32 / ENC_CPR) mod 2^32: pole pairs and counts per revolution \
     for the autonomous loop (the PL has no divider); theta_e = (ENC_POS - \
     MPDTC_ALIGN_POS mod ENC_CPR) x this, mod one turn. Reset: 7 pole pairs, 4096 counts.",
);
/// MPDTC front end: speed to angle step.
pub const MPDTC_FE_SPD_SCALE: Register = fe(
    "MPDTC_FE_SPD_SCALE",
    0x0BC,
    32,
    29_388_314,
    "unsigned 32-bit, 2^-40 electrical turn per control period per (count per ENC_WINDOW) \
     (range 0..2^32-1)",
    "round(pole_pairs Ts 2^40 / (ENC_CPR T_window)): the angle step per control period \
     from ENC_SPEED (w_e Ts). Reset: 7 pole pairs, Ts = 1564 cycles, 4096 counts, \
     ENC_WINDOW 100,000 cycles.",
);
/// MPDTC front end: age of the first instant.
pub const MPDTC_FE_AGE0: Register = fe(
    "MPDTC_FE_AGE0",
    0x0C0,
    18,
    0x3_E000,
    FE_AGE_FMT,
    "Instant of cos0/sin0 relative to the sample, periods: lambda - 1/2 (lambda = age of \
     the averaged measurement). Reset -0.125.",
);
/// MPDTC front end: age of the second instant.
pub const MPDTC_FE_AGE1: Register = fe(
    "MPDTC_FE_AGE1",
    0x0C4,
    18,
    57_344,
    FE_AGE_FMT,
    "Instant of cos1/sin1: lambda + 1/2 periods. Reset 0.875.",
);
/// MPDTC front end: age of the third instant.
pub const MPDTC_FE_AGE2: Register = fe(
    "MPDTC_FE_AGE2",
    0x0C8,
    18,
    122_880,
    FE_AGE_FMT,
    "Instant of cos2/sin2: lambda + 3/2 periods. Reset 1.875.",
);
/// MPDTC front end: ADC offset, phase a.
pub const MPDTC_FE_OFF_A: Register = fe(
    "MPDTC_FE_OFF_A",
    0x0CC,
    16,
    0,
    FE_OFF_FMT,
    "Subtracted from ADC_IA before the gain.",
);
/// MPDTC front end: ADC offset, phase b.
pub const MPDTC_FE_OFF_B: Register = fe(
    "MPDTC_FE_OFF_B",
    0x0D0,
    16,
    0,
    FE_OFF_FMT,
    "Subtracted from ADC_IB before the gain.",
);
/// MPDTC front end: ADC offset, phase c.
pub const MPDTC_FE_OFF_C: Register = fe(
    "MPDTC_FE_OFF_C",
    0x0D4,
    16,
    0,
    FE_OFF_FMT,
    "Subtracted from ADC_IC before the gain.",
);
/// MPDTC front end: ADC gain, phase a.
pub const MPDTC_FE_GAIN_A: Register = fe(
    "MPDTC_FE_GAIN_A",
    0x0D8,
    18,
    0,
    FE_GAIN_FMT,
    "i_a = sat25(round((ADC_IA - OFF_A) GAIN_A / 2^4)), CUR. Reset 0 (no current until the \
     PS sets the board's gain).",
);
/// MPDTC front end: ADC gain, phase b.
pub const MPDTC_FE_GAIN_B: Register = fe(
    "MPDTC_FE_GAIN_B",
    0x0DC,
    18,
    0,
    FE_GAIN_FMT,
    "As MPDTC_FE_GAIN_A, phase b.",
);
/// MPDTC front end: ADC gain, phase c.
pub const MPDTC_FE_GAIN_C: Register = fe(
    "MPDTC_FE_GAIN_C",
    0x0E0,
    18,
    0,
    FE_GAIN_FMT,
    "As MPDTC_FE_GAIN_A, phase c.",
);
/// MPDTC front end: measured i_d.
pub const MPDTC_FE_ID: Register = Register {
    name: "MPDTC_FE_ID",
    offset: 0x0E4,
    access: Access::Ro,
    width: 25,
    reset: 0,
    format: CUR_FMT,
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "i_d of the front end's last result (MPDTC_CTRL.AUTO = 1; Park at the sample's \
          angle), MPDTC_FE_LATENCY_CYCLES = 9 cycles after the averaged sample.",
};
/// MPDTC front end: measured i_q.
pub const MPDTC_FE_IQ: Register = Register {
    name: "MPDTC_FE_IQ",
    offset: 0x0E8,
    access: Access::Ro,
    width: 25,
    reset: 0,
    format: CUR_FMT,
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "i_q of the front end's last result (as MPDTC_FE_ID).",
};

/// Block 0.
pub const TOP: Block = Block {
    name: "TOP",
    index: 0,
    doc: "Identification, mode, status, heartbeat.",
    registers: &[&ID, &VERSION, &CTRL, &STATUS, &ERR, &HEARTBEAT, &SCRATCH],
};
/// Block 1 (registers defined with `mpdtc_core`).
pub const MPDTC: Block = Block {
    name: "MPDTC",
    index: 1,
    doc: "mpdtc_core: inputs and parameter registers (formats: docs/mpdtc-fixed.md), \
          start, status, telemetry.",
    registers: &[
        &MPDTC_CTRL,
        &MPDTC_START,
        &MPDTC_STATUS,
        &MPDTC_LATENCY,
        &MPDTC_IN_ID,
        &MPDTC_IN_IQ,
        &MPDTC_IN_COS0,
        &MPDTC_IN_SIN0,
        &MPDTC_IN_COS1,
        &MPDTC_IN_SIN1,
        &MPDTC_IN_COS2,
        &MPDTC_IN_SIN2,
        &MPDTC_IN_W_TS,
        &MPDTC_IN_T_REF,
        &MPDTC_P_A,
        &MPDTC_P_LAMBDA,
        &MPDTC_P_U0,
        &MPDTC_P_U0_HALF,
        &MPDTC_P_U0_H,
        &MPDTC_P_PSI_L,
        &MPDTC_P_KINV_T,
        &MPDTC_P_TOL,
        &MPDTC_P_K_INT,
        &MPDTC_P_INT_LIM,
        &MPDTC_P_INT_COND,
        &MPDTC_P_KP_O,
        &MPDTC_P_KI_O,
        &MPDTC_P_ETA_LIM,
        &MPDTC_P_W2_0,
        &MPDTC_P_W2_1,
        &MPDTC_P_W2_2,
        &MPDTC_P_W2_3,
        &MPDTC_IQ_REF,
        &MPDTC_SEQ_STATUS,
        &MPDTC_ALIGN_VEC,
        &MPDTC_ALIGN_PERIOD,
        &MPDTC_ALIGN_ON,
        &MPDTC_ALIGN_TIME,
        &MPDTC_ALIGN_POS,
        &MPDTC_FE_ANG_SCALE,
        &MPDTC_FE_SPD_SCALE,
        &MPDTC_FE_AGE0,
        &MPDTC_FE_AGE1,
        &MPDTC_FE_AGE2,
        &MPDTC_FE_OFF_A,
        &MPDTC_FE_OFF_B,
        &MPDTC_FE_OFF_C,
        &MPDTC_FE_GAIN_A,
        &MPDTC_FE_GAIN_B,
        &MPDTC_FE_GAIN_C,
        &MPDTC_FE_ID,
        &MPDTC_FE_IQ,
    ],
};
/// Block 2 (registers defined in [`mpdcc_page`]).
pub const MPDCC: Block = Block {
    name: "MPDCC",
    index: 2,
    doc: "mpdcc_core (paper 001): s(k-1), state, constants and bounds (formats: \
          docs/mpdcc-fpga.md), start, status, the decision and its cost in cycles.",
    registers: &[
        &MPDCC_START,
        &MPDCC_STATUS,
        &MPDCC_N_USE,
        &MPDCC_CONFIG,
        &MPDCC_S_PREV,
        &MPDCC_I_A,
        &MPDCC_I_B,
        &MPDCC_PSI_A,
        &MPDCC_PSI_B,
        &MPDCC_V_N,
        &MPDCC_V_PH_A,
        &MPDCC_V_PH_B,
        &MPDCC_V_PH_C,
        &MPDCC_IREF_A,
        &MPDCC_IREF_B,
        &MPDCC_OMEGA_R,
        &MPDCC_OMEGA_S,
        &MPDCC_C_TAU,
        &MPDCC_C_R,
        &MPDCC_C_W,
        &MPDCC_C_P,
        &MPDCC_C_S,
        &MPDCC_C_3,
        &MPDCC_C_D,
        &MPDCC_C_N,
        &MPDCC_C_PH,
        &MPDCC_S3H,
        &MPDCC_V_PH_REF,
        &MPDCC_C_TAU1,
        &MPDCC_C_R1,
        &MPDCC_C_W1,
        &MPDCC_C_S1,
        &MPDCC_VDC_HALF,
        &MPDCC_G3,
        &MPDCC_GD,
        &MPDCC_G3_1,
        &MPDCC_BND_IA,
        &MPDCC_BND_IB,
        &MPDCC_BND_IC,
        &MPDCC_BND_VN,
        &MPDCC_BND_VPA,
        &MPDCC_BND_VPB,
        &MPDCC_BND_VPC,
        &MPDCC_LAMBDA_N,
        &MPDCC_DECISION,
        &MPDCC_COST,
        &MPDCC_J_DL,
        &MPDCC_CYCLES,
        &MPDCC_DEADLOCKS,
    ],
};
/// Block 3.
pub const PWM: Block = Block {
    name: "PWM",
    index: 3,
    doc: "Gate enable, dead time, centre-aligned PWM, switching state.",
    registers: &[
        &GATE_CTRL,
        &DEAD_TIME,
        &PWM_PERIOD,
        &DUTY_A,
        &DUTY_B,
        &DUTY_C,
        &SW_STATE,
        &GATE_STATUS,
        &PWM_COUNT,
    ],
};
/// Block 4.
pub const ADC: Block = Block {
    name: "ADC",
    index: 4,
    doc: "ADC front end: 3 phase currents, sampled every ADC_PERIOD, averaged by 2^ADC_AVG_LOG2.",
    registers: &[
        &ADC_CTRL,
        &ADC_PERIOD,
        &ADC_IA,
        &ADC_IB,
        &ADC_IC,
        &ADC_COUNT,
        &ADC_AVG_LOG2,
    ],
};
/// Block 5.
pub const ENC: Block = Block {
    name: "ENC",
    index: 5,
    doc: "Incremental encoder (A/B quadrature + index).",
    registers: &[&ENC_CPR, &ENC_POS, &ENC_SPEED, &ENC_WINDOW, &ENC_INDEX],
};
/// Block 6.
pub const FAULT: Block = Block {
    name: "FAULT",
    index: 6,
    doc: "Over-current, external and watchdog faults, latched.",
    registers: &[&FAULT_STATUS, &FAULT_RAW, &OC_LIMIT, &WDG_TIMEOUT],
};
// ---------------------------------------------------------------- block 7
/// Samples the capture buffer holds (`capture_buf`'s ring; a power of two).
pub const CAPTURE_DEPTH: u32 = 1024;
/// Capture trigger sources (`CAP_SOURCE`).
pub mod cap_source {
    /// Only a `CAP_TRIG` write.
    pub const MANUAL: u32 = 0;
    /// A torque-reference step: |CAP_IN_TREF - its previous sample| >= CAP_STEP.
    pub const REF_STEP: u32 = 1;
    /// The channel CAP_THR_CH crosses CAP_THR_LEVEL (edge CAP_THR_EDGE).
    pub const THRESHOLD: u32 = 2;
    /// Any latched fault (FAULT_STATUS != 0) at a sample.
    pub const FAULT: u32 = 3;
}
/// Capture states (`CAP_STATUS.STATE`).
pub mod cap_state {
    /// Not armed: the ring keeps its last record.
    pub const IDLE: u32 = 0;
    /// Armed: samples go into the ring, waiting for the trigger.
    pub const ARMED: u32 = 1;
    /// Triggered: taking the samples after the trigger.
    pub const TRIGGERED: u32 = 2;
    /// The record is complete.
    pub const DONE: u32 = 3;
}
const CAP_I_FMT: &str = "signed 16-bit two's complement, mA (range +-32.767 A)";
const CAP_T_FMT: &str = "signed 16-bit two's complement, 0.1 mN m (range +-3.2767 N m)";
/// CAPTURE: trigger source.
pub const CAP_SOURCE: Register = Register {
    name: "CAP_SOURCE",
    offset: 0x000,
    access: Access::Rw,
    width: 2,
    reset: 0,
    format: "enum: 0 manual, 1 reference step, 2 threshold, 3 fault",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Trigger of the armed capture, tested at each sample; a CAP_TRIG write \
          triggers whatever the source.",
};
/// CAPTURE: pre-trigger length.
pub const CAP_PRE: Register = Register {
    name: "CAP_PRE",
    offset: 0x004,
    access: Access::Rw,
    width: 10,
    reset: 128,
    format: "unsigned, samples",
    invalid: Invalid::Clamp {
        min: 0,
        max: CAPTURE_DEPTH - 1,
    },
    hw: Hw::Plain,
    fields: &[],
    doc: "Samples kept before the trigger sample (latched by CAP_ARM); the record \
          holds CAPTURE_DEPTH - CAP_PRE samples from the trigger on. A trigger before \
          CAP_PRE samples were taken keeps fewer (CAP_STATUS.TRIG_INDEX).",
};
/// CAPTURE: decimation.
pub const CAP_DECIM: Register = Register {
    name: "CAP_DECIM",
    offset: 0x008,
    access: Access::Rw,
    width: 8,
    reset: 0,
    format: "unsigned, averaged ADC results per sample - 1",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "A sample every CAP_DECIM + 1 averaged ADC results (adc_avg_valid): 0 = the \
          MPDTC control rate, 3 = the FOC control rate (one PWM period).",
};
/// CAPTURE: reference-step trigger size.
pub const CAP_STEP: Register = Register {
    name: "CAP_STEP",
    offset: 0x00C,
    access: Access::Rw,
    width: 16,
    reset: 500,
    format: "unsigned, 0.1 mN m",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Source 1 triggers on a sample whose CAP_IN_TREF differs from the previous \
          sample's by at least this much (reset 0.05 N m).",
};
/// CAPTURE: threshold channel.
pub const CAP_THR_CH: Register = Register {
    name: "CAP_THR_CH",
    offset: 0x010,
    access: Access::Rw,
    width: 3,
    reset: 2,
    format: "enum: 0 i_d, 1 i_q, 2 torque, 3 torque reference, 4 selectable",
    invalid: Invalid::Reject { max: 4 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Channel source 2 compares with CAP_THR_LEVEL.",
};
/// CAPTURE: threshold level.
pub const CAP_THR_LEVEL: Register = Register {
    name: "CAP_THR_LEVEL",
    offset: 0x014,
    access: Access::Rw,
    width: 16,
    reset: 0,
    format: "signed 16-bit two's complement, the channel's unit",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Source 2 triggers when the channel crosses this level between two samples \
          (rising: previous < level <= present; falling: previous > level >= present).",
};
/// CAPTURE: threshold edge.
pub const CAP_THR_EDGE: Register = Register {
    name: "CAP_THR_EDGE",
    offset: 0x018,
    access: Access::Rw,
    width: 1,
    reset: 0,
    format: "0 rising, 1 falling",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Direction of the threshold crossing.",
};
/// CAPTURE: selectable channel.
pub const CAP_SEL: Register = Register {
    name: "CAP_SEL",
    offset: 0x01C,
    access: Access::Rw,
    width: 3,
    reset: 0,
    format: "enum: 0 ADC_IA, 1 ADC_IB, 2 ADC_IC, 3 ENC_POS, 4 ENC_SPEED",
    invalid: Invalid::Reject { max: 4 },
    hw: Hw::Plain,
    fields: &[],
    doc: "What the selectable channel records: the low 16 bits of that register.",
};
/// CAPTURE: arm.
pub const CAP_ARM: Register = Register {
    name: "CAP_ARM",
    offset: 0x020,
    access: Access::Rw,
    width: 1,
    reset: 0,
    format: "any value",
    invalid: Invalid::AllValid,
    hw: Hw::Strobe,
    fields: &[],
    doc: "Every write starts a new record: the ring empties, CAP_PRE is latched, \
          state ARMED.",
};
/// CAPTURE: manual trigger.
pub const CAP_TRIG: Register = Register {
    name: "CAP_TRIG",
    offset: 0x024,
    access: Access::Rw,
    width: 1,
    reset: 0,
    format: "any value",
    invalid: Invalid::AllValid,
    hw: Hw::Strobe,
    fields: &[],
    doc: "A write while ARMED triggers at the next sample (any source); ignored \
          otherwise.",
};
/// CAPTURE: status.
pub const CAP_STATUS: Register = Register {
    name: "CAP_STATUS",
    offset: 0x028,
    access: Access::Ro,
    width: 32,
    reset: 0,
    format: "state and counters",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field(
            "STATE",
            0,
            2,
            "0 idle, 1 armed, 2 triggered, 3 done (drive::regmap::cap_state)",
        ),
        field(
            "TRIG_INDEX",
            4,
            11,
            "record index of the trigger sample (valid in DONE)",
        ),
        field(
            "COUNT",
            16,
            11,
            "samples in the record (at most CAPTURE_DEPTH)",
        ),
    ],
    doc: "Capture progress; the record is index 0 (oldest) to COUNT - 1.",
};
/// CAPTURE: PS-written i_d.
pub const CAP_IN_ID: Register = Register {
    name: "CAP_IN_ID",
    offset: 0x030,
    access: Access::Rw,
    width: 16,
    reset: 0,
    format: CAP_I_FMT,
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Channel 0, measured d current, written by the PS every control period.",
};
/// CAPTURE: PS-written i_q.
pub const CAP_IN_IQ: Register = Register {
    name: "CAP_IN_IQ",
    offset: 0x034,
    access: Access::Rw,
    width: 16,
    reset: 0,
    format: CAP_I_FMT,
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Channel 1, measured q current, written by the PS every control period.",
};
/// CAPTURE: PS-written torque.
pub const CAP_IN_TORQUE: Register = Register {
    name: "CAP_IN_TORQUE",
    offset: 0x038,
    access: Access::Rw,
    width: 16,
    reset: 0,
    format: CAP_T_FMT,
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Channel 2, torque from the measured currents, written by the PS every \
          control period.",
};
/// CAPTURE: PS-written torque reference.
pub const CAP_IN_TREF: Register = Register {
    name: "CAP_IN_TREF",
    offset: 0x03C,
    access: Access::Rw,
    width: 16,
    reset: 0,
    format: CAP_T_FMT,
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[],
    doc: "Channel 3, torque reference, written by the PS every control period.",
};
/// CAPTURE: read index.
pub const CAP_RD_INDEX: Register = Register {
    name: "CAP_RD_INDEX",
    offset: 0x040,
    access: Access::Rw,
    width: 10,
    reset: 0,
    format: "unsigned, record index (0 = oldest)",
    invalid: Invalid::Clamp {
        min: 0,
        max: CAPTURE_DEPTH - 1,
    },
    hw: Hw::Plain,
    fields: &[],
    doc: "Sample CAP_DATA0..2 show, one cycle after the write.",
};
/// CAPTURE: read data, currents.
pub const CAP_DATA0: Register = Register {
    name: "CAP_DATA0",
    offset: 0x044,
    access: Access::Ro,
    width: 32,
    reset: 0,
    format: "two 16-bit fields, formats of CAP_IN_ID/IQ",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("I_D", 0, 16, "i_d, mA, two's complement"),
        field("I_Q", 16, 16, "i_q, mA, two's complement"),
    ],
    doc: "Channels 0 and 1 of sample CAP_RD_INDEX.",
};
/// CAPTURE: read data, torques.
pub const CAP_DATA1: Register = Register {
    name: "CAP_DATA1",
    offset: 0x048,
    access: Access::Ro,
    width: 32,
    reset: 0,
    format: "two 16-bit fields, formats of CAP_IN_TORQUE/TREF",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("TORQUE", 0, 16, "torque, 0.1 mN m, two's complement"),
        field(
            "TREF",
            16,
            16,
            "torque reference, 0.1 mN m, two's complement",
        ),
    ],
    doc: "Channels 2 and 3 of sample CAP_RD_INDEX.",
};
/// CAPTURE: read data, switching state and selectable channel.
pub const CAP_DATA2: Register = Register {
    name: "CAP_DATA2",
    offset: 0x04C,
    access: Access::Ro,
    width: 32,
    reset: 0,
    format: "bits and a 16-bit field",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field(
            "SW",
            0,
            3,
            "switching state applied to the gate driver (GATE_STATUS.STATE)",
        ),
        field("SEL", 16, 16, "the selectable channel (CAP_SEL)"),
    ],
    doc: "Channels 5 (switching state) and 4 (selectable) of sample CAP_RD_INDEX.",
};
/// CAPTURE: depth.
pub const CAP_DEPTH: Register = Register {
    name: "CAP_DEPTH",
    offset: 0x050,
    access: Access::Ro,
    width: 16,
    reset: CAPTURE_DEPTH,
    format: "unsigned, samples",
    invalid: Invalid::AllValid,
    hw: Hw::Const,
    fields: &[],
    doc: "Size of the ring.",
};

/// Block 7.
pub const CAPTURE: Block = Block {
    name: "CAPTURE",
    index: 7,
    doc: "Triggered capture buffer (capture_buf): a ring of CAPTURE_DEPTH samples of six \
          channels at the control rate, with pre-trigger.",
    registers: &[
        &CAP_SOURCE,
        &CAP_PRE,
        &CAP_DECIM,
        &CAP_STEP,
        &CAP_THR_CH,
        &CAP_THR_LEVEL,
        &CAP_THR_EDGE,
        &CAP_SEL,
        &CAP_ARM,
        &CAP_TRIG,
        &CAP_STATUS,
        &CAP_IN_ID,
        &CAP_IN_IQ,
        &CAP_IN_TORQUE,
        &CAP_IN_TREF,
        &CAP_RD_INDEX,
        &CAP_DATA0,
        &CAP_DATA1,
        &CAP_DATA2,
        &CAP_DEPTH,
    ],
};

/// Every block, in page order.
pub const BLOCKS: [&Block; 8] = [&TOP, &MPDTC, &MPDCC, &PWM, &ADC, &ENC, &FAULT, &CAPTURE];

/// Direction of a `pl_top` port.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PortDir {
    /// Into the PL.
    In,
    /// Out of the PL.
    Out,
}

/// One external port of `pl_top` besides the clock: the AXI4-Lite slave on
/// GP0 and the pins. The Verilator harness (`csrc/pl_top_shim.cpp` and the
/// `PtIn`/`PtOut` structs of `rtl_sim::pl_top`) is generated from
/// [`PL_TOP_PORTS`], and a test checks `pl_top.v`'s port list against it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Port {
    /// Verilog port name (`_i`/`_o`/`_ni` suffix).
    pub verilog: &'static str,
    /// Field of the harness struct (`PtIn` for inputs, `PtOut` for outputs).
    pub field: &'static str,
    /// Direction.
    pub dir: PortDir,
    /// Width in bits (at most 64).
    pub width: u8,
    /// Inputs: the level the harness drives while it holds the design in
    /// reset (the pin's inactive level).
    pub idle: u64,
    /// Meaning.
    pub doc: &'static str,
}

const fn port_in(verilog: &'static str, field: &'static str, width: u8, doc: &'static str) -> Port {
    Port {
        verilog,
        field,
        dir: PortDir::In,
        width,
        idle: 0,
        doc,
    }
}

const fn port_out(
    verilog: &'static str,
    field: &'static str,
    width: u8,
    doc: &'static str,
) -> Port {
    Port {
        verilog,
        field,
        dir: PortDir::Out,
        width,
        idle: 0,
        doc,
    }
}

/// The external ports of `pl_top` (the clock `clk_i` is the harness's own).
pub const PL_TOP_PORTS: &[Port] = &[
    port_in("s_axi_aresetn_i", "aresetn", 1, "AXI reset, active low."),
    port_in(
        "s_axi_awaddr_i",
        "awaddr",
        AXI_ADDR_BITS as u8,
        "AW channel.",
    ),
    port_in("s_axi_awvalid_i", "awvalid", 1, "AW valid."),
    port_in("s_axi_wdata_i", "wdata", 32, "W data."),
    port_in("s_axi_wstrb_i", "wstrb", 4, "W byte strobes."),
    port_in("s_axi_wvalid_i", "wvalid", 1, "W valid."),
    port_in("s_axi_bready_i", "bready", 1, "B ready."),
    port_in(
        "s_axi_araddr_i",
        "araddr",
        AXI_ADDR_BITS as u8,
        "AR address.",
    ),
    port_in("s_axi_arvalid_i", "arvalid", 1, "AR valid."),
    port_in("s_axi_rready_i", "rready", 1, "R ready."),
    port_in("adc_drdy_i", "adc_drdy", 1, "ADC data-ready strobe."),
    port_in(
        "adc_data_i",
        "adc_data",
        36,
        "ADC data `{ia, ib, ic}`, 12 bits each, ia in bits 35..24.",
    ),
    port_in("enc_a_i", "enc_a", 1, "Encoder A."),
    port_in("enc_b_i", "enc_b", 1, "Encoder B."),
    port_in("enc_z_i", "enc_z", 1, "Encoder index."),
    Port {
        idle: 1,
        ..port_in(
            "fault_ext_ni",
            "fault_ext_n",
            1,
            "External fault pin, active low.",
        )
    },
    port_out("s_axi_awready_o", "awready", 1, "AW ready."),
    port_out("s_axi_wready_o", "wready", 1, "W ready."),
    port_out("s_axi_bresp_o", "bresp", 2, "B response."),
    port_out("s_axi_bvalid_o", "bvalid", 1, "B valid."),
    port_out("s_axi_arready_o", "arready", 1, "AR ready."),
    port_out("s_axi_rdata_o", "rdata", 32, "R data."),
    port_out("s_axi_rresp_o", "rresp", 2, "R response."),
    port_out("s_axi_rvalid_o", "rvalid", 1, "R valid."),
    port_out("gate_hi_o", "gate_hi", 3, "Upper gates (bit 2 = leg a)."),
    port_out("gate_lo_o", "gate_lo", 3, "Lower gates."),
    port_out("adc_cnv_o", "adc_cnv", 1, "ADC convert-start pulse."),
    port_out(
        "adc_avg_valid_o",
        "adc_avg_valid",
        1,
        "Averaged-sample strobe.",
    ),
];

/// Absolute address of `GATE_CTRL` (used by the panic handler).
pub const GATE_CTRL_ADDR: usize = PWM.addr(&GATE_CTRL);
/// Absolute address of `HEARTBEAT`.
pub const HEARTBEAT_ADDR: usize = TOP.addr(&HEARTBEAT);
/// Absolute address of `CTRL`.
pub const CTRL_ADDR: usize = TOP.addr(&CTRL);
/// Absolute address of `FAULT_STATUS`.
pub const FAULT_STATUS_ADDR: usize = FAULT.addr(&FAULT_STATUS);

/// The register at absolute address `addr`, with its block.
pub fn lookup(addr: usize) -> Option<(&'static Block, &'static Register)> {
    let rel = addr.checked_sub(BASE_ADDR)?;
    let block = *BLOCKS.get(rel / BLOCK_SIZE)?;
    let off = rel % BLOCK_SIZE;
    block
        .registers
        .iter()
        .find(|r| r.offset as usize == off)
        .map(|r| (block, *r))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_addresses() {
        // Fixed (the panic handler's one store): block 3, offset 0, bit 0.
        assert_eq!(GATE_CTRL_ADDR, 0x43C0_3000);
        assert_eq!(GATE_CTRL_GATE_EN, 1 << GATE_CTRL.fields[0].lsb);
        assert_eq!(GATE_CTRL.reset, 0);
        assert_eq!(HEARTBEAT_ADDR, 0x43C0_0014);
        let names: Vec<&str> = BLOCKS.iter().map(|b| b.name).collect();
        assert_eq!(
            names,
            ["TOP", "MPDTC", "MPDCC", "PWM", "ADC", "ENC", "FAULT", "CAPTURE"]
        );
        for (i, b) in BLOCKS.iter().enumerate() {
            assert_eq!(b.index as usize, i);
        }
    }

    /// The table is consistent: aligned unique offsets inside the page,
    /// unique names, reset values inside the implemented bits and valid for
    /// their own invalid-value rule, fields inside the width, no overlap.
    #[test]
    fn table_is_consistent() {
        let mut names = Vec::new();
        for b in BLOCKS {
            let mut last = None;
            for r in b.registers {
                assert_eq!(r.offset % 4, 0, "{}", r.name);
                assert!((r.offset as usize) < BLOCK_SIZE, "{}", r.name);
                assert!(last.is_none_or(|l| l < r.offset), "{} not sorted", r.name);
                last = Some(r.offset);
                assert!((1..=32).contains(&r.width), "{}", r.name);
                assert_eq!(r.reset & !r.mask(), 0, "{} reset", r.name);
                if r.access == Access::Rw {
                    assert_eq!(r.apply_write(0, r.reset), Ok(r.reset), "{}", r.name);
                }
                let mut used = 0u64;
                for f in r.fields {
                    let m = ((1u64 << f.width) - 1) << f.lsb;
                    assert!(f.lsb + f.width <= r.width, "{}.{}", r.name, f.name);
                    assert_eq!(used & m, 0, "{}.{} overlaps", r.name, f.name);
                    used |= m;
                }
                // The generated register file supports these combinations.
                let hw_ok = match r.hw {
                    Hw::Plain => true,
                    Hw::Const => r.access == Access::Ro,
                    Hw::Strobe | Hw::HwClear => r.access == Access::Rw,
                    Hw::Errors => {
                        r.access == Access::W1c
                            && r.fields.iter().all(|f| {
                                f.width == 1 && ["BAD_VALUE", "BAD_ADDR"].contains(&f.name)
                            })
                    }
                };
                assert!(hw_ok, "{}: {:?} with {:?}", r.name, r.hw, r.access);
                assert!(
                    r.access == Access::Rw || r.invalid == Invalid::AllValid,
                    "{}: only RW registers have a write rule",
                    r.name
                );
                assert!(!names.contains(&r.name), "duplicate {}", r.name);
                names.push(r.name);
            }
        }
    }

    #[test]
    fn exactly_one_error_register() {
        let errs: Vec<&str> = BLOCKS
            .iter()
            .flat_map(|b| b.registers.iter())
            .filter(|r| r.hw == Hw::Errors)
            .map(|r| r.name)
            .collect();
        assert_eq!(errs, ["ERR"]);
    }

    #[test]
    fn write_rules() {
        assert_eq!(DEAD_TIME.apply_write(50, 5000), Ok(1023));
        // The whole word is clamped, not wrapped into the width.
        assert_eq!(DEAD_TIME.apply_write(50, 0x400), Ok(1023));
        assert_eq!(OC_LIMIT.apply_write(0, 0x8000_0000), Ok(2047));
        // All-valid registers drop the bits above their width.
        assert_eq!(SW_STATE.apply_write(0, 0xF), Ok(7));
        assert_eq!(PWM_PERIOD.apply_write(9, 1), Ok(2));
        assert_eq!(CTRL.apply_write(1, 3), Err(RegError::Rejected));
        assert_eq!(CTRL.apply_write(1, 2), Ok(2));
        assert_eq!(ID.apply_write(ID_VALUE, 0), Err(RegError::ReadOnly));
        assert_eq!(FAULT_STATUS.apply_write(0b111, 0b010), Ok(0b101));
        assert_eq!(WDG_TIMEOUT.apply_write(0, 0), Ok(1000));
        assert_eq!(WDG_TIMEOUT.apply_write(0, u32::MAX), Ok(u32::MAX));
    }

    #[test]
    fn lookup_finds_registers() {
        assert_eq!(lookup(0x43C0_3000).map(|(_, r)| r.name), Some("GATE_CTRL"));
        assert_eq!(
            lookup(0x43C0_6008).map(|(b, r)| (b.name, r.name)),
            Some(("FAULT", "OC_LIMIT"))
        );
        assert_eq!(lookup(0x43C0_1000).map(|(_, r)| r.name), Some("MPDTC_CTRL"));
        assert_eq!(
            lookup(0x43C0_2100).map(|(b, r)| (b.name, r.name)),
            Some(("MPDCC", "MPDCC_DECISION"))
        );
        assert_eq!(lookup(0x43C0_2044), None);
        assert_eq!(lookup(0x43C0_3002), None);
        assert_eq!(lookup(0x43C0_8000), None);
        assert_eq!(lookup(0x1000), None);
    }
}
