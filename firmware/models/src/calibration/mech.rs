//! The mechanics fit of the spin (inertia J, viscous friction b, Coulomb
//! friction T_c) and its uncertainties: pure arithmetic on what the state
//! machine measured in its averaging windows.
//!
//! At each of [`LEVELS`] speeds the spin averages [`PER_LEVEL`] windows:
//! i_d at +I/2, reversed to -I/2, at +I/2 again. The torque is `kt` times
//! the q-axis current in the rotor's true frame, but the currents are
//! measured in the encoder's frame, which is off the true one by the
//! encoder zero's error and by the lag of the current samples behind the
//! position (a few us: an angle growing with the speed). Such a frame
//! error `e` turns i_d into torque, `kt i_d e`: with i_d at 4 A, a tenth of
//! an electrical degree of it is 0.007 A of i_q, 6.8e-4 N m on the default
//! motor, a seventh of a typical Coulomb friction (5e-3 N m). It changes
//! sign with i_d while the friction does not: the reversals measure it.
//!
//! Model: the rotor's momentum at any instant (it turns forwards from the
//! first window to the last, so the friction keeps its sign)
//!
//! `J w(t) = kt int (i_q + i_d e) dt - b theta(t) - T_c t + C`,
//!
//! with `e = e0 + e1 w` left after turning the currents back by the frame
//! error the d-axis voltages give ([`frame_angle`]), `C` a constant. Its
//! mean over each window is one row of a least squares in J, b, T_c, e0,
//! e1 and C: the window's mean speed (its counts at both ends over
//! its duration) against the means of the running integrals, angle and
//! time over it. No instantaneous speed or acceleration enters: the speed
//! loop's ripple and the encoder's quantization within a window do not
//! matter, only the counts at its ends.
//!
//! Uncertainty, added in quadrature:
//! - the rows' own, scaled up by the reduced chi-square of the residuals
//!   when that exceeds one (errors they do not state). Each row's mean
//!   speed is within 0.41 count over its window (the end counts'
//!   quantization, one standard deviation); its running integral of i_q
//!   carries the current's error since the previous window,
//!   [`CURRENT_SIGMA_A`] times the time between them, and all those before
//!   (a random walk: the rows' errors are correlated, the fit is a
//!   generalised least squares);
//! - the same current error as a smooth function of the speed instead
//!   (how it is correlated from window to window is not known: both
//!   extremes are carried): independent errors of [`CURRENT_SIGMA_A`] at
//!   the slowest and the fastest speed, the line through them. A current
//!   error constant over the run looks like Coulomb friction (as a
//!   dead-time offset would), one growing with the speed like viscous
//!   friction (as an iron loss would): no run at a few speeds tells them
//!   apart, T_c and b carry them (the test
//!   `current_offsets_stay_within_the_sigmas`);
//! - the torque constant's relative uncertainty (J, b and T_c scale with
//!   it).
use super::fit::{generalised, weighted};

/// Speed levels of the spin.
pub(super) const LEVELS: usize = 3;
/// Averaging windows per speed: i_d at +I/2, reversed, at +I/2 again.
pub(super) const PER_LEVEL: usize = 3;
/// Averaging windows.
pub(super) const WINDOWS: usize = PER_LEVEL * LEVELS;
/// Standard deviation of the difference of two encoder readings, each
/// floored to a whole count (uniform errors): sqrt(2 / 12) counts.
pub(super) const COUNT_PAIR_SIGMA: f64 = 0.408;
/// Standard uncertainty of the measured q-axis current's mean from one
/// window to the next, A: the period mean of 16 samples of a PWM ripple of
/// about 1 A is good to about a thousandth of it. On the simulated drive
/// the current errors that friction absorbs are about this size
/// (docs/calibration.md, "How sigma is derived").
pub(super) const CURRENT_SIGMA_A: f64 = 0.5e-3;

/// The speed level of window `h`.
pub(super) fn level(h: usize) -> usize {
    h / PER_LEVEL
}

/// The first window at speed level `j`.
pub(super) fn first(j: usize) -> usize {
    j * PER_LEVEL
}

/// Whether window `h` has i_d reversed (-I/2).
pub(super) fn reversed(h: usize) -> bool {
    h % PER_LEVEL == 1
}

/// One averaging window as the fit sees it: means over its periods (the
/// running quantities from any common origin).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Window {
    /// Mean mechanical speed: the angle between its ends over its
    /// duration, rad/s.
    pub w: f64,
    /// Uncertainty of `w`, rad/s.
    pub sigma_w: f64,
    /// Mean angle, rad.
    pub th: f64,
    /// Mean time, s.
    pub t: f64,
    /// Mean running integrals of (i_d, i_q) over time, A s.
    pub i_int: (f64, f64),
    /// Mean running integrals of (i_d, i_q) over the angle, A rad.
    pub i_th: (f64, f64),
}

/// Everything the mechanics fit uses.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Spin {
    /// The windows.
    pub windows: [Window; WINDOWS],
    /// Torque constant 1.5 p psi, N m/A.
    pub kt: f64,
    /// Its uncertainty, N m/A.
    pub sigma_kt: f64,
    /// The encoder frame's angle ahead of the rotor's from the d-axis
    /// voltages ([`frame_angle`]), rad: the currents are turned back by it
    /// first.
    pub e_v: f64,
    /// Inertia for the rows' weights (the configured one; [`fit`] refits
    /// with its own), kg m^2.
    pub j_weight: f64,
}

/// The fitted mechanics, each (value, standard uncertainty).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Mech {
    /// Inertia, kg m^2.
    pub j: (f64, f64),
    /// Viscous friction, N m s/rad.
    pub b: (f64, f64),
    /// Coulomb friction, N m.
    pub tc: (f64, f64),
    /// The frame error left after `e_v`: at standstill (rad) and per unit
    /// of mechanical speed (rad per rad/s).
    pub frame: (f64, f64),
    /// Per speed, from its first window to its last: (mean speed rad/s,
    /// mean friction torque N m).
    pub points: [(f64, f64); LEVELS],
}

/// Components of a vector measured in a frame `a` ahead of the true one,
/// in the true frame.
fn turn_back((d, q): (f64, f64), a: f64) -> (f64, f64) {
    let (s, c) = (libm::sin(a), libm::cos(a));
    (d * c - q * s, q * c + d * s)
}

/// A row: regressors for (J, b, T_c, e0, e1, C), value, uncertainty.
type Row = ([f64; 6], f64, f64);

/// Window `h`'s row: `J w + b theta + T_c t - kt (e0 I_d + e1 Theta_d) - C
/// = kt I_q`, and the standard uncertainty of its speed's share.
fn row(s: &Spin, h: usize) -> Row {
    let win = &s.windows[h];
    let (id, iq) = turn_back(win.i_int, s.e_v);
    let (id_th, _) = turn_back(win.i_th, s.e_v);
    let x = [win.w, win.th, win.t, -s.kt * id, -s.kt * id_th, -1.0];
    (x, s.kt * iq, s.j_weight * win.sigma_w)
}

/// The rows' covariance, (N m s)^2: each speed's own on the diagonal, and
/// the current's error accumulated from window to window (the first
/// window's own goes into the constant C).
fn covariance(s: &Spin, rows: &[Row; WINDOWS]) -> [[f64; WINDOWS]; WINDOWS] {
    let step = s.kt * CURRENT_SIGMA_A;
    let mut walk = [0.0; WINDOWS];
    for h in 1..WINDOWS {
        let dt = s.windows[h].t - s.windows[h - 1].t;
        walk[h] = walk[h - 1] + (step * dt) * (step * dt);
    }
    let mut cov = [[0.0; WINDOWS]; WINDOWS];
    for (h, row) in cov.iter_mut().enumerate() {
        for (g, c) in row.iter_mut().enumerate() {
            *c = walk[h.min(g)];
        }
        row[h] += rows[h].2 * rows[h].2;
    }
    cov
}

/// The mean friction torque between the first and last window at each
/// speed, N m: the momentum balance over that interval with the fitted J
/// and frame error.
fn friction_points(rows: &[Row; WINDOWS], c: &[f64; 6]) -> [(f64, f64); LEVELS] {
    let mut points = [(0.0, 0.0); LEVELS];
    for (lv, pt) in points.iter_mut().enumerate() {
        let (a, z) = (first(lv), first(lv + 1) - 1);
        let d = |i: usize| rows[z].0[i] - rows[a].0[i];
        let (dth, dt) = (d(1), d(2));
        let drive = rows[z].1 - rows[a].1 + c[3] * d(3) + c[4] * d(4);
        let torque = (drive - c[0] * d(0)) / dt;
        *pt = (dth / dt, torque);
    }
    points
}

/// The share of b and T_c (N m s/rad, N m) of independent current errors
/// of [`CURRENT_SIGMA_A`] at the slowest and the fastest speed: the slope
/// of the line through them, and its value at standstill.
fn current_share(s: &Spin) -> (f64, f64) {
    let speeds = s.windows.map(|w| w.w);
    let lo = speeds.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = speeds.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let torque = s.kt * CURRENT_SIGMA_A;
    let span = hi - lo;
    (
        torque * core::f64::consts::SQRT_2 / span,
        torque * libm::hypot(lo, hi) / span,
    )
}

/// The fit and its uncertainties (the module doc); `None` when singular.
/// The rows' speed errors weigh J times a speed: fitted with the
/// configured J first, then again with the fitted one, so that the
/// sigmas do not depend on how far off the configuration was.
pub(super) fn fit(s: &Spin) -> Option<Mech> {
    let m = fit_once(s)?;
    // A J not above zero (a poor fit) keeps the configured weights.
    let j = if m.j.0 > 0.0 { m.j.0 } else { return Some(m) };
    fit_once(&Spin { j_weight: j, ..*s })
}

/// One fit with the rows weighed by `s.j_weight`.
fn fit_once(s: &Spin) -> Option<Mech> {
    let mut rows = [([0.0; 6], 0.0, 0.0); WINDOWS];
    for (h, r) in rows.iter_mut().enumerate() {
        *r = row(s, h);
    }
    let w = generalised(
        &rows.map(|r| r.0),
        &rows.map(|r| r.1),
        &covariance(s, &rows),
    )?;
    let [j, b, tc, e0, e1, _] = w.b;
    // J, b and T_c scale with the torque constant.
    let rel_kt = s.sigma_kt / s.kt;
    let sigma = |i: usize, v: f64| libm::hypot(w.sigma(i), v * rel_kt);
    let (b_i, tc_i) = current_share(s);
    let ok = w.b.iter().all(|v| v.is_finite()) && b_i.is_finite();
    ok.then_some(Mech {
        j: (j, sigma(0, j)),
        b: (b, libm::hypot(sigma(1, b), b_i)),
        tc: (tc, libm::hypot(sigma(2, tc), tc_i)),
        frame: (e0, e1),
        points: friction_points(&rows, &w.b),
    })
}

/// The encoder frame's angle error from the d-axis voltages: with `y_d`
/// the d-axis voltage less its resistive, inductive and dead-time terms,
/// what is left is the back-EMF's share `w_e psi sin(e)` (plus a constant:
/// the dead time's and R's errors), while the q axis carries
/// `w_e psi cos(e)` (the flux fit's slope `psi_q`). Points are (electrical
/// speed rad/s, y_d V); returns the angle in rad, or `None` when singular.
pub(super) fn frame_angle(points: &[(f64, f64); LEVELS], psi_q: f64) -> Option<f64> {
    let rows = points.map(|(w_e, y)| ([w_e / 1000.0, 1.0], y, 1.0));
    let w = weighted(&rows)?;
    let e = libm::atan2(w.b[0] / 1000.0, psi_q);
    e.is_finite().then_some(e)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testrng::Rng;

    /// A simulated spin's truth.
    #[derive(Clone, Copy)]
    struct Truth {
        j: f64,
        b: f64,
        tc: f64,
        kt: f64,
        /// Frame error at standstill (rad) and per rad/s.
        e: (f64, f64),
        /// Error of the measured q-axis current: at standstill (A) and
        /// per rad/s.
        i_err: (f64, f64),
    }

    const T: f64 = 62.5e-6;
    const WINDOW: usize = 512;

    /// The rotor's state and the running quantities the machine keeps.
    #[derive(Default)]
    struct Rotor {
        w: f64,
        k: usize,
        /// Angle (rad), time (s), integrals of the measured (i_d, i_q) over
        /// time (A s) and over the angle (A rad).
        run: [f64; 6],
    }

    impl Rotor {
        /// One period towards `target` rad/s (a 10 ms time constant and a
        /// ripple) with i_d = `id` A, its currents measured in the frame
        /// `e0 + e1 w` ahead of the true one.
        fn step(&mut self, tr: &Truth, target: f64, id: f64) {
            let w = self.w;
            let ripple = libm::sin(self.k as f64 * 0.05);
            let w1 = w + (target - w) * T / 0.01 + ripple * T;
            // The true q current that makes this speed change.
            let iq = (tr.j * (w1 - w) / T + tr.b * w + tr.tc) / tr.kt;
            let e = tr.e.0 + tr.e.1 * w;
            let (s, c) = (libm::sin(e), libm::cos(e));
            let (id_m, iq_m) = (id * c + iq * s, iq * c - id * s);
            let iq_m = iq_m + tr.i_err.0 + tr.i_err.1 * w;
            for (r, x) in self
                .run
                .iter_mut()
                .zip([w, 1.0, id_m, iq_m, id_m * w, iq_m * w])
            {
                *r += x * T;
            }
            self.w = w1;
            self.k += 1;
        }
    }

    /// The spin as the machine records it: a rotor following a speed
    /// that approaches each level, i_d +4 A, reversed for the middle window
    /// of each level.
    fn spin(tr: &Truth) -> Spin {
        let mut s = Spin {
            kt: tr.kt,
            j_weight: tr.j,
            ..Spin::default()
        };
        let mut r = Rotor::default();
        for h in 0..WINDOWS {
            let target = [40.0, 75.0, 110.0][level(h)];
            let id = if reversed(h) { -4.0 } else { 4.0 };
            let settle = if h % PER_LEVEL == 0 { 800 } else { 256 };
            for _ in 0..settle {
                r.step(tr, target, id);
            }
            let th0 = r.run[0];
            let mut mean = [0.0; 6];
            for _ in 0..WINDOW {
                r.step(tr, target, id);
                for (m, x) in mean.iter_mut().zip(r.run) {
                    *m += x / WINDOW as f64;
                }
            }
            s.windows[h] = Window {
                w: (r.run[0] - th0) / (WINDOW as f64 * T),
                sigma_w: 0.02,
                th: mean[0],
                t: mean[1],
                i_int: (mean[2], mean[3]),
                i_th: (mean[4], mean[5]),
            };
        }
        s
    }

    const TRUTH: Truth = Truth {
        j: 8e-5,
        b: 2e-4,
        tc: 5e-3,
        kt: 0.1,
        e: (0.004, 4e-5),
        i_err: (0.0, 0.0),
    };

    #[test]
    fn an_exact_spin_gives_the_mechanics_and_the_frame_error() {
        let m = fit(&spin(&TRUTH)).unwrap();
        // The windows' mean speed stands for the mean of the speeds at
        // their samples, one period apart: parts in 10^5 to 10^4.
        assert!((m.j.0 / TRUTH.j - 1.0).abs() < 1e-4, "{m:?}");
        assert!((m.b.0 / TRUTH.b - 1.0).abs() < 2e-4, "{m:?}");
        assert!((m.tc.0 / TRUTH.tc - 1.0).abs() < 5e-4, "{m:?}");
        assert!((m.frame.0 - TRUTH.e.0).abs() < 1e-5, "{m:?}");
        assert!((m.frame.1 / TRUTH.e.1 - 1.0).abs() < 2e-3, "{m:?}");
        for (lv, (w, t)) in m.points.iter().enumerate() {
            let want = TRUTH.b * w + TRUTH.tc;
            assert!((t - want).abs() < 5e-4 * want, "level {lv}: {m:?}");
        }
    }

    /// A frictionless rotor: b and T_c near zero, within their sigmas.
    #[test]
    fn no_friction_is_found_as_none() {
        let tr = Truth {
            b: 0.0,
            tc: 0.0,
            ..TRUTH
        };
        let m = fit(&spin(&tr)).unwrap();
        assert!(m.b.0.abs() < m.b.1 && m.tc.0.abs() < m.tc.1, "{m:?}");
    }

    /// The windows' speeds with errors of their stated sigma: the truth
    /// within three sigmas of each estimate in all but a few of 200 runs.
    #[test]
    fn noisy_speeds_are_covered_by_the_sigmas() {
        let clean = spin(&TRUTH);
        let mut r = Rng(11);
        let mut out = [0; 3];
        for _ in 0..200 {
            let mut s = clean;
            for win in s.windows.iter_mut() {
                // Uniform of the stated standard deviation.
                win.w += win.sigma_w * 3f64.sqrt() * r.uniform(-1.0, 1.0);
            }
            let m = fit(&s).unwrap();
            let truth = [TRUTH.j, TRUTH.b, TRUTH.tc];
            for ((o, (v, sg)), t) in out.iter_mut().zip([m.j, m.b, m.tc]).zip(truth) {
                *o += usize::from((v - t).abs() > 3.0 * sg);
            }
        }
        assert!(out.iter().all(|&o| o <= 4), "{out:?}");
    }

    #[test]
    fn the_frame_angle_from_the_d_axis_voltages() {
        let (psi, e) = (0.01, 0.02);
        // y_d = w_e psi sin(e) + 0.3 V (the dead time's share), y_q's
        // slope psi cos(e).
        let points = [300.0, 550.0, 800.0].map(|w| (w, w * psi * libm::sin(e) + 0.3));
        let got = frame_angle(&points, psi * libm::cos(e)).unwrap();
        assert!((got - e).abs() < 1e-12, "{got}");
    }

    /// A current error of CURRENT_SIGMA_A throughout (a dead-time-like
    /// offset) moves T_c, one growing with the speed to CURRENT_SIGMA_A at
    /// the top speed (iron-loss-like) moves b: each by less than its sigma.
    /// (Both also through the fit's random walk alone.)
    #[test]
    fn current_offsets_stay_within_the_sigmas() {
        let clean = fit(&spin(&TRUTH)).unwrap();
        let constant = Truth {
            i_err: (CURRENT_SIGMA_A, 0.0),
            ..TRUTH
        };
        let m = fit(&spin(&constant)).unwrap();
        assert!((m.tc.0 - clean.tc.0).abs() < m.tc.1, "{m:?}");
        let growing = Truth {
            i_err: (0.0, CURRENT_SIGMA_A / 110.0),
            ..TRUTH
        };
        let m = fit(&spin(&growing)).unwrap();
        assert!((m.b.0 - clean.b.0).abs() < m.b.1, "{m:?}");
    }
}
