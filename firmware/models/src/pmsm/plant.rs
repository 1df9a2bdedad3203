//! Surface PMSM + ideal 2-level inverter, integrated exactly.
//!
//! Model (stator alpha-beta frame, amplitude-invariant, complex notation
//! `i = i_alpha + j i_beta`):
//! `L di/dt = u - R i - e`, back-EMF `e = j omega_e psi e^{j theta_e}`,
//! torque `T = 1.5 p psi i_q`. In the rotor frame this is the standard
//! `u_d = R i_d + L di_d/dt - omega L_q i_q`,
//! `u_q = R i_q + L di_q/dt + omega (L_d i_d + psi)`, i.e. the paper's eq. (1)
//! with `psi_d = psi_PM`, `psi_q = 0` and its sign of the `psi_q` term read as
//! the standard one (it multiplies zero anyway). For `L_d = L_q` this is
//! linear time-invariant in alpha-beta apart from the rotating back-EMF, so
//! over an interval `h` with a
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
//! [`MechanicalMode::Joint`] is the same with the joint's own mechanics
//! ([`Mechanics`]: inertia, viscous and Coulomb friction, load, spring about
//! the mechanical angle 0, which the plant tracks unwrapped).

use super::frames::{inv_clarke, legs, park, state_from_legs, switch_state_alpha_beta};
use super::mechanics::Mechanics;
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
    /// The rotor on a joint with its own mechanics (not [`MotorParams`]').
    Joint(Mechanics),
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
    /// Mechanical angle since construction (not wrapped), rad.
    theta_m_rad: f64,
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
        check_mode(&mode)?;
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
            theta_m_rad: 0.0,
        })
    }

    /// How the rotor moves.
    pub fn mechanics(&self) -> &MechanicalMode {
        &self.mode
    }

    /// Changes the mechanics (state kept; errors leave it unchanged).
    pub fn set_mechanics(&mut self, mode: MechanicalMode) -> Result<(), ParamError> {
        check_mode(&mode)?;
        self.mode = mode;
        Ok(())
    }

    /// Changes the motor (currents, speed and mechanical angle kept; the
    /// electrical angle follows the mechanical one for the new pole pairs).
    /// Errors (as [`Self::new`]) leave the plant unchanged.
    pub fn set_motor(&mut self, motor: &MotorParams) -> Result<(), ParamError> {
        let p = Plant::new(motor, self.dead_time_s, self.mode, self.st.omega_e_rad_s)?;
        let w_m = self.st.omega_e_rad_s / self.motor.pole_pairs as f64;
        self.motor = p.motor;
        let pp = motor.pole_pairs as f64;
        self.st.omega_e_rad_s = w_m * pp;
        self.st.theta_e_rad = wrap_2pi(self.theta_m_rad * pp);
        Ok(())
    }

    /// Mechanical angle since construction (not wrapped), rad.
    pub fn theta_m_rad(&self) -> f64 {
        self.theta_m_rad
    }

    /// Advances `h_s` seconds with the stator open (no current flows): the
    /// rotor moves under its mechanics alone.
    pub fn advance_open(&mut self, h_s: f64) {
        if h_s.is_nan() || h_s <= 0.0 {
            return;
        }
        let w = self.st.omega_e_rad_s;
        self.st.i_alpha_a = 0.0;
        self.st.i_beta_a = 0.0;
        self.st.theta_e_rad = wrap_2pi(self.st.theta_e_rad + w * h_s);
        self.st.t_s += h_s;
        self.move_rotor(0.0, w, h_s);
    }

    /// Mechanical update of one segment that started at electrical speed
    /// `w` under the mean torque `t_nm`.
    fn move_rotor(&mut self, t_nm: f64, w: f64, h_s: f64) {
        let p = self.motor.pole_pairs as f64;
        let w_m = w / p;
        let theta0 = self.theta_m_rad;
        self.theta_m_rad += w_m * h_s;
        match self.mode {
            MechanicalMode::ConstantSpeed => {}
            MechanicalMode::Inertia { load_torque_nm } => {
                let dw_m = (t_nm - load_torque_nm - self.motor.friction_nm_s_per_rad * w_m)
                    / self.motor.j_kg_m2
                    * h_s;
                self.st.omega_e_rad_s = w + p * dw_m;
            }
            MechanicalMode::Joint(m) => {
                self.st.omega_e_rad_s = p * m.step(t_nm, w_m, theta0, h_s);
            }
        }
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
        match &mut self.mode {
            MechanicalMode::Inertia { load_torque_nm: l } => *l = load_torque_nm,
            MechanicalMode::Joint(m) => m.load_torque_nm = load_torque_nm,
            MechanicalMode::ConstantSpeed => {}
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
        for (x, &lx) in l.iter().enumerate() {
            if self.gate[x] != lx {
                self.transitions[x] += 1;
            }
            self.gate[x] = lx;
            self.pole[x] = lx;
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
        if h_s.is_nan() || h_s <= 0.0 || !u_alpha_v.is_finite() || !u_beta_v.is_finite() {
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
        let t1 = self.torque_nm();
        self.move_rotor(0.5 * (t0 + t1), w, h_s);
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
                        let (t_on, t_off) =
                            (0.5 * period_s * (1.0 - dx), 0.5 * period_s * (1.0 + dx));
                        // A pulse too short to resolve in f64 is no pulse (and
                        // equal times must not reorder on/off in the sort).
                        if t_on < t_off {
                            ev[n_ev] = (t_on, x, 1);
                            ev[n_ev + 1] = (t_off, x, 0);
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

/// Checks the mechanics' parameters.
fn check_mode(mode: &MechanicalMode) -> Result<(), ParamError> {
    match mode {
        MechanicalMode::ConstantSpeed => Ok(()),
        MechanicalMode::Inertia { load_torque_nm } => {
            check_finite("load_torque_nm", *load_torque_nm)
        }
        MechanicalMode::Joint(m) => m.validate(),
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
    let w = omega_e_rad_s;
    let em1 = libm::expm1(-motor.r_s_ohm / motor.l_d_h * h_s); // E - 1, accurate for small h
    let trig = if w != 0.0 {
        let (sh, _) = libm::sincos(0.5 * w * h_s);
        let (swh, _) = libm::sincos(w * h_s);
        Some(ZohTrig {
            sc0: libm::sincos(theta_e_rad),
            sin_half_wh: sh,
            sin_wh: swh,
        })
    } else {
        None
    };
    zoh_alpha_beta_with(motor, i_ab, u_ab, w, em1, trig)
}

/// The angle-dependent factors of [`zoh_alpha_beta`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZohTrig {
    /// `(sin, cos)` of the angle at the start.
    pub sc0: (f64, f64),
    /// `sin(w h / 2)`.
    pub sin_half_wh: f64,
    /// `sin(w h)`.
    pub sin_wh: f64,
}

/// [`zoh_alpha_beta`] with `em1 = expm1(-R h / L)` and the trigonometric
/// factors given (`None` when `omega_e_rad_s` is 0), for callers that reuse
/// them (the FOC computes them once per step).
pub fn zoh_alpha_beta_with(
    motor: &MotorParams,
    i_ab: (f64, f64),
    u_ab: (f64, f64),
    omega_e_rad_s: f64,
    em1: f64,
    trig: Option<ZohTrig>,
) -> (f64, f64) {
    let (r, l, psi) = (motor.r_s_ohm, motor.l_d_h, motor.psi_pm_wb);
    let w = omega_e_rad_s;
    let a = r / l;
    let e = 1.0 + em1;
    // Homogeneous + input parts.
    let mut ia = e * i_ab.0 - em1 / r * u_ab.0;
    let mut ib = e * i_ab.1 - em1 / r * u_ab.1;
    // Back-EMF part: -(psi/L) * c * n / (a + j w), c = j w e^{j th0},
    // n = e^{j w h} - E = (cos wh - 1) - (E - 1) + j sin wh.
    if let Some(ZohTrig {
        sc0: (s0, c0),
        sin_half_wh: sh,
        sin_wh: swh,
    }) = trig
    {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pmsm::frames::{inv_park, switch_state_alpha_beta};
    use std::vec::Vec;

    const R: f64 = 0.555;
    const L: f64 = 0.64e-3;
    const PSI: f64 = 0.009_287_9;

    fn plant(w: f64) -> Plant {
        Plant::new(
            &MotorParams::default(),
            0.0,
            MechanicalMode::ConstantSpeed,
            w,
        )
        .unwrap()
    }

    #[test]
    fn rejects_bad_parameters() {
        let m = MotorParams::default();
        let cs = MechanicalMode::ConstantSpeed;
        assert!(Plant::new(&MotorParams { l_q_h: 1e-3, ..m }, 0.0, cs, 0.0).is_err());
        assert!(Plant::new(
            &MotorParams {
                r_s_ohm: f64::NAN,
                ..m
            },
            0.0,
            cs,
            0.0
        )
        .is_err());
        assert!(Plant::new(&m, -1e-6, cs, 0.0).is_err());
        assert!(Plant::new(&m, 0.0, cs, f64::INFINITY).is_err());
        let bad_load = MechanicalMode::Inertia {
            load_torque_nm: f64::NAN,
        };
        assert!(Plant::new(&m, 0.0, bad_load, 0.0).is_err());
        let mut p = plant(0.0);
        assert!(p.step(&Actuation::SwitchState(4), 0.0, 4, |_| {}).is_err());
        assert!(p.step(&Actuation::SwitchState(4), 1e-5, 0, |_| {}).is_err());
        assert!(p.set_state(f64::NAN, 0.0, 0.0, 0.0).is_err());
        assert_eq!(p.state().t_s, 0.0);
    }

    /// Zero voltage at standstill: i(t) = i0 e^{-R t / L}, sampled every 3.9 us.
    #[test]
    fn zero_voltage_decay() {
        let mut p = plant(0.0);
        p.set_state(3.0, -1.0, 0.0, 0.0).unwrap();
        let mut n = 0;
        for _ in 0..200 {
            p.step(&Actuation::SwitchState(0b111), 15.625e-6, 4, |q| {
                n += 1;
                let t = q.state().t_s;
                let e = (-R * t / L).exp();
                assert!((q.state().i_alpha_a - 3.0 * e).abs() < 1e-12, "{t}");
                assert!((q.state().i_beta_a + e).abs() < 1e-12);
            })
            .unwrap();
        }
        assert_eq!(n, 800);
    }

    /// Constant voltage (state 100 = 32 V on alpha) at standstill:
    /// i(tau) = (1 - 1/e) u / R, and u / R in steady state.
    #[test]
    fn steady_state_at_constant_voltage() {
        let mut p = plant(0.0);
        let u = 2.0 / 3.0 * 48.0;
        p.hold(0b100, L / R);
        assert!((p.state().i_alpha_a - (1.0 - (-1.0f64).exp()) * u / R).abs() < 1e-10);
        p.hold(0b100, 40e-3);
        assert!((p.state().i_alpha_a - u / R).abs() < 1e-9);
        assert!(p.state().i_beta_a.abs() < 1e-12);
        assert_eq!(p.transitions(), [1, 0, 0]);
        // At speed with the zero vector the rotor-frame current is the
        // short-circuit current -j w psi / (R + j w L), constant in dq.
        let w = 500.0;
        let mut p = plant(w);
        p.hold(0b000, 40e-3);
        let den = R * R + w * w * L * L;
        let (id, iq) = p.i_dq_a();
        assert!((id + w * w * L * PSI / den).abs() < 1e-9, "{id}");
        assert!((iq + w * R * PSI / den).abs() < 1e-9, "{iq}");
        // Braking torque 1.5 p psi iq.
        assert!((p.torque_nm() - 1.5 * 7.0 * PSI * iq).abs() < 1e-12);
    }

    /// Independent solution: RK4 with a 5 ns step of the rotor-frame (dq)
    /// equations under the same piecewise-constant stator voltage.
    fn rk4_dq(segments: &[(f64, (f64, f64))], w: f64, mut x: [f64; 2], mut th: f64) -> [f64; 2] {
        let f = |x: [f64; 2], th: f64, u_ab: (f64, f64)| {
            let (ud, uq) = park(u_ab.0, u_ab.1, th);
            [
                (ud - R * x[0] + w * L * x[1]) / L,
                (uq - R * x[1] - w * L * x[0] - w * PSI) / L,
            ]
        };
        for &(dur, u) in segments {
            let n = (dur / 5e-9).ceil() as usize;
            let h = dur / n as f64;
            for _ in 0..n {
                let k1 = f(x, th, u);
                let x2 = [x[0] + 0.5 * h * k1[0], x[1] + 0.5 * h * k1[1]];
                let k2 = f(x2, th + 0.5 * h * w, u);
                let x3 = [x[0] + 0.5 * h * k2[0], x[1] + 0.5 * h * k2[1]];
                let k3 = f(x3, th + 0.5 * h * w, u);
                let x4 = [x[0] + h * k3[0], x[1] + h * k3[1]];
                let k4 = f(x4, th + h * w, u);
                for i in 0..2 {
                    x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
                }
                th += h * w;
            }
        }
        x
    }

    /// Centre-aligned PWM with edges inside the period at speed, against the
    /// hand-built sequence of switch states and an RK4 solution in dq.
    #[test]
    fn pwm_edges_inside_the_period_match_rk4() {
        let w = 800.0;
        let t = 62.5e-6;
        let mut p = plant(w);
        p.set_state(1.0, 2.0, 0.3, w).unwrap();
        let (i0d, i0q) = p.i_dq_a();
        p.step(&Actuation::DutyAbc([0.7, 0.4, 0.2]), t, 16, |_| {})
            .unwrap();
        // Leg on-intervals: a [0.15, 0.85] T, b [0.30, 0.70] T, c [0.40, 0.60] T.
        let seq = [
            (0.15, 0b000),
            (0.15, 0b100),
            (0.10, 0b110),
            (0.20, 0b111),
            (0.10, 0b110),
            (0.15, 0b100),
            (0.15, 0b000),
        ];
        let segs: Vec<(f64, (f64, f64))> = seq
            .iter()
            .map(|&(f, s)| (f * t, switch_state_alpha_beta(s, 48.0)))
            .collect();
        let x = rk4_dq(&segs, w, [i0d, i0q], 0.3);
        let (id, iq) = p.i_dq_a();
        assert!(
            (id - x[0]).abs() < 1e-9 && (iq - x[1]).abs() < 1e-9,
            "{id} {iq} vs {x:?}"
        );
        // Six gate edges (one on, one off per leg).
        assert_eq!(p.transitions(), [2, 2, 2]);
        assert!((p.state().t_s - t).abs() < 1e-18);
        // Degenerate duties: a vanishing pulse is no pulse, 1 is a full period,
        // out-of-range and NaN duties clamp.
        let mut q = plant(w);
        q.step(&Actuation::DutyAbc([1e-300, f64::NAN, -3.0]), t, 4, |_| {})
            .unwrap();
        assert_eq!((q.transitions(), q.gate_state()), ([0, 0, 0], 0));
        q.step(&Actuation::DutyAbc([1.0, 2.0, 0.0]), t, 4, |_| {})
            .unwrap();
        assert_eq!((q.transitions(), q.gate_state()), ([1, 1, 0], 0b110));
    }

    /// Energy balance over an arbitrary switching sequence at speed:
    /// input = copper loss + change of magnetic energy + mechanical work.
    #[test]
    fn energy_balance() {
        let w = 600.0;
        let mut p = plant(w);
        let (mut e_in, mut e_cu, mut e_mech) = (0.0, 0.0, 0.0);
        let w_mag = |p: &Plant| {
            let s = p.state();
            0.75 * L * (s.i_alpha_a * s.i_alpha_a + s.i_beta_a * s.i_beta_a)
        };
        let w0 = w_mag(&p);
        let states = [4u8, 6, 7, 2, 3, 0, 1, 5, 4, 4, 6, 2];
        for (k, &s) in states.iter().cycle().take(300).enumerate() {
            let dur = (3.0 + (k % 7) as f64) * 1e-6;
            let (ua, ub) = switch_state_alpha_beta(s, 48.0);
            // Simpson over 64 sub-steps of the exact solution.
            let n = 64;
            let h = dur / n as f64;
            let pw = |p: &Plant| {
                let st = p.state();
                let (_, iq) = p.i_dq_a();
                let i2 = st.i_alpha_a * st.i_alpha_a + st.i_beta_a * st.i_beta_a;
                (
                    1.5 * (ua * st.i_alpha_a + ub * st.i_beta_a),
                    1.5 * R * i2,
                    1.5 * PSI * w * iq,
                )
            };
            let mut acc = [0.0; 3];
            let mut add = |p: &Plant, c: f64| {
                let v = pw(p);
                acc[0] += c * v.0;
                acc[1] += c * v.1;
                acc[2] += c * v.2;
            };
            p.hold(s, 0.0);
            add(&p, 1.0);
            for j in 1..=n {
                p.hold(s, h);
                add(
                    &p,
                    if j == n {
                        1.0
                    } else if j % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    },
                );
            }
            e_in += acc[0] * h / 3.0;
            e_cu += acc[1] * h / 3.0;
            e_mech += acc[2] * h / 3.0;
        }
        let dw = w_mag(&p) - w0;
        let resid = e_in - e_cu - dw - e_mech;
        assert!(e_in.abs() > 1e-4, "{e_in}");
        assert!(
            resid.abs() < 1e-9 * e_in.abs().max(e_cu),
            "in {e_in} cu {e_cu} dW {dw} mech {e_mech} resid {resid}"
        );
    }

    /// Dead time, hand-constructed: i_a > 0, i_b, i_c < 0, duties 0.5, 1 us
    /// dead time. Leg a turns on 1 us late; legs b, c turn off 1 us late.
    #[test]
    fn dead_time_follows_current_direction() {
        let m = MotorParams::default();
        let t = 62.5e-6;
        let dt = 1e-6;
        let mut p = Plant::new(&m, dt, MechanicalMode::ConstantSpeed, 0.0).unwrap();
        p.set_state(5.0, 0.0, 0.0, 0.0).unwrap();
        p.step(&Actuation::DutyAbc([0.5; 3]), t, 16, |_| {})
            .unwrap();
        let mut q = plant(0.0);
        q.set_state(5.0, 0.0, 0.0, 0.0).unwrap();
        let (on, off) = (0.25 * t, 0.75 * t);
        for (dur, s) in [
            (on, 0b000),
            (dt, 0b011),
            (off - on - dt, 0b111),
            (dt, 0b011),
            (t - off - dt, 0b000),
        ] {
            q.hold(s, dur);
        }
        let (a, b) = (p.state(), q.state());
        assert!(
            (a.i_alpha_a - b.i_alpha_a).abs() < 1e-12 && (a.i_beta_a - b.i_beta_a).abs() < 1e-12
        );
        // The dead time cost leg a 1 us of U_dc, visibly: the current is lower
        // than without dead time.
        let mut r = plant(0.0);
        r.set_state(5.0, 0.0, 0.0, 0.0).unwrap();
        r.step(&Actuation::DutyAbc([0.5; 3]), t, 16, |_| {})
            .unwrap();
        assert!(r.state().i_alpha_a - a.i_alpha_a > 1e-3);
        assert_eq!(p.transitions(), [2, 2, 2]);
        // A pending transition carries over a period boundary: switch state
        // 100 from 000 with i_a > 0 and the edge delayed past the period end.
        let mut p = Plant::new(&m, dt, MechanicalMode::ConstantSpeed, 0.0).unwrap();
        p.set_state(5.0, 0.0, 0.0, 0.0).unwrap();
        p.step(&Actuation::SwitchState(0b100), 0.5e-6, 1, |_| {})
            .unwrap();
        p.step(&Actuation::SwitchState(0b100), 10e-6, 1, |_| {})
            .unwrap();
        let mut q = plant(0.0);
        q.set_state(5.0, 0.0, 0.0, 0.0).unwrap();
        q.hold(0b000, dt);
        q.hold(0b100, 9.5e-6);
        assert!((p.state().i_alpha_a - q.state().i_alpha_a).abs() < 1e-12);
    }

    /// Inertia mode: with the current held at i_q = 4 A (constant torque)
    /// against a 0.1 N m load, the electrical speed ramps at p (T - T_L) / J.
    #[test]
    fn inertia_mode_ramps_at_torque_over_inertia() {
        let m = MotorParams::default();
        let load = 0.1;
        let mut p = Plant::new(
            &m,
            0.0,
            MechanicalMode::Inertia {
                load_torque_nm: load,
            },
            0.0,
        )
        .unwrap();
        // Keep i_q = 4 A, i_d = 0 by applying, every 1 us, the exact voltage
        // R i + back-EMF in the rotor frame (held in alpha-beta for 1 us).
        let iq = 4.0;
        let (a0, b0) = inv_park(0.0, iq, 0.0);
        p.set_state(a0, b0, 0.0, 0.0).unwrap();
        for _ in 0..5000 {
            let s = *p.state();
            let (ud, uq) = (-s.omega_e_rad_s * L * iq, R * iq + s.omega_e_rad_s * PSI);
            let (ua, ub) = inv_park(ud, uq, s.theta_e_rad + 0.5e-6 * s.omega_e_rad_s);
            p.advance_voltage(ua, ub, 1e-6);
        }
        let torque = 1.5 * 7.0 * PSI * iq;
        let (_, q) = p.i_dq_a();
        assert!((q - iq).abs() < 0.01, "{q}");
        let want = 7.0 * (torque - load) / m.j_kg_m2 * 5e-3;
        let got = p.state().omega_e_rad_s;
        assert!((got - want).abs() < 0.005 * want, "{got} vs {want}");
    }
}
