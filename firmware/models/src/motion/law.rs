//! The position loop and the impedance law: torque references for the
//! torque loop, in revolutions.
//!
//! Position loop (cascade): velocity command `v_c = kp_pos (p_ref - p) +
//! v_ff`, then the velocity PI ([`super::velocity`]) with the acceleration
//! feedforward `J 2 pi a_ff` (`J` the load inertia the drive is told, kg
//! m^2) as its torque feedforward. With `J` right and no disturbance the
//! feedforward alone makes the move; the loops correct the rest and the
//! PI's integrator holds a constant load without a position error.
//!
//! Impedance: `T = clamp(kp (p_des - p) + kd (v_des - v) + T_ff, +-T_max)`
//! every step (kp in N m/rev, kd in N m s/rev): a spring and damper about
//! the desired state, the MIT Mini Cheetah's joint command.
use super::trajectory::Setpoint;
use super::velocity::{PiGains, VelocityPi};
use super::RAD_PER_REV;

/// Position-loop parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionGains {
    /// Position gain, (rev/s)/rev = 1/s.
    pub kp: f64,
    /// The velocity loop under it.
    pub vel: PiGains,
    /// Inertia for the acceleration feedforward, kg m^2.
    pub inertia_kg_m2: f64,
}

/// One step of the position loop: the torque, N m.
pub fn position_step(
    g: &PositionGains,
    pi: &mut VelocityPi,
    sp: &Setpoint,
    p: f64,
    v: f64,
    dt_s: f64,
) -> f64 {
    let v_cmd = g.kp * (sp.p - p) + sp.v;
    let t_ff = g.inertia_kg_m2 * RAD_PER_REV * sp.a;
    pi.step(&g.vel, v_cmd, v, t_ff, dt_s)
}

/// An impedance command.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Impedance {
    /// Desired position, rev.
    pub p: f64,
    /// Desired velocity, rev/s.
    pub v: f64,
    /// Stiffness, N m/rev (>= 0).
    pub kp: f64,
    /// Damping, N m s/rev (>= 0).
    pub kd: f64,
    /// Feedforward torque, N m.
    pub t_ff: f64,
}

impl Impedance {
    /// The torque at position `p` and velocity `v`, clamped to
    /// `+-limit_nm`, N m (NaN gives 0).
    pub fn torque(&self, p: f64, v: f64, limit_nm: f64) -> f64 {
        let t = self.kp * (self.p - p) + self.kd * (self.v - v) + self.t_ff;
        if t.is_nan() {
            0.0
        } else {
            t.clamp(-limit_nm, limit_nm)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::trajectory::Trapezoid;
    use super::*;

    #[test]
    fn impedance_is_a_spring_and_damper_within_the_limit() {
        let c = Impedance {
            p: 1.0,
            v: 0.0,
            kp: 2.0,
            kd: 0.01,
            t_ff: 0.1,
        };
        // 2 N m/rev x 0.1 rev + 0.01 x -(-5) + 0.1 = 0.35 N m.
        assert!((c.torque(0.9, -5.0, 1.0) - 0.35).abs() < 1e-12);
        assert_eq!(c.torque(-10.0, 0.0, 1.0), 1.0);
        assert_eq!(c.torque(f64::NAN, 0.0, 1.0), 0.0);
    }

    /// The loop on a rigid inertia it knows exactly, stepped finely: the
    /// feedforward makes the move, the error stays tiny and ends at zero.
    #[test]
    fn position_loop_follows_a_trapezoid_on_a_known_inertia() {
        let j = 8.1e-5;
        let g = PositionGains {
            kp: 100.0,
            vel: PiGains {
                kp: 0.25,
                ki: 30.0,
                limit_nm: 1.0,
            },
            inertia_kg_m2: j,
        };
        let tr = Trapezoid::new(0.0, 1.0, 20.0, 500.0).unwrap();
        let dt = 1.0 / 16_000.0;
        let (mut p, mut v) = (0.0, 0.0);
        let mut pi = VelocityPi::default();
        let mut worst: f64 = 0.0;
        for k in 0..3200 {
            let sp = tr.at(k as f64 * dt);
            let t = position_step(&g, &mut pi, &sp, p, v, dt);
            let acc = t / (j * RAD_PER_REV);
            p += v * dt + 0.5 * acc * dt * dt;
            v += acc * dt;
            // The plant is now one step on.
            worst = worst.max((tr.at((k + 1) as f64 * dt).p - p).abs());
        }
        assert!(
            worst * 4096.0 < 1.0,
            "following error {} counts",
            worst * 4096.0
        );
        assert!((p - 1.0).abs() * 4096.0 < 0.01);
    }
}
