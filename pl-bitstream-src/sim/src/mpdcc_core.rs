//! Safe wrapper of the Verilated `mpdcc_core` in its two datapaths (shims:
//! `csrc/mpdcc_core_shim.cpp`, `csrc/mpdcc_core_shared_shim.cpp`; 6
//! explorers instantiated, `n_use` of them used): one call = one decision
//! from the state registers (`models::mpdcc::mpdcc_fixed::Inputs`).
use core::ffi::c_void;
use core::ptr::NonNull;

use models::mpdcc::controller::DecisionKind;
use models::mpdcc::mpdcc_fixed::{Coeffs, Inputs};

/// Explorers instantiated in the Verilated model.
pub const MAX_EXPLORERS: u32 = 6;

#[repr(C)]
struct MkIn {
    s_prev: [i32; 3],
    i_ab: [i32; 2],
    psi_ab: [i32; 2],
    v_n: i32,
    v_ph: [i32; 3],
    i_ref_ab: [i32; 2],
    omega_r: i32,
    omega_s: i32,
    c_tau: i32,
    c_r: i32,
    c_w: i32,
    c_p: i32,
    c_s: i32,
    c_3: i32,
    c_d: i32,
    c_n: i32,
    c_ph: i32,
    s3h: i32,
    v_ph_ref: i32,
    c_tau1: i32,
    c_r1: i32,
    c_w1: i32,
    c_s1: i32,
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
    fn mk_decide(p: *mut c_void, c: *const MkIn, n_use: i32, out: *mut MkOut);
    fn mk_free(p: *mut c_void);
    fn mks_new() -> *mut c_void;
    fn mks_decide(p: *mut c_void, c: *const MkIn, n_use: i32, out: *mut MkOut);
    fn mks_free(p: *mut c_void);
}

/// The datapath of a Verilated `mpdcc_core` (its `II` parameter).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoreConfig {
    /// `II = 1`: one candidate per clock per explorer, seven search lanes.
    FullRate,
    /// `pl_top`'s configuration: one candidate every [`CoreConfig::ii`]
    /// clocks per explorer on shared search lanes.
    PlTop,
}

impl CoreConfig {
    /// Clocks per candidate of each explorer (`mpdcc_core` parameter `II`).
    pub fn ii(self) -> u32 {
        match self {
            Self::FullRate => 1,
            Self::PlTop => env!("RTL_SIM_MPDCC_CORE_SHARED_II")
                .parse()
                .expect("II set by build.rs"),
        }
    }
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
    config: CoreConfig,
}

impl MpdccCoreSim {
    /// A new full-rate core (`II = 1`) after reset.
    pub fn new() -> Self {
        Self::with_config(CoreConfig::FullRate)
    }

    /// A new core of the given datapath after reset.
    pub fn with_config(config: CoreConfig) -> Self {
        // SAFETY: mk_new / mks_new return a fresh heap object owned by this value.
        let raw = unsafe {
            match config {
                CoreConfig::FullRate => mk_new(),
                CoreConfig::PlTop => mks_new(),
            }
        };
        let ptr = NonNull::new(raw).expect("mk_new returned null");
        Self { ptr, config }
    }

    /// The datapath of this core.
    pub fn config(&self) -> CoreConfig {
        self.config
    }

    /// One decision on the state registers `x` with the constants `k` and
    /// `n_use` explorers (clamped to 1..=6 by the core).
    pub fn decide(&mut self, k: &Coeffs, x: &Inputs, n_use: u32) -> RtlDecision {
        let w = i32::from;
        let cm = MkIn {
            s_prev: x.s_prev.map(i32::from),
            i_ab: x.i_ab.map(w),
            psi_ab: x.psi_ab.map(w),
            v_n: w(x.v_n),
            v_ph: x.v_ph.map(w),
            i_ref_ab: x.i_ref_ab.map(w),
            omega_r: w(x.omega_r),
            omega_s: w(x.omega_s),
            c_tau: w(k.c_tau),
            c_r: w(k.c_r),
            c_w: w(k.c_w),
            c_p: w(k.c_p),
            c_s: w(k.c_s),
            c_3: w(k.c_3),
            c_d: w(k.c_d),
            c_n: w(k.c_n),
            c_ph: w(k.c_ph),
            s3h: w(k.s3h),
            v_ph_ref: w(k.v_ph_ref),
            c_tau1: w(k.c_tau1),
            c_r1: w(k.c_r1),
            c_w1: w(k.c_w1),
            c_s1: w(k.c_s1),
            vdc_half: w(k.v_dc_half),
            g3: w(k.g3),
            gd: w(k.gd),
            g3_1: w(k.g3_1),
            bnd: k.bnd.map(w),
            lambda_n: i32::from(k.lambda_n),
        };
        let mut o = MkOut::default();
        // SAFETY: live object; repr(C) structs that match the shim.
        unsafe {
            match self.config {
                CoreConfig::FullRate => {
                    mk_decide(self.ptr.as_ptr(), &cm, n_use.min(7) as i32, &mut o)
                }
                CoreConfig::PlTop => {
                    mks_decide(self.ptr.as_ptr(), &cm, n_use.min(7) as i32, &mut o)
                }
            }
        };
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
        // SAFETY: the pointer came from mk_new / mks_new (by config) and is
        // freed exactly once, by the matching function.
        unsafe {
            match self.config {
                CoreConfig::FullRate => mk_free(self.ptr.as_ptr()),
                CoreConfig::PlTop => mks_free(self.ptr.as_ptr()),
            }
        }
    }
}
