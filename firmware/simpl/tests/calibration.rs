//! `calibrate` on the simulated PL and motor: the drive's calibration
//! (`drive::servo::calibrate` running `models::calibration`) against
//! simulated motors whose true parameters are drawn at random, with the
//! simulated inverter's dead time and the ADC's quantization and delay.
use drive::pl::top::Mode;
use drive::servo::sensors::PlTime;
use drive::servo::{Servo, ServoConfig, StepResult};
use models::calibration::{Estimate, MechEst, Outcome, Phases, Results};
use models::pmsm::sim_motor::SimMotor;
use models::testrng::Rng;
use regmap::bus::{BusError, RegisterBus};
use simpl::{SimConfig, SimDrive};

/// The simulated PL with its time under the drive's control.
struct Bus(SimDrive);

impl RegisterBus for Bus {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        self.0.read(addr)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.0.write(addr, value)
    }
}

impl PlTime for Bus {
    fn wait_cycles(&mut self, cycles: u64) {
        let _ = self.0.advance(cycles);
    }
}

/// Nominal friction of the draws (the simulated motor's default has none).
const B_NOMINAL: f64 = 2e-4;
const COULOMB_NOMINAL: f64 = 5e-3;

/// A motor within +-40 % of the defaults, encoder anywhere, either way.
fn draw(r: &mut Rng) -> SimMotor {
    let mut m = SimMotor::default();
    let mut f = |x: f64| x * r.uniform(0.6, 1.4);
    m.motor.r_s_ohm = f(m.motor.r_s_ohm);
    let l = f(m.motor.l_d_h);
    m.motor.l_d_h = l;
    m.motor.l_q_h = l;
    m.motor.psi_pm_wb = f(m.motor.psi_pm_wb);
    m.motor.pole_pairs = libm::round(f(7.0)) as u32;
    m.mech.j_kg_m2 = f(m.motor.j_kg_m2);
    m.mech.b_nm_s_per_rad = f(B_NOMINAL);
    m.mech.coulomb_nm = f(COULOMB_NOMINAL);
    m.enc_offset = r.range(0, 4095) as u32;
    m.enc_dir = if r.range(0, 1) == 0 { 1 } else { -1 };
    m.locked = false;
    m
}

fn calibrate(m: &SimMotor) -> (Results, u64) {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    sim.apply_sim_motor(m).unwrap();
    let cfg = ServoConfig::for_plant(
        models::pmsm::params::MotorParams::default(),
        sim.config().adc_amps_per_count,
    );
    let mut bus = Bus(sim);
    let mut s = Servo::new(&cfg).unwrap();
    s.init(&mut bus).unwrap();
    s.set_mode(&mut bus, Mode::Foc).unwrap();
    let setup = s.calibration_setup(8.0, 16.0, Phases::ALL);
    let rep = s
        .calibrate(&mut bus, &setup, &mut |_| {}, &mut || false)
        .unwrap();
    assert_eq!(rep.stopped, None);
    assert!(!s.gates_on(&mut bus).unwrap());
    (rep.results, rep.cycles)
}

fn el_deg(m: &SimMotor, est_counts: f64) -> f64 {
    let p = f64::from(m.motor.pole_pairs);
    let d = (est_counts - f64::from(m.enc_offset)) * p * 360.0 / 4096.0;
    d - 360.0 * (d / 360.0).round()
}

/// Relative error.
fn rel(est: f64, truth: f64) -> f64 {
    (est - truth) / truth
}

/// Ten seeded draws: every estimate within the bounds of the accuracy
/// table (docs/calibration.md), direction and pole pairs exact. Prints
/// the table's rows.
#[test]
fn calibrate_all_on_ten_random_motors() {
    let mut r = Rng(23);
    let mut worst = [0.0f64; 7];
    let mut periods = (u64::MAX, 0);
    std::println!("draw | R % | L % | psi % | offset el deg | J % | b % | T_c % | dir | p");
    for d in 0..10 {
        let m = draw(&mut r);
        let (res, _) = calibrate(&m);
        let e = *res
            .encoder
            .good()
            .unwrap_or_else(|| panic!("draw {d}: {:?} {m:?}", res.encoder));
        assert_eq!(
            (e.dir, e.pole_pairs),
            (m.enc_dir, m.motor.pole_pairs),
            "draw {d}"
        );
        let off = el_deg(&m, f64::from(e.zero_counts));
        let r_ = rel(res.resistance.good().unwrap().value, m.motor.r_s_ohm);
        let l_ = rel(res.inductance.good().unwrap().value, m.motor.l_d_h);
        let psi = rel(res.flux.good().unwrap().value, m.motor.psi_pm_wb);
        let mech = res.mechanics.good().unwrap();
        let j = rel(mech.j.value, m.mech.j_kg_m2);
        let b = rel(mech.b.value, m.mech.b_nm_s_per_rad);
        let tc = rel(mech.coulomb.value, m.mech.coulomb_nm);
        periods = (periods.0.min(res.periods), periods.1.max(res.periods));
        std::println!(
            "{d} | {:+.2} | {:+.2} | {:+.2} | {:+.2} | {:+.2} | {:+.2} | {:+.1} | {} | {}",
            100.0 * r_,
            100.0 * l_,
            100.0 * psi,
            off,
            100.0 * j,
            100.0 * b,
            100.0 * tc,
            e.dir,
            e.pole_pairs
        );
        for (w, x) in worst.iter_mut().zip([r_, l_, psi, off / 100.0, j, b, tc]) {
            *w = w.max(x.abs());
        }
    }
    std::println!(
        "worst | {:.2} % | {:.2} % | {:.2} % | {:.2} deg | {:.2} % | {:.2} % | {:.1} %",
        100.0 * worst[0],
        100.0 * worst[1],
        100.0 * worst[2],
        100.0 * worst[3],
        100.0 * worst[4],
        100.0 * worst[5],
        100.0 * worst[6]
    );
    std::println!("PWM periods: {} to {}", periods.0, periods.1);
    assert!(worst[0] < 0.03 && worst[1] < 0.03, "{worst:?}");
    assert!(worst[2] < 0.02, "{worst:?}");
    assert!(worst[3] < 0.01, "{worst:?}");
    assert!(worst[4] < 0.03 && worst[5] < 0.03, "{worst:?}");
    assert!(worst[6] < 0.10, "{worst:?}");
}

/// One drawn motor (seed 1: 7 pole pairs, encoder offset 1397 counts):
/// every estimate within the accuracy bounds, the mechanics within three
/// sigmas.
#[test]
fn calibrate_all_on_one_random_motor() {
    let mut r = Rng(1);
    let m = draw(&mut r);
    let (res, _) = calibrate(&m);
    std::println!("{res:?}");
    let e = *res.encoder.good().expect("encoder");
    assert_eq!((e.dir, e.pole_pairs), (m.enc_dir, m.motor.pole_pairs));
    assert!(el_deg(&m, f64::from(e.zero_counts)).abs() < 1.0, "{e:?}");
    assert!(rel(res.resistance.good().unwrap().value, m.motor.r_s_ohm).abs() < 0.03);
    assert!(rel(res.inductance.good().unwrap().value, m.motor.l_d_h).abs() < 0.03);
    assert!(rel(res.flux.good().unwrap().value, m.motor.psi_pm_wb).abs() < 0.02);
    let mech = res.mechanics.good().unwrap();
    assert!(rel(mech.j.value, m.mech.j_kg_m2).abs() < 0.03, "{mech:?}");
    assert!(
        rel(mech.b.value, m.mech.b_nm_s_per_rad).abs() < 0.03,
        "{mech:?}"
    );
    assert_eq!(uncovered(mech, &m), None, "{mech:?}");
}

/// The truth's distance from each of J, b and T_c in sigmas, and the
/// name of the first beyond three (`None`: all within).
fn uncovered(e: &MechEst, m: &SimMotor) -> Option<&'static str> {
    let z = |est: Estimate, truth: f64| (est.value - truth).abs() / est.sigma;
    [
        ("J", z(e.j, m.mech.j_kg_m2)),
        ("b", z(e.b, m.mech.b_nm_s_per_rad)),
        ("T_c", z(e.coulomb, m.mech.coulomb_nm)),
    ]
    .into_iter()
    .find(|(_, z)| z.is_nan() || *z > 3.0)
    .map(|(n, _)| n)
}

/// The README's walk-through motor (docs/calibration.md).
fn readme_motor() -> SimMotor {
    let mut m = SimMotor::default();
    m.motor.r_s_ohm = 0.7;
    m.motor.l_d_h = 0.9e-3;
    m.motor.l_q_h = 0.9e-3;
    m.motor.psi_pm_wb = 0.012;
    m.motor.pole_pairs = 5;
    m.mech.j_kg_m2 = 1e-4;
    m.mech.b_nm_s_per_rad = B_NOMINAL;
    m.mech.coulomb_nm = COULOMB_NOMINAL;
    m.enc_offset = 1000;
    m.locked = false;
    m
}

/// The two reported motors: the default one turning free without
/// friction (Coulomb friction was reported at -4.19e-3 N m +-5.9e-6) and
/// the README's (b +20.7 %, T_c +96 %, each 70 to 700 sigmas off; J
/// about -5 % on both). Now: J within 2 %, b and T_c not negative, all
/// three within three sigmas. Prints the estimates.
#[test]
fn the_reported_motors_get_honest_mechanics() {
    let free = SimMotor {
        locked: false,
        ..SimMotor::default()
    };
    for (name, m) in [("frictionless", free), ("readme", readme_motor())] {
        let (res, _) = calibrate(&m);
        let e = *res.mechanics.good().unwrap_or_else(|| panic!("{res:?}"));
        std::println!(
            "{name}: J {:.4e} +-{:.1e} ({:+.2} %) b {:.3e} +-{:.1e} T_c {:.3e} +-{:.1e}",
            e.j.value,
            e.j.sigma,
            100.0 * rel(e.j.value, m.mech.j_kg_m2),
            e.b.value,
            e.b.sigma,
            e.coulomb.value,
            e.coulomb.sigma
        );
        assert!(rel(e.j.value, m.mech.j_kg_m2).abs() < 0.02, "{name}: {e:?}");
        assert!(e.b.value >= 0.0 && e.coulomb.value >= 0.0, "{name}: {e:?}");
        assert_eq!(uncovered(&e, &m), None, "{name}: {e:?}");
    }
}

/// Draws for the mechanics: as [`draw`], and every third one without
/// friction.
fn draw_mechanics(r: &mut Rng, k: usize) -> SimMotor {
    let mut m = draw(r);
    if k % 3 == 2 {
        m.mech.b_nm_s_per_rad = 0.0;
        m.mech.coulomb_nm = 0.0;
    }
    m
}

/// Trials of the coverage test: about 100 with a good encoder fit, so
/// that 99 % allows one miss; about 35 s in `--release` on 2 idle cores
/// (two threads). `CAL_COVERAGE_TRIALS` and `CAL_COVERAGE_SEED` override
/// it and the seed for a larger run (docs/calibration.md).
const COVERAGE_TRIALS: usize = 120;
const COVERAGE_SEED: u64 = 31;

/// The environment's `name` as a number, or `default`.
fn env_or<T: std::str::FromStr>(name: &str, default: T) -> T {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// How one trial of the coverage test ended.
#[derive(Debug, Clone, PartialEq)]
enum Trial {
    /// J, b and T_c within three sigmas.
    Covered,
    /// This one beyond three sigmas.
    Uncovered(&'static str),
    /// The encoder fit poor and the mechanics reported without a bound.
    Unbounded,
    /// Anything else (refused, or a bound after a poor encoder fit).
    Bad(String),
}

/// `calibrate all` on `m` for the coverage test, and the truth's
/// distances from J, b and T_c in sigmas (zero when not bounded).
fn coverage_trial(m: &SimMotor) -> (Trial, [f64; 3]) {
    let (res, _) = calibrate(m);
    let encoder_poor = matches!(res.encoder, Outcome::Poor(..));
    let e = match res.mechanics {
        Outcome::Done(e) | Outcome::Poor(e, _) => e,
        other => return (Trial::Bad(format!("{other:?}")), [0.0; 3]),
    };
    if encoder_poor {
        let t = match e.j.sigma.is_infinite() {
            true => Trial::Unbounded,
            false => Trial::Bad(format!("bounded after a poor encoder fit: {e:?}")),
        };
        return (t, [0.0; 3]);
    }
    let z = |est: Estimate, truth: f64| (est.value - truth) / est.sigma;
    let zs = [
        z(e.j, m.mech.j_kg_m2),
        z(e.b, m.mech.b_nm_s_per_rad),
        z(e.coulomb, m.mech.coulomb_nm),
    ];
    match uncovered(&e, m) {
        None => (Trial::Covered, zs),
        Some(n) => (Trial::Uncovered(n), zs),
    }
}

/// Seeded random motors (a third without friction), `calibrate all` on
/// each: the true J, b and T_c within three sigmas of the estimates in at
/// least 99 % of the trials whose encoder fit was good. A trial whose
/// encoder fit was poor (a pole pair count off, on some of the motors
/// with few pole pairs) must report its mechanics with no bound (infinite
/// sigmas): its spin turned in a wrong frame. Prints each trial.
#[test]
fn mechanics_sigmas_cover_the_truth_on_random_motors() {
    let n = env_or("CAL_COVERAGE_TRIALS", COVERAGE_TRIALS);
    let mut r = Rng(env_or("CAL_COVERAGE_SEED", COVERAGE_SEED));
    let motors: Vec<SimMotor> = (0..n).map(|k| draw_mechanics(&mut r, k)).collect();
    let mut trials = vec![(Trial::Covered, [0.0; 3]); n];
    std::thread::scope(|sc| {
        let (first, second) = trials.split_at_mut(n / 2);
        for (start, out) in [(0, first), (n / 2, second)] {
            let motors = &motors[start..];
            sc.spawn(move || {
                for (t, m) in out.iter_mut().zip(motors) {
                    *t = coverage_trial(m);
                }
            });
        }
    });
    let count = |f: &dyn Fn(&Trial) -> bool| trials.iter().filter(|(t, _)| f(t)).count();
    let covered = count(&|t| *t == Trial::Covered);
    let bounded = covered + count(&|t| matches!(t, Trial::Uncovered(_)));
    let (mut sq, mut worst) = ([0.0; 3], 0.0f64);
    for (k, (t, z)) in trials.iter().enumerate() {
        std::println!(
            "{k}: {t:?} z J {:+.2} b {:+.2} T_c {:+.2}",
            z[0],
            z[1],
            z[2]
        );
        if !matches!(t, Trial::Covered) {
            std::println!("  {:?}", motors[k]);
        }
        for (s, z) in sq.iter_mut().zip(z) {
            *s += z * z / bounded.max(1) as f64;
            worst = worst.max(z.abs());
        }
    }
    let rms = sq.map(f64::sqrt);
    std::println!(
        "covered {covered} of {bounded} bounded trials ({n} in all); \
         rms z J {:.2} b {:.2} T_c {:.2}, worst |z| {worst:.2}",
        rms[0],
        rms[1],
        rms[2]
    );
    assert!(covered * 100 >= bounded * 99, "{covered} of {bounded}");
    assert!(bounded * 4 >= n * 3, "{bounded}");
    assert_eq!(count(&|t| matches!(t, Trial::Bad(_))), 0);
}

/// A 0.4 N m step from rest on the simulated motor with the drive
/// configured `cfg`: the drive's
/// metrics and the plant's true torque at the end, or the error that
/// refused it.
fn step_04(sim: &mut SimDrive, cfg: &ServoConfig, mode: Mode) -> Result<(StepResult, f64), String> {
    let mut s = Servo::new(cfg).map_err(|e| format!("{e:?}"))?;
    s.init(sim).unwrap();
    s.set_mode(sim, mode).unwrap();
    s.enable(sim).map_err(|e| format!("{e:?}"))?;
    let run = |s: &mut Servo, sim: &mut SimDrive, n: u32, until_done: bool| {
        for _ in 0..n {
            sim.advance_to_boundary(20_000);
            s.control_step(sim).unwrap();
            if until_done && !s.step_pending() {
                break;
            }
        }
    };
    // 2 ms first, after the MPDTC's rotor alignment.
    while !s.controlling() {
        run(&mut s, sim, 1, false);
    }
    let n = (2e-3 * s.control_rate_hz()) as u32;
    run(&mut s, sim, n, false);
    s.begin_step(sim, 0.4, 2e-3).map_err(|e| format!("{e:?}"))?;
    run(&mut s, sim, 10_000, true);
    let r = s
        .step_result()
        .ok_or("no step result (gates off: a fault)")?;
    let truth = sim.truth().torque_nm;
    s.disable(sim).unwrap();
    Ok((r, truth))
}

/// The motor 30 % off the configuration in R, L and psi, its encoder a
/// quarter electrical turn from the configured zero: the FOC and the
/// MPDTC `step 0.4` with the exact parameters, with the configured ones
/// (before), and after `calibrate all` (results through `Config::set`):
/// after, both settle within 5 % of their exact-parameter figures.
#[test]
fn calibration_restores_the_steps_of_the_exact_parameters() {
    use drive::config::Config;
    let base = ServoConfig::for_plant(
        models::pmsm::params::MotorParams::default(),
        SimConfig::default().adc_amps_per_count,
    );
    let mut m = SimMotor::default();
    m.motor.r_s_ohm *= 1.3;
    m.motor.l_d_h *= 1.3;
    m.motor.l_q_h *= 1.3;
    m.motor.psi_pm_wb *= 1.3;
    // A quarter electrical turn: 4096 / 7 / 4 counts.
    m.enc_offset = 146;
    m.mech.b_nm_s_per_rad = B_NOMINAL;
    m.mech.coulomb_nm = COULOMB_NOMINAL;
    let held = SimMotor { locked: true, ..m };
    let sim_with = |mm: &SimMotor| {
        let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
        sim.apply_sim_motor(mm).unwrap();
        sim
    };
    let exact = ServoConfig {
        motor: m.motor,
        enc_zero: m.enc_offset,
        ..base
    };
    // Calibrate the free rotor, apply what it found.
    let mut bus = Bus(sim_with(&SimMotor { locked: false, ..m }));
    let mut s = Servo::new(&base).unwrap();
    s.init(&mut bus).unwrap();
    let setup = s.calibration_setup(8.0, 16.0, Phases::ALL);
    let rep = s
        .calibrate(&mut bus, &setup, &mut |_| {}, &mut || false)
        .unwrap();
    let r = rep.results;
    let mut c = Config::from_servo(&base);
    let e = r.encoder.good().expect("encoder");
    for (n, v) in [
        ("motor_pole_pairs", f64::from(e.pole_pairs)),
        ("enc_zero", f64::from(e.zero_counts)),
        ("motor_r_s", r.resistance.good().unwrap().value),
        ("motor_l", r.inductance.good().unwrap().value),
        ("motor_psi_pm", r.flux.good().unwrap().value),
        ("load_inertia", r.mechanics.good().unwrap().j.value),
    ] {
        c.set(&base, n, v).unwrap();
    }
    let after = c.apply(&base);
    // The steps on the rotor where the calibration left it (the encoder's
    // index passed: positions are absolute), held.
    let mut done = bus.0.clone();
    done.apply_sim_motor(&held).unwrap();
    std::println!("| | exact parameters | configured (before) | after `calibrate all` |");
    std::println!("|---|---|---|---|");
    for mode in [Mode::Foc, Mode::Mpdtc] {
        let row: Vec<_> = [&exact, &base, &after]
            .iter()
            .map(|cfg| step_04(&mut done.clone(), cfg, mode))
            .collect();
        let show = |x: &Result<(StepResult, f64), String>| match x {
            Ok((r, t)) => format!(
                "settling {} ms, overshoot {:.1} %, final {:.3} N m (plant {:.3} N m)",
                r.settling_s
                    .map_or("none".into(), |s| format!("{:.3}", s * 1e3)),
                r.overshoot_percent,
                r.final_nm,
                t
            ),
            Err(e) => format!("refused: {e}"),
        };
        std::println!(
            "| {mode:?} step 0.4 | {} | {} | {} |",
            show(&row[0]),
            show(&row[1]),
            show(&row[2])
        );
        let (ex, ex_t) = row[0].clone().unwrap();
        let (af, af_t) = row[2].clone().unwrap();
        let (ts_ex, ts_af) = (
            ex.settling_s.unwrap(),
            af.settling_s.expect("settled after"),
        );
        assert!(
            (ts_af - ts_ex).abs() <= 0.05 * ts_ex,
            "{mode:?}: {ts_af} vs {ts_ex}"
        );
        assert!(
            (af_t - ex_t).abs() <= 0.05 * ex_t.abs(),
            "{mode:?}: {af_t} vs {ex_t}"
        );
    }
}

/// Refusals change nothing: limits beyond the drive's (current at or above
/// `current_limit`, voltage above `u_dc` / 2), the gates on.
#[test]
fn refusals_leave_the_gates_off_and_the_configuration_alone() {
    use drive::servo::ServoError;
    let sim = SimDrive::new(&SimConfig::default()).unwrap();
    let cfg = ServoConfig::for_plant(sim.config().motor, sim.config().adc_amps_per_count);
    let mut bus = Bus(sim);
    let mut s = Servo::new(&cfg).unwrap();
    s.init(&mut bus).unwrap();
    s.set_mode(&mut bus, Mode::Foc).unwrap();
    for (i, v) in [(14.0, 16.0), (8.0, 24.5), (f64::NAN, 16.0)] {
        let setup = s.calibration_setup(i, v, Phases::ALL);
        let r = s.calibrate(&mut bus, &setup, &mut |_| {}, &mut || false);
        assert!(matches!(r, Err(ServoError::BadConfig(_))), "{i} {v}: {r:?}");
        assert!(!s.gates_on(&mut bus).unwrap());
    }
    s.enable(&mut bus).unwrap();
    let setup = s.calibration_setup(8.0, 16.0, Phases::ALL);
    let r = s.calibrate(&mut bus, &setup, &mut |_| {}, &mut || false);
    assert!(matches!(r, Err(ServoError::GatesOn)), "{r:?}");
    assert_eq!(*s.config(), cfg);
    // Stopped at once (Ctrl-C): gates off, nothing measured.
    s.disable(&mut bus).unwrap();
    let rep = s
        .calibrate(&mut bus, &setup, &mut |_| {}, &mut || true)
        .unwrap();
    assert_eq!(
        rep.stopped,
        Some(drive::servo::calibrate::CalStop::Interrupted)
    );
    assert!(!s.gates_on(&mut bus).unwrap());
}

/// A coasting rotor is refused before anything is driven: its back EMF
/// would drive currents the phases do not command (an OVERCURRENT trip
/// at 55 rev/s, seen through the console).
#[test]
fn a_turning_rotor_is_refused_and_nothing_changes() {
    use drive::servo::{ServoError, CAL_REST_REV_S};
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    sim.apply_sim_motor(&SimMotor {
        locked: false,
        ..SimMotor::default()
    })
    .unwrap();
    let cfg = ServoConfig::for_plant(sim.config().motor, sim.config().adc_amps_per_count);
    let mut bus = Bus(sim);
    let mut s = Servo::new(&cfg).unwrap();
    s.init(&mut bus).unwrap();
    s.set_mode(&mut bus, Mode::Foc).unwrap();
    s.enable(&mut bus).unwrap();
    // The frictionless rotor spun up by 0.05 N m, then left to coast.
    s.set_torque_ref(0.05).unwrap();
    let mut speed = 0.0;
    for _ in 0..20_000 {
        bus.0.advance_to_boundary(20_000);
        s.control_step(&mut bus.0).unwrap();
        speed = s.motion_status().velocity_rev_s;
        if speed > 2.0 * CAL_REST_REV_S {
            break;
        }
    }
    assert!(speed > 2.0 * CAL_REST_REV_S, "{speed} rev/s");
    s.set_torque_ref(0.0).unwrap();
    s.disable(&mut bus).unwrap();
    for _ in 0..100 {
        bus.0.advance_to_boundary(20_000);
        s.control_step(&mut bus.0).unwrap();
    }
    let coasting = s.motion_status().velocity_rev_s;
    assert!(coasting > CAL_REST_REV_S, "{coasting} rev/s");
    let setup = s.calibration_setup(8.0, 16.0, Phases::ALL);
    let r = s.calibrate(&mut bus, &setup, &mut |_| {}, &mut || false);
    match r {
        Err(ServoError::RotorTurning(v)) => {
            assert!((v - coasting).abs() < 0.05 * coasting, "{v} vs {coasting}")
        }
        other => panic!("{other:?}"),
    }
    assert!(!s.gates_on(&mut bus).unwrap());
    assert_eq!(*s.config(), cfg);
}
