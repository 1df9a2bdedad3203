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
    candidates, candidates_reduced, rotate, Bounds, Controller, CtrlState, Decision, DecisionKind,
    StateError,
};
use super::machine::{self, Discrete};
use super::params::{DriveParams, ParamError};
use crate::frames::{clarke, inv_clarke};

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
pub struct MpdccRef {
    p: DriveParams,
    bounds: Bounds,
    ts_pu: f64,
    disc: Discrete,
    disc_omega_r: f64,
    /// Phase current references `i*_abc(k+l)`, l = 0..=N_bar.
    iref: [[f64; 3]; MAX_H + 1],
    /// Use [`candidates_reduced`] (an experiment) instead of all admissible positions.
    reduced: bool,
}

impl MpdccRef {
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
            reduced: false,
        })
    }

    /// The same controller enumerating the reduced 64-candidate set of
    /// [`candidates_reduced`] (the experiment on paper 001's Table II count).
    pub fn with_reduced_candidates(p: &DriveParams) -> Result<Self, ParamError> {
        let mut r = Self::new(p)?;
        r.reduced = true;
        Ok(r)
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
        self.iref[0] = inv_clarke(i[0], i[1]);
        for l in 1..=h {
            i = rotate(i, c, s);
            self.iref[l] = inv_clarke(i[0], i[1]);
        }
    }

    /// Extends candidate `s` from `st` for at most `max_l` steps (needs
    /// `prepare` for `st` first).
    fn extend(&self, st: &CtrlState, s: [u8; 3], max_l: u32) -> Extension {
        let mut xm = st.x_m;
        let mut xi = [st.v_n_pu, st.v_ph_pu[0], st.v_ph_pu[1], st.v_ph_pu[2]];
        let i0 = inv_clarke(xm[0], xm[1]);
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
        for l in 1..=max_l as usize {
            self.model_step(&mut xm, &mut xi, s);
            let i_abc = inv_clarke(xm[0], xm[1]);
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

    /// One step of the controller model with `s` held: exact machine step
    /// with `v_abc(s, v_n, v_ph)`, eq. (2) for the inverter states
    /// `[v_n, v_ph,abc]` (currents held over the step).
    fn model_step(&self, xm: &mut [f64; 4], xi: &mut [f64; 4], s: [u8; 3]) {
        let inv = &self.p.inverter;
        let i_abc = inv_clarke(xm[0], xm[1]);
        let v = anpc::output_voltages(s, inv.v_dc_pu, xi[0], [xi[1], xi[2], xi[3]]);
        anpc::inverter_euler_step(xi, s, i_abc, self.ts_pu, inv.c_dc_pu, inv.c_ph_pu);
        *xm = self.disc.step(xm, clarke(v).into());
    }

    // --- switching-horizon hook (used by `super::horizon_ref`) ---

    /// The controller model's state `l` steps after `st` with `s` held:
    /// machine and inverter states from [`Self::model_step`], the current
    /// reference rotated by `omega_s l T_s`, `s_prev = s` (the start of the
    /// next switching event of a longer horizon).
    pub fn predict(&mut self, st: &CtrlState, s: [u8; 3], l: u32) -> Result<CtrlState, StateError> {
        st.check()?;
        self.prepare(st);
        let mut xm = st.x_m;
        let mut xi = [st.v_n_pu, st.v_ph_pu[0], st.v_ph_pu[1], st.v_ph_pu[2]];
        for _ in 0..l {
            self.model_step(&mut xm, &mut xi, s);
        }
        let th = st.omega_s_pu * self.ts_pu * l as f64;
        Ok(CtrlState {
            x_m: xm,
            v_n_pu: xi[0],
            v_ph_pu: [xi[1], xi[2], xi[3]],
            i_ref_ab_pu: rotate(st.i_ref_ab_pu, libm::cos(th), libm::sin(th)),
            s_prev: s,
            ..*st
        })
    }

    // --- end of switching-horizon hook ---

    /// Cost of eqs. (10)-(12) of moving from `s_prev` to `s` with extension
    /// `e`: `f_s / L* + lambda_n v_n(k+L*)^2` (transitions per step), `+inf`
    /// for `L* = 0`.
    pub fn cost(&self, s_prev: [u8; 3], s: [u8; 3], e: &Extension) -> f64 {
        if e.l_star == 0 {
            return f64::INFINITY;
        }
        anpc::switch_transitions(s_prev, s) as f64 / e.l_star as f64
            + self.p.controller.lambda_n * e.v_n_end * e.v_n_end
    }

    /// `L*`, terminal `v_n` and first-step excess of candidate `s` from `st`
    /// (public for tests and experiments).
    pub fn evaluate(&mut self, st: &CtrlState, s: [u8; 3]) -> Result<Extension, StateError> {
        st.check()?;
        self.prepare(st);
        Ok(self.extend(st, s, self.p.controller.horizon_max_steps))
    }
}

impl Controller for MpdccRef {
    fn name(&self) -> &'static str {
        if self.reduced {
            "reference (64 candidates)"
        } else {
            "reference"
        }
    }

    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
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
        let (full, red);
        let cands: &[[u8; 3]] = if self.reduced {
            let i_abc = inv_clarke(st.x_m[0], st.x_m[1]);
            red = candidates_reduced(st.s_prev, i_abc, st.v_ph_pu, self.bounds.v_ph_ref);
            &red
        } else {
            full = candidates(st.s_prev);
            &full
        };
        let h = self.p.controller.horizon_max_steps;
        let mut best: Option<([u8; 3], f64, u32)> = None;
        let mut best_dl: Option<([u8; 3], f64)> = None;
        for &s in cands.iter() {
            let e = self.extend(st, s, h);
            if e.l_star > 0 {
                let j = self.cost(st.s_prev, s, &e);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mpdcc::controller::MAX_CANDIDATES;
    use crate::mpdcc::plant::{Plant, PlantState};

    fn state(p: &DriveParams, x_m: [f64; 4], s_prev: [u8; 3]) -> CtrlState {
        CtrlState {
            x_m,
            v_n_pu: 0.0,
            v_ph_pu: [p.inverter.v_ph_ref_pu(); 3],
            omega_r_pu: p.operating_point.omega_r_pu,
            omega_s_pu: p.operating_point.omega_s_pu,
            i_ref_ab_pu: [x_m[0], x_m[1]],
            s_prev,
        }
    }

    /// Eq. (15) evaluated independently: one step of the exact coupled plant
    /// (a different integrator from the reference's model), then the worst
    /// bound excess at k+1.
    fn j_dl_by_plant(p: &DriveParams, st: &CtrlState, s: [u8; 3]) -> f64 {
        let mut plant = Plant::new(p).unwrap();
        let z = PlantState {
            x_m: st.x_m,
            v_n_pu: st.v_n_pu,
            v_ph_pu: st.v_ph_pu,
        };
        let y = plant.step(&z, s);
        let th = st.omega_s_pu * p.controller.ts_pu(&p.machine);
        let [ra, rb] = rotate(st.i_ref_ab_pu, libm::cos(th), libm::sin(th));
        let r = inv_clarke(ra, rb);
        let i = inv_clarke(y.x_m[0], y.x_m[1]);
        let b = Bounds::new(&p.controller, &p.inverter);
        b.worst_excess([r[0] - i[0], r[1] - i[1], r[2] - i[2]], y.v_n_pu, y.v_ph_pu)
    }

    /// A constructed deadlock: the current is on its reference except a
    /// alpha-axis error just inside the bound (phase a at `-(delta_i - 1e-3)`),
    /// and `s(k-1) = [7, 0, 0]` drives `i_a` up at ~0.03 pu per step. Every
    /// admissible candidate can lower the phase-a voltage by at most one level,
    /// which still leaves a rising `i_a`: all `L* = 0`. Eqs. (15)-(16) must pick
    /// the candidate with the smallest worst excess at k+1 (checked against an
    /// independent brute force over the plant), and that is the one stepping
    /// every phase one level towards zero (a: +1, b and c: -1).
    #[test]
    fn constructed_deadlock_is_resolved_by_eq_15_16() {
        let p = DriveParams::default();
        let mut c = MpdccRef::new(&p).unwrap();
        // Reference at angle 90 deg (i*_a = 0): back-EMF's alpha part is small.
        let i_ref = [0.0, 1.0];
        let psi = machine::steady_state_flux(&p.machine, i_ref, 1.0, p.operating_point.omega_r_pu);
        let err = p.controller.delta_i_pu - 1e-3;
        let mut st = state(&p, [i_ref[0] + err, i_ref[1], psi[0], psi[1]], [7, 0, 0]);
        st.i_ref_ab_pu = i_ref;
        // Every candidate is infeasible at k+1 (independent check).
        let cands = candidates(st.s_prev);
        let excess: heapless::Vec<f64, MAX_CANDIDATES> =
            cands.iter().map(|&s| j_dl_by_plant(&p, &st, s)).collect();
        assert!(
            excess.iter().all(|&e| e > 0.0),
            "not a deadlock: {excess:?}"
        );
        let d = c.step(&st).unwrap();
        assert_eq!(d.kind, DecisionKind::Deadlock);
        let best = excess.iter().cloned().fold(f64::INFINITY, f64::min);
        let chosen = cands.iter().position(|&s| s == d.s).unwrap();
        // 1e-5 pu: the plant lets v_ph vary within the step, the reference's
        // model (eq. 2) does not; near-equal candidates differ by ~1e-6 pu,
        // while one level changes the excess by ~0.015 pu.
        assert!(
            excess[chosen] - best < 1e-5,
            "chose {:?} with {} > min {}",
            d.s,
            excess[chosen],
            best
        );
        let (a, b, cc) = (d.s[0], d.s[1], d.s[2]);
        assert!(
            matches!(a, 5 | 6) && matches!(b, 1 | 2) && matches!(cc, 1 | 2),
            "{:?}",
            d.s
        );
        // And it beats keeping the previous position.
        assert!(excess[chosen] < j_dl_by_plant(&p, &st, st.s_prev));
    }

    /// An output already outside its bound at k (here `v_ph,a`) gives `L* = 0`
    /// for every candidate (eq. 24's `|a_j| > y_bnd`), so the reference falls
    /// back to eq. (16); the chosen position must discharge phase a's capacitor.
    #[test]
    fn output_outside_at_k_forces_deadlock_resolution_towards_bound() {
        let p = DriveParams::default();
        let mut c = MpdccRef::new(&p).unwrap();
        let i_ref = [1.0, 0.0]; // i_a = +1 pu
        let psi = machine::steady_state_flux(&p.machine, i_ref, 1.0, p.operating_point.omega_r_pu);
        let mut st = state(&p, [i_ref[0], i_ref[1], psi[0], psi[1]], [6, 3, 3]);
        st.v_ph_pu[0] += p.controller.v_ph_bound_pu + 0.01;
        let d = c.step(&st).unwrap();
        assert_eq!(d.kind, DecisionKind::Deadlock);
        // With i_a > 0 a discharging position has ph_current = -1 (s = 1 or 5).
        assert_eq!(anpc::TABLE[d.s[0] as usize].ph_current, -1, "{:?}", d.s);
    }

    /// Lazy evaluation: on the reference with a matching position the
    /// previous position is kept, and no candidate is evaluated.
    #[test]
    fn lazy_evaluation_keeps_previous_position() {
        let p = DriveParams::default();
        let mut c = MpdccRef::new(&p).unwrap();
        let i_ref = [0.0, 1.0];
        let psi = machine::steady_state_flux(&p.machine, i_ref, 1.0, p.operating_point.omega_r_pu);
        let st = state(&p, [i_ref[0], i_ref[1], psi[0], psi[1]], [4, 4, 4]);
        // One step with all phases at level 0 moves the current by far less
        // than delta_i = 0.12 pu: must be kept.
        let d = c.step(&st).unwrap();
        assert_eq!(d.kind, DecisionKind::Kept);
        assert_eq!(d.s, [4, 4, 4]);
        assert_eq!(d.candidates, 0);
    }

    /// `L*` of a candidate equals a step-by-step count with the plant (an
    /// independent integrator) to within one step, and the optimal decision's
    /// cost is minimal over all candidates (eq. 10).
    #[test]
    fn horizon_and_cost_are_consistent_with_brute_force() {
        let p = DriveParams::default();
        let mut c = MpdccRef::new(&p).unwrap();
        let i_ref = [0.3, 0.95];
        let psi = machine::steady_state_flux(&p.machine, i_ref, 1.0, p.operating_point.omega_r_pu);
        // Phase a current below its reference by nearly delta_i and falling
        // (phase a at level -1, b and c at +1): the lazy check must fail.
        let err = p.controller.delta_i_pu - 0.002;
        let mut st = state(&p, [i_ref[0] - err, i_ref[1], psi[0], psi[1]], [1, 6, 6]);
        st.i_ref_ab_pu = i_ref;
        let d = c.step(&st).unwrap();
        assert_eq!(d.kind, DecisionKind::Optimal);
        let lam = p.controller.lambda_n;
        let mut best = f64::INFINITY;
        for s in candidates(st.s_prev) {
            let e = c.evaluate(&st, s).unwrap();
            if e.l_star > 0 {
                let j = anpc::switch_transitions(st.s_prev, s) as f64 / e.l_star as f64
                    + lam * e.v_n_end * e.v_n_end;
                best = best.min(j);
            }
            // Brute-force L* with the plant.
            let mut plant = Plant::new(&p).unwrap();
            let mut z = PlantState {
                x_m: st.x_m,
                v_n_pu: st.v_n_pu,
                v_ph_pu: st.v_ph_pu,
            };
            let th = st.omega_s_pu * p.controller.ts_pu(&p.machine);
            let mut r = st.i_ref_ab_pu;
            let mut l = 0;
            while l < p.controller.horizon_max_steps {
                z = plant.step(&z, s);
                r = rotate(r, libm::cos(th), libm::sin(th));
                let ra = inv_clarke(r[0], r[1]);
                let i = inv_clarke(z.x_m[0], z.x_m[1]);
                let ex = c.bounds().worst_excess(
                    [ra[0] - i[0], ra[1] - i[1], ra[2] - i[2]],
                    z.v_n_pu,
                    z.v_ph_pu,
                );
                if ex > 0.0 {
                    break;
                }
                l += 1;
            }
            assert!(
                (l as i64 - e.l_star as i64).abs() <= 1,
                "{s:?}: plant {l} vs reference {}",
                e.l_star
            );
        }
        let e = c.evaluate(&st, d.s).unwrap();
        let j = anpc::switch_transitions(st.s_prev, d.s) as f64 / e.l_star as f64
            + lam * e.v_n_end * e.v_n_end;
        assert_eq!(j, best);
        assert_eq!(e.l_star, d.horizon_steps);
    }

    #[test]
    fn bad_input_is_rejected() {
        let p = DriveParams::default();
        let mut c = MpdccRef::new(&p).unwrap();
        let mut st = state(&p, [0.0; 4], [3, 3, 3]);
        st.v_n_pu = f64::NAN;
        assert!(c.step(&st).is_err());
        let mut bad = p;
        bad.controller.delta_i_pu = 0.0;
        assert!(MpdccRef::new(&bad).is_err());
    }
}
