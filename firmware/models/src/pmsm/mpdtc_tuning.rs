//! What one control period of the MPDTC can do to the torque, and the
//! tuning derived from it (docs/mpdtc-step-map.md).
//!
//! The MPDTC applies one switch state for a whole period, so the torque
//! moves in steps: an active vector changes `i_q` by its q-axis share of
//! `U0 = (Ts / L) 2/3 U_dc` in one period (at standstill, neglecting the
//! resistive drop), i.e. the torque by `k_T q U0`. With the rotor's d axis
//! on phase a (the simulated motor's locked rotor and the map's
//! configuration) the q axis lies midway between two active vectors: every
//! vector that moves the torque moves it by `q = sqrt(3)/2` of `k_T U0`, the
//! others (on the d axis) not at all. That step is
//!
//! - the smallest torque ripple a one-vector-per-period loop can hold (a
//!   settling band narrower than it cannot be met by any such loop), and
//! - the scale of the ripple the torque integrator sees, which sets its
//!   gain: [`integrator_gain_per_s`].
use super::params::MotorParams;

/// Share of `U0` an active vector puts on the q axis when the q axis lies
/// midway between two vectors (rotor d axis on a phase axis): `sqrt(3)/2`.
pub const Q_SHARE_MIDWAY: f64 = 0.866_025_403_784_438_6;

/// `K Ts h`, N m: the integrator's gain times the control period times one
/// period's full-vector torque step `h` ([`period_torque_step_nm`] with
/// `q = 1`). Chosen by measurement (the host step map over the 27 motors
/// of R, L, psi in {0.65, 1, 1.35} x nominal, 12 start phases each, with
/// the drive's band `T_tol` = 0.075 N m): 0.0119 N m misses 1 of 1,620 runs
/// of the cells a one-vector loop can meet; 5 % lower or higher misses 4 and
/// more (docs/mpdtc-step-map.md). On the nominal motor (h = 0.0762 N m at
/// 64 kHz) it gives K = 9,996 1/s.
pub const K_TS_STEP_NM: f64 = 0.0119;

/// The six torque steps `(from, to)` (N m, of a 1 N m limit) the tuning
/// above was measured on and the step map judges (docs/mpdtc-step-map.md):
/// from rest, to the limit's 0.8, across zero and back, the full reversal.
pub const STEP_CASES_NM: [(f64, f64); 6] = [
    (0.0, 0.4),
    (0.0, 0.8),
    (0.1, 0.9),
    (-0.4, 0.4),
    (0.4, -0.4),
    (-0.8, 0.8),
];

/// Largest `K Ts` the derivation hands out: the integrator then moves the
/// reference by at most half the error per period.
pub const K_TS_MAX: f64 = 0.5;

/// Current change of a full active vector over one period at standstill,
/// A: `U0 = (Ts / L_q) 2/3 U_dc`.
pub fn full_vector_current_step_a(model: &MotorParams, ts_s: f64) -> f64 {
    ts_s / model.l_q_h * 2.0 / 3.0 * model.u_dc_v
}

/// Torque change of one period of an active vector with q-axis share `q`
/// (`q = 1`: the vector on the q axis; [`Q_SHARE_MIDWAY`]: the q axis midway
/// between two vectors), N m: `k_T q U0`.
pub fn period_torque_step_nm(model: &MotorParams, ts_s: f64, q: f64) -> f64 {
    model.k_t_nm_per_a() * q * full_vector_current_step_a(model, ts_s)
}

/// The torque integrator's gain for `model` at control period `ts_s`,
/// 1/s: `K = K_TS_STEP_NM / (Ts h)`, `h` the full-vector step, at most
/// `K_TS_MAX / Ts`. A motor whose period moves the torque further gets a
/// proportionally smaller gain, so that the ripple does not drive the
/// integrator into a limit cycle of its own.
pub fn integrator_gain_per_s(model: &MotorParams, ts_s: f64) -> f64 {
    let h = period_torque_step_nm(model, ts_s, 1.0);
    (K_TS_STEP_NM / (ts_s * h)).min(K_TS_MAX / ts_s)
}

/// Whether a step `from -> to` (N m) can settle into the 10 % band
/// ([`super::metrics::settling_band`]) under a one-vector-per-period loop
/// with the rotor as [`Q_SHARE_MIDWAY`] assumes: not when one period's torque
/// step is wider than the band (`2 x` the band's half-width).
pub fn band_holds_one_period(model: &MotorParams, ts_s: f64, from_nm: f64, to_nm: f64) -> bool {
    period_torque_step_nm(model, ts_s, Q_SHARE_MIDWAY)
        <= 2.0 * super::metrics::settling_band(from_nm, to_nm)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TS: f64 = 1.0 / 64_000.0;

    /// Nominal motor by hand: U0 = 15.625 us / 0.64 mH x 32 V = 0.78125 A;
    /// k_T = 1.5 x 7 x 0.0092879 Wb = 0.097523 N m/A; h = 0.076190 N m;
    /// midway: x 0.866 = 0.065982 N m (the slope of the simulated PL's
    /// reversal, 0.066 N m per period).
    #[test]
    fn the_nominal_motors_period_steps() {
        let m = MotorParams::default();
        assert!((full_vector_current_step_a(&m, TS) - 0.78125).abs() < 1e-9);
        assert!((period_torque_step_nm(&m, TS, 1.0) - 0.076190).abs() < 1e-5);
        assert!((period_torque_step_nm(&m, TS, Q_SHARE_MIDWAY) - 0.065982).abs() < 1e-5);
        // K = 0.0119 / (15.625 us x 0.076190 N m) = 9,996 1/s.
        assert!((integrator_gain_per_s(&m, TS) - 9_996.0).abs() < 2.0);
    }

    /// L x 0.65 and psi x 1.35: h x 1.35 / 0.65 (K / 2.077); a large L and
    /// a small psi meet the K Ts cap instead of a gain near 1 per period.
    #[test]
    fn the_gain_follows_the_period_step_and_is_capped() {
        let m = MotorParams::default();
        let low_l = MotorParams {
            l_d_h: m.l_d_h * 0.65,
            l_q_h: m.l_q_h * 0.65,
            psi_pm_wb: m.psi_pm_wb * 1.35,
            ..m
        };
        let r = integrator_gain_per_s(&m, TS) / integrator_gain_per_s(&low_l, TS);
        assert!((r - 1.35 / 0.65).abs() < 1e-9, "{r}");
        let tiny = MotorParams {
            l_d_h: m.l_d_h * 20.0,
            l_q_h: m.l_q_h * 20.0,
            ..m
        };
        assert!((integrator_gain_per_s(&tiny, TS) * TS - K_TS_MAX).abs() < 1e-12);
    }

    /// The band of a 0.4 N m step (+-0.04 N m, 0.08 wide) holds the
    /// nominal motor's 0.066 N m step, not the 0.1015 N m of L x 0.65; an
    /// 0.8 N m step's band (0.16 wide) holds both.
    #[test]
    fn which_bands_hold_one_periods_step() {
        let m = MotorParams::default();
        let low_l = MotorParams {
            l_d_h: m.l_d_h * 0.65,
            l_q_h: m.l_q_h * 0.65,
            ..m
        };
        assert!(band_holds_one_period(&m, TS, 0.0, 0.4));
        assert!(!band_holds_one_period(&low_l, TS, 0.0, 0.4));
        assert!(band_holds_one_period(&low_l, TS, -0.4, 0.4));
    }
}
