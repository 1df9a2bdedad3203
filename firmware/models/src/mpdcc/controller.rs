//! The controller interface shared by the idealized `f64` MPDCC reference
//! ([`super::mpdcc_ref`]) and the 16-bit FPGA model, plus the parts of the
//! problem statement both must agree on (bounds, candidate set, `f_s`, the
//! meaning of `L*`), so that the closed loop and the mismatch experiment can
//! drive either one.
//!
//! # Shared semantics (paper 001, Secs. III-IV, as we read them)
//!
//! At step `k` the controller gets the measured state `x(k)` (machine and
//! inverter), the current reference `i*_ab(k)` and the previous position
//! `s(k-1)`, and returns `s(k)`, applied over `[k, k+1)`.
//! 1. **Lazy check (Alg. 1, line 1)**: predict `y(k+1)` with `s(k-1)`; if all
//!    seven outputs are inside their bounds, keep `s(k-1)`
//!    ([`DecisionKind::Kept`]). (Sec. III-C words it "at time step k"; we
//!    follow Algorithm 1, which checks `k+1`.)
//! 2. Otherwise enumerate [`candidates`] of `s(k-1)` in ascending order of the
//!    code `64 s_a + 8 s_b + s_c`; for each compute `L*(s)`, the largest
//!    `l <= N_bar` with all outputs inside their bounds at `k, k+1, ..., k+l`
//!    (`L* = 0` if an output is already outside at `k`: this is eq. (24)'s
//!    `|a_j| > y_bnd => l_j = 0`; `L*` is capped at `N_bar =
//!    horizon_max_steps`, the paper's `L_bar = N`).
//! 3. Cost (eqs. 10-12): `J = f_s(s(k-1), s) / L* + lambda_n v_n(k+L*)^2` for
//!    `L* > 0`, `+inf` otherwise. The smallest `J` wins; ties keep the first
//!    in enumeration order ([`DecisionKind::Optimal`]).
//! 4. **Deadlock** (all `L* = 0`, eqs. 15-16): pick the candidate minimizing
//!    `J_dl = max_j (|y*_j(k+1) - y_j(k+1)| - y_bnd,j)`, first on ties
//!    ([`DecisionKind::Deadlock`]).
//!
//! Outputs and bounds: `|i*_x - i_x| <= delta_i` (x = a, b, c),
//! `|v_n| <= v_n_bound`, `|v_ph,x - V_dc/4| <= v_ph_bound`.
//! The current reference rotates with `omega_s`: `i*(k+l) = R(omega_s l T_s) i*(k)`.
#![allow(clippy::needless_range_loop)] // index loops mirror the matrix equations

use super::anpc;
use super::params::{ControllerParams, InverterParams};

/// Everything a controller may read at step `k` (all pu).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CtrlState {
    /// Machine state `[i_s_alpha, i_s_beta, psi_r_alpha, psi_r_beta]`, pu.
    pub x_m: [f64; 4],
    /// Neutral point potential `v_n`, pu.
    pub v_n_pu: f64,
    /// Phase capacitor voltages `v_ph,abc`, pu.
    pub v_ph_pu: [f64; 3],
    /// Rotor electrical speed `omega_r`, pu.
    pub omega_r_pu: f64,
    /// Stator reference angular frequency `omega_s`, pu.
    pub omega_s_pu: f64,
    /// Stator current reference `i*_s,alpha_beta(k)`, pu.
    pub i_ref_ab_pu: [f64; 2],
    /// Previous switch position `s(k-1)`, each 0..=7.
    pub s_prev: [u8; 3],
}

/// Why a [`CtrlState`] was rejected.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StateError {
    /// A field is NaN or infinite.
    NonFinite(&'static str),
    /// A switch position is outside 0..=7.
    BadPosition,
    /// A speed is outside +-2 pu (where the discretization was not checked).
    SpeedOutOfRange,
}

impl core::fmt::Display for StateError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            StateError::NonFinite(n) => write!(f, "controller input `{n}` is not finite"),
            StateError::BadPosition => write!(f, "switch position outside 0..=7"),
            StateError::SpeedOutOfRange => write!(f, "speed outside +-2 pu"),
        }
    }
}

impl CtrlState {
    /// Rejects NaN/inf, positions > 7 and speeds beyond +-2 pu.
    pub fn check(&self) -> Result<(), StateError> {
        let fin = |n: &'static str, v: &[f64]| {
            if v.iter().all(|x| x.is_finite()) {
                Ok(())
            } else {
                Err(StateError::NonFinite(n))
            }
        };
        fin("x_m", &self.x_m)?;
        fin("v_n_pu", &[self.v_n_pu])?;
        fin("v_ph_pu", &self.v_ph_pu)?;
        fin("omega_r_pu", &[self.omega_r_pu])?;
        fin("omega_s_pu", &[self.omega_s_pu])?;
        fin("i_ref_ab_pu", &self.i_ref_ab_pu)?;
        if self.s_prev.iter().any(|&s| s > 7) {
            return Err(StateError::BadPosition);
        }
        if libm::fabs(self.omega_r_pu) > 2.0 || libm::fabs(self.omega_s_pu) > 2.0 {
            return Err(StateError::SpeedOutOfRange);
        }
        Ok(())
    }
}

/// How a decision was reached.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DecisionKind {
    /// Lazy evaluation: `s(k-1)` keeps all outputs inside at `k+1`.
    Kept,
    /// Minimum of eq. (10)-(12) over candidates with `L* > 0`.
    Optimal,
    /// No candidate had `L* > 0`; eq. (16) chose.
    Deadlock,
}

/// A controller's answer for one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Decision {
    /// `s(k)`, each 0..=7.
    pub s: [u8; 3],
    /// How it was chosen.
    pub kind: DecisionKind,
    /// `L*` of the chosen candidate, steps (0 for `Kept` and `Deadlock`).
    pub horizon_steps: u32,
    /// Candidates evaluated (0 for `Kept`).
    pub candidates: u32,
}

/// The interface both MPDCC implementations provide.
pub trait Controller {
    /// Short name for reports ("reference", "fpga").
    fn name(&self) -> &'static str;
    /// Decides `s(k)`; rejects bad input without changing internal state.
    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError>;
}

/// The seven output bounds `y_bnd` and references, pu.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Current bound half-width `delta_i`, pu.
    pub delta_i: f64,
    /// `|v_n| <= v_n`, pu.
    pub v_n: f64,
    /// `|v_ph - v_ph_ref| <= v_ph`, pu.
    pub v_ph: f64,
    /// Phase capacitor reference `V_dc / 4`, pu.
    pub v_ph_ref: f64,
}

impl Bounds {
    /// From the (validated) parameters.
    pub fn new(c: &ControllerParams, inv: &InverterParams) -> Self {
        Self {
            delta_i: c.delta_i_pu,
            v_n: c.v_n_bound_pu,
            v_ph: c.v_ph_bound_pu,
            v_ph_ref: inv.v_ph_ref_pu(),
        }
    }

    /// `max_j (|y*_j - y_j| - y_bnd,j)` over the seven outputs: `<= 0` means
    /// all inside (eq. 15's inner expression).
    #[inline]
    pub fn worst_excess(&self, i_err_abc: [f64; 3], v_n: f64, v_ph: [f64; 3]) -> f64 {
        let mut w = f64::NEG_INFINITY;
        for e in i_err_abc {
            w = w.max(libm::fabs(e) - self.delta_i);
        }
        w = w.max(libm::fabs(v_n) - self.v_n);
        for v in v_ph {
            w = w.max(libm::fabs(v - self.v_ph_ref) - self.v_ph);
        }
        w
    }
}

/// Maximum number of candidates (6 admissible positions per phase).
pub const MAX_CANDIDATES: usize = 216;

/// Admissible next positions of `s_prev` (one level up/down per phase,
/// [`anpc::admissible_phase`]), in ascending `64 s_a + 8 s_b + s_c` order.
/// `s_prev` itself is included (it may be feasible only from `k+2` on; it
/// then costs `+inf` in practice because the lazy check failed).
pub fn candidates(s_prev: [u8; 3]) -> heapless::Vec<[u8; 3], MAX_CANDIDATES> {
    let mut v = heapless::Vec::new();
    for a in 0..8u8 {
        if !anpc::admissible_phase(s_prev[0], a) {
            continue;
        }
        for b in 0..8u8 {
            if !anpc::admissible_phase(s_prev[1], b) {
                continue;
            }
            for c in 0..8u8 {
                if anpc::admissible_phase(s_prev[2], c) {
                    // Capacity 216 = 6^3 bounds the product of the per-phase counts.
                    let _ = v.push([a, b, c]);
                }
            }
        }
    }
    v
}

/// Candidates of the reduced set (at most 64).
pub const MAX_REDUCED_CANDIDATES: usize = 64;

/// Per-phase options of the reduced set: stay, the redundant partner at the
/// same level, one position one level up and one one level down. Where the
/// new level has two positions, the one with fewer device turn-ons is
/// taken; on a tie, the one whose phase-capacitor current `c(s) i` moves
/// `v_ph` towards `v_ph_ref`; then the lower index.
pub fn reduced_phase_options(s_prev: u8, i: f64, v_ph: f64, v_ph_ref: f64) -> heapless::Vec<u8, 4> {
    let s_prev = s_prev & 7;
    let lvl = anpc::TABLE[s_prev as usize].level;
    let mut v = heapless::Vec::new();
    let _ = v.push(s_prev);
    if let Some(p) = (0..8u8).find(|&t| t != s_prev && anpc::TABLE[t as usize].level == lvl) {
        let _ = v.push(p);
    }
    let want = if v_ph_ref >= v_ph { 1.0 } else { -1.0 };
    for target in [lvl + 1, lvl - 1] {
        let best = (0..8u8)
            .filter(|&t| anpc::TABLE[t as usize].level == target)
            .min_by(|&a, &b| {
                let ka = anpc::phase_transitions(s_prev, a);
                let kb = anpc::phase_transitions(s_prev, b);
                // Helps = the capacitor current moves v_ph the wanted way (1) or not (0).
                let ha = u8::from(anpc::TABLE[a as usize].ph_current as f64 * i * want > 0.0);
                let hb = u8::from(anpc::TABLE[b as usize].ph_current as f64 * i * want > 0.0);
                (ka, core::cmp::Reverse(ha), a).cmp(&(kb, core::cmp::Reverse(hb), b))
            });
        if let Some(t) = best {
            let _ = v.push(t);
        }
    }
    v.sort_unstable();
    v
}

/// A reduced candidate set of at most 4 positions per phase, 64 in all (see
/// [`reduced_phase_options`]), in ascending code order. Paper 001's Table II
/// (`47 + 2176/n`, 2176 = 64 x 34) suggests a set of this size, built
/// "taking into account ... the stator currents" (Sec. V); the text does
/// not define it, so this is our guess, used only for an experiment with
/// the reference (the default and the FPGA model use [`candidates`]).
pub fn candidates_reduced(
    s_prev: [u8; 3],
    i_abc: [f64; 3],
    v_ph: [f64; 3],
    v_ph_ref: f64,
) -> heapless::Vec<[u8; 3], MAX_REDUCED_CANDIDATES> {
    let o: [heapless::Vec<u8, 4>; 3] =
        core::array::from_fn(|x| reduced_phase_options(s_prev[x], i_abc[x], v_ph[x], v_ph_ref));
    let mut v = heapless::Vec::new();
    for &a in o[0].iter() {
        for &b in o[1].iter() {
            for &c in o[2].iter() {
                let _ = v.push([a, b, c]);
            }
        }
    }
    v
}

/// Rotation of the current reference by angle `theta`: `R(theta) i`.
#[inline]
pub fn rotate(i: [f64; 2], cos_t: f64, sin_t: f64) -> [f64; 2] {
    [cos_t * i[0] - sin_t * i[1], sin_t * i[0] + cos_t * i[1]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn candidate_sets_are_admissible_ordered_and_complete() {
        for code in 0..512u32 {
            let sp = [(code >> 6) as u8, ((code >> 3) & 7) as u8, (code & 7) as u8];
            let c = candidates(sp);
            let mut expect = 0;
            for t in 0..512u32 {
                let s = [(t >> 6) as u8, ((t >> 3) & 7) as u8, (t & 7) as u8];
                if anpc::admissible(sp, s) {
                    assert_eq!(c[expect], s);
                    expect += 1;
                }
            }
            assert_eq!(c.len(), expect);
        }
        assert_eq!(candidates([3, 4, 3]).len(), 216);
        assert_eq!(candidates([0, 7, 0]).len(), 27);
    }

    #[test]
    fn reduced_set_by_hand() {
        // From s = 4 (level 0, d1 = 1): partner 3; up: 5 and 6 both cost one
        // turn-on, i > 0 and v_ph below its reference -> the charging one (6);
        // down: 1 and 2 both cost 3 -> charging one (2).
        assert_eq!(
            reduced_phase_options(4, 1.0, 0.4, 0.48).as_slice(),
            &[2, 3, 4, 6]
        );
        // Same with v_ph above its reference -> the discharging ones (1, 5).
        assert_eq!(
            reduced_phase_options(4, 1.0, 0.5, 0.48).as_slice(),
            &[1, 3, 4, 5]
        );
        // From 7 (level +2): stay and one level down, no partner.
        assert_eq!(
            reduced_phase_options(7, -1.0, 0.5, 0.48).as_slice(),
            &[6, 7]
        );
        // From 5 (level +1): partner 6, up 7, down 4 (one turn-on) not 3 (three).
        assert_eq!(
            reduced_phase_options(5, 1.0, 0.5, 0.48).as_slice(),
            &[4, 5, 6, 7]
        );
        let all = candidates_reduced([4, 3, 5], [1.0, -0.5, -0.5], [0.48; 3], 0.4825);
        assert_eq!(all.len(), 64);
        assert!(all.iter().all(|&s| anpc::admissible([4, 3, 5], s)));
        assert!(all.windows(2).all(|w| w[0] < w[1]));
    }

    #[test]
    fn worst_excess_by_hand() {
        let b = Bounds {
            delta_i: 0.1,
            v_n: 0.05,
            v_ph: 0.05,
            v_ph_ref: 0.4825,
        };
        let w = b.worst_excess([0.05, -0.12, 0.0], 0.01, [0.4825, 0.50, 0.46]);
        assert!((w - 0.02).abs() < 1e-12);
        let w = b.worst_excess([0.0; 3], -0.09, [0.4825; 3]);
        assert!((w - 0.04).abs() < 1e-12);
    }

    #[test]
    fn bad_state_is_rejected() {
        let ok = CtrlState {
            x_m: [0.0; 4],
            v_n_pu: 0.0,
            v_ph_pu: [0.48; 3],
            omega_r_pu: 0.99,
            omega_s_pu: 1.0,
            i_ref_ab_pu: [1.0, 0.0],
            s_prev: [3, 4, 3],
        };
        assert!(ok.check().is_ok());
        let mut s = ok;
        s.x_m[2] = f64::NAN;
        assert_eq!(s.check(), Err(StateError::NonFinite("x_m")));
        let mut s = ok;
        s.s_prev[1] = 8;
        assert_eq!(s.check(), Err(StateError::BadPosition));
        let mut s = ok;
        s.omega_r_pu = 3.0;
        assert_eq!(s.check(), Err(StateError::SpeedOutOfRange));
    }
}
