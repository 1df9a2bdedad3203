//! Safe wrapper of the Verilated `mpdcc_core` (shim:
//! `csrc/mpdcc_core_shim.cpp`, 6 explorers instantiated, `n_use` of them
//! used): one call = one decision from the common terms of
//! `drive::mpdcc::fpga`.
use core::ffi::c_void;
use core::ptr::NonNull;

use drive::mpdcc::controller::DecisionKind;
use drive::mpdcc::fpga::{Coeffs, Common};

/// Explorers instantiated in the Verilated model.
pub const MAX_EXPLORERS: u32 = 6;

#[repr(C)]
struct MkCommon {
    s_prev: [i32; 3],
    e0: [i32; 7],
    dn: [[i32; 3]; 4],
    dn1: [i32; 3],
    pn: [i64; 3],
    pph: [i64; 3],
    v_n: i32,
    v_ph: [i32; 3],
    vdc_half: i32,
    g3: i32,
    gd: i32,
    g3_1: i32,
    bnd: [i32; 7],
    lambda_n: i32,
}

#[repr(C)]
#[derive(Default)]
struct MkOut {
    s: [i32; 3],
    kind: i32,
    l_star: i32,
    cost: u32,
    j_dl: i32,
    candidates: i32,
    cycles: i32,
    measured_cycles: i32,
}

extern "C" {
    fn mk_new() -> *mut c_void;
    fn mk_decide(p: *mut c_void, c: *const MkCommon, n_use: i32, out: *mut MkOut);
    fn mk_free(p: *mut c_void);
}

/// One decision of the RTL core.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RtlDecision {
    /// Chosen position.
    pub s: [u8; 3],
    /// Kept, optimal or deadlock (`None`: an encoding the core never gives).
    pub kind: Option<DecisionKind>,
    /// `L*` of an optimal decision, else 0.
    pub horizon_steps: u32,
    /// `J` of the chosen candidate (kept: 0).
    pub cost: u32,
    /// `J_dl` of the chosen candidate (kept: 0).
    pub j_dl: i32,
    /// Candidates evaluated (kept: 0).
    pub candidates: u32,
    /// The core's own cycle count (`cycles_o`).
    pub cycles: u32,
    /// Clock edges from the start strobe to `done_o`, counted by the bench
    /// (`None`: no `done_o` within 2000 cycles).
    pub measured_cycles: Option<u32>,
}

/// One Verilated `mpdcc_core`.
pub struct MpdccCoreSim {
    ptr: NonNull<c_void>,
}

impl MpdccCoreSim {
    /// A new core after reset.
    pub fn new() -> Self {
        // SAFETY: mk_new returns a fresh heap object owned by this value.
        let ptr = NonNull::new(unsafe { mk_new() }).expect("mk_new returned null");
        Self { ptr }
    }

    /// One decision with `n_use` explorers (clamped to 1..=6 by the core).
    pub fn decide(&mut self, k: &Coeffs, c: &Common, s_prev: [u8; 3], n_use: u32) -> RtlDecision {
        let cm = MkCommon {
            s_prev: s_prev.map(i32::from),
            e0: c.e0.map(i32::from),
            dn: c.dn.map(|r| r.map(i32::from)),
            dn1: c.dn_1.map(i32::from),
            pn: c.pn,
            pph: c.pph,
            v_n: i32::from(c.v_n),
            v_ph: c.v_ph.map(i32::from),
            vdc_half: i32::from(k.v_dc_half),
            g3: i32::from(k.g3),
            gd: i32::from(k.gd),
            g3_1: i32::from(k.g3_1),
            bnd: k.bnd.map(i32::from),
            lambda_n: i32::from(k.lambda_n),
        };
        let mut o = MkOut::default();
        // SAFETY: live object; repr(C) structs that match the shim.
        unsafe { mk_decide(self.ptr.as_ptr(), &cm, n_use.min(7) as i32, &mut o) };
        RtlDecision {
            s: o.s.map(|v| v as u8),
            kind: match o.kind {
                0 => Some(DecisionKind::Kept),
                1 => Some(DecisionKind::Optimal),
                2 => Some(DecisionKind::Deadlock),
                _ => None,
            },
            horizon_steps: o.l_star as u32,
            cost: o.cost,
            j_dl: o.j_dl,
            candidates: o.candidates as u32,
            cycles: o.cycles as u32,
            measured_cycles: u32::try_from(o.measured_cycles).ok(),
        }
    }
}

impl Default for MpdccCoreSim {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for MpdccCoreSim {
    fn drop(&mut self) {
        // SAFETY: the pointer came from mk_new and is freed exactly once.
        unsafe { mk_free(self.ptr.as_ptr()) }
    }
}
