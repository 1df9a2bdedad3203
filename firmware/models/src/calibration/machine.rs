//! The calibration's state machine: one [`Calibrator::step`] per control
//! period. Each phase is a short script of stages (counted in periods);
//! the fits accumulate sums as the samples arrive and are solved when the
//! phase ends.
use super::fit::{Lsq, Mean};
use super::mech::{self, first, level, reversed, Spin, Window, COUNT_PAIR_SIGMA, LEVELS, WINDOWS};
use super::{
    bounds, Command, EncoderEst, Estimate, Measurement, MechEst, Outcome, Phase, Results, Setup,
};
use crate::frames::{clarke, inv_park, park};
use core::f64::consts::{PI, TAU};

/// Periods per electrical turn of the encoder phase's field (80 Hz at the
/// 16 kHz PWM rate).
const TURN_STEPS: u32 = 200;
/// A raised-cosine speed ramp of this many periods covers exactly one turn.
const RAMP_STEPS: u32 = 2 * TURN_STEPS;
/// Electrical turns fitted in each direction.
const FIT_TURNS: u32 = 6;
/// Most electrical turns forwards before the index must have passed (64
/// pole pairs and a margin).
const MAX_TURNS: u32 = 80;
/// Encoder counts below which the rotor did not follow the field: locked.
const LOCKED_COUNTS: i64 = 8;
/// Resistance levels, fractions of the calibration current.
const R_LEVELS: [f64; 4] = [0.5, 2.0 / 3.0, 5.0 / 6.0, 1.0];
/// Periods to settle at a level, and to average it.
const R_SETTLE: u32 = 160;
const R_AVG: u32 = 256;
/// Periods of each voltage step of the inductance phase (4 steps).
const L_STEP: u32 = 192;
const L_STEPS: usize = 4;
/// Periods of the settle and average windows at each spin speed.
const SPIN_SETTLE: u32 = 768;
const SPIN_AVG: u32 = 512;
/// Spin speeds, fractions of the top speed.
const SPIN_LEVELS: [f64; LEVELS] = [0.35, 0.65, 0.95];
/// Periods from a reversal of i_d to the next window: the current settles
/// in a few periods, the speed loop takes up most of the torque step the
/// frame's error makes of it (its windows follow the rest).
const FLIP_SETTLE: u32 = 256;

/// Periods over which the speed is measured for the speed loop.
const SPEED_WINDOW: usize = 16;
/// Current ramp periods (up or down).
const CURRENT_RAMP: u32 = 160;
/// d-axis current while spinning, fraction of the calibration current.
const SPIN_ID: f64 = 0.5;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Stage {
    Next,
    EncAlign,
    EncFwdRamp,
    EncFwd,
    EncFwdStop,
    EncBwdRamp,
    EncBwd,
    EncBwdStop,
    EncHold,
    RLevel(usize),
    LStep(usize),
    SpinPre,
    SpinAccel(usize),
    SpinSettle(usize),
    /// Window `h` (see [`mech::WINDOWS`]).
    SpinAvg(usize),
    /// i_d reversed before window `h`, settling.
    SpinFlip(usize),
    SpinStop,
    Release,
    Finished,
}

/// Current PI in a rotating frame, output clamped to a circle.
#[derive(Debug, Clone, Copy, Default)]
struct Pi {
    kp: f64,
    ki_t: f64,
    int: (f64, f64),
    vmax: f64,
}

/// Finite and above zero (NaN is not).
fn positive(x: f64) -> bool {
    x > 0.0 && x.is_finite()
}

/// The estimates with no bound on their errors (infinite sigmas).
fn unbounded(e: MechEst) -> MechEst {
    let inf = |v: Estimate| Estimate {
        sigma: f64::INFINITY,
        ..v
    };
    MechEst {
        j: inf(e.j),
        b: inf(e.b),
        coulomb: inf(e.coulomb),
    }
}

/// A friction, which cannot be negative: a fit below zero is reported as
/// zero with its sigma, which still covers the truth (the truth is at
/// least zero, so it is nearer zero than the fit).
fn non_negative((value, sigma): (f64, f64)) -> Estimate {
    Estimate {
        value: value.max(0.0),
        sigma,
    }
}

fn clamp_circle((x, y): (f64, f64), r: f64) -> (f64, f64) {
    let m = libm::hypot(x, y);
    if m > r && m > 0.0 {
        (x * r / m, y * r / m)
    } else {
        (x, y)
    }
}

impl Pi {
    fn new(r: f64, l: f64, t: f64, vmax: f64) -> Self {
        // 250 Hz bandwidth: a quarter radian of lag from the two-period
        // delay at the crossover.
        let w = TAU * 250.0;
        Self {
            kp: l * w,
            ki_t: r * w * t,
            int: (0.0, 0.0),
            vmax,
        }
    }
    fn step(&mut self, e: (f64, f64)) -> (f64, f64) {
        self.int = clamp_circle(
            (self.int.0 + self.ki_t * e.0, self.int.1 + self.ki_t * e.1),
            self.vmax,
        );
        clamp_circle(
            (self.kp * e.0 + self.int.0, self.kp * e.1 + self.int.1),
            self.vmax,
        )
    }
}

/// Sums of a line fit `y = s x + c` (per direction of the encoder phase).
#[derive(Debug, Clone, Copy, Default)]
struct Line {
    n: f64,
    x: f64,
    y: f64,
    xx: f64,
    xy: f64,
    yy: f64,
}

impl Line {
    fn add(&mut self, x: f64, y: f64) {
        self.n += 1.0;
        self.x += x;
        self.y += y;
        self.xx += x * x;
        self.xy += x * y;
        self.yy += y * y;
    }
    fn slope(&self) -> f64 {
        let sxx = self.xx - self.x * self.x / self.n;
        (self.xy - self.x * self.y / self.n) / sxx
    }
    /// Mean and standard deviation of `y - s x` for a given slope.
    fn offset(&self, s: f64) -> (f64, f64) {
        let mean = (self.y - s * self.x) / self.n;
        let sq = self.yy - 2.0 * s * self.xy + s * s * self.xx;
        let var = (sq / self.n - mean * mean).max(0.0);
        (mean, libm::sqrt(var))
    }
}

/// The means of one averaging window: v_d, v_q, i_d, i_q (V, A; the
/// flux fit), then the running quantities at the ends of its periods:
/// angle (rad), time (s), integrals of i_d and i_q over time (A s) and
/// over the angle (A rad; the mechanics fit).
type WindowMeans = [Mean; 10];

/// The calibration in progress (see the module doc of [`super`]).
pub struct Calibrator {
    s: Setup,
    res: Results,
    stage: Stage,
    n: u32,
    k: u64,
    phase: Option<Phase>,
    /// Phases still to run, in order.
    todo: [Option<Phase>; 5],
    todo_i: usize,
    // Encoder tracking.
    raw: u32,
    raw_prev: u32,
    pos_u: i64,
    pos_u_prev: i64,
    hist: [i64; SPEED_WINDOW + 1],
    started: bool,
    // Commands issued 2 and 1 steps ago: voltage and frame angle.
    issued: [((f64, f64), f64); 2],
    pi: Pi,
    i_ref: (f64, f64),
    /// Field angle of the encoder phase (unwrapped), rad.
    theta_ref: f64,
    travel: i64,
    turns: u32,
    fit_turn0: Option<u32>,
    x0: Option<(i64, u32)>,
    lines: [Line; 2],
    dir_idx: usize,
    locked: bool,
    /// +1 or -1: the encoder's counting direction with the field, from
    /// the first turn (0 before).
    s_r: f64,
    /// Mean mechanical speed of the encoder phase's damping, rad/s.
    w_avg: f64,
    // Resistance.
    r_v: [Mean; 4],
    r_i: [Mean; 4],
    r_fit: Option<(f64, f64, f64)>,
    // Inductance.
    l_fit: Lsq<3>,
    l_v: [(f64, f64); 2],
    i_prev: f64,
    // Spin.
    w_ref: f64,
    w_int: f64,
    /// Integrals of the measured (i_d, i_q) over time, A s.
    i_int: (f64, f64),
    /// Integrals of the measured (i_d, i_q) over the mechanical angle, A rad.
    i_th: (f64, f64),
    spin_v: [WindowMeans; WINDOWS],
    /// Each window's (position counts, period) at its start and end.
    spin_pos: [[(i64, u64); 2]; WINDOWS],
    spin_top: f64,
    spin_start: i64,
    spin_done: bool,
    last_i: (f64, f64),
}

impl Calibrator {
    /// A calibration of `setup` (checked by [`Setup::validate`] first).
    pub fn new(setup: &Setup) -> Self {
        let mut todo = [None; 5];
        let mut n = 0;
        for p in Phase::ALL {
            let needed = setup.phases.has(p)
                // L needs the R levels; mechanics and flux share the spin.
                || (p == Phase::Resistance && setup.phases.has(Phase::Inductance));
            if needed && !(p == Phase::Mechanics && setup.phases.has(Phase::Flux)) {
                todo[n] = Some(p);
                n += 1;
            }
        }
        let m = &setup.motor;
        Self {
            s: *setup,
            res: Results::default(),
            stage: Stage::Next,
            n: 0,
            k: 0,
            phase: None,
            todo,
            todo_i: 0,
            raw: 0,
            raw_prev: 0,
            pos_u: 0,
            pos_u_prev: 0,
            hist: [0; SPEED_WINDOW + 1],
            started: false,
            issued: [((0.0, 0.0), 0.0); 2],
            pi: Pi::new(m.r_s_ohm, m.l_d_h, setup.period_s, setup.voltage_v),
            i_ref: (0.0, 0.0),
            theta_ref: 0.0,
            travel: 0,
            turns: 0,
            fit_turn0: None,
            x0: None,
            lines: [Line::default(); 2],
            dir_idx: 0,
            locked: false,
            s_r: 0.0,
            w_avg: 0.0,
            r_v: [Mean::default(); 4],
            r_i: [Mean::default(); 4],
            r_fit: None,
            l_fit: Lsq::default(),
            l_v: [(0.0, 0.0); 2],
            i_prev: 0.0,
            w_ref: 0.0,
            w_int: 0.0,
            i_int: (0.0, 0.0),
            i_th: (0.0, 0.0),
            spin_v: [[Mean::default(); 10]; WINDOWS],
            spin_pos: [[(0, 0); 2]; WINDOWS],
            spin_top: 0.0,
            spin_start: 0,
            spin_done: false,
            last_i: (0.0, 0.0),
        }
    }

    /// The phase running now (`None` before the first step and at the end).
    pub fn phase(&self) -> Option<Phase> {
        self.phase
    }

    /// What was found so far (all of it after [`Command::Done`]).
    pub fn results(&self) -> &Results {
        &self.res
    }

    /// Stops now: the running phase and those after it are refused with
    /// `why`; the next step answers [`Command::Done`].
    pub fn abort(&mut self, why: &'static str) {
        if let Some(p) = self.phase {
            self.refuse(p, why);
        }
        while let Some(p) = self.todo.get(self.todo_i).copied().flatten() {
            self.refuse(p, why);
            self.todo_i += 1;
        }
        self.stage = Stage::Finished;
        self.phase = None;
    }

    fn refuse(&mut self, p: Phase, why: &'static str) {
        match p {
            Phase::Encoder => self.res.encoder = Outcome::Refused(why),
            Phase::Resistance => {
                if self.s.phases.has(Phase::Resistance) {
                    self.res.resistance = Outcome::Refused(why)
                }
                if self.s.phases.has(Phase::Inductance) {
                    self.res.inductance = Outcome::Refused(why)
                }
            }
            Phase::Inductance => self.res.inductance = Outcome::Refused(why),
            Phase::Flux | Phase::Mechanics => {
                if self.s.phases.has(Phase::Flux) {
                    self.res.flux = Outcome::Refused(why);
                }
                if self.s.phases.has(Phase::Mechanics) {
                    self.res.mechanics = Outcome::Refused(why);
                }
            }
        }
    }

    fn cpr(&self) -> f64 {
        f64::from(self.s.cpr)
    }

    /// Best knowledge of (direction, pole pairs, zero counts).
    fn rotor_model(&self) -> (f64, f64, f64) {
        match self.res.encoder {
            Outcome::Done(e) | Outcome::Poor(e, _) => {
                (f64::from(e.dir), f64::from(e.pole_pairs), e.zero_exact)
            }
            _ => (
                1.0,
                f64::from(self.s.motor.pole_pairs),
                f64::from(self.s.enc_zero),
            ),
        }
    }

    fn rotor_angle(&self, pos: f64) -> f64 {
        let (dir, p, zero) = self.rotor_model();
        dir * p * TAU * (pos - zero) / self.cpr()
    }

    fn r_best(&self) -> f64 {
        self.r_fit.map_or(self.s.motor.r_s_ohm, |f| f.0)
    }
    fn l_best(&self) -> f64 {
        match self.res.inductance {
            Outcome::Done(e) => e.value,
            _ => self.s.motor.l_d_h,
        }
    }
    fn psi_best(&self) -> f64 {
        match self.res.flux {
            Outcome::Done(e) => e.value,
            _ => self.s.motor.psi_pm_wb,
        }
    }

    /// Mechanical speed over the last [`SPEED_WINDOW`] periods, rad/s (rotor
    /// positive direction).
    fn speed_m(&self) -> f64 {
        let (dir, _, _) = self.rotor_model();
        let d = self.pos_u - self.hist[0];
        dir * d as f64 * TAU / self.cpr() / (SPEED_WINDOW as f64 * self.s.period_s)
    }

    /// A q-axis current against the rotor's speed, A: damps its swing
    /// about the field at standstill (zero when the encoder's direction
    /// and pole pairs are not measured in this run: a wrong sign would
    /// excite it).
    fn damping_a(&self) -> f64 {
        if self.res.encoder.good().is_none() {
            return 0.0;
        }
        let (_, p, _) = self.rotor_model();
        let kt = 1.5 * p * self.s.motor.psi_pm_wb;
        let i = -self.s.motor.j_kg_m2 * TAU * 30.0 / kt * self.speed_m();
        i.clamp(-0.5 * self.s.current_a, 0.5 * self.s.current_a)
    }

    /// The encoder phase's damping: a q-axis current (field frame) against
    /// the rotor's swing, the mechanical speed less its mean over about a
    /// turn (a high-pass: no pull on a steady rotation), once the first
    /// turn showed which way the encoder counts. Gain: a 30 Hz damping rate
    /// with the configured inertia, flux and pole pairs.
    fn field_damping_a(&mut self) -> f64 {
        if self.s_r == 0.0 {
            return 0.0;
        }
        let d = self.pos_u - self.hist[0];
        let w = self.s_r * d as f64 * TAU / self.cpr() / (SPEED_WINDOW as f64 * self.s.period_s);
        self.w_avg += (w - self.w_avg) * self.s.period_s / 0.025;
        let m = &self.s.motor;
        let k = m.j_kg_m2 * TAU * 30.0 / (1.5 * f64::from(m.pole_pairs) * m.psi_pm_wb);
        (-k * (w - self.w_avg)).clamp(-0.5 * self.s.current_a, 0.5 * self.s.current_a)
    }

    /// One control period: the measurement of period `k` in, the voltage
    /// for period `k + 2` out.
    pub fn step(&mut self, m: &Measurement) -> Command {
        if self.stage == Stage::Finished {
            return Command::Done;
        }
        self.track(m);
        let i_ab = clarke(m.i_abc_a);
        let big = libm::hypot(i_ab.0, i_ab.1);
        if big.is_nan() || big > 2.0 * self.s.current_a {
            self.abort("current beyond twice calibration_current");
            return Command::Done;
        }
        // The command applied in this period and its frame angle.
        let (v_app, th_app) = self.issued[0];
        let cmd = self.run(i_ab, v_app, th_app);
        self.k += 1;
        self.res.periods = self.k;
        match cmd {
            Some((v, th)) => {
                self.issued = [self.issued[1], (v, th)];
                Command::Voltage {
                    alpha_v: v.0,
                    beta_v: v.1,
                }
            }
            None => {
                self.stage = Stage::Finished;
                self.phase = None;
                Command::Done
            }
        }
    }

    fn track(&mut self, m: &Measurement) {
        let cpr = i64::from(self.s.cpr);
        let pos = i64::from(m.enc_pos % self.s.cpr);
        if !self.started {
            self.started = true;
            self.raw = pos as u32;
            self.raw_prev = pos as u32;
            return;
        }
        let mut d = (pos - i64::from(self.raw)).rem_euclid(cpr);
        if d > cpr / 2 {
            d -= cpr;
        }
        // The index pulse re-zeroes the counter once: a jump no motor makes
        // in a period (a 64th of a turn in 62.5 us: 250 rev/s) is that,
        // not motion.
        if d.abs() > (cpr / 64).max(2) {
            d = 0;
        }
        self.raw_prev = self.raw;
        self.raw = pos as u32;
        self.pos_u_prev = self.pos_u;
        self.pos_u += d;
        self.hist.rotate_left(1);
        self.hist[SPEED_WINDOW] = self.pos_u;
    }

    /// Current control in the frame at `th_meas` (measurement) and
    /// `th_cmd` (the command's period); returns the stationary voltage.
    fn current_loop(&mut self, i_ab: (f64, f64), th_meas: f64, th_cmd: f64) -> (f64, f64) {
        let (ix, iy) = park(i_ab.0, i_ab.1, th_meas);
        self.last_i = (ix, iy);
        let v = self.pi.step((self.i_ref.0 - ix, self.i_ref.1 - iy));
        inv_park(v.0, v.1, th_cmd)
    }

    fn set_stage(&mut self, st: Stage) {
        self.stage = st;
        self.n = 0;
    }

    /// The next phase, or the release of the current at the end.
    fn next_phase(&mut self) {
        match self.todo.get(self.todo_i).copied().flatten() {
            Some(p) => {
                self.todo_i += 1;
                self.phase = Some(p);
                let motion = p.needs_motion();
                if motion && self.locked {
                    self.refuse(p, "rotor locked: this phase needs the rotor to turn");
                    self.next_phase();
                    return;
                }
                match p {
                    Phase::Encoder => self.set_stage(Stage::EncAlign),
                    Phase::Resistance => self.set_stage(Stage::RLevel(0)),
                    Phase::Inductance => self.set_stage(Stage::LStep(0)),
                    Phase::Flux | Phase::Mechanics => self.set_stage(Stage::SpinPre),
                }
            }
            None => {
                self.phase = None;
                self.set_stage(Stage::Release);
            }
        }
    }

    fn ramp_to(&self, from: f64, to: f64, n: u32, len: u32) -> f64 {
        if n >= len {
            to
        } else {
            from + (to - from) * f64::from(n + 1) / f64::from(len)
        }
    }

    /// The stage machine; `None` when finished.
    fn run(
        &mut self,
        i_ab: (f64, f64),
        v_app: (f64, f64),
        th_app: f64,
    ) -> Option<((f64, f64), f64)> {
        if self.stage == Stage::Next {
            self.next_phase();
        }
        let i_cal = self.s.current_a;
        let n = self.n;
        self.n += 1;
        let w_turn = TAU / f64::from(TURN_STEPS);
        match self.stage {
            Stage::Next | Stage::Finished => None,
            Stage::Release => {
                // Current down in the frame in use, then off.
                let th = th_app;
                self.i_ref.0 = self.ramp_to(self.i_ref.0, 0.0, 0, 20);
                self.i_ref.1 = self.ramp_to(self.i_ref.1, 0.0, 0, 20);
                let v = self.current_loop(i_ab, th, th);
                if n >= 40 {
                    return None;
                }
                Some((v, th))
            }
            Stage::EncAlign => {
                self.i_ref = (i_cal * f64::from((n + 1).min(320)) / 320.0, 0.0);
                let v = self.current_loop(i_ab, th_app, self.theta_ref);
                if n + 1 >= 800 {
                    self.travel = 0;
                    self.turns = 0;
                    self.set_stage(Stage::EncFwdRamp);
                }
                Some((v, self.theta_ref))
            }
            Stage::EncFwdRamp | Stage::EncBwdRamp | Stage::EncFwdStop | Stage::EncBwdStop => {
                let x = f64::from(n) + 0.5;
                let c = libm::cos(PI * x / f64::from(RAMP_STEPS));
                let up = matches!(self.stage, Stage::EncFwdRamp | Stage::EncBwdRamp);
                let frac = if up { 0.5 * (1.0 - c) } else { 0.5 * (1.0 + c) };
                let fwd = matches!(self.stage, Stage::EncFwdRamp | Stage::EncFwdStop);
                let sgn = if fwd { 1.0 } else { -1.0 };
                self.travel += self.pos_u - self.pos_u_prev;
                self.theta_ref += sgn * w_turn * frac;
                self.i_ref.1 = self.field_damping_a();
                let v = self.current_loop(i_ab, th_app, self.theta_ref);
                if n + 1 >= RAMP_STEPS {
                    let next = match self.stage {
                        Stage::EncFwdRamp => {
                            if self.travel.abs() < LOCKED_COUNTS {
                                self.locked = true;
                                self.res.encoder = Outcome::Refused(
                                    "rotor locked: the encoder did not follow the turning field",
                                );
                                self.theta_ref = 0.0;
                                Stage::Next
                            } else {
                                // Which way the encoder counts with the field.
                                self.s_r = if self.travel > 0 { 1.0 } else { -1.0 };
                                let d = self.pos_u - self.hist[0];
                                self.w_avg = self.s_r * d as f64 * TAU
                                    / self.cpr()
                                    / (SPEED_WINDOW as f64 * self.s.period_s);
                                Stage::EncFwd
                            }
                        }
                        Stage::EncFwdStop => Stage::EncBwdRamp,
                        Stage::EncBwdRamp => Stage::EncBwd,
                        _ => Stage::EncHold,
                    };
                    self.turns = 0;
                    self.set_stage(next);
                    if next == Stage::Next {
                        // Field back to 0 without a jump: hold where it is.
                        return Some((v, th_app));
                    }
                }
                Some((v, self.theta_ref))
            }
            Stage::EncFwd | Stage::EncBwd => {
                let fwd = self.stage == Stage::EncFwd;
                self.dir_idx = usize::from(!fwd);
                self.travel += self.pos_u - self.pos_u_prev;
                let in_fit = match self.fit_turn0 {
                    Some(t0) => self.turns >= t0,
                    None => false,
                };
                if in_fit {
                    // The current vector's angle in this period against the
                    // encoder position at its middle.
                    let (ix, iy) = park(i_ab.0, i_ab.1, th_app);
                    let y = th_app + libm::atan2(iy, ix);
                    let (p0, raw0) = *self.x0.get_or_insert((self.pos_u_prev, self.raw_prev));
                    let mid = 0.5 * (self.pos_u + self.pos_u_prev) as f64 - p0 as f64;
                    let x = (f64::from(raw0) + mid) / self.cpr();
                    self.lines[self.dir_idx].add(x, y / TAU);
                }
                let w = if fwd { w_turn } else { -w_turn };
                self.theta_ref += w;
                self.i_ref.1 = self.field_damping_a();
                let v = self.current_loop(i_ab, th_app, self.theta_ref);
                if (n + 1) % TURN_STEPS == 0 {
                    self.turns += 1;
                    if self.fit_turn0.is_none() {
                        let ready = !fwd || self.travel.abs() >= self.s.cpr as i64 * 5 / 4;
                        if ready {
                            // Backwards: one settling turn first.
                            self.fit_turn0 = Some(self.turns + u32::from(!fwd));
                        } else if self.turns >= MAX_TURNS {
                            self.res.encoder = Outcome::Refused(
                                "the rotor did not make a mechanical turn in 80 electrical turns",
                            );
                            self.set_stage(Stage::EncHold);
                            return Some((v, self.theta_ref));
                        }
                    } else if let Some(t0) = self.fit_turn0 {
                        if self.turns >= t0 + FIT_TURNS {
                            self.fit_turn0 = None;
                            self.x0 = None;
                            self.set_stage(if fwd {
                                Stage::EncFwdStop
                            } else {
                                Stage::EncBwdStop
                            });
                        }
                    }
                }
                Some((v, self.theta_ref))
            }
            Stage::EncHold => {
                if n == 0 && !matches!(self.res.encoder, Outcome::Refused(_)) {
                    self.res.encoder = self.encoder_fit();
                }
                self.i_ref.1 = self.damping_a();
                let v = self.current_loop(i_ab, th_app, self.theta_ref);
                if n + 1 >= 1600 {
                    // Whole turns both ways: the field is at angle 0 again.
                    self.theta_ref = libm::remainder(self.theta_ref, TAU);
                    self.set_stage(Stage::Next);
                }
                Some((v, self.theta_ref))
            }
            Stage::RLevel(j) => {
                let level = R_LEVELS[j] * i_cal;
                // The first level starts with a ramp (the rotor, when free,
                // aligns with the field).
                let from = if j == 0 { self.i_ref.0 } else { level };
                self.i_ref = (self.ramp_to(from, level, n, CURRENT_RAMP), self.damping_a());
                if j == 0 && n < CURRENT_RAMP {
                    self.i_ref.0 =
                        from + (level - from) * f64::from(n + 1) / f64::from(CURRENT_RAMP);
                }
                let settle = if j == 0 {
                    CURRENT_RAMP + 2 * R_SETTLE
                } else {
                    R_SETTLE
                };
                if n >= settle {
                    self.r_v[j].add(v_app.0);
                    self.r_i[j].add(i_ab.0);
                }
                let v = self.current_loop(i_ab, 0.0, 0.0);
                if n + 1 >= settle + R_AVG {
                    if j + 1 < R_LEVELS.len() {
                        self.set_stage(Stage::RLevel(j + 1));
                    } else {
                        self.resistance_fit();
                        self.set_stage(Stage::Next);
                    }
                }
                Some((v, 0.0))
            }
            Stage::LStep(j) => {
                // Open loop: the mean voltages of the 0.5 and 1.0 levels.
                if j == 0 && n == 0 {
                    self.l_v = [(self.r_v[0].mean(), 0.0), (self.r_v[3].mean(), 0.0)];
                    self.i_prev = i_ab.0;
                }
                let hi = j % 2 == 1;
                if n >= 4 {
                    self.l_fit.add(
                        [
                            self.i_prev,
                            f64::from(u8::from(hi)),
                            f64::from(u8::from(!hi)),
                        ],
                        i_ab.0,
                    );
                }
                self.i_prev = i_ab.0;
                let v = self.l_v[usize::from(hi)];
                if n + 1 >= L_STEP {
                    if j + 1 < L_STEPS {
                        self.set_stage(Stage::LStep(j + 1));
                    } else {
                        self.res.inductance = self.inductance_fit();
                        // Back to current control, bumpless.
                        self.pi.int = v;
                        self.i_ref = (i_cal, 0.0);
                        self.set_stage(Stage::Next);
                    }
                }
                Some((v, 0.0))
            }
            Stage::SpinPre
            | Stage::SpinAccel(_)
            | Stage::SpinSettle(_)
            | Stage::SpinAvg(_)
            | Stage::SpinFlip(_)
            | Stage::SpinStop => Some(self.spin(i_ab, v_app, n)),
        }
    }

    fn rotor_frame_angles(&self) -> (f64, f64, f64) {
        let (_, p, _) = self.rotor_model();
        let end = self.rotor_angle(f64::from(self.raw));
        let prev = self.rotor_angle(f64::from(self.raw_prev));
        let d = libm::remainder(end - prev, TAU);
        let mid = prev + 0.5 * d;
        // The rotor angle grows at p times the mechanical speed.
        let w_e = p * self.speed_m();
        (mid, end + 1.5 * w_e * self.s.period_s, w_e)
    }

    fn spin(&mut self, i_ab: (f64, f64), v_app: (f64, f64), n: u32) -> ((f64, f64), f64) {
        let t = self.s.period_s;
        let (mid, th_cmd, _) = self.rotor_frame_angles();
        let stage = self.stage;
        if stage == Stage::SpinPre && n == 0 {
            let (_, p, _) = self.rotor_model();
            self.pi = Pi::new(self.r_best(), self.l_best(), t, self.s.voltage_v);
            self.w_ref = 0.0;
            self.w_int = 0.0;
            // Top speed: half the voltage limit as back-EMF.
            self.spin_top = 0.5 * self.s.voltage_v / self.psi_best() / p;
        }
        // The running integrals through this period: a window's means pair
        // them with the position at this period's end.
        let (id_m, iq_m) = park(i_ab.0, i_ab.1, mid);
        let dth = self.rad_per_count() * (self.pos_u - self.pos_u_prev) as f64;
        self.i_int = (self.i_int.0 + id_m * t, self.i_int.1 + iq_m * t);
        self.i_th = (self.i_th.0 + id_m * dth, self.i_th.1 + iq_m * dth);
        let id_target = match stage {
            Stage::SpinFlip(h) | Stage::SpinAvg(h) if reversed(h) => -SPIN_ID,
            _ => SPIN_ID,
        };
        self.i_ref.0 = self.ramp_to(self.i_ref.0, id_target * self.s.current_a, 0, 20);
        self.speed_loop();
        match stage {
            Stage::SpinPre => self.spin_hold(n),
            Stage::SpinAccel(j) => self.spin_accel(j, n),
            Stage::SpinSettle(j) => self.spin_settle(n, SPIN_SETTLE, first(j)),
            Stage::SpinFlip(h) => self.spin_settle(n, FLIP_SETTLE, h),
            Stage::SpinAvg(h) => {
                let (vd, vq) = park(v_app.0, v_app.1, mid);
                let th = self.rad_per_count() * (self.pos_u - self.spin_start) as f64;
                let time = self.k as f64 * t;
                let (i, it) = (self.i_int, self.i_th);
                let x = [vd, vq, id_m, iq_m, th, time, i.0, i.1, it.0, it.1];
                for (m, x) in self.spin_v[h].iter_mut().zip(x) {
                    m.add(x);
                }
                self.spin_window(h, n);
            }
            _ => {
                if self.w_ref == 0.0 && n >= 320 {
                    self.i_ref = (self.i_ref.0, 0.0);
                    self.pi.int = (self.pi.int.0, 0.0);
                    self.set_stage(Stage::Next);
                }
            }
        }
        (self.current_loop(i_ab, mid, th_cmd), th_cmd)
    }

    /// The speed of the spin's stage, rad/s.
    fn spin_target(&self) -> f64 {
        let level = match self.stage {
            Stage::SpinAccel(j) | Stage::SpinSettle(j) => j,
            Stage::SpinFlip(h) | Stage::SpinAvg(h) => level(h),
            _ => return 0.0,
        };
        SPIN_LEVELS[level] * self.spin_top
    }

    /// Speed loop (20 Hz) on the i_q reference, within the current limit,
    /// the reference ramped at half the torque the limit gives the
    /// configured inertia.
    fn speed_loop(&mut self) {
        let t = self.s.period_s;
        let i_cal = self.s.current_a;
        let (_, p, _) = self.rotor_model();
        let kt = 1.5 * p * self.psi_best();
        let j_g = self.s.motor.j_kg_m2;
        let acc = 0.5 * kt * i_cal / j_g * t;
        let dw_ref = (self.spin_target() - self.w_ref).clamp(-acc, acc);
        self.w_ref += dw_ref;
        // The reference's acceleration torque fed forward (configured J):
        // without it the integrator carried that current through the ramp
        // and the speed overshot by a quarter, still settling in the
        // averaging windows.
        let i_ff = j_g * dw_ref / t / kt;
        let ww = TAU * 20.0;
        let kp = j_g * ww / kt;
        let e = self.w_ref - self.speed_m();
        self.w_int = (self.w_int + kp * ww / 2.0 * t * e).clamp(-i_cal, i_cal);
        let iq_max = libm::sqrt((i_cal * i_cal - self.i_ref.0 * self.i_ref.0).max(0.0));
        self.i_ref.1 = (kp * e + self.w_int + i_ff).clamp(-iq_max, iq_max);
    }

    fn spin_accel(&mut self, j: usize, n: u32) {
        if j == 0 && n == 800 && (self.pos_u - self.spin_start).abs() < LOCKED_COUNTS {
            self.locked = true;
            self.refuse(
                Phase::Flux,
                "rotor locked: the back-EMF needs the rotor to turn",
            );
            self.set_stage(Stage::SpinStop);
            self.spin_done = true;
        } else if self.w_ref == self.spin_target() {
            self.set_stage(Stage::SpinSettle(j));
        }
    }

    /// Period `n` of `periods` settling before window `h`.
    fn spin_settle(&mut self, n: u32, periods: u32, h: usize) {
        if n + 1 >= periods {
            self.spin_pos[h][0] = (self.pos_u, self.k);
            self.set_stage(Stage::SpinAvg(h));
        }
    }

    /// Period `n` of window `h`; at its end the next stage (after the
    /// last, the fits).
    fn spin_window(&mut self, h: usize, n: u32) {
        if n + 1 < SPIN_AVG {
            return;
        }
        self.spin_pos[h][1] = (self.pos_u, self.k);
        if level(h + 1) == level(h) {
            self.set_stage(Stage::SpinFlip(h + 1));
        } else if h + 1 < WINDOWS {
            self.set_stage(Stage::SpinAccel(level(h + 1)));
        } else {
            self.spin_fit();
            self.spin_done = true;
            if self.s.phases.has(Phase::Mechanics) {
                // The same run gave the mechanics.
                self.phase = Some(Phase::Mechanics);
            }
            self.set_stage(Stage::SpinStop);
        }
    }

    /// Period `n` of the current's rise before the first speed (the
    /// speed loop holds the rotor: a frame error turns i_d into torque).
    fn spin_hold(&mut self, n: u32) {
        if n + 1 >= CURRENT_RAMP {
            self.spin_start = self.pos_u;
            self.set_stage(Stage::SpinAccel(0));
        }
    }

    /// Mechanical angle of one encoder count, signed with the rotor's
    /// positive direction, rad.
    fn rad_per_count(&self) -> f64 {
        let (dir, _, _) = self.rotor_model();
        dir * TAU / self.cpr()
    }

    /// Window `h`'s mean speed: the angle between its ends over its
    /// duration, rad/s.
    ///
    /// The window spans the ends of periods k0 to k0 + SPIN_AVG. Its speed
    /// once came from the counts over SPIN_AVG + 1 periods and the
    /// acceleration in it from halves of 257 and 255 periods taken as 256
    /// each: every speed 0.2 % low and a false deceleration of 2 w / 256
    /// per half window, +20 % on b and, through b's share of the speed
    /// steps, J 5 % low.
    fn window_speed(&self, h: usize) -> f64 {
        let [(p0, k0), (p1, k1)] = self.spin_pos[h];
        self.rad_per_count() * (p1 - p0) as f64 / ((k1 - k0) as f64 * self.s.period_s)
    }

    fn encoder_fit(&self) -> Outcome<EncoderEst> {
        let [f, b] = self.lines;
        if f.n < 10.0 || b.n < 10.0 {
            return Outcome::Refused("too few samples");
        }
        let (sf, sb) = (f.slope(), b.slope());
        let dir = if sf + sb >= 0.0 { 1 } else { -1 };
        let p_exact = 0.5 * libm::fabs(sf + sb);
        let p = libm::round(p_exact).clamp(1.0, 64.0);
        let s = f64::from(dir) * p;
        let (cf, df) = f.offset(s);
        let (cb, db) = b.offset(s);
        // Forwards and backwards lag the field by the same friction angle:
        // the mean cancels it.
        let d = cb - cf - libm::round(cb - cf);
        let c = cf + 0.5 * d;
        // The count where the rotor's electrical angle is 0: s x + c = 0.
        let per = self.cpr() / p;
        let x = -c / s * self.cpr();
        let zero = x - libm::floor(x / per) * per;
        let zero_counts = (libm::round(zero) as u32) % (libm::round(per).max(1.0) as u32);
        // Residuals: correlated over about a turn's oscillation; count
        // one independent sample per 16 periods.
        let se = |dev: f64, n: f64| dev / libm::sqrt((n / 16.0).max(1.0));
        let sig_turns = 0.5 * libm::hypot(se(df, f.n), se(db, b.n));
        let q = 0.29 * p / self.cpr();
        let sigma_deg = 360.0 * libm::hypot(sig_turns, q);
        let est = EncoderEst {
            dir,
            pole_pairs: p as u32,
            zero_counts,
            zero_exact: zero,
            sigma_deg,
            pole_pairs_exact: p_exact,
        };
        if libm::fabs(p_exact - p) > bounds::POLE_PAIRS_FRAC {
            Outcome::Poor(
                est,
                "pole pairs: electrical per mechanical turns not a whole number",
            )
        } else if sigma_deg > bounds::ZERO_DEG {
            Outcome::Poor(
                est,
                "encoder offset: the rotor did not follow the field smoothly",
            )
        } else {
            Outcome::Done(est)
        }
    }

    fn resistance_fit(&mut self) {
        let mut f = Lsq::<2>::default();
        for (j, (v, i)) in self.r_v.iter().zip(self.r_i.iter()).enumerate() {
            f.add([i.mean(), 1.0], v.mean());
            self.res.r_points[j] = (i.mean(), v.mean());
        }
        let Some(sol) = f.solve() else {
            self.res.resistance = Outcome::Refused("singular fit");
            return;
        };
        let r = sol.b[0];
        // Floor: the ADC's resolution over the averaged current span.
        let sigma = libm::hypot(sol.se(0), 1e-3 * r);
        self.r_fit = Some((r, sol.b[1], sigma));
        self.res.dead_time_v = sol.b[1];
        if !self.s.phases.has(Phase::Resistance) {
            return;
        }
        let est = Estimate { value: r, sigma };
        self.res.resistance = if !positive(r) {
            Outcome::Poor(est, "resistance not positive")
        } else if est.rel() > bounds::R_REL {
            Outcome::Poor(est, "resistance: the levels do not lie on a line")
        } else {
            Outcome::Done(est)
        };
    }

    fn inductance_fit(&self) -> Outcome<Estimate> {
        let Some(sol) = self.l_fit.solve() else {
            return Outcome::Refused("singular fit");
        };
        let Some((r, _, sr)) = self.r_fit else {
            return Outcome::Refused("no resistance");
        };
        let a = sol.b[0];
        if !(a > 0.0 && a < 1.0) {
            return Outcome::Poor(
                Estimate {
                    value: f64::NAN,
                    sigma: f64::NAN,
                },
                "inductance: the current did not decay exponentially",
            );
        }
        let la = libm::log(a);
        let tau = -self.s.period_s / la;
        let l = tau * r;
        let rel_tau = sol.se(0) / (a * libm::fabs(la));
        let sigma = l * libm::hypot(rel_tau, sr / r);
        let est = Estimate { value: l, sigma };
        if est.rel() > bounds::L_REL {
            Outcome::Poor(est, "inductance: the step responses are not first order")
        } else {
            Outcome::Done(est)
        }
    }

    fn spin_fit(&mut self) {
        let (_, p, _) = self.rotor_model();
        let r = self.r_best();
        let l = self.l_best();
        // The dead time's loss along the current: its fundamental in a
        // turning field is 3/pi of the loss along phase a at standstill.
        let v_dt = 3.0 / PI * self.res.dead_time_v;
        let mut f = Lsq::<2>::default();
        let mut d_points = [(0.0, 0.0); LEVELS];
        // The first window at each speed (i_d at +I/2).
        for (j, d) in d_points.iter_mut().enumerate() {
            let m = &self.spin_v[first(j)];
            let [vd, vq, id, iq] = [0, 1, 2, 3].map(|i| m[i].mean());
            let w = self.window_speed(first(j)) * p;
            let mag = libm::hypot(id, iq).max(1e-9);
            let y = vq - v_dt * iq / mag - r * iq - w * l * id;
            f.add([w / 1000.0, 1.0], y);
            self.res.flux_points[j] = (w, y);
            *d = (w, vd - v_dt * id / mag - r * id + w * l * iq);
        }
        let flux = match f.solve() {
            Some(sol) => {
                let psi = sol.b[0] / 1000.0;
                let sigma = libm::hypot(sol.se(0) / 1000.0, 1e-3 * psi);
                let est = Estimate { value: psi, sigma };
                if !positive(psi) {
                    Outcome::Poor(est, "flux linkage not positive")
                } else if est.rel() > bounds::PSI_REL {
                    Outcome::Poor(est, "flux linkage: the speeds do not lie on a line")
                } else {
                    Outcome::Done(est)
                }
            }
            None => Outcome::Refused("singular fit"),
        };
        if self.s.phases.has(Phase::Flux) {
            self.res.flux = flux;
        }
        if self.s.phases.has(Phase::Mechanics) {
            self.res.mechanics = self.mechanics_fit(flux, &d_points);
        }
    }

    /// The flux linkage for the torque and its uncertainty, Wb: the fit's
    /// when good; otherwise the configured one, uncertain by its distance
    /// from the fitted one (all of it when there is none).
    fn torque_flux(&self, flux: Outcome<Estimate>) -> (f64, f64) {
        let psi_g = self.psi_best();
        match flux {
            Outcome::Done(e) => (e.value, e.sigma),
            Outcome::Poor(e, _) if e.value.is_finite() => {
                (psi_g, libm::fabs(e.value - psi_g).max(e.sigma))
            }
            _ => (psi_g, psi_g),
        }
    }

    /// What the mechanics fit needs of the spin (see [`mech`]).
    fn spin_record(&self) -> Spin {
        let span = f64::from(SPIN_AVG) * self.s.period_s;
        let mut s = Spin {
            j_weight: self.s.motor.j_kg_m2,
            ..Spin::default()
        };
        for (h, m) in self.spin_v.iter().enumerate() {
            let [_, _, _, _, th, t, i_d, i_q, th_d, th_q] = m.map(|x| x.mean());
            s.windows[h] = Window {
                w: self.window_speed(h),
                sigma_w: COUNT_PAIR_SIGMA * libm::fabs(self.rad_per_count()) / span,
                th,
                t,
                i_int: (i_d, i_q),
                i_th: (th_d, th_q),
            };
        }
        s
    }

    fn mechanics_fit(
        &mut self,
        flux: Outcome<Estimate>,
        d_points: &[(f64, f64); LEVELS],
    ) -> Outcome<MechEst> {
        let (_, p, _) = self.rotor_model();
        let (psi, sigma_psi) = self.torque_flux(flux);
        let Some(e_v) = mech::frame_angle(d_points, psi) else {
            return Outcome::Refused("singular fit");
        };
        let spin = Spin {
            kt: 1.5 * p * psi,
            sigma_kt: 1.5 * p * sigma_psi,
            e_v,
            ..self.spin_record()
        };
        let Some(m) = mech::fit(&spin) else {
            return Outcome::Refused("singular fit");
        };
        self.res.friction_points = m.points;
        let est = MechEst {
            j: Estimate {
                value: m.j.0,
                sigma: m.j.1,
            },
            b: non_negative(m.b),
            coulomb: non_negative(m.tc),
        };
        if matches!(self.res.encoder, Outcome::Poor(..)) {
            // The spin turned in the encoder fit's frame: with its pole
            // pairs or zero wrong the currents are not the torque's, and
            // nothing here bounds the error.
            Outcome::Poor(unbounded(est), "mechanics: the encoder's fit is poor")
        } else if !positive(est.j.value) {
            Outcome::Poor(est, "inertia not positive")
        } else if est.j.rel() > bounds::J_REL {
            Outcome::Poor(est, "inertia: the speed steps disagree")
        } else {
            Outcome::Done(est)
        }
    }
}
