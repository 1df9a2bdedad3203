//! The outer loops on the PS over the torque loop of the mode: velocity,
//! position (trapezoidal trajectory + position loop with velocity and
//! acceleration feedforward) and impedance, with the multi-turn position
//! and velocity they feed back, the `move` recorder and the soft limits.
//!
//! They run every control period (64 kHz in MPDTC, 16 kHz in FOC) and give
//! the torque reference the FOC or the PL's MPDTC loop follows; the
//! arithmetic is `models::motion`'s. The last of `torque`, `vel`, `pos`,
//! `imp` (or `step`, `move`) selects the loop; the gates going off (any
//! reason) return to the torque loop at 0 N m. A loop selected while the
//! MPDTC aligns the rotor starts at the first period after the alignment,
//! from the position then.
use models::motion::law::{position_step, Impedance, PositionGains};
use models::motion::position::{PositionEstimator, TRACKING_BANDWIDTH_RAD_S};
use models::motion::trajectory::{Setpoint, Trapezoid};
use models::motion::velocity::{PiGains, Ramp, VelocityPi};
use models::validate::{check_finite, check_nonneg, check_pos, ParamError};

/// Overspeed trip: this factor above `vel_limit`.
pub const OVERSPEED_MARGIN: f64 = 1.1;
/// `move`'s settling band, counts.
pub const MOVE_BAND_COUNTS: f64 = 2.0;
/// Longest `move` window after the trajectory, s.
pub const MOVE_WINDOW_MAX_S: f64 = 0.5;

/// The outer loops' parameters (`config`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionConfig {
    /// Velocity PI proportional gain, N m s/rev.
    pub vel_kp: f64,
    /// Velocity PI integral gain, N m/rev.
    pub vel_ki: f64,
    /// Position gain, 1/s.
    pub pos_kp: f64,
    /// Inertia the acceleration feedforward assumes, kg m^2.
    pub load_inertia_kg_m2: f64,
    /// Trajectory velocity limit, rev/s (also `vel`'s acceleration limit's partner).
    pub traj_vel_limit: f64,
    /// Trajectory (and `vel`) acceleration limit, rev/s^2.
    pub traj_accel_limit: f64,
    /// Largest velocity command, rev/s; `OVERSPEED` latches above it by
    /// [`OVERSPEED_MARGIN`].
    pub vel_limit: f64,
    /// Soft limits, rev: `POSITION_LIMIT` latches outside them.
    pub pos_min: f64,
    /// See `pos_min`.
    pub pos_max: f64,
    /// Largest `imp` stiffness, N m/rev.
    pub imp_kp_max: f64,
    /// Largest `imp` damping, N m s/rev.
    pub imp_kd_max: f64,
}

impl Default for MotionConfig {
    /// Robust to a load the drive was not told about: every `move` stays
    /// stable and ends within 2 counts with the true inertia anywhere from
    /// 0.3 to 10 times `load_inertia` (the paper's bare rotor, 8.1e-5
    /// kg m^2: 2.4e-5 to 8.1e-4) and Coulomb friction up to 5 % of the
    /// torque limit (`drivectl`'s `motion::tests::robustness_table`). The
    /// velocity loop's bandwidth `vel_kp / (2 pi J)` is 156 Hz on the bare
    /// rotor and 16 Hz at 10x, still 2.5 times the position loop's 40/s;
    /// its integrator a fifth of the bare rotor's (`vel_ki / vel_kp` =
    /// 120/s); 100 rev/s^2 needs half the 1 N m torque limit at 10x (500
    /// rev/s^2 would need 2.5 N m: the trajectory ran away from the rotor
    /// and the move overshot by 0.7 rev). A known inertia J
    /// (`calibrate mechanics`) allows the faster gain rule of the README
    /// ("Tuning the outer loops"): `vel_kp` = 3100 J, `vel_ki` = 120
    /// `vel_kp`, `pos_kp` = 100, `traj_accel_limit` = 0.25 `torque_limit` /
    /// (2 pi J).
    fn default() -> Self {
        Self {
            vel_kp: 0.5,
            vel_ki: 60.0,
            pos_kp: 40.0,
            load_inertia_kg_m2: 8.1e-5,
            traj_vel_limit: 20.0,
            traj_accel_limit: 100.0,
            vel_limit: 50.0,
            pos_min: -1000.0,
            pos_max: 1000.0,
            imp_kp_max: 20.0,
            imp_kd_max: 1.0,
        }
    }
}

impl MotionConfig {
    /// Checks the values together: gains >= 0, limits > 0, `pos_min < pos_max`.
    pub fn validate(&self) -> Result<(), ParamError> {
        check_nonneg("vel_kp", self.vel_kp)?;
        check_nonneg("vel_ki", self.vel_ki)?;
        check_nonneg("pos_kp", self.pos_kp)?;
        check_pos("load_inertia", self.load_inertia_kg_m2)?;
        check_pos("traj_vel_limit", self.traj_vel_limit)?;
        check_pos("traj_accel_limit", self.traj_accel_limit)?;
        check_pos("vel_limit", self.vel_limit)?;
        check_finite("pos_min", self.pos_min)?;
        check_finite("pos_max", self.pos_max)?;
        check_nonneg("imp_kp_max", self.imp_kp_max)?;
        check_nonneg("imp_kd_max", self.imp_kd_max)?;
        if self.pos_min >= self.pos_max {
            return Err(ParamError {
                field: "pos_min",
                reason: "must be below pos_max",
            });
        }
        Ok(())
    }
}

/// Why an outer-loop command was refused (nothing changed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MotionError {
    /// A position outside the soft limits: (rev, pos_min, pos_max).
    Position(f64, f64, f64),
    /// A `move` whose end is outside the soft limits (or not a number).
    MoveTarget {
        /// The distance asked for, rev.
        distance: f64,
        /// The position at the command, rev.
        from: f64,
        /// `pos_min`, `pos_max`, rev.
        limits: (f64, f64),
    },
    /// A velocity beyond `vel_limit`: (rev/s, vel_limit).
    Velocity(f64, f64),
    /// An `imp` gain negative or above its maximum: (name, value, max).
    Gain(&'static str, f64, f64),
    /// Not a finite number.
    NotFinite(&'static str),
    /// `pos zero` while the position or impedance loop holds a position.
    Holding,
    /// A `move` window outside (0, [`MOVE_WINDOW_MAX_S`]] s.
    Window(f64),
}

impl core::fmt::Display for MotionError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match *self {
            MotionError::Position(x, lo, hi) => write!(
                f,
                "{x} rev is outside the soft limits [{lo}..{hi}] rev (pos_min, pos_max)"
            ),
            // The limits first: the end position is a sum the user did not
            // type, printed rounded to the display's 6 decimals.
            MotionError::MoveTarget {
                distance,
                from,
                limits: (lo, hi),
            } => write!(
                f,
                "outside the soft limits [{lo}..{hi}] rev (pos_min, pos_max): a move by \
                 {distance} rev from {from:.6} rev would end at {:.6} rev; nothing changed",
                from + distance
            ),
            MotionError::Velocity(x, lim) => {
                write!(f, "{x} rev/s is beyond vel_limit ({lim} rev/s)")
            }
            MotionError::Gain(n, x, max) => write!(f, "{n} {x} is outside [0..{max}]"),
            MotionError::NotFinite(n) => write!(f, "{n} must be a finite number"),
            MotionError::Holding => {
                f.write_str("the position or impedance loop holds a position (`torque 0` first)")
            }
            MotionError::Window(w) => write!(
                f,
                "window {} ms is outside (0, {}] ms",
                w * 1e3,
                MOVE_WINDOW_MAX_S * 1e3
            ),
        }
    }
}

/// Which loop writes the torque reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LoopKind {
    /// `torque`, `step`, `sweep`: the reference as given.
    #[default]
    Torque,
    /// `vel`.
    Velocity,
    /// `pos`, `move`.
    Position,
    /// `imp`.
    Impedance,
}

impl LoopKind {
    /// Console name.
    pub fn name(self) -> &'static str {
        match self {
            LoopKind::Torque => "torque",
            LoopKind::Velocity => "velocity",
            LoopKind::Position => "position",
            LoopKind::Impedance => "impedance",
        }
    }
}

/// What `status` shows of the outer loops.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MotionStatus {
    /// The active loop.
    pub kind: LoopKind,
    /// Multi-turn position, rev.
    pub position_rev: f64,
    /// Counts since the last zero.
    pub counts: i64,
    /// Velocity estimate, rev/s.
    pub velocity_rev_s: f64,
    /// Position reference, rev (position and impedance loops).
    pub position_ref_rev: f64,
    /// Velocity reference, rev/s (outer loops).
    pub velocity_ref_rev_s: f64,
    /// Position reference minus position, counts (outer loops).
    pub following_error_counts: f64,
}

/// Figures of one `move`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoveResult {
    /// Distance, rev.
    pub distance_rev: f64,
    /// Trajectory duration, s.
    pub move_time_s: f64,
    /// From the trajectory's end until the position stays within
    /// +-[`MOVE_BAND_COUNTS`] of the target, s; `None`: not within the window.
    pub settling_s: Option<f64>,
    /// Largest travel past the target in the direction of the move, counts.
    pub overshoot_counts: f64,
    /// Largest |position reference - position| during the run, counts.
    pub max_following_error_counts: f64,
    /// Target - position at the window's end, counts.
    pub final_error_counts: f64,
    /// Window after the trajectory, s.
    pub window_s: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
struct MoveRun {
    distance: f64,
    window_s: f64,
    /// Planned at the first running period.
    traj: Option<Trapezoid>,
    max_fe: f64,
    overshoot: f64,
    /// Time after the trajectory's end of the last sample outside the band.
    last_out_s: Option<f64>,
    result: Option<MoveResult>,
}

/// The outer loops' state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Motion {
    est: PositionEstimator,
    kind: LoopKind,
    pi: VelocityPi,
    ramp: Ramp,
    vel_target: f64,
    /// Position loop: target waiting for the first running period.
    pending_target: Option<f64>,
    traj: Option<Trapezoid>,
    /// Periods since the trajectory's start.
    k: u64,
    imp: Impedance,
    sp: Setpoint,
    mv: Option<MoveRun>,
    /// The last reference computed, N m.
    torque_nm: f64,
}

impl Motion {
    /// Torque loop, position 0.
    pub fn new(cpr: u32) -> Result<Self, ParamError> {
        Ok(Self {
            est: PositionEstimator::new(cpr, TRACKING_BANDWIDTH_RAD_S)?,
            kind: LoopKind::Torque,
            pi: VelocityPi::default(),
            ramp: Ramp::default(),
            vel_target: 0.0,
            pending_target: None,
            traj: None,
            k: 0,
            imp: Impedance::default(),
            sp: Setpoint::default(),
            mv: None,
            torque_nm: 0.0,
        })
    }

    /// The active loop.
    pub fn kind(&self) -> LoopKind {
        self.kind
    }

    /// The estimator (position, velocity).
    pub fn estimator(&self) -> &PositionEstimator {
        &self.est
    }

    /// Takes this period's encoder reading (every period, gates on or
    /// off) with the torque reference of the period that ended, N m: over
    /// `inertia` (kg m^2) the acceleration the estimator expects.
    pub fn measure(&mut self, pos: u32, dt_s: f64, torque_nm: f64, inertia: f64) {
        let a = torque_nm / (inertia * models::motion::RAD_PER_REV);
        self.est.update_with_accel(pos, dt_s, a);
    }

    /// Back to the torque loop (gates off, `torque`, `step`); a `move`
    /// in progress ends without a result.
    pub fn to_torque(&mut self) {
        self.kind = LoopKind::Torque;
        self.pending_target = None;
        self.traj = None;
        self.mv = None;
    }

    fn start(&mut self, kind: LoopKind) {
        if self.kind != kind {
            self.pi = VelocityPi::default();
            self.ramp.value = self.est.velocity_rev_s();
        }
        self.kind = kind;
        self.mv = None;
    }

    /// `vel <rev/s>`.
    pub fn set_velocity(&mut self, c: &MotionConfig, v: f64) -> Result<(), MotionError> {
        if !v.is_finite() {
            return Err(MotionError::NotFinite("velocity"));
        }
        if libm::fabs(v) > c.vel_limit {
            return Err(MotionError::Velocity(v, c.vel_limit));
        }
        self.start(LoopKind::Velocity);
        self.vel_target = v;
        Ok(())
    }

    /// `pos <rev>`: a trajectory to `target` from where the loop is.
    pub fn set_position(&mut self, c: &MotionConfig, target: f64) -> Result<(), MotionError> {
        check_target(c, target)?;
        self.start(LoopKind::Position);
        self.pending_target = Some(target);
        Ok(())
    }

    /// The arguments of [`Self::begin_move`] checked against the present
    /// position and the soft limits; nothing changes.
    pub fn check_move(
        &self,
        c: &MotionConfig,
        distance: f64,
        window_s: f64,
    ) -> Result<(), MotionError> {
        if !distance.is_finite() {
            return Err(MotionError::NotFinite("distance"));
        }
        if !(window_s > 0.0 && window_s <= MOVE_WINDOW_MAX_S) {
            return Err(MotionError::Window(window_s));
        }
        let from = self.est.position_rev();
        if !(c.pos_min..=c.pos_max).contains(&(from + distance)) {
            return Err(MotionError::MoveTarget {
                distance,
                from,
                limits: (c.pos_min, c.pos_max),
            });
        }
        Ok(())
    }

    /// A `pos` target checked against the soft limits; nothing changes.
    pub fn check_position(c: &MotionConfig, target: f64) -> Result<(), MotionError> {
        check_target(c, target)
    }

    /// `move <rev> [<window>]`: a move by `distance` from the position at
    /// its start, then `window_s` of holding; [`Self::move_result`] after.
    pub fn begin_move(
        &mut self,
        c: &MotionConfig,
        distance: f64,
        window_s: f64,
    ) -> Result<(), MotionError> {
        self.check_move(c, distance, window_s)?;
        self.start(LoopKind::Position);
        self.pending_target = None;
        self.traj = None;
        self.mv = Some(MoveRun {
            distance,
            window_s,
            traj: None,
            max_fe: 0.0,
            overshoot: 0.0,
            last_out_s: None,
            result: None,
        });
        Ok(())
    }

    /// `imp ...`.
    pub fn set_impedance(
        &mut self,
        c: &MotionConfig,
        imp: &Impedance,
        torque_limit_nm: f64,
    ) -> Result<(), MotionError> {
        for (n, x) in [
            ("position", imp.p),
            ("velocity", imp.v),
            ("kp", imp.kp),
            ("kd", imp.kd),
            ("torque_ff", imp.t_ff),
        ] {
            if !x.is_finite() {
                return Err(MotionError::NotFinite(n));
            }
        }
        check_target(c, imp.p)?;
        if libm::fabs(imp.v) > c.vel_limit {
            return Err(MotionError::Velocity(imp.v, c.vel_limit));
        }
        if !(0.0..=c.imp_kp_max).contains(&imp.kp) {
            return Err(MotionError::Gain("kp", imp.kp, c.imp_kp_max));
        }
        if !(0.0..=c.imp_kd_max).contains(&imp.kd) {
            return Err(MotionError::Gain("kd", imp.kd, c.imp_kd_max));
        }
        if libm::fabs(imp.t_ff) > torque_limit_nm {
            return Err(MotionError::Gain(
                "|torque_ff| (Nm)",
                imp.t_ff,
                torque_limit_nm,
            ));
        }
        self.start(LoopKind::Impedance);
        self.imp = *imp;
        Ok(())
    }

    /// `pos zero`: the present position becomes 0 (refused while a
    /// position is held: its reference would jump).
    pub fn zero(&mut self) -> Result<(), MotionError> {
        if matches!(self.kind, LoopKind::Position | LoopKind::Impedance) {
            return Err(MotionError::Holding);
        }
        self.est.zero();
        Ok(())
    }

    /// The `move` figures once its window is over.
    pub fn move_result(&self) -> Option<MoveResult> {
        self.mv.and_then(|m| m.result)
    }

    /// Whether a `move` is waiting or running.
    pub fn move_pending(&self) -> bool {
        self.kind == LoopKind::Position && self.mv.is_some_and(|m| m.result.is_none())
    }

    /// One running control period of an outer loop: the torque reference,
    /// N m, clamped to `limit_nm`; `None` in the torque loop.
    pub fn step(&mut self, c: &MotionConfig, limit_nm: f64, dt_s: f64) -> Option<f64> {
        let p = self.est.position_rev();
        let v = self.est.velocity_rev_s();
        let gains = PositionGains {
            kp: c.pos_kp,
            vel: PiGains {
                kp: c.vel_kp,
                ki: c.vel_ki,
                limit_nm,
            },
            inertia_kg_m2: c.load_inertia_kg_m2,
        };
        let t = match self.kind {
            LoopKind::Torque => return None,
            LoopKind::Velocity => {
                let r = self.ramp.step(self.vel_target, c.traj_accel_limit, dt_s);
                self.sp = Setpoint { p, v: r, a: 0.0 };
                self.pi.step(&gains.vel, r, v, 0.0, dt_s)
            }
            LoopKind::Impedance => {
                self.sp = Setpoint {
                    p: self.imp.p,
                    v: self.imp.v,
                    a: 0.0,
                };
                self.imp.torque(p, v, limit_nm)
            }
            LoopKind::Position => {
                self.plan(c, p);
                self.sp = match &self.traj {
                    Some(tr) => tr.at(self.k as f64 * dt_s),
                    None => Setpoint { p, v: 0.0, a: 0.0 },
                };
                self.k += 1;
                self.score_move(p, dt_s);
                position_step(&gains, &mut self.pi, &self.sp, p, v, dt_s)
            }
        };
        self.torque_nm = t;
        Some(t)
    }

    /// Plans a pending trajectory from the present reference (or position).
    fn plan(&mut self, c: &MotionConfig, p: f64) {
        let target = match (self.pending_target.take(), &mut self.mv) {
            (Some(t), _) => t,
            (None, Some(m)) if m.traj.is_none() => p + m.distance,
            _ => return,
        };
        let from = match self.traj {
            Some(_) => self.sp.p,
            None => p,
        };
        self.traj = Trapezoid::new(from, target, c.traj_vel_limit, c.traj_accel_limit).ok();
        self.k = 0;
        if let (Some(m), Some(tr)) = (&mut self.mv, self.traj) {
            m.traj = Some(tr);
        }
    }

    /// The `move` figures of this period (the reference is one period on).
    fn score_move(&mut self, p: f64, dt_s: f64) {
        let Some(m) = &mut self.mv else { return };
        let Some(tr) = m.traj else { return };
        if m.result.is_some() {
            return;
        }
        let cpr = f64::from(self.est.cpr());
        let target = tr.target();
        let dir = if m.distance < 0.0 { -1.0 } else { 1.0 };
        m.max_fe = m.max_fe.max(libm::fabs(self.sp.p - p) * cpr);
        m.overshoot = m.overshoot.max((p - target) * dir * cpr);
        let t_after = self.k as f64 * dt_s - tr.duration_s();
        if t_after < 0.0 {
            return;
        }
        let err = (target - p) * cpr;
        if libm::fabs(err) > MOVE_BAND_COUNTS {
            m.last_out_s = Some(t_after);
        }
        if t_after + 0.5 * dt_s >= m.window_s {
            m.result = Some(MoveResult {
                distance_rev: m.distance,
                move_time_s: tr.duration_s(),
                settling_s: match m.last_out_s {
                    None => Some(0.0),
                    Some(t) if t + 1.5 * dt_s < m.window_s => Some(t + dt_s),
                    Some(_) => None,
                },
                overshoot_counts: m.overshoot,
                max_following_error_counts: m.max_fe,
                final_error_counts: err,
                window_s: m.window_s,
            });
        }
    }

    /// What `status` shows.
    pub fn status(&self) -> MotionStatus {
        let p = self.est.position_rev();
        let outer = self.kind != LoopKind::Torque;
        MotionStatus {
            kind: self.kind,
            position_rev: p,
            counts: self.est.counts(),
            velocity_rev_s: self.est.velocity_rev_s(),
            position_ref_rev: if outer { self.sp.p } else { p },
            velocity_ref_rev_s: if outer { self.sp.v } else { 0.0 },
            following_error_counts: if outer {
                (self.sp.p - p) * f64::from(self.est.cpr())
            } else {
                0.0
            },
        }
    }

    /// The soft-limit and overspeed checks (gates on): which trip.
    pub fn limits_violated(&self, c: &MotionConfig) -> (bool, bool) {
        let p = self.est.position_rev();
        let v = self.est.velocity_rev_s();
        (
            !(c.pos_min..=c.pos_max).contains(&p),
            libm::fabs(v) > c.vel_limit * OVERSPEED_MARGIN,
        )
    }
}

fn check_target(c: &MotionConfig, target: f64) -> Result<(), MotionError> {
    if !target.is_finite() {
        return Err(MotionError::NotFinite("position"));
    }
    if !(c.pos_min..=c.pos_max).contains(&target) {
        return Err(MotionError::Position(target, c.pos_min, c.pos_max));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn refused_commands_change_nothing() {
        let c = MotionConfig::default();
        let mut m = Motion::new(4096).unwrap();
        m.set_velocity(&c, 5.0).unwrap();
        let before = m;
        assert_eq!(
            m.set_velocity(&c, 60.0),
            Err(MotionError::Velocity(60.0, 50.0))
        );
        assert!(m.set_velocity(&c, f64::NAN).is_err());
        assert!(m.set_position(&c, 1e4).is_err());
        assert!(m.begin_move(&c, 1.0, 0.0).is_err());
        let bad = Impedance {
            kp: -1.0,
            ..Impedance::default()
        };
        assert!(m.set_impedance(&c, &bad, 1.0).is_err());
        let bad = Impedance {
            kd: 2.0,
            ..Impedance::default()
        };
        assert!(m.set_impedance(&c, &bad, 1.0).is_err());
        let bad = Impedance {
            t_ff: 1.5,
            ..Impedance::default()
        };
        assert!(m.set_impedance(&c, &bad, 1.0).is_err());
        assert_eq!(m, before);
        m.set_position(&c, 0.5).unwrap();
        assert_eq!(m.zero(), Err(MotionError::Holding));
    }

    #[test]
    fn a_move_on_an_ideal_inertia_is_scored() {
        // Rotor of 8.1e-5 kg m^2 driven by the torque reference directly,
        // the encoder quantised to 4096 counts: the default tuning moves 1
        // rev at 100 rev/s^2 (a triangle peaking at 10 rev/s) in 200 ms
        // and settles at once.
        let c = MotionConfig::default();
        let (j, dt) = (8.1e-5 * core::f64::consts::TAU, 1.0 / 16_000.0);
        let mut m = Motion::new(4096).unwrap();
        m.measure(0, dt, 0.0, c.load_inertia_kg_m2);
        m.begin_move(&c, 1.0, 0.02).unwrap();
        let (mut p, mut v) = (0.0f64, 0.0f64);
        let mut n = 0;
        while m.move_result().is_none() {
            let t = m.step(&c, 1.0, dt).unwrap();
            p += v * dt + 0.5 * t / j * dt * dt;
            v += t / j * dt;
            let count = (libm::floor(p * 4096.0) as i64).rem_euclid(4096) as u32;
            m.measure(count, dt, t, c.load_inertia_kg_m2);
            n += 1;
            assert!(n < 20_000);
        }
        let r = m.move_result().unwrap();
        assert!((r.move_time_s - 0.2).abs() < 1e-9);
        assert!(r.final_error_counts.abs() <= 1.0, "{r:?}");
        assert!(r.settling_s.unwrap() <= 5e-3, "{r:?}");
        assert!(r.overshoot_counts <= 2.0, "{r:?}");
    }
}
