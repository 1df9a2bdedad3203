//! Surface PMSM + ideal 2-level inverter, integrated exactly.
//!
//! Model (stator alpha-beta frame, amplitude-invariant, complex notation
//! `i = i_alpha + j i_beta`):
//! `L di/dt = u - R i - e`, back-EMF `e = j omega_e psi e^{j theta_e}`,
//! torque `T = 1.5 p psi i_q`. For `L_d = L_q` this is linear time-invariant in
//! alpha-beta apart from the rotating back-EMF, so over an interval `h` with a
//! constant stator voltage `u` (zero-order hold in the stator frame) and a
//! constant speed it has the closed form
//! `i(h) = E i0 + (1-E)/R u - (psi/L) j omega e^{j theta0} (e^{j omega h} - E)/(a + j omega)`,
//! `a = R/L`, `E = e^{-a h}` (the matrix exponential of eq. (2), evaluated
//! analytically; no Euler step anywhere).
//!
//! A control period is split at every event: gate edges of centre-aligned PWM
//! inside the period, dead-time-delayed leg transitions and ADC sample instants.
//! Between events the leg potentials are constant, so the closed form is exact.
//!
//! Dead time: when a gate command changes, the outgoing switch turns off at
//! once and the incoming one after `dead_time_s`; meanwhile the phase current
//! flows through a diode: leg x is at 0 if `i_x > 0` (lower diode) and at
//! `U_dc` if `i_x < 0` (upper diode). So a 0->1 edge is delayed when `i_x > 0`
//! and a 1->0 edge when `i_x < 0`; the sign is taken at the gate edge
//! (a zero crossing inside the dead time is neglected, and `i_x = 0` counts as
//! not delaying). A gate edge that arrives before a pending delayed transition
//! completes cancels it (the pulse was shorter than the dead time).
//!
//! Mechanics: [`MechanicalMode::ConstantSpeed`] keeps `omega_e` fixed (exact).
//! In [`MechanicalMode::Inertia`] `J d(omega_m)/dt = T - T_load - b omega_m`,
//! `omega_e = p omega_m`; the speed is held constant inside each segment
//! (segments are at most one ADC period, 3.9 us, against a mechanical time scale of
//! milliseconds) and updated after it with the mean of the torques at the
//! segment ends (trapezoid). The angle advances by `omega h` with the speed the
//! electrical solution used, so angle and currents stay consistent.

use super::frames::{clarke, inv_clarke, legs, park, state_from_legs, switch_state_alpha_beta};
use super::params::{check_finite, check_nonneg, MotorParams, ParamError};
use core::f64::consts::PI;

/// What the inverter does during one control period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Actuation {
    /// Switch state `4 Sa + 2 Sb + Sc` held for the whole period (gate edges,
    /// if any, at the period start).
    SwitchState(u8),
    /// Centre-aligned PWM duties of legs a, b, c (0..=1, clamped; NaN counts
    /// as 0). Leg x is on for `|t - T/2| < d_x T / 2` within the period, so the
    /// period starts and ends with the lower switches on (carrier valley).
    DutyAbc([f64; 3]),
}

/// How the rotor moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MechanicalMode {
    /// Electrical speed held constant (the rotor is driven by a dynamometer).
    ConstantSpeed,
    /// Rotor inertia and friction of [`MotorParams`] with a load torque, N m
    /// (opposing positive speed when positive).
    Inertia {
        /// Load torque, N m.
        load_torque_nm: f64,
    },
}

/// Instantaneous state of the plant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlantState {
    /// Simulated time, s.
    pub t_s: f64,
    /// Stator current alpha component, A.
    pub i_alpha_a: f64,
    /// Stator current beta component, A.
    pub i_beta_a: f64,
    /// Electrical rotor angle (alpha axis to d axis), rad, kept in `[0, 2 pi)`.
    pub theta_e_rad: f64,
    /// Electrical speed, rad/s.
    pub omega_e_rad_s: f64,
}

/// The PMSM + inverter plant.
#[derive(Debug, Clone)]
pub struct Plant {
    motor: MotorParams,
    dead_time_s: f64,
    mode: MechanicalMode,
    st: PlantState,
    /// Gate commands per leg (0/1).
    gate: [u8; 3],
    /// Actual leg potentials per leg (0/1 of U_dc); differ from `gate` during dead time.
    pole: [u8; 3],
    /// Time (relative to the current period start) of a pending dead-time
    /// delayed pole transition to `gate`, per leg.
    pending_s: [Option<f64>; 3],
    /// Gate transitions counted per leg since construction.
    transitions: [u64; 3],
}

impl Plant {
    /// A plant at rest current (i = 0), angle 0, time 0, gates 000.
    ///
    /// Errors: invalid motor parameters, `l_q_h != l_d_h` (the closed form
    /// needs a surface PMSM), negative/NaN dead time, non-finite speed or load.
    pub fn new(
        motor: &MotorParams,
        dead_time_s: f64,
        mode: MechanicalMode,
        omega_e_rad_s: f64,
    ) -> Result<Self, ParamError> {
        motor.validate()?;
        if libm::fabs(motor.l_q_h - motor.l_d_h) > 1e-9 * motor.l_d_h {
            return Err(ParamError {
                field: "l_q_h",
                reason: "the plant models a surface PMSM: l_q_h must equal l_d_h",
            });
        }
        check_nonneg("dead_time_s", dead_time_s)?;
        check_finite("omega_e_rad_s", omega_e_rad_s)?;
        if let MechanicalMode::Inertia { load_torque_nm } = mode {
            check_finite("load_torque_nm", load_torque_nm)?;
        }
        Ok(Self {
            motor: *motor,
            dead_time_s,
            mode,
            st: PlantState {
                t_s: 0.0,
                i_alpha_a: 0.0,
                i_beta_a: 0.0,
                theta_e_rad: 0.0,
                omega_e_rad_s,
            },
            gate: [0; 3],
            pole: [0; 3],
            pending_s: [None; 3],
            transitions: [0; 3],
        })
    }

    /// Motor parameters of the plant.
    pub fn motor(&self) -> &MotorParams {
        &self.motor
    }

    /// Current state.
    pub fn state(&self) -> &PlantState {
        &self.st
    }

    /// Overwrites currents, angle and speed (e.g. to start in steady state).
    /// Non-finite values are rejected and leave the plant unchanged.
    pub fn set_state(
        &mut self,
        i_alpha_a: f64,
        i_beta_a: f64,
        theta_e_rad: f64,
        omega_e_rad_s: f64,
    ) -> Result<(), ParamError> {
        check_finite("i_alpha_a", i_alpha_a)?;
        check_finite("i_beta_a", i_beta_a)?;
        check_finite("theta_e_rad", theta_e_rad)?;
        check_finite("omega_e_rad_s", omega_e_rad_s)?;
        self.st.i_alpha_a = i_alpha_a;
        self.st.i_beta_a = i_beta_a;
        self.st.theta_e_rad = wrap_2pi(theta_e_rad);
        self.st.omega_e_rad_s = omega_e_rad_s;
        Ok(())
    }

    /// Changes the load torque (Inertia mode only; ignored otherwise).
    pub fn set_load_torque_nm(&mut self, load_torque_nm: f64) -> Result<(), ParamError> {
        check_finite("load_torque_nm", load_torque_nm)?;
        if let MechanicalMode::Inertia { load_torque_nm: l } = &mut self.mode {
            *l = load_torque_nm;
        }
        Ok(())
    }

    /// Phase currents, A.
    pub fn i_abc_a(&self) -> [f64; 3] {
        inv_clarke(self.st.i_alpha_a, self.st.i_beta_a)
    }

    /// Rotor-frame currents `(i_d, i_q)`, A.
    pub fn i_dq_a(&self) -> (f64, f64) {
        park(self.st.i_alpha_a, self.st.i_beta_a, self.st.theta_e_rad)
    }

    /// Electromagnetic torque, N m (eq. (8)).
    pub fn torque_nm(&self) -> f64 {
        let (d, q) = self.i_dq_a();
        self.motor.torque_nm(d, q)
    }

    /// Gate commands as a switch state index.
    pub fn gate_state(&self) -> u8 {
        state_from_legs(self.gate)
    }

    /// Gate transitions per leg since construction.
    pub fn transitions(&self) -> [u64; 3] {
        self.transitions
    }

    /// Applies switch state `s` for `h_s` seconds with an ideal inverter (no
    /// dead time, edges at the start), exactly. Counts transitions.
    pub fn hold(&mut self, s: u8, h_s: f64) {
        let l = legs(s);
        for x in 0..3 {
            if self.gate[x] != l[x] {
                self.transitions[x] += 1;
            }
            self.gate[x] = l[x];
            self.pole[x] = l[x];
            self.pending_s[x] = None;
        }
        if h_s > 0.0 {
            self.advance(h_s);
        }
    }

    /// Applies an arbitrary constant stator voltage `(u_alpha, u_beta)`, V, for
    /// `h_s` seconds, exactly (a zero-order hold in the stator frame).
    /// Leaves the gate bookkeeping untouched.
    pub fn advance_voltage(&mut self, u_alpha_v: f64, u_beta_v: f64, h_s: f64) {
        if !(h_s > 0.0) || !u_alpha_v.is_finite() || !u_beta_v.is_finite() {
            return;
        }
        let t0 = self.torque_nm();
        let w = self.st.omega_e_rad_s;
        let (ia, ib) = zoh_alpha_beta(
            &self.motor,
            (self.st.i_alpha_a, self.st.i_beta_a),
            (u_alpha_v, u_beta_v),
            self.st.theta_e_rad,
            w,
            h_s,
        );
        self.st.i_alpha_a = ia;
        self.st.i_beta_a = ib;
        self.st.theta_e_rad = wrap_2pi(self.st.theta_e_rad + w * h_s);
        self.st.t_s += h_s;
        if let MechanicalMode::Inertia { load_torque_nm } = self.mode {
            let t1 = self.torque_nm();
            let p = self.motor.pole_pairs as f64;
            let w_m = w / p;
            let dw_m = (0.5 * (t0 + t1) - load_torque_nm - self.motor.friction_nm_s_per_rad * w_m)
                / self.motor.j_kg_m2
                * h_s;
            self.st.omega_e_rad_s = w + p * dw_m;
        }
    }

    /// Advances `h_s` with the present leg potentials.
    fn advance(&mut self, h_s: f64) {
        let (ua, ub) = switch_state_alpha_beta(state_from_legs(self.pole), self.motor.u_dc_v);
        self.advance_voltage(ua, ub, h_s);
    }

    /// Applies a new gate command `g` on leg `x` at relative time `t` (dead time logic).
    fn gate_edge(&mut self, x: usize, g: u8, t: f64) {
        if self.gate[x] == g {
            return;
        }
        self.gate[x] = g;
        self.transitions[x] += 1;
        self.pending_s[x] = None;
        if self.pole[x] == g {
            return; // a pending transition was cancelled: the pole never left g
        }
        let i_x = self.i_abc_a()[x];
        let delayed = self.dead_time_s > 0.0 && ((g == 1 && i_x > 0.0) || (g == 0 && i_x < 0.0));
        if delayed {
            self.pending_s[x] = Some(t + self.dead_time_s);
        } else {
            self.pole[x] = g;
        }
    }

    /// Simulates one control period of `period_s` seconds under `act`, calling
    /// `on_sample(self)` at the end of each of the `n_sub` equal sub-intervals
    /// (the ADC sample instants; the last one is the period end).
    ///
    /// Errors (plant unchanged): `period_s` not finite and > 0, `n_sub` not in
    /// 1..=4096.
    pub fn step(
        &mut self,
        act: &Actuation,
        period_s: f64,
        n_sub: usize,
        mut on_sample: impl FnMut(&Plant),
    ) -> Result<(), ParamError> {
        if !(period_s.is_finite() && period_s > 0.0) {
            return Err(ParamError {
                field: "period_s",
                reason: "must be finite and > 0",
            });
        }
        if n_sub == 0 || n_sub > 4096 {
            return Err(ParamError {
                field: "n_sub",
                reason: "must be in 1..=4096",
            });
        }
        // Gate edges of this period: (relative time, leg, new gate), time-sorted.
        let mut ev = [(0.0f64, 0usize, 0u8); 9];
        let mut n_ev = 0;
        match *act {
            Actuation::SwitchState(s) => {
                let l = legs(s);
                for (x, &g) in l.iter().enumerate() {
                    ev[n_ev] = (0.0, x, g);
                    n_ev += 1;
                }
            }
            Actuation::DutyAbc(d) => {
                for (x, &dx) in d.iter().enumerate() {
                    let dx = if dx.is_nan() { 0.0 } else { dx.clamp(0.0, 1.0) };
                    if dx >= 1.0 {
                        ev[n_ev] = (0.0, x, 1);
                        n_ev += 1;
                    } else {
                        ev[n_ev] = (0.0, x, 0);
                        n_ev += 1;
                        if dx > 0.0 {
                            ev[n_ev] = (0.5 * period_s * (1.0 - dx), x, 1);
                            ev[n_ev + 1] = (0.5 * period_s * (1.0 + dx), x, 0);
                            n_ev += 2;
                        }
                    }
                }
            }
        }
        ev[..n_ev].sort_unstable_by(|a, b| a.0.total_cmp(&b.0));

        let dt_sample = period_s / n_sub as f64;
        let mut t = 0.0;
        let mut k_ev = 0;
        let mut k_sample = 1;
        loop {
            let ts = if k_sample == n_sub {
                period_s
            } else {
                k_sample as f64 * dt_sample
            };
            let tg = if k_ev < n_ev {
                ev[k_ev].0
            } else {
                f64::INFINITY
            };
            let tp = self
                .pending_s
                .iter()
                .flatten()
                .fold(f64::INFINITY, |m, &v| m.min(v));
            let t_next = ts.min(tg).min(tp);
            if t_next > t {
                self.advance(t_next - t);
                t = t_next;
            }
            for x in 0..3 {
                if matches!(self.pending_s[x], Some(tp) if tp <= t) {
                    self.pending_s[x] = None;
                    self.pole[x] = self.gate[x];
                }
            }
            while k_ev < n_ev && ev[k_ev].0 <= t {
                let (_, x, g) = ev[k_ev];
                self.gate_edge(x, g, t);
                k_ev += 1;
            }
            if ts <= t {
                on_sample(self);
                if k_sample == n_sub {
                    break;
                }
                k_sample += 1;
            }
        }
        // Pending dead-time transitions carry over into the next period.
        for p in self.pending_s.iter_mut().flatten() {
            *p -= period_s;
        }
        Ok(())
    }
}

/// Exact solution of the alpha-beta current equation over `h_s` seconds with a
/// constant stator voltage `u_ab`, V, constant speed `omega_e_rad_s` and angle
/// `theta_e_rad` at the start (closed form in the module doc; uses `r_s_ohm`,
/// `l_d_h` and `psi_pm_wb` of `motor`, surface PMSM). Returns `(i_alpha, i_beta)`, A.
pub fn zoh_alpha_beta(
    motor: &MotorParams,
    i_ab: (f64, f64),
    u_ab: (f64, f64),
    theta_e_rad: f64,
    omega_e_rad_s: f64,
    h_s: f64,
) -> (f64, f64) {
    let (r, l, psi) = (motor.r_s_ohm, motor.l_d_h, motor.psi_pm_wb);
    let w = omega_e_rad_s;
    let a = r / l;
    let em1 = libm::expm1(-a * h_s); // E - 1, accurate for small h
    let e = 1.0 + em1;
    // Homogeneous + input parts.
    let mut ia = e * i_ab.0 - em1 / r * u_ab.0;
    let mut ib = e * i_ab.1 - em1 / r * u_ab.1;
    // Back-EMF part: -(psi/L) * c * n / (a + j w), c = j w e^{j th0},
    // n = e^{j w h} - E = (cos wh - 1) - (E - 1) + j sin wh.
    if w != 0.0 {
        let (s0, c0) = libm::sincos(theta_e_rad);
        let (sh, _) = libm::sincos(0.5 * w * h_s);
        let (swh, _) = libm::sincos(w * h_s);
        let (nr, ni) = (-2.0 * sh * sh - em1, swh);
        let (cr, ci) = (-w * s0, w * c0);
        let (pr, pi) = (cr * nr - ci * ni, cr * ni + ci * nr);
        let den = a * a + w * w;
        let (qr, qi) = ((pr * a + pi * w) / den, (pi * a - pr * w) / den);
        ia -= psi / l * qr;
        ib -= psi / l * qi;
    }
    (ia, ib)
}

/// Wraps an angle into `[0, 2 pi)`.
pub fn wrap_2pi(x: f64) -> f64 {
    let y = libm::fmod(x, 2.0 * PI);
    let y = if y < 0.0 { y + 2.0 * PI } else { y };
    if y >= 2.0 * PI {
        0.0
    } else {
        y
    }
}

/// Torque of a given `(i_alpha, i_beta)` at angle `theta` for `motor`, N m.
pub fn torque_alpha_beta_nm(motor: &MotorParams, i_ab: (f64, f64), theta_e_rad: f64) -> f64 {
    let (d, q) = park(i_ab.0, i_ab.1, theta_e_rad);
    motor.torque_nm(d, q)
}

/// Phase currents to `(alpha, beta)` (re-export for convenience).
pub fn i_alpha_beta(i_abc: [f64; 3]) -> (f64, f64) {
    clarke(i_abc)
}
