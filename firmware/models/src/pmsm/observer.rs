//! PI model-error observer of paper 000, eqs. (14)-(16), one per axis.
//!
//! Interpretation (paper eqs. 14-16, written down because the paper is loose):
//! - Eq. (14) has `+ R Ts / L` on the current; the model (5) it comes from has
//!   `1 - R Ts / L`. We use `a = 1 - R Ts / L` (the paper's sign is a typo:
//!   with `+` the open-loop model would be unstable).
//! - The observer is a *parallel model* (Luenberger form): its estimate `i_hat`
//!   evolves from its own previous value, `i_hat[k+1] = a i_hat[k] + b (v[k] +
//!   eps[k])`, and `eps` is the PI of the error `e = i_meas - i_hat` (eq. 15).
//!   That is how eq. (16) is built (it substitutes `i_hat[k+1] = z i_hat[k]`).
//! - `Ki Ts / (z - 1)` is a delayed accumulator: `nu[k+1] = nu[k] + Kp Ki Ts
//!   e[k]`, `eps[k] = Kp e[k] + nu[k]`.
//! - Per axis: `A` and `B` of eq. (5) are diagonal, so d and q observers are
//!   independent; the coupling terms are inside `v` (eq. 6) computed from the
//!   measured currents, as the paper defines `V`.
//!
//! Error dynamics (plant `i[k+1] = a i[k] + b (v[k] + d)`, constant `d`):
//! `e[k+1] = a e[k] + b d - b eps[k]`, which gives the characteristic polynomial
//! `(z - a)(z - 1) + b Kp (z - 1) + b Kp Ki Ts = z^2 + c1 z + c0` with
//! `c1 = b Kp - a - 1`, `c0 = a - b Kp + b Kp Ki Ts`. The paper's sentence
//! "the observer is stable only if the roots ... locate in the unit circle"
//! is checked by [`observer_is_stable`] (Jury test) and enforced by
//! `MpdtcParams::validate`. At steady state the integral makes `e -> 0` and
//! `eps -> d`: `eps` is the lumped model error in volts.

/// Coefficients `(c1, c0)` of the monic characteristic polynomial
/// `z^2 + c1 z + c0` of the observer error dynamics.
/// `a` = `1 - R Ts / L` (1), `b` = `Ts / L` (A/V), `kp_v_per_a` = Kp (V/A),
/// `ki_per_s` = Ki (1/s), `ts_s` = control period (s).
pub fn observer_char_poly(a: f64, b: f64, kp_v_per_a: f64, ki_per_s: f64, ts_s: f64) -> (f64, f64) {
    let kp = b * kp_v_per_a;
    let ki = kp * ki_per_s * ts_s;
    (kp - a - 1.0, a - kp + ki)
}

/// Jury (Schur) test of `z^2 + c1 z + c0`: both roots strictly inside the unit
/// circle iff `|c0| < 1`, `1 + c1 + c0 > 0` and `1 - c1 + c0 > 0`.
pub fn second_order_is_schur(c1: f64, c0: f64) -> bool {
    c0.abs() < 1.0 && 1.0 + c1 + c0 > 0.0 && 1.0 - c1 + c0 > 0.0
}

/// The observer's stability condition (paper, after eq. 16).
pub fn observer_is_stable(a: f64, b: f64, kp_v_per_a: f64, ki_per_s: f64, ts_s: f64) -> bool {
    let (c1, c0) = observer_char_poly(a, b, kp_v_per_a, ki_per_s, ts_s);
    c1.is_finite() && c0.is_finite() && second_order_is_schur(c1, c0)
}

/// Spectral radius of `z^2 + c1 z + c0` (largest root magnitude), for reports.
pub fn spectral_radius(c1: f64, c0: f64) -> f64 {
    let disc = c1 * c1 - 4.0 * c0;
    if disc >= 0.0 {
        let s = libm::sqrt(disc);
        let r1 = libm::fabs((-c1 + s) * 0.5);
        let r2 = libm::fabs((-c1 - s) * 0.5);
        if r1 > r2 {
            r1
        } else {
            r2
        }
    } else {
        // Complex pair: |z|^2 = c0.
        libm::sqrt(c0)
    }
}

/// State of one axis of the f64 observer.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AxisObserver {
    /// Observer current estimate `i_hat[k]`, A.
    pub i_hat_a: f64,
    /// Integral part `nu[k]` of `eps`, V.
    pub nu_v: f64,
}

/// Gains of one axis, precomputed from the parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisGains {
    /// `1 - R Ts / L`.
    pub a: f64,
    /// `Ts / L`, A/V.
    pub b_a_per_v: f64,
    /// Kp, V/A.
    pub kp_v_per_a: f64,
    /// `Kp Ki Ts`, V/A (per period).
    pub kint_v_per_a: f64,
    /// Clamp of `|eps|` and `|nu|`, V (anti-windup; a fault would saturate here).
    pub limit_v: f64,
}

impl AxisObserver {
    /// One observer period. `i_meas_a`: measured current at k; `v_v`: the
    /// eq. (6) voltage applied over [k, k+1] (without `eps`). Returns
    /// `(eps[k], next state)`.
    pub fn step(&self, g: &AxisGains, i_meas_a: f64, v_v: f64) -> (f64, AxisObserver) {
        let e = i_meas_a - self.i_hat_a;
        let eps = clamp(g.kp_v_per_a * e + self.nu_v, g.limit_v);
        let nu = clamp(self.nu_v + g.kint_v_per_a * e, g.limit_v);
        let i_hat = g.a * self.i_hat_a + g.b_a_per_v * (v_v + eps);
        (
            eps,
            AxisObserver {
                i_hat_a: i_hat,
                nu_v: nu,
            },
        )
    }
}

fn clamp(x: f64, lim: f64) -> f64 {
    x.clamp(-lim, lim)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jury_matches_root_magnitudes() {
        // Hand cases: (z-0.5)(z-0.2) stable; (z-1.1)(z-0.1) unstable;
        // z^2 + 0.81 (roots +-0.9j) stable; z^2 + 1.21 unstable.
        assert!(second_order_is_schur(-0.7, 0.1));
        assert!(!second_order_is_schur(-1.2, 0.11));
        assert!(second_order_is_schur(0.0, 0.81));
        assert!(!second_order_is_schur(0.0, 1.21));
        assert!((spectral_radius(-0.7, 0.1) - 0.5).abs() < 1e-12);
        assert!((spectral_radius(0.0, 0.81) - 0.9).abs() < 1e-12);
        // Brute force: the Jury verdict agrees with explicit roots on a grid.
        for i in -20..=20 {
            for j in -20..=20 {
                let (c1, c0) = (i as f64 * 0.11, j as f64 * 0.057);
                let rho = spectral_radius(c1, c0);
                if (rho - 1.0).abs() > 1e-9 {
                    assert_eq!(second_order_is_schur(c1, c0), rho < 1.0, "{c1} {c0}");
                }
            }
        }
    }

    /// The error of a simulated observer decays iff the Jury test says so, and
    /// with a constant model error `d` the estimate `eps` converges to `d`.
    #[test]
    fn observer_simulation_agrees_with_stability_test() {
        let (ts, l, r) = (1.0 / 64e3, 0.64e-3, 0.555);
        let (a, b) = (1.0 - r * ts / l, ts / l);
        for &(kp, ki) in &[
            (10.0, 2000.0),
            (30.0, 5000.0),
            (80.0, 500.0),
            (90.0, 40000.0),
            (170.0, 2000.0),
            (5.0, 200000.0),
        ] {
            let stable = observer_is_stable(a, b, kp, ki, ts);
            let g = AxisGains {
                a,
                b_a_per_v: b,
                kp_v_per_a: kp,
                kint_v_per_a: kp * ki * ts,
                limit_v: 1e9,
            };
            let d = 3.0; // volts of unmodelled voltage
            let (mut i, mut obs) = (0.0, AxisObserver::default());
            let mut eps = 0.0;
            for k in 0..4000 {
                let v = if k % 7 < 3 { 20.0 } else { -15.0 };
                let (e, n) = obs.step(&g, i, v);
                eps = e;
                obs = n;
                i = a * i + b * (v + d);
            }
            if stable {
                assert!((eps - d).abs() < 1e-6, "kp {kp} ki {ki}: eps {eps}");
            } else {
                assert!(
                    !eps.is_finite() || (eps - d).abs() > 1.0,
                    "kp {kp} ki {ki}: eps {eps}"
                );
            }
        }
        // Hand checks (b = Ts/L = 0.0244 A/V, a = 0.98645):
        // Kp = 170: b Kp = 4.15, 1 - c1 + c0 = 2 + 2a - 2 b Kp + b Kp Ki Ts < 0.
        assert!(!observer_is_stable(a, b, 170.0, 2000.0, ts));
        // Ki Ts = 3.125: c0 = a + b Kp (Ki Ts - 1) = 1.245 > 1.
        assert!(!observer_is_stable(a, b, 5.0, 200000.0, ts));
        assert!(observer_is_stable(a, b, 90.0, 40000.0, ts));
        assert!(observer_is_stable(a, b, 30.0, 5000.0, ts));
    }
}
