//! Block 2, the MPDCC page: the registers of `mpdcc_core` (paper 001's
//! scheduler and N explorers) as `pl_top` instantiates it.
//!
//! Inputs and constants are the words of `models::mpdcc::mpdcc_fixed::Inputs` and
//! `Coeffs`, one 16-bit two's complement word per register (formats in
//! docs/mpdcc-fpga.md). An `MPDCC_START` write while the core is idle takes
//! a snapshot of every input and constant register at the end of that cycle
//! and starts the core on the snapshot the next cycle, so the PS may write
//! the next period's inputs while a decision runs. The result registers
//! change when the decision is done; `MPDCC_STATUS.BUSY` is high from the
//! cycle after the START write until the cycle after the result registers
//! changed, and `DONE` then says they hold the decision of the last START.
use super::{field, Access, Field, Hw, Invalid, Register};

/// Explorer units `pl_top` instantiates by default (its `MPDCC_N` parameter).
pub const MPDCC_EXPLORERS: u32 = 1;
/// Clocks per candidate of each explorer in `pl_top`'s default build (its
/// `MPDCC_II` parameter; 1 = full rate): the explorers share two search
/// lanes, so a decision on 216 candidates takes 927 cycles
/// (`models::mpdcc::cycles::pipelined_core_cycles_ii`). Only the cycle
/// count depends on it; `MPDCC_CYCLES` reports the core's own count.
pub const MPDCC_II: u32 = 4;
/// `lambda = log2 L` the core is built for (`L` = 8 steps).
pub const MPDCC_LAMBDA: u32 = 3;
/// `M = log2 N_bar` of the core's search (`N_bar` = 128 steps).
pub const MPDCC_M_BITS: u32 = 7;
/// Interpolation nodes of the core.
pub const MPDCC_NODES: u32 = 4;
/// Cycles from the `MPDCC_START` write to the core's start strobe.
pub const MPDCC_START_DELAY: u32 = 1;

/// `MPDCC_DECISION.KIND` values (`models::mpdcc::controller::DecisionKind`).
pub mod mpdcc_kind {
    /// The lazy check passed: `s(k-1)` kept.
    pub const KEPT: u32 = 0;
    /// The feasible candidate with the lowest cost.
    pub const OPTIMAL: u32 = 1;
    /// No candidate feasible: the one with the lowest `J_dl` (eqs. 15-16).
    pub const DEADLOCK: u32 = 2;
}

const Q2_13: &str = "Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)";
const Q1_14: &str = "Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)";
const F17: &str = "signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6)";

/// An RW 16-bit input or constant word (reset 0, every value valid).
const fn mc(name: &'static str, offset: u16, format: &'static str, doc: &'static str) -> Register {
    Register {
        name,
        offset,
        access: Access::Rw,
        width: 16,
        reset: 0,
        format,
        invalid: Invalid::AllValid,
        hw: Hw::Plain,
        fields: &[],
        doc,
    }
}

/// An RO result word.
const fn mr(
    name: &'static str,
    offset: u16,
    width: u8,
    format: &'static str,
    fields: &'static [Field],
    doc: &'static str,
) -> Register {
    Register {
        name,
        offset,
        access: Access::Ro,
        width,
        reset: 0,
        format,
        invalid: Invalid::AllValid,
        hw: Hw::Plain,
        fields,
        doc,
    }
}

/// MPDCC: start.
pub const MPDCC_START: Register = Register {
    name: "MPDCC_START",
    offset: 0x000,
    access: Access::Rw,
    width: 1,
    reset: 0,
    format: "any value",
    invalid: Invalid::AllValid,
    hw: Hw::Strobe,
    fields: &[],
    doc: "A write while MPDCC_STATUS.BUSY = 0 snapshots the input and constant registers \
          and starts one decision (ignored while busy). Reads back the last value.",
};
/// MPDCC: status.
pub const MPDCC_STATUS: Register = mr(
    "MPDCC_STATUS",
    0x004,
    32,
    "bits and a counter",
    &[
        field(
            "BUSY",
            0,
            1,
            "a decision runs (from the cycle after the START write)",
        ),
        field(
            "DONE",
            1,
            1,
            "the result registers hold the decision of the last START (0 from the START \
             write until BUSY falls, and after reset)",
        ),
        field("COUNT", 16, 16, "decisions completed since reset (wraps)"),
    ],
    "State of the core; poll until BUSY = 0 and DONE = 1.",
);
/// MPDCC: explorers used.
pub const MPDCC_N_USE: Register = Register {
    name: "MPDCC_N_USE",
    offset: 0x008,
    access: Access::Rw,
    width: 3,
    reset: MPDCC_EXPLORERS,
    format: "unsigned, explorer units",
    invalid: Invalid::Clamp { min: 1, max: 6 },
    hw: Hw::Plain,
    fields: &[],
    doc: "Explorers the next decision uses (n_use); the core takes at most \
          MPDCC_CONFIG.EXPLORERS of them. Only the cycle count depends on it.",
};
/// MPDCC: build-time configuration.
pub const MPDCC_CONFIG: Register = Register {
    reset: MPDCC_CONFIG_VALUE,
    ..mr(
        "MPDCC_CONFIG",
        0x00C,
        16,
        "four unsigned fields",
        &[
            field("EXPLORERS", 0, 4, "explorer units instantiated (N)"),
            field("LAMBDA", 4, 4, "lambda = log2 L, extrapolation steps"),
            field("M_BITS", 8, 4, "M = log2 N_bar, search bits"),
            field("NODES", 12, 4, "interpolation nodes"),
        ],
        "The constants the core is built with (reset: the default build); Coeffs \
         must agree (lambda, m_bits, nodes).",
    )
};
/// The reset (and default-build) value of `MPDCC_CONFIG`.
pub const MPDCC_CONFIG_VALUE: u32 =
    MPDCC_EXPLORERS | (MPDCC_LAMBDA << 4) | (MPDCC_M_BITS << 8) | (MPDCC_NODES << 12);
/// MPDCC input: `s(k-1)`.
pub const MPDCC_S_PREV: Register = Register {
    name: "MPDCC_S_PREV",
    offset: 0x010,
    access: Access::Rw,
    width: 9,
    reset: 0,
    format: "three unsigned 3-bit switch positions 0..7",
    invalid: Invalid::AllValid,
    hw: Hw::Plain,
    fields: &[
        field("A", 0, 3, "phase a position"),
        field("B", 3, 3, "phase b position"),
        field("C", 6, 3, "phase c position"),
    ],
    doc: "Switch positions applied in the previous period, s(k-1).",
};
/// MPDCC input: `i_s,alpha`.
pub const MPDCC_I_A: Register = mc("MPDCC_I_A", 0x014, Q2_13, "Stator current i_s,alpha.");
/// MPDCC input: `i_s,beta`.
pub const MPDCC_I_B: Register = mc("MPDCC_I_B", 0x018, Q2_13, "Stator current i_s,beta.");
/// MPDCC input: `psi_r,alpha`.
pub const MPDCC_PSI_A: Register = mc("MPDCC_PSI_A", 0x01C, Q1_14, "Rotor flux psi_r,alpha, pu.");
/// MPDCC input: `psi_r,beta`.
pub const MPDCC_PSI_B: Register = mc("MPDCC_PSI_B", 0x020, Q1_14, "Rotor flux psi_r,beta, pu.");
/// MPDCC input: `v_n`.
pub const MPDCC_V_N: Register = mc("MPDCC_V_N", 0x024, Q2_13, "Neutral-point voltage v_n.");
/// MPDCC input: `v_ph,a`.
pub const MPDCC_V_PH_A: Register = mc("MPDCC_V_PH_A", 0x028, Q2_13, "Phase capacitor voltage, a.");
/// MPDCC input: `v_ph,b`.
pub const MPDCC_V_PH_B: Register = mc("MPDCC_V_PH_B", 0x02C, Q2_13, "Phase capacitor voltage, b.");
/// MPDCC input: `v_ph,c`.
pub const MPDCC_V_PH_C: Register = mc("MPDCC_V_PH_C", 0x030, Q2_13, "Phase capacitor voltage, c.");
/// MPDCC input: `i_s*,alpha`.
pub const MPDCC_IREF_A: Register = mc(
    "MPDCC_IREF_A",
    0x034,
    Q2_13,
    "Current reference i_s*,alpha(k).",
);
/// MPDCC input: `i_s*,beta`.
pub const MPDCC_IREF_B: Register = mc(
    "MPDCC_IREF_B",
    0x038,
    Q2_13,
    "Current reference i_s*,beta(k).",
);
/// MPDCC input: `omega_r`.
pub const MPDCC_OMEGA_R: Register = mc("MPDCC_OMEGA_R", 0x03C, Q2_13, "Rotor speed omega_r.");
/// MPDCC input: `omega_s`.
pub const MPDCC_OMEGA_S: Register = mc(
    "MPDCC_OMEGA_S",
    0x040,
    Q2_13,
    "Stator (reference) frequency omega_s.",
);
/// MPDCC constant `c_tau`.
pub const MPDCC_C_TAU: Register = mc("MPDCC_C_TAU", 0x080, Q1_14, "L T / tau_s.");
/// MPDCC constant `c_r`.
pub const MPDCC_C_R: Register = mc("MPDCC_C_R", 0x084, Q1_14, "L T X_m / (D tau_r).");
/// MPDCC constant `c_w`.
pub const MPDCC_C_W: Register = mc("MPDCC_C_W", 0x088, Q1_14, "L T X_m / D (times omega_r).");
/// MPDCC constant `c_p`.
pub const MPDCC_C_P: Register = mc("MPDCC_C_P", 0x08C, Q1_14, "p (L T)^2 (times omega_r^2).");
/// MPDCC constant `c_s`.
pub const MPDCC_C_S: Register = mc("MPDCC_C_S", 0x090, Q1_14, "L T (times omega_s).");
/// MPDCC constant `c_3`.
pub const MPDCC_C_3: Register = mc(
    "MPDCC_C_3",
    0x094,
    Q1_14,
    "(L T)^2 / 6 (third-order rotation).",
);
/// MPDCC constant `c_d`.
pub const MPDCC_C_D: Register = mc("MPDCC_C_D", 0x098, Q1_14, "Stator damping L T / (2 tau_s).");
/// MPDCC constant `c_n`.
pub const MPDCC_C_N: Register = mc("MPDCC_C_N", 0x09C, Q1_14, "L T / (2 C_dc) (times i_x).");
/// MPDCC constant `c_ph`.
pub const MPDCC_C_PH: Register = mc("MPDCC_C_PH", 0x0A0, Q1_14, "L T / C_ph (times i_x).");
/// MPDCC constant `sqrt(3)/2`.
pub const MPDCC_S3H: Register = mc("MPDCC_S3H", 0x0A4, Q1_14, "sqrt(3) / 2.");
/// MPDCC constant `v_ph_ref`.
pub const MPDCC_V_PH_REF: Register = mc(
    "MPDCC_V_PH_REF",
    0x0A8,
    Q2_13,
    "Phase capacitor reference V_dc / 4.",
);
/// MPDCC constant `c_tau1`.
pub const MPDCC_C_TAU1: Register = mc("MPDCC_C_TAU1", 0x0AC, F17, "One step: T / tau_s.");
/// MPDCC constant `c_r1`.
pub const MPDCC_C_R1: Register = mc("MPDCC_C_R1", 0x0B0, F17, "One step: T X_m / (D tau_r).");
/// MPDCC constant `c_w1`.
pub const MPDCC_C_W1: Register = mc("MPDCC_C_W1", 0x0B4, F17, "One step: T X_m / D.");
/// MPDCC constant `c_s1`.
pub const MPDCC_C_S1: Register = mc("MPDCC_C_S1", 0x0B8, F17, "One step: T.");
/// MPDCC constant `V_dc/2`.
pub const MPDCC_VDC_HALF: Register = mc("MPDCC_VDC_HALF", 0x0BC, Q2_13, "V_dc / 2.");
/// MPDCC constant `g3`.
pub const MPDCC_G3: Register = mc("MPDCC_G3", 0x0C0, Q1_14, "L T X_r / (3 D).");
/// MPDCC constant `gd`.
pub const MPDCC_GD: Register = mc("MPDCC_GD", 0x0C4, Q1_14, "g3 c_d.");
/// MPDCC constant `g3_1`.
pub const MPDCC_G3_1: Register = mc("MPDCC_G3_1", 0x0C8, F17, "One step: T X_r / (3 D).");
/// A bound register: non-negative Q2.13.
const fn bnd(name: &'static str, offset: u16, doc: &'static str) -> Register {
    Register {
        invalid: Invalid::Reject { max: 0x7FFF },
        ..mc(name, offset, "Q2.13, 0..32767 (0..4 pu)", doc)
    }
}
/// MPDCC bound on the current error, phase a.
pub const MPDCC_BND_IA: Register = bnd("MPDCC_BND_IA", 0x0CC, "Bound delta_i, phase a current.");
/// MPDCC bound on the current error, phase b.
pub const MPDCC_BND_IB: Register = bnd("MPDCC_BND_IB", 0x0D0, "Bound delta_i, phase b current.");
/// MPDCC bound on the current error, phase c.
pub const MPDCC_BND_IC: Register = bnd("MPDCC_BND_IC", 0x0D4, "Bound delta_i, phase c current.");
/// MPDCC bound on `v_n`.
pub const MPDCC_BND_VN: Register = bnd("MPDCC_BND_VN", 0x0D8, "Bound on |v_n|.");
/// MPDCC bound on `v_ph,a`.
pub const MPDCC_BND_VPA: Register = bnd("MPDCC_BND_VPA", 0x0DC, "Bound on |v_ph,a - V_dc/4|.");
/// MPDCC bound on `v_ph,b`.
pub const MPDCC_BND_VPB: Register = bnd("MPDCC_BND_VPB", 0x0E0, "Bound on |v_ph,b - V_dc/4|.");
/// MPDCC bound on `v_ph,c`.
pub const MPDCC_BND_VPC: Register = bnd("MPDCC_BND_VPC", 0x0E4, "Bound on |v_ph,c - V_dc/4|.");
/// MPDCC weight `lambda_n`.
pub const MPDCC_LAMBDA_N: Register = mc(
    "MPDCC_LAMBDA_N",
    0x0E8,
    "UQ8.8 unsigned 16-bit (0..256, LSB 3.9e-3)",
    "Weight lambda_n of the terminal v_n^2 term of J.",
);
/// MPDCC result: the decision.
pub const MPDCC_DECISION: Register = mr(
    "MPDCC_DECISION",
    0x100,
    24,
    "three 3-bit positions, an enum, an unsigned step count",
    &[
        field("S_A", 0, 3, "phase a position s(k)"),
        field("S_B", 3, 3, "phase b position"),
        field("S_C", 6, 3, "phase c position"),
        field(
            "KIND",
            12,
            2,
            "0 kept, 1 optimal, 2 deadlock (regmap::mpdcc_kind)",
        ),
        field(
            "L_STAR",
            16,
            8,
            "L*, steps, of an optimal decision (else 0)",
        ),
    ],
    "The last decision.",
);
/// MPDCC result: cost.
pub const MPDCC_COST: Register = mr(
    "MPDCC_COST",
    0x104,
    32,
    "UQ15.17 unsigned, transitions per step (0xFFFFFFFF = +inf)",
    &[],
    "J of the chosen candidate (kept: 0).",
);
/// MPDCC result: deadlock cost.
pub const MPDCC_J_DL: Register = mr(
    "MPDCC_J_DL",
    0x108,
    32,
    "signed 32-bit two's complement, Q2.13 pu",
    &[],
    "J_dl (eq. 15) of the chosen candidate (kept: 0).",
);
/// MPDCC result: cycles and candidates.
pub const MPDCC_CYCLES: Register = mr(
    "MPDCC_CYCLES",
    0x10C,
    24,
    "unsigned PL clock cycles and an unsigned count",
    &[
        field(
            "CYCLES",
            0,
            16,
            "clock edges from the core's start strobe to its done strobe",
        ),
        field(
            "CANDIDATES",
            16,
            8,
            "candidates evaluated (kept: 0; the search runs anyway)",
        ),
    ],
    "Cost in time of the last decision.",
);
/// MPDCC result: deadlocks.
pub const MPDCC_DEADLOCKS: Register = mr(
    "MPDCC_DEADLOCKS",
    0x110,
    16,
    "unsigned, wraps",
    &[],
    "Deadlock decisions (KIND = 2) since reset.",
);
