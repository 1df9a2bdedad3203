//! Trapezoidal trajectory from rest to rest: constant acceleration `a` up
//! to the velocity limit `v`, cruise, constant deceleration; a move too
//! short to reach `v` is a triangle (peak `sqrt(a D)`). Distance `D`:
//! acceleration time `t_a = v / a`, cruise `t_c = D / v - v / a`, duration
//! `2 t_a + t_c` (triangle: `t_a = sqrt(D / a)`, `t_c = 0`).
use crate::validate::{check_finite, check_pos, ParamError};

/// Position, velocity and acceleration of the reference at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Setpoint {
    /// Position, rev.
    pub p: f64,
    /// Velocity, rev/s.
    pub v: f64,
    /// Acceleration, rev/s^2.
    pub a: f64,
}

/// A planned move.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trapezoid {
    start: f64,
    dir: f64,
    dist: f64,
    accel: f64,
    v_peak: f64,
    t_a: f64,
    t_c: f64,
}

impl Trapezoid {
    /// A move from `start` to `target` (rev) under `v_max` (rev/s) and
    /// `a_max` (rev/s^2), both > 0.
    pub fn new(start: f64, target: f64, v_max: f64, a_max: f64) -> Result<Self, ParamError> {
        check_finite("start", start)?;
        check_finite("target", target)?;
        check_pos("v_max", v_max)?;
        check_pos("a_max", a_max)?;
        let d = target - start;
        let dist = libm::fabs(d);
        let (v_peak, t_a, t_c) = if dist >= v_max * v_max / a_max {
            (v_max, v_max / a_max, dist / v_max - v_max / a_max)
        } else {
            let t_a = libm::sqrt(dist / a_max);
            (a_max * t_a, t_a, 0.0)
        };
        Ok(Self {
            start,
            dir: if d < 0.0 { -1.0 } else { 1.0 },
            dist,
            accel: a_max,
            v_peak,
            t_a,
            t_c,
        })
    }

    /// Duration, s.
    pub fn duration_s(&self) -> f64 {
        2.0 * self.t_a + self.t_c
    }

    /// The target, rev.
    pub fn target(&self) -> f64 {
        self.start + self.dir * self.dist
    }

    /// The reference at `t_s` seconds after the start (held at the ends).
    pub fn at(&self, t_s: f64) -> Setpoint {
        let (a, t_a, t_c) = (self.accel, self.t_a, self.t_c);
        let (s, v, acc) = if t_s.is_nan() || t_s <= 0.0 {
            (0.0, 0.0, 0.0)
        } else if t_s < t_a {
            (0.5 * a * t_s * t_s, a * t_s, a)
        } else if t_s < t_a + t_c {
            (
                0.5 * a * t_a * t_a + self.v_peak * (t_s - t_a),
                self.v_peak,
                0.0,
            )
        } else if t_s < self.duration_s() {
            let r = self.duration_s() - t_s;
            (self.dist - 0.5 * a * r * r, a * r, -a)
        } else {
            (self.dist, 0.0, 0.0)
        };
        Setpoint {
            p: self.start + self.dir * s,
            v: self.dir * v,
            a: self.dir * acc,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_revolution_at_20_rev_s_and_500_rev_s2() {
        // t_a = 40 ms covering 0.4 rev each way, cruise 0.2 rev at 20 rev/s
        // = 10 ms: 90 ms in all.
        let t = Trapezoid::new(0.0, 1.0, 20.0, 500.0).unwrap();
        assert!((t.duration_s() - 0.09).abs() < 1e-12);
        let s = t.at(0.04);
        assert!((s.p - 0.4).abs() < 1e-12 && (s.v - 20.0).abs() < 1e-12);
        assert!((t.at(0.045).p - 0.5).abs() < 1e-12);
        assert_eq!(t.at(0.09).p, 1.0);
        assert_eq!(
            t.at(1.0),
            Setpoint {
                p: 1.0,
                v: 0.0,
                a: 0.0
            }
        );
        // Velocity is the derivative of position everywhere.
        for k in 1..899 {
            let x = k as f64 * 1e-4;
            let dv = (t.at(x + 1e-7).p - t.at(x - 1e-7).p) / 2e-7;
            assert!((dv - t.at(x).v).abs() < 1e-3, "{x}: {dv} vs {}", t.at(x).v);
        }
    }

    #[test]
    fn short_moves_are_triangles_and_backward_moves_mirror() {
        let t = Trapezoid::new(2.0, 1.9, 20.0, 500.0).unwrap();
        // sqrt(0.1 / 500) = 14.14 ms per half.
        assert!((t.duration_s() - 2.0 * (0.1f64 / 500.0).sqrt()).abs() < 1e-12);
        let mid = t.at(t.duration_s() / 2.0);
        assert!((mid.p - 1.95).abs() < 1e-12);
        assert!(mid.v < 0.0);
        assert!((t.at(10.0).p - 1.9).abs() < 1e-12);
        assert_eq!(
            Trapezoid::new(0.0, 0.0, 1.0, 1.0).unwrap().duration_s(),
            0.0
        );
        assert!(Trapezoid::new(0.0, 1.0, 0.0, 1.0).is_err());
        assert!(Trapezoid::new(0.0, f64::NAN, 1.0, 1.0).is_err());
    }
}
