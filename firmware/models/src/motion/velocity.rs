//! Velocity PI with anti-windup, and the acceleration limit in front of it.
//!
//! Torque `T = clamp(kp e + I + T_ff, -T_max, T_max)`, `e = v_ref - v`,
//! `I += ki e dt` only while that does not push a saturated output further
//! into its limit (conditional integration), and `|I| <= T_max` always, so
//! the integrator never winds up beyond what the output can use.
//! Gains in revolutions: `kp` in N m per rev/s, `ki` in N m per rev.

/// Velocity PI gains and the torque limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PiGains {
    /// Proportional gain, N m s/rev.
    pub kp: f64,
    /// Integral gain, N m/rev.
    pub ki: f64,
    /// Output limit, N m (> 0).
    pub limit_nm: f64,
}

/// The velocity PI's state.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VelocityPi {
    integral_nm: f64,
}

impl VelocityPi {
    /// One step: the torque for reference `v_ref` and measurement `v`
    /// (rev/s) with feedforward `t_ff_nm`, N m.
    pub fn step(&mut self, g: &PiGains, v_ref: f64, v: f64, t_ff_nm: f64, dt_s: f64) -> f64 {
        let e = v_ref - v;
        let lim = g.limit_nm;
        let u = g.kp * e + self.integral_nm + t_ff_nm;
        let pushing_out = (u >= lim && e > 0.0) || (u <= -lim && e < 0.0);
        if !pushing_out && e.is_finite() && dt_s.is_finite() {
            self.integral_nm = (self.integral_nm + g.ki * e * dt_s).clamp(-lim, lim);
        }
        let u = g.kp * e + self.integral_nm + t_ff_nm;
        if u.is_nan() {
            0.0
        } else {
            u.clamp(-lim, lim)
        }
    }

    /// The integrator, N m.
    pub fn integral_nm(&self) -> f64 {
        self.integral_nm
    }
}

/// A reference that moves toward its target at most `rate` per second.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Ramp {
    /// The present value.
    pub value: f64,
}

impl Ramp {
    /// Moves toward `target` by at most `rate * dt_s`; returns the value.
    pub fn step(&mut self, target: f64, rate: f64, dt_s: f64) -> f64 {
        let d = (target - self.value).clamp(-rate * dt_s, rate * dt_s);
        if d.is_finite() {
            self.value += d;
        }
        self.value
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const G: PiGains = PiGains {
        kp: 0.2,
        ki: 20.0,
        limit_nm: 1.0,
    };

    #[test]
    fn pi_on_an_inertia_reaches_the_reference_without_error() {
        // J = 1e-4 kg m^2 with a 0.05 N m load: J dv/dt (rev/s^2 x 2 pi) = T - 0.05.
        let (j, dt) = (1e-4, 1e-4);
        let mut pi = VelocityPi::default();
        let mut v = 0.0;
        for _ in 0..20_000 {
            let t = pi.step(&G, 5.0, v, 0.0, dt);
            v += (t - 0.05) / (j * crate::motion::RAD_PER_REV) * dt;
        }
        assert!((v - 5.0).abs() < 1e-6, "{v}");
        // The integrator holds the load.
        assert!((pi.integral_nm() - 0.05).abs() < 1e-6);
    }

    #[test]
    fn saturation_does_not_wind_up_the_integrator() {
        let mut pi = VelocityPi::default();
        // A large error for a long time: the output is at the limit and the
        // integrator does not grow past it.
        for _ in 0..100_000 {
            assert_eq!(pi.step(&G, 100.0, 0.0, 0.0, 1e-4), 1.0);
        }
        assert!(pi.integral_nm() <= 1.0);
        // Integration stopped once the output saturated: kp e alone is 20 N m.
        assert!(pi.integral_nm() < 1e-9, "{}", pi.integral_nm());
        // The error reverses: the output leaves the limit at once.
        assert!(pi.step(&G, 0.0, 1.0, 0.0, 1e-4) < 0.0);
        // NaN in, no torque and no state change.
        let i0 = pi.integral_nm();
        assert_eq!(pi.step(&G, f64::NAN, 0.0, 0.0, 1e-4), 0.0);
        assert_eq!(pi.integral_nm(), i0);
    }

    #[test]
    fn ramp_moves_at_its_rate_and_stops_on_target() {
        let mut r = Ramp::default();
        for _ in 0..10 {
            r.step(1.0, 50.0, 1e-3);
        }
        assert!((r.value - 0.5).abs() < 1e-12);
        for _ in 0..100 {
            r.step(1.0, 50.0, 1e-3);
        }
        assert_eq!(r.value, 1.0);
        r.step(f64::NAN, 50.0, 1e-3);
        assert_eq!(r.value, 1.0);
    }
}
