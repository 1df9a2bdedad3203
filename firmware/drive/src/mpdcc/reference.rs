//! Idealized `f64` MPDCC reference (paper 001, Sec. VII-B's "Matlab"
//! implementation): exact discretization of the machine, output trajectories
//! extended step by step with the full controller model (eqs. 2-3: exact
//! machine step with the actual `v_abc(s, v_n, v_ph)`, eq. 2 for the inverter
//! states), switching horizon "SE", lazy evaluation, cost eqs. (10)-(12) with
//! the terminal neutral-point weight, deadlock resolution eqs. (15)-(16).
//! The shared semantics (what `L*` means, tie-breaking, ordering) are written
//! down in [`super::controller`].
//!
//! Decisions specific to the reference:
//! - "Exact discretization" is the zero-order-hold discretization of the
//!   machine for the voltage of the step ([`machine::Discrete::exact`]); the
//!   inverter states use eq. (2) exactly as the paper's controller model
//!   does (currents held over a step). The plant ([`super::plant`]) is
//!   exact for the coupled system, so the reference's model is not
//!   bit-identical to the plant, but the difference is ~1e-7 pu per step.
//! - The extension runs until the first step with an output outside its
//!   bound, or `N_bar` steps (then `L* = N_bar`).
#![allow(clippy::needless_range_loop)]

use super::anpc;
use super::controller::{
    candidates, rotate, Bounds, CtrlState, Decision, DecisionKind, MpdccController, StateError,
};
use super::machine::{self, clarke, inv_clarke, Discrete};
use super::params::{DriveParams, ParamError};

/// Largest supported `N_bar` (see `ControllerParams::validate`).
const MAX_H: usize = 1024;

/// Result of extending one candidate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extension {
    /// `L*(s)`, steps.
    pub l_star: u32,
    /// `v_n(k + L*)`, pu (the terminal weight's argument).
    pub v_n_end: f64,
    /// `max_j (|y*_j(k+1) - y_j(k+1)| - y_bnd,j)` (eq. 15), pu.
    pub excess_k1: f64,
}

/// The idealized MPDCC controller.
pub struct Reference {
    p: DriveParams,
    bounds: Bounds,
    ts_pu: f64,
    disc: Discrete,
    disc_omega_r: f64,
    /// Phase current references `i*_abc(k+l)`, l = 0..=N_bar.
    iref: [[f64; 3]; MAX_H + 1],
}

impl Reference {
    /// Builds the controller; rejects invalid parameters.
    pub fn new(p: &DriveParams) -> Result<Self, ParamError> {
        p.validate()?;
        let ts_pu = p.controller.ts_pu(&p.machine);
        let w = p.operating_point.omega_r_pu;
        let disc = Discrete::exact(&machine::continuous(&p.machine, w), ts_pu);
        Ok(Self {
            p: *p,
            bounds: Bounds::new(&p.controller, &p.inverter),
            ts_pu,
            disc,
            disc_omega_r: w,
            iref: [[0.0; 3]; MAX_H + 1],
        })
    }

    /// The bounds in use.
    pub fn bounds(&self) -> &Bounds {
        &self.bounds
    }

    fn prepare(&mut self, st: &CtrlState) {
        if st.omega_r_pu != self.disc_omega_r {
            self.disc = Discrete::exact(
                &machine::continuous(&self.p.machine, st.omega_r_pu),
                self.ts_pu,
            );
            self.disc_omega_r = st.omega_r_pu;
        }
        let th = st.omega_s_pu * self.ts_pu;
        let (c, s) = (libm::cos(th), libm::sin(th));
        let h = self.p.controller.horizon_max_steps as usize;
        let mut i = st.i_ref_ab_pu;
        self.iref[0] = inv_clarke(i);
        for l in 1..=h {
            i = rotate(i, c, s);
            self.iref[l] = inv_clarke(i);
        }
    }

    /// Extends candidate `s` from `st` for at most `max_l` steps (needs
    /// `prepare` for `st` first).
    fn extend(&self, st: &CtrlState, s: [u8; 3], max_l: u32) -> Extension {
        let inv = &self.p.inverter;
        let mut xm = st.x_m;
        let mut xi = [st.v_n_pu, st.v_ph_pu[0], st.v_ph_pu[1], st.v_ph_pu[2]];
        let i0 = inv_clarke([xm[0], xm[1]]);
        let e0 = [
            self.iref[0][0] - i0[0],
            self.iref[0][1] - i0[1],
            self.iref[0][2] - i0[2],
        ];
        let mut inside = self.bounds.worst_excess(e0, xi[0], [xi[1], xi[2], xi[3]]) <= 0.0;
        let mut ext = Extension {
            l_star: 0,
            v_n_end: xi[0],
            excess_k1: f64::INFINITY,
        };
        let mut i_abc = i0;
        for l in 1..=max_l as usize {
            let v = anpc::output_voltages(s, inv.v_dc_pu, xi[0], [xi[1], xi[2], xi[3]]);
            anpc::inverter_euler_step(&mut xi, s, i_abc, self.ts_pu, inv.c_dc_pu, inv.c_ph_pu);
            xm = self.disc.step(&xm, clarke(v));
            i_abc = inv_clarke([xm[0], xm[1]]);
            let r = &self.iref[l];
            let e = [r[0] - i_abc[0], r[1] - i_abc[1], r[2] - i_abc[2]];
            let w = self.bounds.worst_excess(e, xi[0], [xi[1], xi[2], xi[3]]);
            if l == 1 {
                ext.excess_k1 = w;
            }
            inside = inside && w <= 0.0;
            if !inside {
                break;
            }
            ext.l_star = l as u32;
            ext.v_n_end = xi[0];
        }
        ext
    }

    /// `L*`, terminal `v_n` and first-step excess of candidate `s` from `st`
    /// (public for tests and experiments).
    pub fn evaluate(&mut self, st: &CtrlState, s: [u8; 3]) -> Result<Extension, StateError> {
        st.check()?;
        self.prepare(st);
        Ok(self.extend(st, s, self.p.controller.horizon_max_steps))
    }
}

impl MpdccController for Reference {
    fn name(&self) -> &'static str {
        "reference"
    }

    fn decide(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        st.check()?;
        self.prepare(st);
        // Lazy evaluation (Algorithm 1, line 1).
        let lazy = self.extend(st, st.s_prev, 1);
        if lazy.excess_k1 <= 0.0 {
            return Ok(Decision {
                s: st.s_prev,
                kind: DecisionKind::Kept,
                horizon_steps: 0,
                candidates: 0,
            });
        }
        let cands = candidates(st.s_prev);
        let h = self.p.controller.horizon_max_steps;
        let lambda = self.p.controller.lambda_n;
        let mut best: Option<([u8; 3], f64, u32)> = None;
        let mut best_dl: Option<([u8; 3], f64)> = None;
        for &s in cands.iter() {
            let e = self.extend(st, s, h);
            if e.l_star > 0 {
                let j = anpc::switch_transitions(st.s_prev, s) as f64 / e.l_star as f64
                    + lambda * e.v_n_end * e.v_n_end;
                if best.is_none_or(|b| j < b.1) {
                    best = Some((s, j, e.l_star));
                }
            } else if best.is_none() && best_dl.is_none_or(|b| e.excess_k1 < b.1) {
                // J_dl is only needed while no feasible candidate is known
                // (the paper's "so far" shortcut, Sec. V-B).
                best_dl = Some((s, e.excess_k1));
            }
        }
        let n = cands.len() as u32;
        Ok(match (best, best_dl) {
            (Some((s, _, l)), _) => Decision {
                s,
                kind: DecisionKind::Optimal,
                horizon_steps: l,
                candidates: n,
            },
            (None, Some((s, _))) => Decision {
                s,
                kind: DecisionKind::Deadlock,
                horizon_steps: 0,
                candidates: n,
            },
            // Unreachable: the candidate set always contains s_prev. Keep it.
            (None, None) => Decision {
                s: st.s_prev,
                kind: DecisionKind::Deadlock,
                horizon_steps: 0,
                candidates: n,
            },
        })
    }
}
