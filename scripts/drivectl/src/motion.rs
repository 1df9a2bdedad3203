//! Host simulation of the outer loops: the product's `Servo` (the same
//! loops, estimator and torque loops the firmware runs) on the simulated PL
//! and motor (`simpl::SimDrive`, the same plant code the firmware's
//! simulated PL runs), one control step per control-period boundary as the
//! firmware's control interrupt does. The QEMU system tests compare the
//! firmware's `move` with [`run_move`].
use drive::pl::top::Mode;
use drive::servo::motion::{MotionStatus, MoveResult};
use drive::servo::{Servo, ServoConfig};
use simpl::{SimConfig, SimDrive};

/// One sample of a run, every control period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time since the command, s.
    pub t_s: f64,
    /// The outer loops' view.
    pub motion: MotionStatus,
    /// Torque reference, N m.
    pub torque_ref_nm: f64,
    /// Measured torque, N m.
    pub torque_nm: f64,
}

/// The servo on the simulated PL with the simulated motor's parameters
/// `sim` (`name`, value as `sim set` takes them), in `mode`, gates on,
/// after the MPDTC's rotor alignment (`MPDTC_ALIGN_TIME`, 0.2 s by
/// default) and `settle_s` of running at 0 N m.
pub fn setup(mode: Mode, sim: &[(&str, f64)], settle_s: f64) -> anyhow::Result<(Servo, SimDrive)> {
    setup_with(mode, sim, &firmware_config(), settle_s)
}

/// The configuration the firmware starts with on the simulated PL.
pub fn firmware_config() -> ServoConfig {
    ServoConfig::for_plant(
        SimConfig::default().motor,
        SimConfig::default().adc_amps_per_count,
    )
}

/// [`setup`] with the drive's configuration `cfg`.
pub fn setup_with(
    mode: Mode,
    sim: &[(&str, f64)],
    cfg: &ServoConfig,
    settle_s: f64,
) -> anyhow::Result<(Servo, SimDrive)> {
    let mut d = SimDrive::new(&SimConfig::default()).map_err(|e| anyhow::anyhow!("{e}"))?;
    for (n, v) in sim {
        d.sim_set(n, *v)
            .map_err(|e| anyhow::anyhow!("sim set {n} {v}: {e:?}"))?;
    }
    let mut s = Servo::new(cfg).map_err(|e| anyhow::anyhow!("{e}"))?;
    s.init(&mut d).map_err(|e| anyhow::anyhow!("{e:?}"))?;
    s.set_mode(&mut d, mode)
        .map_err(|e| anyhow::anyhow!("{e:?}"))?;
    s.enable(&mut d).map_err(|e| anyhow::anyhow!("{e:?}"))?;
    let align = f64::from(cfg.align_cycles) / f64::from(regmap::PL_CLOCK_HZ);
    let n = ((align + 1e-3) * s.control_rate_hz()) as usize;
    run(&mut s, &mut d, n, |s| s.controlling())?;
    anyhow::ensure!(s.controlling(), "the MPDTC's rotor alignment did not end");
    let n = (settle_s * s.control_rate_hz()) as usize;
    run(&mut s, &mut d, n, |_| false)?;
    Ok((s, d))
}

/// Runs up to `max` control periods until `done`; the samples.
pub fn run(
    s: &mut Servo,
    d: &mut SimDrive,
    max: usize,
    mut done: impl FnMut(&Servo) -> bool,
) -> anyhow::Result<Vec<Sample>> {
    let mut out = Vec::new();
    let dt = s.control_period_s();
    for k in 0..max {
        let a = d.advance_to_boundary(20_000);
        anyhow::ensure!(a.control_periods >= 1, "no control boundary in 200 us");
        s.control_step(d).map_err(|e| anyhow::anyhow!("{e:?}"))?;
        out.push(Sample {
            t_s: (k + 1) as f64 * dt,
            motion: s.motion_status(),
            torque_ref_nm: s.torque_ref_nm(),
            torque_nm: s.measured().torque_nm,
        });
        if done(s) {
            break;
        }
    }
    Ok(out)
}

/// `move <distance> [<window>]` after [`setup`]: its figures and samples.
pub fn run_move(
    mode: Mode,
    sim: &[(&str, f64)],
    distance_rev: f64,
    window_s: f64,
) -> anyhow::Result<(MoveResult, Vec<Sample>)> {
    run_move_with(mode, sim, &firmware_config(), distance_rev, window_s)
}

/// [`run_move`] with the drive's configuration `cfg`.
pub fn run_move_with(
    mode: Mode,
    sim: &[(&str, f64)],
    cfg: &ServoConfig,
    distance_rev: f64,
    window_s: f64,
) -> anyhow::Result<(MoveResult, Vec<Sample>)> {
    let (mut s, mut d) = setup_with(mode, sim, cfg, 3e-3)?;
    s.begin_move(&mut d, distance_rev, window_s)
        .map_err(|e| anyhow::anyhow!("{e:?}"))?;
    let samples = run(&mut s, &mut d, 200_000, |s| !s.move_pending())?;
    let r = s.move_result().ok_or_else(|| {
        anyhow::anyhow!("the move did not complete (faults: {:?})", s.faults(&mut d))
    })?;
    Ok((r, samples))
}

fn e<E: std::fmt::Debug>(x: E) -> anyhow::Error {
    anyhow::anyhow!("{x:?}")
}

/// Holding position, a load step of `load_nm`: the largest deviation,
/// counts, and the time after the step until the position stays within
/// +-2 counts of the hold (over 100 ms), s (`None`: not within).
pub fn load_step(
    mode: Mode,
    sim: &[(&str, f64)],
    cfg: &ServoConfig,
    load_nm: f64,
) -> anyhow::Result<(f64, Option<f64>)> {
    let (mut s, mut d) = setup_with(mode, sim, cfg, 3e-3)?;
    let p0 = s.motion_status().position_rev;
    s.set_position(&mut d, p0).map_err(e)?;
    let n = (0.02 * s.control_rate_hz()) as usize;
    run(&mut s, &mut d, n, |_| false)?;
    let hold = s.motion_status().position_ref_rev;
    d.sim_set("load_torque", load_nm).map_err(e)?;
    let n = (0.1 * s.control_rate_hz()) as usize;
    let samples = run(&mut s, &mut d, n, |_| false)?;
    let cpr = f64::from(s.config().enc_cpr);
    let dev = |x: &Sample| (x.motion.position_rev - hold) * cpr;
    let worst = samples.iter().map(|x| dev(x).abs()).fold(0.0, f64::max);
    let last_out = samples.iter().rposition(|x| dev(x).abs() > 2.0);
    let recovery = match last_out {
        None => Some(0.0),
        Some(k) if k + 1 < samples.len() => Some(samples[k + 1].t_s),
        Some(_) => None,
    };
    Ok((worst, recovery))
}

/// `vel <v>` from rest: the time until the velocity (from the position,
/// over 1 ms) stays within 2 % of `v`, s, and its mean over the last
/// 10 ms, rev/s; the run lasts the ramp (`traj_accel_limit`) and 50 ms.
pub fn velocity_step(
    mode: Mode,
    sim: &[(&str, f64)],
    cfg: &ServoConfig,
    v: f64,
) -> anyhow::Result<(Option<f64>, f64)> {
    let (mut s, mut d) = setup_with(mode, sim, cfg, 3e-3)?;
    s.set_velocity(&mut d, v).map_err(e)?;
    let rate = s.control_rate_hz();
    let t_end = v.abs() / cfg.motion.traj_accel_limit + 0.05;
    let samples = run(&mut s, &mut d, (t_end * rate) as usize, |_| false)?;
    let w = (1e-3 * rate) as usize;
    let vel: Vec<(f64, f64)> = samples
        .windows(w + 1)
        .map(|x| {
            let (a, b) = (x[0], x[w]);
            (
                b.t_s,
                (b.motion.position_rev - a.motion.position_rev) / (b.t_s - a.t_s),
            )
        })
        .collect();
    let out = vel.iter().rposition(|(_, x)| (x / v - 1.0).abs() > 0.02);
    let settle = match out {
        None => Some(0.0),
        Some(k) if k + 1 < vel.len() => Some(vel[k + 1].0),
        Some(_) => None,
    };
    let n10 = (0.01 * rate) as usize;
    let (a, b) = (samples[samples.len() - 1 - n10], samples[samples.len() - 1]);
    let mean = (b.motion.position_rev - a.motion.position_rev) / (b.t_s - a.t_s);
    Ok((settle, mean))
}

/// `imp 0 0 kp kd 0` under `sim load_torque load_nm` after 300 ms: the
/// static stiffness `load / deflection`, N m/rev (kd damps the spring and
/// the inertia `j` critically).
pub fn stiffness(
    mode: Mode,
    sim: &[(&str, f64)],
    cfg: &ServoConfig,
    kp: f64,
    load_nm: f64,
) -> anyhow::Result<f64> {
    let (mut s, mut d) = setup_with(mode, sim, cfg, 3e-3)?;
    let j = cfg.motion.load_inertia_kg_m2;
    let tau = std::f64::consts::TAU;
    let kd = 2.0 * (kp / tau * j).sqrt() * tau;
    let p0 = s.motion_status().position_rev;
    let imp = models::motion::law::Impedance {
        p: p0,
        v: 0.0,
        kp,
        kd: kd.min(cfg.motion.imp_kd_max),
        t_ff: 0.0,
    };
    s.set_impedance(&mut d, &imp).map_err(e)?;
    d.sim_set("load_torque", load_nm).map_err(e)?;
    let n = (0.3 * s.control_rate_hz()) as usize;
    run(&mut s, &mut d, n, |_| false)?;
    Ok(load_nm / (p0 - s.motion_status().position_rev))
}

/// The joint load of the results table: ten times the rotor's inertia,
/// viscous and Coulomb friction and a spring (`sim set` names), and the
/// drive told the inertia with its velocity loop scaled to keep the bare
/// rotor's bandwidth.
pub const JOINT: &[(&str, f64)] = &[
    ("locked", 0.0),
    ("j", 8.1e-4),
    ("b", 1e-3),
    ("coulomb", 0.02),
    ("spring", 0.02),
];

/// The drive's configuration for [`JOINT`].
/// The outer-loop gain rule for a known inertia `j_kg_m2` (what
/// `calibrate mechanics` measures), the README's "Tuning the outer loops":
/// `load_inertia` = J, `vel_kp` = 3100 J (a velocity loop of about 78 Hz,
/// in rev units: `vel_kp / (2 pi J)` = 490 rad/s), `vel_ki` = 120
/// `vel_kp` (its integrator a fifth of that), `pos_kp` = 100/s, and a
/// trajectory acceleration that needs a quarter of the torque limit,
/// `0.25 torque_limit / (2 pi J)`.
pub fn tuned_config(j_kg_m2: f64) -> ServoConfig {
    let mut c = firmware_config();
    let m = &mut c.motion;
    m.load_inertia_kg_m2 = j_kg_m2;
    m.vel_kp = 3100.0 * j_kg_m2;
    m.vel_ki = 120.0 * m.vel_kp;
    m.pos_kp = 100.0;
    m.traj_accel_limit = 0.25 * c.torque_limit_nm / (std::f64::consts::TAU * j_kg_m2);
    c
}

pub fn joint_config() -> ServoConfig {
    let mut c = firmware_config();
    c.motion.load_inertia_kg_m2 = 8.1e-4;
    c.motion.vel_kp = 2.5;
    c.motion.vel_ki = 300.0;
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use drive::servo::motion::MOVE_BAND_COUNTS;

    const FREE: &[(&str, f64)] = &[("locked", 0.0)];

    fn check_move(mode: Mode) {
        let (r, _) = run_move(mode, FREE, 1.0, 0.02).unwrap();
        println!("{mode:?} move 1 rev on the host: {r:?}");
        // The default 100 rev/s^2: a triangle of 200 ms.
        assert!((r.move_time_s - 0.2).abs() < 1e-9);
        assert!(r.final_error_counts.abs() <= 1.0, "{r:?}");
        assert!(r.settling_s.is_some_and(|t| t <= 5e-3), "{r:?}");
        assert!(r.overshoot_counts <= 2.0, "{r:?}");
    }

    #[test]
    fn move_one_revolution_mpdtc() {
        check_move(Mode::Mpdtc);
    }

    #[test]
    fn move_one_revolution_foc() {
        check_move(Mode::Foc);
    }

    /// The README's results table (`cargo test -p drivectl --lib
    /// motion::tests::results_table -- --nocapture`), goals pinned.
    #[test]
    fn results_table() {
        println!("| | FOC | MPDTC |\n|---|---|---|");
        let both = |f: &dyn Fn(Mode) -> String| {
            let (a, b) = (f(Mode::Foc), f(Mode::Mpdtc));
            format!("{a} | {b}")
        };
        // The bare rotor with the gain rule for its known 8.1e-5 kg m^2
        // (rounded: vel_kp 0.25, vel_ki 30, pos_kp 100, 500 rev/s^2).
        let mut bare = tuned_config(8.1e-5);
        bare.motion.vel_kp = 0.25;
        bare.motion.vel_ki = 30.0;
        for (name, sim, cfg, accel) in [
            ("bare rotor", FREE, bare, 500.0),
            ("joint load", JOINT, joint_config(), 100.0),
        ] {
            let mut cfg = cfg;
            cfg.motion.traj_accel_limit = accel;
            let row = both(&|m| {
                let (r, _) = run_move_with(m, sim, &cfg, 1.0, 0.02).unwrap();
                assert!(r.final_error_counts.abs() <= 1.0, "{name} {m:?} {r:?}");
                assert!(r.overshoot_counts <= 2.0, "{name} {m:?} {r:?}");
                assert!(
                    r.settling_s.is_some_and(|t| t <= 5e-3),
                    "{name} {m:?} {r:?}"
                );
                format!(
                    "move {:.0} ms, settling {:.2} ms, overshoot {:.0}, max following error {:.1}, final {:.0} counts",
                    r.move_time_s * 1e3,
                    r.settling_s.unwrap() * 1e3,
                    r.overshoot_counts,
                    r.max_following_error_counts,
                    r.final_error_counts
                )
            });
            println!("| 1 rev move, 20 rev/s, {accel} rev/s^2, {name} | {row} |");
            let row = both(&|m| {
                let (w, rec) = load_step(m, sim, &cfg, 0.3).unwrap();
                format!(
                    "largest deviation {w:.0} counts, recovery {}",
                    rec.map_or("none in 100 ms".into(), |t| format!("{:.1} ms", t * 1e3))
                )
            });
            println!("| 0.3 N m load step holding, {name} | {row} |");
            // The outer loops set the deviation; the MPDTC's faster torque
            // loop must not make it worse.
            let foc = load_step(Mode::Foc, sim, &cfg, 0.3).unwrap().0;
            let mpdtc = load_step(Mode::Mpdtc, sim, &cfg, 0.3).unwrap().0;
            assert!(
                mpdtc <= foc + 1.0,
                "{name}: MPDTC {mpdtc} counts, FOC {foc} counts"
            );
            let row = both(&|m| {
                let (t, v) = velocity_step(m, sim, &cfg, 10.0).unwrap();
                assert!((v / 10.0 - 1.0).abs() <= 0.02, "{name} {m:?} {v}");
                format!(
                    "within 2 % after {}, {v:.3} rev/s",
                    t.map_or("never".into(), |t| format!("{:.1} ms", t * 1e3))
                )
            });
            println!("| velocity step 0 -> 10 rev/s at {accel} rev/s^2, {name} | {row} |");
        }
        for kp in [1.0, 2.0, 5.0] {
            let row = both(&|m| {
                let k = stiffness(m, FREE, &firmware_config(), kp, 0.2).unwrap();
                assert!((k / kp - 1.0).abs() <= 0.02, "{m:?} kp {kp}: {k}");
                format!("{k:.3} N m/rev ({:+.2} %)", (k / kp - 1.0) * 100.0)
            });
            println!("| static stiffness, imp kp {kp} N m/rev, 0.2 N m load | {row} |");
        }
    }

    /// A load the drive was not told about, with the default gains: the
    /// true inertia 0.3 to 10 times `load_inertia` (the bare rotor's
    /// 8.1e-5 kg m^2) and Coulomb friction 0 or 5 % of the 1 N m torque
    /// limit; `move 1` with a 300 ms window in both torque loops. Every
    /// move settles into +-2 counts within the window and ends there (the
    /// README's "Tuning the outer loops" prints this table: `cargo test
    /// --release -p drivectl --lib motion::tests::robustness_table --
    /// --nocapture`). With the former defaults (500 rev/s^2, `pos_kp`
    /// 100, `vel_kp` 0.25) the 10x cells overshot by 0.6 rev or tripped
    /// OVERCURRENT.
    #[test]
    fn robustness_table() {
        let j0 = firmware_config().motion.load_inertia_kg_m2;
        println!("| true inertia | Coulomb friction | FOC: done after, overshoot, final | MPDTC: done after, overshoot, final |");
        println!("|---|---|---|---|");
        for jm in [0.3, 1.0, 3.0, 10.0] {
            for tc in [0.0, 0.05] {
                let sim = [("locked", 0.0), ("j", j0 * jm), ("coulomb", tc)];
                let cell = |m: Mode| {
                    let (r, _) = run_move(m, &sim, 1.0, 0.3)
                        .unwrap_or_else(|e| panic!("{jm}x, {tc} N m, {m:?}: {e}"));
                    let settle = r.settling_s.unwrap_or_else(|| {
                        panic!("{jm}x, {tc} N m, {m:?}: not within 2 counts: {r:?}")
                    });
                    assert!(
                        r.final_error_counts.abs() <= MOVE_BAND_COUNTS,
                        "{jm}x, {tc} N m, {m:?}: {r:?}"
                    );
                    format!(
                        "{:.0} ms, {:.0} counts, {:.0} counts",
                        (r.move_time_s + settle) * 1e3,
                        r.overshoot_counts,
                        r.final_error_counts
                    )
                };
                println!(
                    "| {jm} x ({:.1e} kg m^2) | {tc} N m | {} | {} |",
                    j0 * jm,
                    cell(Mode::Foc),
                    cell(Mode::Mpdtc)
                );
            }
        }
    }
}
