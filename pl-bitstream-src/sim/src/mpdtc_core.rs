//! Safe wrapper of the Verilated `mpdtc_core` (shim: `csrc/mpdtc_core_shim.cpp`):
//! one call = one decision, in the types of `models::pmsm::mpdtc_fixed`.
use core::ffi::c_void;
use core::ptr::NonNull;

use models::pmsm::mpdtc_fixed::{FixedInputs, FixedOutputs, FixedParams, FixedState};

#[repr(C)]
#[derive(Default)]
struct McState {
    s_applied: i32,
    s_prev: i32,
    eta_d: i32,
    eta_q: i32,
    x: i32,
    band: i32,
    iq_ref_prev: i32,
    i_hat_d: i32,
    i_hat_q: i32,
    nu_d: i32,
    nu_q: i32,
}

#[repr(C)]
struct McIn {
    i_d: i32,
    i_q: i32,
    cos0: i32,
    sin0: i32,
    cos1: i32,
    sin1: i32,
    cos2: i32,
    sin2: i32,
    w_ts: i32,
    t_ref: i32,
}

#[repr(C)]
struct McParams {
    a: i32,
    lambda: i32,
    u0: i32,
    u0_half: i32,
    u0_h: i32,
    psi_l: i32,
    kinv_t: i32,
    tol: i32,
    k_int: i32,
    int_lim: i32,
    int_cond: i32,
    kp_o: i32,
    ki_o: i32,
    eta_lim: i32,
    w2: [i32; 4],
}

#[repr(C)]
#[derive(Default)]
struct McOut {
    s_next: i32,
    iq_ref: i32,
    eta_d: i32,
    eta_q: i32,
    i1_d: i32,
    i1_q: i32,
    i2_d: [i32; 8],
    i2_q: [i32; 8],
    err: [i32; 8],
    cost2: [i64; 8],
    next: McState,
    latency: i32,
    ready_after: i32,
}

extern "C" {
    fn mc_new() -> *mut c_void;
    fn mc_decide(
        p: *mut c_void,
        st: *const McState,
        inp: *const McIn,
        pr: *const McParams,
        out: *mut McOut,
    );
    fn mc_free(p: *mut c_void);
}

/// Result of one decision of the RTL.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RtlDecision {
    /// Every output in the model's types.
    pub out: FixedOutputs,
    /// Cycles from the input strobe to the output strobe.
    pub latency_cycles: u32,
    /// The core was ready for the next input in the output cycle.
    pub ready_at_output: bool,
}

/// One Verilated `mpdtc_core`.
pub struct MpdtcCoreSim {
    ptr: NonNull<c_void>,
}

impl MpdtcCoreSim {
    /// A new core after reset.
    pub fn new() -> Self {
        // SAFETY: mc_new returns a fresh heap object owned by this value.
        let ptr = NonNull::new(unsafe { mc_new() }).expect("mc_new returned null");
        Self { ptr }
    }

    /// Loads `st`, runs one decision on `inp` with `p`, returns the outputs.
    pub fn decide(&mut self, st: &FixedState, inp: &FixedInputs, p: &FixedParams) -> RtlDecision {
        let s = McState {
            s_applied: i32::from(st.s_applied),
            s_prev: i32::from(st.s_prev),
            eta_d: st.eta_prev.0,
            eta_q: st.eta_prev.1,
            x: st.x,
            band: i32::from(st.band_reached),
            iq_ref_prev: st.iq_ref_prev,
            i_hat_d: st.i_hat.0,
            i_hat_q: st.i_hat.1,
            nu_d: st.nu.0,
            nu_q: st.nu.1,
        };
        let i = McIn {
            i_d: inp.i_dq.0,
            i_q: inp.i_dq.1,
            cos0: inp.trig[0].0,
            sin0: inp.trig[0].1,
            cos1: inp.trig[1].0,
            sin1: inp.trig[1].1,
            cos2: inp.trig[2].0,
            sin2: inp.trig[2].1,
            w_ts: inp.w_ts,
            t_ref: inp.t_ref,
        };
        let pr = McParams {
            a: p.a,
            lambda: p.lambda,
            u0: p.u0,
            u0_half: p.u0_half,
            u0_h: p.u0_h,
            psi_l: p.psi_l,
            kinv_t: p.kinv_t,
            tol: p.tol,
            k_int: p.k_int,
            int_lim: p.int_lim,
            int_cond: i32::from(p.int_conditional),
            kp_o: p.kp_o,
            ki_o: p.ki_o,
            eta_lim: p.eta_lim,
            w2: p.w2,
        };
        let mut o = McOut::default();
        // SAFETY: live object; all structs are repr(C) and match the shim.
        unsafe { mc_decide(self.ptr.as_ptr(), &s, &i, &pr, &mut o) };
        let mut out = FixedOutputs {
            s_next: o.s_next as u8,
            iq_ref: o.iq_ref,
            eta: (o.eta_d, o.eta_q),
            i1: (o.i1_d, o.i1_q),
            ..Default::default()
        };
        for k in 0..8 {
            out.i2[k] = (o.i2_d[k], o.i2_q[k]);
            out.err[k] = o.err[k];
            out.cost2[k] = o.cost2[k];
        }
        let n = &o.next;
        out.next = FixedState {
            s_applied: n.s_applied as u8,
            s_prev: n.s_prev as u8,
            eta_prev: (n.eta_d, n.eta_q),
            x: n.x,
            band_reached: n.band != 0,
            iq_ref_prev: n.iq_ref_prev,
            i_hat: (n.i_hat_d, n.i_hat_q),
            nu: (n.nu_d, n.nu_q),
        };
        RtlDecision {
            out,
            latency_cycles: o.latency as u32,
            ready_at_output: o.ready_after == 0,
        }
    }
}

impl Default for MpdtcCoreSim {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for MpdtcCoreSim {
    fn drop(&mut self) {
        // SAFETY: the pointer came from mc_new and is freed exactly once.
        unsafe { mc_free(self.ptr.as_ptr()) }
    }
}
