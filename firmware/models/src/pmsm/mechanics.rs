//! Rotor mechanics of a joint: `J dw/dt = T - T_load - b w - T_c sgn(w) - k theta`.
//!
//! `w` and `theta` are the rotor's mechanical speed (rad/s) and angle (rad,
//! not wrapped, 0 where the spring is relaxed); `T` the electromagnetic
//! torque, `T_load` a constant load (positive opposes positive speed), `b`
//! viscous friction, `T_c` Coulomb friction and `k` a joint spring about
//! angle 0. Coulomb friction sticks: at rest the rotor stays at rest while
//! the other torques stay within `T_c`, and a step that would carry the
//! speed through zero ends at rest (the friction cannot reverse it).
//!
//! One step of `h` seconds (the plant calls it once per segment, a few us
//! against a mechanical time scale of ms) uses the mean electromagnetic
//! torque over the segment (trapezoid) and the angle and speed at its start
//! (explicit Euler for the slow terms).
use super::params::{check_finite, check_nonneg, check_pos, ParamError};

/// Mechanical parameters of the rotor and its load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mechanics {
    /// Total inertia on the rotor, kg m^2.
    pub j_kg_m2: f64,
    /// Viscous friction, N m s/rad (mechanical speed).
    pub b_nm_s_per_rad: f64,
    /// Coulomb friction, N m (magnitude).
    pub coulomb_nm: f64,
    /// Constant load torque, N m (positive opposes positive speed).
    pub load_torque_nm: f64,
    /// Joint spring about angle 0, N m/rad.
    pub spring_nm_per_rad: f64,
}

impl Mechanics {
    /// A bare rotor of inertia `j_kg_m2` with viscous friction `b`.
    pub const fn rotor(j_kg_m2: f64, b_nm_s_per_rad: f64) -> Self {
        Self {
            j_kg_m2,
            b_nm_s_per_rad,
            coulomb_nm: 0.0,
            load_torque_nm: 0.0,
            spring_nm_per_rad: 0.0,
        }
    }

    /// Checks every field: inertia > 0, friction and spring >= 0, load finite.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_pos("j_kg_m2", self.j_kg_m2)?;
        check_nonneg("b_nm_s_per_rad", self.b_nm_s_per_rad)?;
        check_nonneg("coulomb_nm", self.coulomb_nm)?;
        check_finite("load_torque_nm", self.load_torque_nm)?;
        check_nonneg("spring_nm_per_rad", self.spring_nm_per_rad)
    }

    /// The speed after `h_s` seconds from speed `w` and angle `theta` under
    /// the mean electromagnetic torque `t_nm`, rad/s (Coulomb sticking as in
    /// the module doc).
    pub fn step(&self, t_nm: f64, w: f64, theta: f64, h_s: f64) -> f64 {
        let drive = t_nm - self.load_torque_nm - self.spring_nm_per_rad * theta;
        let tc = self.coulomb_nm;
        if w == 0.0 && libm::fabs(drive) <= tc {
            return 0.0;
        }
        let sign = if w != 0.0 { w.signum() } else { drive.signum() };
        let net = drive - self.b_nm_s_per_rad * w - tc * sign;
        let w1 = w + net / self.j_kg_m2 * h_s;
        if tc > 0.0 && w != 0.0 && w1.signum() != w.signum() {
            // Friction stops the rotor; it does not push it back.
            0.0
        } else {
            w1
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn integrate(m: &Mechanics, t: f64, w0: f64, th0: f64, h: f64, n: usize) -> (f64, f64) {
        let (mut w, mut th) = (w0, th0);
        for _ in 0..n {
            let w1 = m.step(t, w, th, h);
            th += 0.5 * (w + w1) * h;
            w = w1;
        }
        (w, th)
    }

    #[test]
    fn free_inertia_ramps_at_net_torque_over_inertia() {
        let m = Mechanics {
            load_torque_nm: 0.1,
            ..Mechanics::rotor(1e-4, 0.0)
        };
        let (w, _) = integrate(&m, 0.3, 0.0, 0.0, 1e-5, 1000);
        // (0.3 - 0.1) / 1e-4 * 10 ms = 20 rad/s.
        assert!((w - 20.0).abs() < 1e-9, "{w}");
    }

    #[test]
    fn coulomb_friction_holds_below_and_slips_above_its_level() {
        let m = Mechanics {
            coulomb_nm: 0.05,
            ..Mechanics::rotor(1e-4, 0.0)
        };
        assert_eq!(integrate(&m, 0.049, 0.0, 0.0, 1e-5, 100).0, 0.0);
        assert_eq!(integrate(&m, -0.049, 0.0, 0.0, 1e-5, 100).0, 0.0);
        // 0.06 N m: 0.01 N m net, 1 ms -> 0.1 rad/s.
        let (w, _) = integrate(&m, 0.06, 0.0, 0.0, 1e-5, 100);
        assert!((w - 0.1).abs() < 1e-9, "{w}");
        // Coasting from 1 rad/s with no torque: stops after J w / Tc = 2 ms
        // and stays stopped.
        let (w, th) = integrate(&m, 0.0, 1.0, 0.0, 1e-5, 1000);
        assert_eq!(w, 0.0);
        // Angle of a uniform deceleration: w0^2 / (2 a) = 1 / (2 * 500) rad.
        assert!((th - 1e-3).abs() < 1e-5, "{th}");
    }

    #[test]
    fn spring_oscillates_at_its_natural_frequency() {
        // k = 1 N m/rad, J = 1e-4: w_n = 100 rad/s, period 62.83 ms. From
        // theta = 0.1 rad at rest, a half period later theta = -0.1 rad.
        let m = Mechanics {
            spring_nm_per_rad: 1.0,
            ..Mechanics::rotor(1e-4, 0.0)
        };
        let h = 1e-6;
        let n = (core::f64::consts::PI / 100.0 / h) as usize;
        let (_, th) = integrate(&m, 0.0, 0.0, 0.1, h, n);
        assert!((th + 0.1).abs() < 1e-4, "{th}");
    }

    #[test]
    fn invalid_parameters_are_refused() {
        let ok = Mechanics::rotor(1e-4, 0.0);
        assert!(ok.validate().is_ok());
        for bad in [
            Mechanics { j_kg_m2: 0.0, ..ok },
            Mechanics {
                b_nm_s_per_rad: -1.0,
                ..ok
            },
            Mechanics {
                coulomb_nm: f64::NAN,
                ..ok
            },
            Mechanics {
                load_torque_nm: f64::INFINITY,
                ..ok
            },
            Mechanics {
                spring_nm_per_rad: -0.1,
                ..ok
            },
        ] {
            assert!(bad.validate().is_err(), "{bad:?}");
        }
    }
}
