//! Safe wrapper of the Verilated `mpdcc_explorer` (shim:
//! `csrc/mpdcc_explorer_shim.cpp`): one call = the candidates of one
//! decision streamed one per clock, in the types of `models::mpdcc::mpdcc_fixed`.
use core::ffi::c_void;
use core::ptr::NonNull;

use models::mpdcc::mpdcc_fixed::{Coeffs, Common};

#[repr(C)]
struct MeCommon {
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
#[derive(Default, Clone, Copy)]
struct MeOut {
    s: [i32; 3],
    l_star: i32,
    cost: u32,
    j_dl: i32,
    fs: i32,
    d0: [i32; 7],
    latency: i32,
}

extern "C" {
    fn me_new() -> *mut c_void;
    fn me_run(p: *mut c_void, c: *const MeCommon, n: i32, s: *const i32, out: *mut MeOut) -> i32;
    fn me_free(p: *mut c_void);
}

/// What the RTL explorer returns for one candidate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RtlResult {
    /// The candidate.
    pub s: [u8; 3],
    /// `L*`, steps.
    pub l_star: u32,
    /// `J`, UQ15.17; `u32::MAX` = `+inf`.
    pub cost: u32,
    /// `J_dl`, Q2.13.
    pub j_dl: i32,
    /// `f_s`, device turn-ons.
    pub fs: u32,
    /// `Delta_j` over `L` steps, Q2.13.
    pub deltas: [i16; 7],
    /// Cycles from the candidate's strobe to its result strobe.
    pub latency_cycles: u32,
}

/// One Verilated `mpdcc_explorer`.
pub struct MpdccExplorerSim {
    ptr: NonNull<c_void>,
}

impl MpdccExplorerSim {
    /// A new explorer after reset.
    pub fn new() -> Self {
        // SAFETY: me_new returns a fresh heap object owned by this value.
        let ptr = NonNull::new(unsafe { me_new() }).expect("me_new returned null");
        Self { ptr }
    }

    /// Evaluates `cands` (one per clock) against the common terms `c` of
    /// `s_prev` with the constants `k`; results in arrival order.
    pub fn run(
        &mut self,
        k: &Coeffs,
        c: &Common,
        s_prev: [u8; 3],
        cands: &[[u8; 3]],
    ) -> Vec<RtlResult> {
        let cm = MeCommon {
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
        let s: Vec<i32> = cands.iter().flat_map(|c| c.map(i32::from)).collect();
        let mut out = vec![MeOut::default(); cands.len()];
        let n = i32::try_from(cands.len()).expect("candidate count");
        // SAFETY: live object; buffers hold n candidates / results, repr(C).
        let got = unsafe { me_run(self.ptr.as_ptr(), &cm, n, s.as_ptr(), out.as_mut_ptr()) };
        out.truncate(got.max(0) as usize);
        out.iter()
            .map(|o| RtlResult {
                s: o.s.map(|v| v as u8),
                l_star: o.l_star as u32,
                cost: o.cost,
                j_dl: o.j_dl,
                fs: o.fs as u32,
                deltas: o.d0.map(|v| v as i16),
                latency_cycles: o.latency as u32,
            })
            .collect()
    }
}

impl Default for MpdccExplorerSim {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for MpdccExplorerSim {
    fn drop(&mut self) {
        // SAFETY: the pointer came from me_new and is freed exactly once.
        unsafe { me_free(self.ptr.as_ptr()) }
    }
}
