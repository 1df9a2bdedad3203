//! MPDTC of paper 000, `f64` reference: one pure [`decide`] per control period.
//!
//! Timing (paper Fig. 3): at instant k the controller gets the measured
//! current `I[k]`; the switch state `S[k]` decided one period earlier is being
//! applied over [k, k+1]; the decision made now, `S[k+1]`, is applied over
//! [k+1, k+2]. Hence the delay compensation of eq. (10) and the prediction to
//! k+2 of eq. (11).
//!
//! Interpretations of the paper (each with its reason):
//! 1. Eq. (1) signs: the standard PMSM model `u_d = R i_d + L di_d/dt - w L i_q`,
//!    `u_q = R i_q + L di_q/dt + w L i_d + w psi`. The paper's eq. (6) `V` is
//!    used as printed (it is consistent with this model).
//! 2. `R = 1.5 R_phase`: not applied (see `params.rs`): amplitude-invariant
//!    Clarke/Park keeps per-phase R and L in the dq model.
//! 3. Voltage vectors (eq. 9): the paper scales them by `U_dc`; the
//!    amplitude-invariant transform of the phase-to-neutral voltages gives
//!    `2/3 U_dc`, which is what the plant sees, so we use `2/3 U_dc`.
//! 4. Park: `u_d = cos(th) u_a + sin(th) u_b`, `u_q = -sin(th) u_a + cos(th) u_b`
//!    (rotation by `-th`; the printed matrix of eq. 9 is the inverse rotation,
//!    which would turn the rotor the wrong way).
//! 5. Rotor angle: the voltage is constant in the stator frame during a period
//!    while the dq frame turns, so the dq voltage of a period is evaluated at
//!    the *middle* of that period: `th[k] + 0.5 w Ts` for `S[k]` (eq. 10) and
//!    `th[k] + 1.5 w Ts` for the candidates (eq. 11). The mean of `e^{-j th}`
//!    over the period differs from its mid value by `O((w Ts)^2)`.
//! 6. Discretisation: the paper's first-order `A = 1 - R Ts / L`, `B = Ts / L`
//!    (eq. 5) with the coupling terms in `V` (eq. 6) from the start-of-step
//!    currents, as printed (the error of this Euler step is what the observer
//!    is there to absorb).
//! 7. 8 states for 7 voltages: all 8 states are candidates; 000 and 111 give
//!    the same voltage and differ only in the switching weight, so the cost
//!    picks the zero state that needs fewer transitions.
//! 8. `w_s^p` = `2^(n p)`, `n` = number of legs that change between `S[k+1]`
//!    (the state applied before the candidate) and the candidate: Table 1 is
//!    exactly `2^n` ([`SWITCH_WEIGHT`], checked by a test). The transitions
//!    counted are those at the start of the candidate's period.
//! 9. `|I|` of the predicted current at k+2: [`CostNorm`]. Default: the
//!    *squared* Euclidean norm `i_d^2 + i_q^2` (proportional to copper
//!    loss; what an FPGA computes without a square root). With the plain norm
//!    `sqrt(i_d^2 + i_q^2)` the relative cost change of a d-current
//!    correction is half as large, the switching weight dominates it, and
//!    `|I_d|` drifts to 8-11 A at p = 0.1..0.2 (paper Table 4: 1.1-4.1 A);
//!    the squared norm reproduces the paper's magnitudes. Note the two are
//!    the same family: `2^(np) |I|^2` orders candidates like
//!    `2^(np/2) |I|`.
//! 10. Band logic (Fig. 4): candidates with `|T* - T_hat[k+2]| <= T_tol` are
//!     in the band; if any, the one with the least `J` wins; if none, the
//!     least `|T* - T_hat|` wins. Ties (e.g. 000 and 111, or `J = 0` at zero
//!     current where the weight cannot act): fewer transitions, then lowest
//!     state index. Same rules in the fixed model.
//! 11. Eq. (13) as printed is proportional; the text says it "accumulates the
//!     previous tracking error": we implement the accumulating integrator
//!     `x[k] = x[k-1] + K Ts (T*_origin[k-1] - T_meas[k])`, `T*[k] =
//!     T*_origin[k] + x[k]`. The error uses the *original* reference (with the
//!     modified one the integrator would chase itself) and the torque computed
//!     from the measured current at k (the torque that period k-1 produced).
//!     `|x|` is clamped (anti-windup). Option `int_conditional` (off by
//!     default) integrates only after decisions that had a candidate in the
//!     band; measured on Fig. 10 it *slows* the toggles (0.39 ms instead of
//!     0.17 ms): the integrator holds the band bias of the old sign through
//!     the transient and unwinds it afterwards.
//! 12. Observer (eqs. 14-16): see [`super::observer`]; `eps` (volts, per axis)
//!     is added to `V` in both prediction steps (10) and (11).
//! 13. Torque equation (8)/(11) uses its own flux `torque_psi_wb` (the
//!     calibrated torque constant `k_T = 1.5 p psi`), separate from the
//!     back-EMF flux of the voltage model: an error in the torque constant
//!     scales the produced torque and no observer on the electrical equations
//!     can see it; an error in the voltage model is what eqs. (13)-(16) fix.
//! 14. Measurement delay (abstract: "estimated by considering calculation and
//!     measurement delay"): the measured current is the mean of the last 4 ADC
//!     samples, i.e. the current `lambda = 0.375` periods before `t_k`. Under
//!     the constant voltage of `S[k-1]` the current is linear in time to first
//!     order, so the current at `t_k` is recovered by a fractional step of eq.
//!     (5): `I[k] = I_m + lambda ((A - 1) I_m + B (V[k-1] + eps[k-1]))`, with
//!     `V[k-1]` at the middle of [k-1, k]. Without it, every voltage change
//!     shows up as a 0.3 A model error that the observer chases.

use super::frames::{legs_switched, park, switch_state_alpha_beta};
use super::observer::{observer_is_stable, AxisGains, AxisObserver};
use super::params::{check_nonneg, check_pos, MotorParams, ParamError};

/// Table 1 of paper 000: original weight of the switching times, row `S[k]`,
/// column `S[k+1]`, states indexed `4 Sa + 2 Sb + Sc`.
pub const SWITCH_WEIGHT: [[u8; 8]; 8] = [
    [1, 2, 2, 4, 2, 4, 4, 8],
    [2, 1, 4, 2, 4, 2, 8, 4],
    [2, 4, 1, 2, 4, 8, 2, 4],
    [4, 2, 2, 1, 8, 4, 4, 2],
    [2, 4, 4, 8, 1, 2, 2, 4],
    [4, 2, 8, 4, 2, 1, 4, 2],
    [4, 8, 2, 4, 2, 4, 1, 2],
    [8, 4, 4, 2, 4, 2, 2, 1],
];

/// Number of legs that change between two switch states (0..=3), the `n`
/// of `w_s^p = 2^(n p)` ([`legs_switched`]).
pub fn transitions(from: u8, to: u8) -> u32 {
    legs_switched(from, to)
}

/// Stator-frame voltage of a switch state, per unit of `2/3 U_dc`:
/// `(u_alpha, u_beta)` = `(Sa - (Sb + Sc)/2, sqrt(3)/2 (Sb - Sc))`
/// (the plant's [`switch_state_alpha_beta`] at `U_dc = 3/2`).
pub fn state_vector_pu(s: u8) -> (f64, f64) {
    switch_state_alpha_beta(s, 1.5)
}

/// dq voltage of state `s` at rotor angle `th_rad`, V: the plant's stator
/// voltage ([`switch_state_alpha_beta`]) through [`park`].
pub fn state_voltage_dq(s: u8, th_rad: f64, u_dc_v: f64) -> (f64, f64) {
    let (a, b) = switch_state_alpha_beta(s, u_dc_v);
    park(a, b, th_rad)
}

/// The norm `|I|` of eq. (12) (interpretation 9).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum CostNorm {
    /// `i_d^2 + i_q^2` (default).
    Squared,
    /// `sqrt(i_d^2 + i_q^2)`.
    Euclidean,
}

/// Tuning of the MPDTC (paper values where the paper gives them).
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(default, deny_unknown_fields))]
pub struct MpdtcParams {
    /// Control period Ts, s (paper: 1/64 kHz).
    pub control_period_s: f64,
    /// Torque tolerance band `T_tol`, N m (paper: 0.08 for Figs. 9-11).
    pub t_tol_nm: f64,
    /// Switching weight exponent `p` of eq. (12) (paper: 0.1).
    pub p_weight: f64,
    /// The norm of eq. (12).
    pub cost_norm: CostNorm,
    /// Gain K of eq. (13), 1/s (accumulating integrator; not given in paper).
    pub k_int_per_s: f64,
    /// Clamp of the integrator output `|x|`, N m.
    pub int_limit_nm: f64,
    /// Integrate only after decisions that reached the band (interpretation 11).
    pub int_conditional: bool,
    /// Observer Kp of eq. (15), V/A.
    pub obs_kp_v_per_a: f64,
    /// Observer Ki of eq. (15), 1/s.
    pub obs_ki_per_s: f64,
    /// Clamp of the observer output `|eps|` and its integral, V.
    pub obs_limit_v: f64,
    /// Flux used in the torque equation (8)/(11), Wb; `None` = the model's
    /// `psi_pm_wb`. See interpretation 13.
    pub torque_psi_wb: Option<f64>,
    /// Age of the measured current at the control instant, control periods
    /// (interpretation 14; paper chain: mean of 4 samples at 256 kHz -> 0.375).
    pub meas_age_periods: f64,
}

impl Default for MpdtcParams {
    fn default() -> Self {
        Self {
            control_period_s: 1.0 / 64_000.0,
            t_tol_nm: 0.08,
            p_weight: 0.1,
            cost_norm: CostNorm::Squared,
            k_int_per_s: 2000.0,
            int_limit_nm: 0.2,
            int_conditional: false,
            obs_kp_v_per_a: 20.0,
            obs_ki_per_s: 4000.0,
            obs_limit_v: 24.0,
            torque_psi_wb: None,
            meas_age_periods: 0.375,
        }
    }
}

impl MpdtcParams {
    /// Checks ranges and the observer stability condition for `model`.
    pub fn validate(&self, model: &MotorParams) -> Result<(), ParamError> {
        model.validate()?;
        let (pos, nonneg) = (check_pos, check_nonneg);
        pos("control_period_s", self.control_period_s)?;
        nonneg("t_tol_nm", self.t_tol_nm)?;
        if !(self.p_weight.is_finite() && (0.0..=0.5).contains(&self.p_weight)) {
            return Err(ParamError {
                field: "p_weight",
                reason: "must be in [0, 0.5]",
            });
        }
        nonneg("k_int_per_s", self.k_int_per_s)?;
        if self.k_int_per_s * self.control_period_s >= 1.0 {
            return Err(ParamError {
                field: "k_int_per_s",
                reason: "K Ts must be < 1 (integrator step below one period's error)",
            });
        }
        nonneg("int_limit_nm", self.int_limit_nm)?;
        nonneg("obs_kp_v_per_a", self.obs_kp_v_per_a)?;
        nonneg("obs_ki_per_s", self.obs_ki_per_s)?;
        pos("obs_limit_v", self.obs_limit_v)?;
        if !(self.meas_age_periods.is_finite() && (0.0..=1.0).contains(&self.meas_age_periods)) {
            return Err(ParamError {
                field: "meas_age_periods",
                reason: "must be in [0, 1]",
            });
        }
        if let Some(psi) = self.torque_psi_wb {
            pos("torque_psi_wb", psi)?;
        }
        let ts = self.control_period_s;
        for l in [model.l_d_h, model.l_q_h] {
            let a = 1.0 - model.r_s_ohm * ts / l;
            if !(a > 0.0 && a < 1.0) {
                return Err(ParamError {
                    field: "control_period_s",
                    reason: "R Ts / L must be in (0, 1) for the first-order model",
                });
            }
            if !observer_is_stable(a, ts / l, self.obs_kp_v_per_a, self.obs_ki_per_s, ts) {
                return Err(ParamError {
                    field: "obs_kp_v_per_a",
                    reason: "observer unstable: roots of eq. (16) outside the unit circle",
                });
            }
        }
        Ok(())
    }
}

/// Controller model and tuning, validated; build with [`MpdtcConfig::new`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MpdtcConfig {
    /// The controller's motor model (may differ from the plant).
    pub model: MotorParams,
    /// Tuning.
    pub params: MpdtcParams,
    obs_d: AxisGains,
    obs_q: AxisGains,
}

impl MpdtcConfig {
    /// Validates and precomputes the observer gains.
    pub fn new(model: MotorParams, params: MpdtcParams) -> Result<Self, ParamError> {
        params.validate(&model)?;
        Ok(Self::with_checked(model, params))
    }

    /// The model's and observer's per-axis gains for checked `params`.
    fn with_checked(model: MotorParams, params: MpdtcParams) -> Self {
        let ts = params.control_period_s;
        let gains = |l: f64| AxisGains {
            a: 1.0 - model.r_s_ohm * ts / l,
            b_a_per_v: ts / l,
            kp_v_per_a: params.obs_kp_v_per_a,
            kint_v_per_a: params.obs_kp_v_per_a * params.obs_ki_per_s * ts,
            limit_v: params.obs_limit_v,
        };
        Self {
            model,
            params,
            obs_d: gains(model.l_d_h),
            obs_q: gains(model.l_q_h),
        }
    }

    /// The motor model alone at period `control_period_s` (no observer, no
    /// integrator): [`Self::predict_u`] for another controller's period.
    pub fn prediction_model(model: MotorParams, control_period_s: f64) -> Result<Self, ParamError> {
        model.validate()?;
        check_pos("control_period_s", control_period_s)?;
        let params = MpdtcParams {
            control_period_s,
            k_int_per_s: 0.0,
            obs_kp_v_per_a: 0.0,
            obs_ki_per_s: 0.0,
            ..MpdtcParams::default()
        };
        for l in [model.l_d_h, model.l_q_h] {
            let a = 1.0 - model.r_s_ohm * control_period_s / l;
            if !(a > 0.0 && a < 1.0) {
                return Err(ParamError {
                    field: "control_period_s",
                    reason: "R Ts / L must be in (0, 1) for the first-order model",
                });
            }
        }
        Ok(Self::with_checked(model, params))
    }

    /// Flux of the torque equation, Wb.
    pub fn torque_psi_wb(&self) -> f64 {
        self.params.torque_psi_wb.unwrap_or(self.model.psi_pm_wb)
    }

    /// Torque of eq. (8) with the controller's constants, N m.
    pub fn torque_nm(&self, i_d_a: f64, i_q_a: f64) -> f64 {
        let m = &self.model;
        1.5 * m.pole_pairs as f64
            * (self.torque_psi_wb() * i_q_a + (m.l_d_h - m.l_q_h) * i_d_a * i_q_a)
    }

    /// One step of eq. (5)/(10): `I[k+1] = A I[k] + B (V[k] + eps)` with `V`
    /// of eq. (6) for state `s` at angle `th_rad`. Returns `(i_d, i_q)`, A.
    pub fn predict(
        &self,
        i_dq: (f64, f64),
        s: u8,
        th_rad: f64,
        w_rad_s: f64,
        eps_v: (f64, f64),
    ) -> (f64, f64) {
        let u_dq = state_voltage_dq(s, th_rad, self.model.u_dc_v);
        self.predict_u(i_dq, u_dq, w_rad_s, eps_v)
    }

    /// [`Self::predict`] for any inverter voltage `u_dq` (V, in the rotor
    /// frame of the step's start): a switching state's, or the mean of a
    /// PWM period's duties. Returns `(i_d, i_q)`, A.
    pub fn predict_u(
        &self,
        i_dq: (f64, f64),
        u_dq: (f64, f64),
        w_rad_s: f64,
        eps_v: (f64, f64),
    ) -> (f64, f64) {
        let (vd, vq) = self.v_eq6_u(i_dq, u_dq, w_rad_s);
        (
            self.obs_d.a * i_dq.0 + self.obs_d.b_a_per_v * (vd + eps_v.0),
            self.obs_q.a * i_dq.1 + self.obs_q.b_a_per_v * (vq + eps_v.1),
        )
    }

    /// `V` of eq. (6), V: the inverter voltage plus the coupling and back-EMF
    /// terms, computed from the currents `i_dq` at the start of the step.
    pub fn v_eq6(&self, i_dq: (f64, f64), s: u8, th_rad: f64, w_rad_s: f64) -> (f64, f64) {
        let u_dq = state_voltage_dq(s, th_rad, self.model.u_dc_v);
        self.v_eq6_u(i_dq, u_dq, w_rad_s)
    }

    /// [`Self::v_eq6`] for any inverter voltage `u_dq`, V.
    fn v_eq6_u(&self, i_dq: (f64, f64), (ud, uq): (f64, f64), w_rad_s: f64) -> (f64, f64) {
        let m = &self.model;
        (
            ud + w_rad_s * m.l_q_h * i_dq.1,
            uq - w_rad_s * m.l_d_h * i_dq.0 - m.psi_pm_wb * w_rad_s,
        )
    }
}

/// What the controller remembers between periods.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MpdtcState {
    /// State `S[k]` being applied over [k, k+1] (decided one period ago).
    pub s_applied: u8,
    /// State `S[k-1]` applied over [k-1, k] (for the measurement age).
    pub s_prev: u8,
    /// Observer output of the previous period `eps[k-1]` (d, q), V.
    pub eps_prev_v: (f64, f64),
    /// Integrator output `x[k-1]` of eq. (13), N m.
    pub int_nm: f64,
    /// The previous decision had a candidate in the band (integrator enable).
    pub band_reached: bool,
    /// Original reference of the previous period `T*_origin[k-1]`, N m.
    pub t_ref_prev_nm: f64,
    /// Observers (d, q).
    pub obs_d: AxisObserver,
    pub obs_q: AxisObserver,
}

/// Measurements and reference at instant k.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MpdtcInputs {
    /// Measured d current at k, A.
    pub i_d_a: f64,
    /// Measured q current at k, A.
    pub i_q_a: f64,
    /// Electrical rotor angle at k, rad.
    pub theta_e_rad: f64,
    /// Electrical speed, rad/s (held constant over the horizon, paper).
    pub omega_e_rad_s: f64,
    /// Torque reference `T*_origin[k]`, N m.
    pub t_ref_nm: f64,
}

/// Per-candidate prediction (for diagnostics and tests).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Candidate {
    /// Predicted `(i_d, i_q)` at k+2, A.
    pub i_dq_k2_a: (f64, f64),
    /// Predicted torque at k+2, N m.
    pub torque_k2_nm: f64,
    /// `|T* - T_hat[k+2]|`, N m.
    pub abs_err_nm: f64,
    /// Inside the tolerance band.
    pub in_band: bool,
    /// Cost `J = 2^(n p) |I|`: A^2 with the default squared norm, A with
    /// the Euclidean one.
    pub cost: f64,
}

/// Result of one period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MpdtcOutputs {
    /// `S[k+1]`, applied over [k+1, k+2]; bits `SaSbSc`.
    pub s_next: u8,
    /// An input was not finite: the period was skipped (zero vector, state
    /// kept apart from the switch-state history).
    pub input_fault: bool,
    /// Modified reference `T*[k]` of eq. (13), N m.
    pub t_ref_mod_nm: f64,
    /// Observer outputs `eps[k]` (d, q), V.
    pub eps_v: (f64, f64),
    /// Delay-compensated prediction `I_hat[k+1]` (eq. 10), A.
    pub i_dq_k1_a: (f64, f64),
    /// All 8 candidates.
    pub candidates: [Candidate; 8],
    /// State for the next period.
    pub next: MpdtcState,
}

/// Cost of eq. (12): `J = 2^(n p) |I|` with the chosen norm.
pub fn cost(n_transitions: u32, p: f64, norm: CostNorm, i_dq: (f64, f64)) -> f64 {
    let sq = i_dq.0 * i_dq.0 + i_dq.1 * i_dq.1;
    let m = match norm {
        CostNorm::Squared => sq,
        CostNorm::Euclidean => libm::sqrt(sq),
    };
    libm::exp2(n_transitions as f64 * p) * m
}

/// Band logic (interpretation 10) over candidates `(abs_err, in_band, cost)`
/// with the switching counts `n[s]`. Returns the winning index.
pub fn select(c: &[Candidate; 8], n: &[u32; 8]) -> u8 {
    let mut best = 0usize;
    for s in 1..8 {
        let (b, x) = (&c[best], &c[s]);
        let better = match (x.in_band, b.in_band) {
            (true, false) => true,
            (false, true) => false,
            (true, true) => x.cost < b.cost || (x.cost == b.cost && n[s] < n[best]),
            (false, false) => {
                x.abs_err_nm < b.abs_err_nm || (x.abs_err_nm == b.abs_err_nm && n[s] < n[best])
            }
        };
        if better {
            best = s;
        }
    }
    best as u8
}

/// One control period of the reference MPDTC. Pure: same inputs, same result.
pub fn decide(state: &MpdtcState, inp: &MpdtcInputs, cfg: &MpdtcConfig) -> MpdtcOutputs {
    let finite = [
        inp.i_d_a,
        inp.i_q_a,
        inp.theta_e_rad,
        inp.omega_e_rad_s,
        inp.t_ref_nm,
    ];
    if !finite.iter().all(|x| x.is_finite()) {
        // Bad measurement or command: apply the zero vector reachable with
        // the fewest transitions and leave integrator and observer untouched.
        let s_next = if transitions(state.s_applied, 0) <= transitions(state.s_applied, 7) {
            0
        } else {
            7
        };
        return MpdtcOutputs {
            s_next,
            input_fault: true,
            t_ref_mod_nm: 0.0,
            eps_v: state.eps_prev_v,
            i_dq_k1_a: (0.0, 0.0),
            candidates: [Candidate::default(); 8],
            next: MpdtcState {
                s_applied: s_next,
                s_prev: state.s_applied,
                ..*state
            },
        };
    }
    let p = &cfg.params;
    let ts = p.control_period_s;
    let w = inp.omega_e_rad_s;
    let im = (inp.i_d_a, inp.i_q_a);
    // Interpretation 14: current at t_k from the averaged measurement.
    let lam = p.meas_age_periods;
    let i_meas = if lam > 0.0 {
        let th0 = inp.theta_e_rad - 0.5 * w * ts;
        let full = cfg.predict(im, state.s_prev, th0, w, state.eps_prev_v);
        (im.0 + lam * (full.0 - im.0), im.1 + lam * (full.1 - im.1))
    } else {
        im
    };

    // Eq. (13), accumulating (interpretation 11).
    let t_meas = cfg.torque_nm(i_meas.0, i_meas.1);
    let int_nm = if state.band_reached || !p.int_conditional {
        (state.int_nm + p.k_int_per_s * ts * (state.t_ref_prev_nm - t_meas))
            .clamp(-p.int_limit_nm, p.int_limit_nm)
    } else {
        state.int_nm
    };
    let t_ref = inp.t_ref_nm + int_nm;

    // Observer (14)-(16), fed with V[k] of the applied state.
    let th1 = inp.theta_e_rad + 0.5 * w * ts;
    let v1 = cfg.v_eq6(i_meas, state.s_applied, th1, w);
    let (eps_d, obs_d) = state.obs_d.step(&cfg.obs_d, i_meas.0, v1.0);
    let (eps_q, obs_q) = state.obs_q.step(&cfg.obs_q, i_meas.1, v1.1);
    let eps = (eps_d, eps_q);

    // Eq. (10): delay compensation.
    let i1 = cfg.predict(i_meas, state.s_applied, th1, w, eps);
    // Eq. (11): the 8 candidates for [k+1, k+2].
    let th2 = inp.theta_e_rad + 1.5 * w * ts;
    let mut cands = [Candidate::default(); 8];
    let mut n = [0u32; 8];
    for s in 0..8u8 {
        let i2 = cfg.predict(i1, s, th2, w, eps);
        let t2 = cfg.torque_nm(i2.0, i2.1);
        let err = libm::fabs(t_ref - t2);
        n[s as usize] = transitions(state.s_applied, s);
        cands[s as usize] = Candidate {
            i_dq_k2_a: i2,
            torque_k2_nm: t2,
            abs_err_nm: err,
            in_band: err <= p.t_tol_nm,
            cost: cost(n[s as usize], p.p_weight, p.cost_norm, i2),
        };
    }
    let s_next = select(&cands, &n);
    MpdtcOutputs {
        s_next,
        input_fault: false,
        t_ref_mod_nm: t_ref,
        eps_v: eps,
        i_dq_k1_a: i1,
        candidates: cands,
        next: MpdtcState {
            s_applied: s_next,
            s_prev: state.s_applied,
            eps_prev_v: eps,
            int_nm,
            band_reached: cands.iter().any(|c| c.in_band),
            t_ref_prev_nm: inp.t_ref_nm,
            obs_d,
            obs_q,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cfg() -> MpdtcConfig {
        MpdtcConfig::new(MotorParams::default(), MpdtcParams::default()).unwrap()
    }

    #[test]
    fn table1_is_two_to_the_transitions() {
        for from in 0..8u8 {
            for to in 0..8u8 {
                assert_eq!(
                    SWITCH_WEIGHT[from as usize][to as usize] as u32,
                    1 << transitions(from, to)
                );
            }
        }
        // Spot checks typed from the paper: 000->111 = 8, 011->100 = 8, 101->101 = 1.
        assert_eq!(SWITCH_WEIGHT[0][7], 8);
        assert_eq!(SWITCH_WEIGHT[3][4], 8);
        assert_eq!(SWITCH_WEIGHT[5][5], 1);
        assert_eq!(SWITCH_WEIGHT[6][1], 8);
    }

    #[test]
    fn voltage_vectors_match_eq9() {
        // 100 -> (1, 0), 110 -> (1/2, sqrt3/2), 010 -> (-1/2, sqrt3/2),
        // 011 -> (-1, 0), 001 -> (-1/2, -sqrt3/2), 101 -> (1/2, -sqrt3/2).
        let h = 3f64.sqrt() / 2.0;
        let want = [
            (0b100, 1.0, 0.0),
            (0b110, 0.5, h),
            (0b010, -0.5, h),
            (0b011, -1.0, 0.0),
            (0b001, -0.5, -h),
            (0b101, 0.5, -h),
            (0, 0.0, 0.0),
            (7, 0.0, 0.0),
        ];
        for (s, a, b) in want {
            let (x, y) = state_vector_pu(s);
            assert!((x - a).abs() < 1e-12 && (y - b).abs() < 1e-12, "{s:03b}");
        }
        // At th = 90 deg the d axis is on beta: 010 has u_d = 2/3 Udc sqrt3/2.
        let (ud, uq) = state_voltage_dq(0b010, core::f64::consts::FRAC_PI_2, 48.0);
        assert!(
            (ud - 32.0 * h).abs() < 1e-9 && (uq - 16.0).abs() < 1e-9,
            "{ud} {uq}"
        );
    }

    #[test]
    fn cost_is_weight_times_current_norm() {
        let (e, q) = (CostNorm::Euclidean, CostNorm::Squared);
        // Hand: n = 2, p = 0.1 -> 2^0.2 = 1.148698; |(3,4)| = 5, squared 25.
        assert!((cost(2, 0.1, e, (3.0, 4.0)) - 5.0 * 1.148_698_354_997_035).abs() < 1e-12);
        assert!((cost(2, 0.1, q, (3.0, 4.0)) - 25.0 * 1.148_698_354_997_035).abs() < 1e-12);
        assert_eq!(cost(0, 0.3, e, (0.0, -2.0)), 2.0);
        assert_eq!(cost(0, 0.3, q, (0.0, -2.0)), 4.0);
        // p = 1 reproduces Table 1 exactly.
        for from in 0..8u8 {
            for to in 0..8u8 {
                let w = SWITCH_WEIGHT[from as usize][to as usize] as f64;
                assert!((cost(transitions(from, to), 1.0, e, (1.0, 0.0)) - w).abs() < 1e-12);
            }
        }
    }

    fn cand(err: f64, tol: f64, cost: f64) -> Candidate {
        Candidate {
            abs_err_nm: err,
            in_band: err <= tol,
            cost,
            ..Default::default()
        }
    }

    #[test]
    fn band_logic_on_constructed_cases() {
        let n = [0, 1, 1, 2, 1, 2, 2, 3];
        // Some candidates in band: least cost among them wins, even if another
        // (out of band) has lower cost or another in band has lower error.
        let tol = 0.08;
        let mut c = [cand(0.5, tol, 0.1); 8];
        c[2] = cand(0.07, tol, 3.0);
        c[5] = cand(0.01, tol, 4.0);
        c[6] = cand(0.08, tol, 2.5); // exactly on the edge counts as in band
        assert_eq!(select(&c, &n), 6);
        // None in band: least error wins regardless of cost.
        let mut c = [cand(0.5, tol, 0.1); 8];
        c[3] = cand(0.2, tol, 9.0);
        c[4] = cand(0.3, tol, 0.0);
        assert_eq!(select(&c, &n), 3);
        // None in band, equal error (000 and 111): fewer transitions wins.
        let mut c = [cand(0.5, tol, 1.0); 8];
        c[0] = cand(0.2, tol, 1.0);
        c[7] = cand(0.2, tol, 1.0);
        assert_eq!(select(&c, &[3, 2, 2, 1, 2, 1, 1, 0]), 7);
        assert_eq!(select(&c, &n), 0);
        // In band with equal cost: fewer transitions, then lowest index.
        let mut c = [cand(0.5, tol, 1.0); 8];
        c[4] = cand(0.0, tol, 1.0);
        c[1] = cand(0.05, tol, 1.0);
        c[3] = cand(0.05, tol, 1.0);
        assert_eq!(select(&c, &n), 1);
        assert_eq!(select(&c, &[3, 2, 2, 1, 2, 1, 1, 0]), 3);
    }

    /// Zero reference, zero current, zero speed: every state gives a small
    /// torque change (~0.07 Nm) inside T_tol = 0.08, and the zero vector
    /// reached without switching has the least cost: the controller keeps 000
    /// (or 111 when 111 is applied), i.e. it does not switch at rest.
    #[test]
    fn holds_zero_vector_at_rest() {
        let c = cfg();
        for s0 in [0u8, 7] {
            let st = MpdtcState {
                s_applied: s0,
                ..Default::default()
            };
            let out = decide(&st, &MpdtcInputs::default(), &c);
            assert_eq!(out.s_next, s0);
            assert!(out.candidates.iter().all(|x| x.in_band));
        }
        // T_tol = 0 with 011 applied: I_hat[k+1] = b u(011) = (-0.78 A, 0).
        // Torque error 0 (in band) only for candidates with u_q = 0 at th = 0:
        // 000, 111, 100, 011. Least |I[k+2]|: 100 (drives i_d back to ~0).
        let c0 = MpdtcConfig::new(
            MotorParams::default(),
            MpdtcParams {
                t_tol_nm: 0.0,
                ..Default::default()
            },
        )
        .unwrap();
        let out = decide(
            &MpdtcState {
                s_applied: 0b011,
                ..Default::default()
            },
            &MpdtcInputs::default(),
            &c0,
        );
        let in_band: Vec<usize> = (0..8).filter(|&s| out.candidates[s].in_band).collect();
        assert_eq!(in_band, [0, 3, 4, 7]);
        assert_eq!(out.s_next, 0b100);
    }

    /// A large positive torque demand at theta = 0 (d on phase a) picks the
    /// vector with the largest q component: 010 (+120 deg, u_q = +27.7 V) or
    /// 011/... by hand: q components of 2/3 Udc * (-sin(th) a + cos(th) b) at
    /// th = 0 are `32 * b`: 110 and 010 have b = +sqrt3/2. From 000, 010 and
    /// 100.. need 1 and 2 transitions: with the reference out of reach neither
    /// is in band, both have equal error -> 010 (fewer transitions).
    #[test]
    fn big_step_picks_max_q_voltage() {
        let c = cfg();
        let inp = MpdtcInputs {
            t_ref_nm: 0.4,
            ..Default::default()
        };
        let out = decide(&MpdtcState::default(), &inp, &c);
        assert_eq!(out.s_next, 0b010);
        // Hand-computed prediction: I1 = 0 (000 applied, no eps at start),
        // i_q2 = b * 32 * sqrt3/2 = (Ts/L) 27.71 V.
        let b = c.params.control_period_s / c.model.l_q_h;
        let iq2 = b * 32.0 * 3f64.sqrt() / 2.0;
        assert!((out.candidates[2].i_dq_k2_a.1 - iq2).abs() < 1e-9);
        let st = MpdtcState {
            s_applied: 0b100,
            ..Default::default()
        };
        assert_eq!(decide(&st, &inp, &c).s_next, 0b110);
    }

    #[test]
    fn non_finite_inputs_hold_a_zero_vector_and_keep_the_state() {
        let c = cfg();
        let st = MpdtcState {
            s_applied: 0b110,
            int_nm: 0.01,
            ..Default::default()
        };
        for bad in [f64::NAN, f64::INFINITY] {
            let inp = MpdtcInputs {
                i_q_a: bad,
                t_ref_nm: 0.4,
                ..Default::default()
            };
            let o = decide(&st, &inp, &c);
            assert!(o.input_fault);
            assert_eq!(o.s_next, 7, "111 is one transition from 110");
            assert_eq!(o.next.int_nm, 0.01);
            assert_eq!(o.next.obs_q, st.obs_q);
            let inp = MpdtcInputs {
                t_ref_nm: bad,
                ..Default::default()
            };
            assert!(decide(&st, &inp, &c).input_fault);
        }
        assert!(!decide(&st, &MpdtcInputs::default(), &c).input_fault);
    }

    #[test]
    fn validation_rejects_bad_params() {
        let m = MotorParams::default();
        let bad = [
            MpdtcParams {
                t_tol_nm: f64::NAN,
                ..Default::default()
            },
            MpdtcParams {
                p_weight: -0.1,
                ..Default::default()
            },
            MpdtcParams {
                control_period_s: 0.0,
                ..Default::default()
            },
            MpdtcParams {
                obs_kp_v_per_a: 200.0,
                ..Default::default()
            },
            MpdtcParams {
                obs_ki_per_s: 1e7,
                ..Default::default()
            },
            MpdtcParams {
                k_int_per_s: 1e6,
                ..Default::default()
            },
            MpdtcParams {
                torque_psi_wb: Some(0.0),
                ..Default::default()
            },
        ];
        for (i, p) in bad.iter().enumerate() {
            assert!(MpdtcConfig::new(m, *p).is_err(), "case {i}");
        }
        assert!(MpdtcConfig::new(
            MotorParams {
                r_s_ohm: f64::NAN,
                ..m
            },
            MpdtcParams::default()
        )
        .is_err());
    }
}
