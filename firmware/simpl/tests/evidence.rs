//! The open-phase and dead-encoder checks (`drive::servo::evidence`) on
//! the simulated PL. The fast tier (one period's evidence): an open phase
//! and a dead encoder above its speed trip at the first step after the
//! cause, at many instants of the cause, in FOC and MPDTC; the window
//! tier (0.5 ms) trips a dead encoder below that speed. No trip, with the
//! margins printed (`-- --nocapture`), on a locked rotor at 0.5 N m,
//! torque steps and reversals at the torque limit, a slow rotor, a motor
//! whose parameters are 30 % off the controller's, and the MPDTC's rotor
//! alignment; the same runs with the fault injected do trip.
use drive::pl::fault::Faults;
use drive::pl::top::Mode;
use drive::servo::{evidence, Servo, ServoConfig};
use simpl::{SimConfig, SimDrive};

/// A running drive in `mode` at `torque` N m, `locked` or free, after the
/// `sim` settings, stepped until `ready` (or 20 000 steps).
fn running_with(
    mode: Mode,
    torque: f64,
    locked: bool,
    sim_set: &[(&str, f64)],
    ready: impl Fn(&Servo, u32) -> bool,
) -> (Servo, SimDrive, u64) {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    let mut s = Servo::new(&ServoConfig::for_plant(
        sim.config().motor,
        sim.config().adc_amps_per_count,
    ))
    .unwrap();
    s.init(&mut sim).unwrap();
    sim.sim_set("locked", if locked { 1.0 } else { 0.0 })
        .unwrap();
    for (k, v) in sim_set {
        sim.sim_set(k, *v).unwrap();
    }
    s.set_mode(&mut sim, mode).unwrap();
    s.enable(&mut sim).unwrap();
    s.set_torque_ref(torque).unwrap();
    let period = period(&s);
    // Steps of the running controller (after the MPDTC's alignment).
    let (mut k, mut n) = (0, 0);
    while !(s.controlling() && ready(&s, k)) {
        sim.advance_to_boundary(2 * period);
        s.control_step(&mut sim).unwrap();
        k += u32::from(s.controlling());
        n += 1;
        assert!(n < 30_000, "{mode:?}: not ready");
        let f = s.faults(&mut sim).unwrap().0;
        assert_eq!(f, 0, "{mode:?}: trip {f:#x} at {k}: {:?}", s.fast_verdict());
    }
    (s, sim, period)
}

fn running(
    mode: Mode,
    torque: f64,
    locked: bool,
    ready: impl Fn(&Servo, u32) -> bool,
) -> (Servo, SimDrive, u64) {
    running_with(mode, torque, locked, &[], ready)
}

fn period(s: &Servo) -> u64 {
    libm::round(f64::from(regmap::PL_CLOCK_HZ) / s.control_rate_hz()) as u64
}

fn step(s: &mut Servo, sim: &mut SimDrive, period: u64) {
    sim.advance_to_boundary(2 * period);
    s.control_step(sim).unwrap();
}

/// Control steps from the cause (right after a step) to the one that
/// turns the gates off, and the faults then latched.
fn steps_to_gates_off(s: &mut Servo, sim: &mut SimDrive, period: u64) -> (u32, u32) {
    let mut j = 0;
    while s.gates_on(sim).unwrap() {
        step(s, sim, period);
        j += 1;
        assert!(j < 1000, "no trip: {:?}", s.fast_verdict());
    }
    (j, s.faults(sim).unwrap().0)
}

/// The fast tier's allowances in `mode`.
fn allowance(mode: Mode) -> evidence::Allowance {
    if mode == Mode::Foc {
        evidence::FOC_ALLOWANCE
    } else {
        evidence::MPDTC_ALLOWANCE
    }
}

/// Electrical speed from which the fast tier sees a dead encoder: its
/// count threshold per control period, rad/s.
fn fast_speed(s: &Servo) -> f64 {
    let c = ServoConfig::for_plant(
        SimConfig::default().motor,
        SimConfig::default().adc_amps_per_count,
    );
    let ts = 1.0 / s.control_rate_hz();
    allowance(s.mode()).dead_counts * 2.0 * core::f64::consts::PI / f64::from(c.enc_cpr) / ts
        * f64::from(c.motor.pole_pairs)
}

#[test]
fn an_open_phase_trips_at_the_next_step_at_any_instant() {
    for mode in [Mode::Foc, Mode::Mpdtc] {
        let mut fast = 0;
        for (n, extra) in (0..100).step_by(7).enumerate() {
            // Each phase in turn; a locked rotor at 0.2 N m (the matrix's
            // cell: on the d axis, phase a carries no current) and a free
            // one at 0.5 N m.
            let phase = 1 + n % 3;
            let (torque, locked) = if n % 2 == 0 {
                (0.2, true)
            } else {
                (0.5, false)
            };
            let phase = if locked { 2 + n % 2 } else { phase };
            let (mut s, mut sim, period) = running(mode, torque, locked, |_, k| k > 200 + extra);
            let win = evidence::window_periods(period as f64 / f64::from(regmap::PL_CLOCK_HZ));
            // The phase carries current the next step predicts: the fast
            // tier decides; else the window does.
            let carries = s.fast_verdict().pred_abc[phase - 1].abs() >= 1.2;
            sim.sim_set("phase_open", phase as f64).unwrap();
            let cause = sim.pl_cycles();
            let (j, f) = steps_to_gates_off(&mut s, &mut sim, period);
            assert_eq!(f, Faults::PHASE_OPEN, "{mode:?} +{extra}: after {j} steps");
            if carries {
                assert_eq!(j, 1, "{mode:?} +{extra} phase {phase}");
                let off = sim.gates_off_since().unwrap() - cause;
                assert!(off <= period, "{mode:?} +{extra}: {off} cycles");
                fast += 1;
            } else {
                assert!(j <= win + 1, "{mode:?} +{extra}: {j} steps");
            }
        }
        assert!(fast >= 8, "{mode:?}: {fast} of 15 in one period");
    }
}

#[test]
fn a_dead_encoder_trips_at_the_next_step_above_the_fast_tiers_speed() {
    for mode in [Mode::Foc, Mode::Mpdtc] {
        for extra in (0..300).step_by(23) {
            // Free rotor at 0.5 N m, 1.5x the fast tier's speed.
            let (mut s, mut sim, period) = running(mode, 0.5, false, |s, k| {
                k > extra && s.measured().omega_e_rad_s.abs() > 1.5 * fast_speed(s)
            });
            // Right after a step, as `debug fault` injects it.
            sim.sim_set("enc_dead", 1.0).unwrap();
            let cause = sim.pl_cycles();
            let (j, f) = steps_to_gates_off(&mut s, &mut sim, period);
            assert_eq!(f, Faults::ENCODER_DEAD, "{mode:?} +{extra}: after {j}");
            assert_eq!(j, 1, "{mode:?} +{extra}");
            let off = sim.gates_off_since().unwrap() - cause;
            assert!(off <= period, "{mode:?} +{extra}: {off} cycles");
        }
    }
}

#[test]
fn a_dead_encoder_below_the_fast_tiers_speed_trips_at_the_window() {
    for mode in [Mode::Foc, Mode::Mpdtc] {
        for extra in (0..30).step_by(6) {
            // Free rotor at 0.5 N m between the window's threshold (161
            // rad/s) and the fast tier's speed.
            let (mut s, mut sim, period) = running(mode, 0.5, false, |s, _| {
                s.measured().omega_e_rad_s.abs() > 250.0 + extra as f64
            });
            let w = s.measured().omega_e_rad_s.abs();
            assert!(w < fast_speed(&s), "{mode:?}: {w} rad/s");
            let win = evidence::window_periods(period as f64 / f64::from(regmap::PL_CLOCK_HZ));
            sim.sim_set("enc_dead", 1.0).unwrap();
            let (j, f) = steps_to_gates_off(&mut s, &mut sim, period);
            assert_eq!(f, Faults::ENCODER_DEAD, "{mode:?} +{extra}: after {j}");
            assert!(j <= win + 1, "{mode:?} +{extra}: {j} steps, window {win}");
        }
    }
}

/// The fast tier's closest approach to a trip over `n` steps with `act`
/// run before each (step index): the smallest measured/predicted ratio
/// of a phase predicted at 1 A or more, and the most counts the back-EMF
/// proved in a period where the count stood still. Asserts no trip.
fn margins(
    s: &mut Servo,
    sim: &mut SimDrive,
    period: u64,
    n: u32,
    mut act: impl FnMut(&mut Servo, u32),
) -> (f64, f64) {
    let (mut ratio, mut counts) = (f64::INFINITY, 0.0_f64);
    for k in 0..n {
        act(s, k);
        step(s, sim, period);
        let f = s.faults(sim).unwrap().0;
        assert_eq!(f, 0, "trip {f:#x} at step {k}: {:?}", s.fast_verdict());
        let v = s.fast_verdict();
        ratio = ratio.min(v.open_ratio);
        if v.still {
            counts = counts.max(v.counts);
        }
    }
    (ratio, counts)
}

#[test]
fn no_trip_without_a_fault_and_the_margins() {
    for mode in [Mode::Foc, Mode::Mpdtc] {
        let c = allowance(mode).dead_counts;
        // Steps at the torque limit (1 N m); the MPDTC's reversal of 2 N m
        // on a locked rotor overshoots into OVERCURRENT (13.4 A): 0.8 N m.
        let amp = if mode == Mode::Foc { 1.0 } else { 0.8 };
        let mut report = Vec::new();
        let r = allowance(mode).open_fraction;
        // A locked rotor at 0.5 N m for 20 ms.
        let (mut s, mut sim, p) = running(mode, 0.5, true, |_, k| k > 10);
        let n = (2_000_000 / p) as u32;
        println!("{mode:?} locked");
        report.push(("locked 0.5 N m", margins(&mut s, &mut sim, p, n, |_, _| {})));
        // Steps 0 -> 1 N m -> -1 N m -> 0 every 2 ms, locked and free.
        for locked in [true, false] {
            println!("{mode:?} steps {locked}");
            let (mut s, mut sim, p) = running(mode, 0.0, locked, |_, k| k > 10);
            let seg = (200_000 / p) as u32;
            let m = margins(&mut s, &mut sim, p, 8 * seg, |s, k| {
                if k % seg == 0 {
                    let t = [1.0, -1.0, 0.0, 1.0, 0.0, -1.0, 1.0, 0.0][(k / seg) as usize];
                    let t = t * amp;
                    s.set_torque_ref(t).unwrap();
                }
            });
            report.push((
                if locked {
                    "steps, locked"
                } else {
                    "steps, free"
                },
                m,
            ));
        }
        // A slow rotor: 0.1 N m from rest for 20 ms.
        println!("{mode:?} slow");
        let (mut s, mut sim, p) = running(mode, 0.1, false, |_, k| k > 10);
        report.push(("slow, free", margins(&mut s, &mut sim, p, n, |_, _| {})));
        // The motor 30 % off the controller's model, each way, stepped.
        for f in [0.7, 1.3] {
            let mo = SimConfig::default().motor;
            let set = [
                ("r_s", mo.r_s_ohm * f),
                ("l", mo.l_d_h * f),
                ("psi_pm", mo.psi_pm_wb * (2.0 - f)),
            ];
            println!("{mode:?} mismatch {f}");
            let (mut s, mut sim, p) = running_with(mode, 0.0, false, &set, |_, k| k > 10);
            let seg = (200_000 / p) as u32;
            let m = margins(&mut s, &mut sim, p, 6 * seg, |s, k| {
                if k % seg == 0 {
                    let t = [1.0, -1.0, 1.0, 0.0, -1.0, 0.5][(k / seg) as usize] * amp;
                    s.set_torque_ref(t).unwrap();
                }
            });
            report.push((
                if f < 1.0 {
                    "motor -30 %"
                } else {
                    "motor +30 %"
                },
                m,
            ));
        }
        for (what, (ratio, counts)) in &report {
            println!(
                "{mode:?} {what}: measured/predicted >= {ratio:.3} (trips at {r}), \
                 still-count periods <= {counts:.2} counts (trips at {c})"
            );
            // 20 % margin on the ratio, 10 % with the motor 30 % off the
            // model (the MPDTC's trip share, 0.55, sits close to the 0.5 an
            // open phase gives when half an average precedes the cause).
            let k = if what.starts_with("motor") { 1.1 } else { 1.2 };
            assert!(*ratio > k * r && *counts < 0.75 * c, "{mode:?} {what}");
        }
    }
}

/// A boundary served without a step (an overrun: the co-simulation's
/// late interrupt) or a step whose ADC read came after the next result:
/// the step's currents are then not those of the voltage the checks pair
/// them with. On a free rotor spinning up slowly (a still count most
/// periods) the one-period check then proved tens of counts of motion
/// (`ENCODER_DEAD` in the fault matrix's co-simulated MPDTC cells with
/// `overruns: 4`); the checks start afresh after such a period instead.
#[test]
fn a_period_without_its_step_is_no_evidence() {
    for mode in [Mode::Foc, Mode::Mpdtc] {
        for (n, skip_at) in (20..80).step_by(3).enumerate() {
            let (mut s, mut sim, period) = running(mode, 0.5, false, |_, k| k > 5);
            for k in 0..100 {
                if k == skip_at {
                    if n % 2 == 0 {
                        // A boundary served without a step.
                        sim.advance_to_boundary(2 * period);
                        s.note_overruns(1);
                    } else {
                        // The step starts late: its read follows the next
                        // result (MPDTC) or the next period's first (FOC).
                        sim.advance_to_boundary(2 * period);
                        sim.advance(period - 40);
                        s.control_step(&mut sim).unwrap();
                        continue;
                    }
                }
                step(&mut s, &mut sim, period);
                let f = s.faults(&mut sim).unwrap().0;
                assert_eq!(
                    f,
                    0,
                    "{mode:?} skip at {skip_at} ({n}): trip {f:#x} at {k}: {:?}",
                    s.fast_verdict()
                );
            }
        }
    }
}

/// A 1 rev move in MPDTC on ten times the configured inertia with
/// Coulomb friction of 0.05 N m (`motion::a_move_on_a_load_it_was_not_told_about...`
/// under QEMU), started at 40 instants after the alignment: no fault. The
/// MPDTC leaves the d-axis current free (-1.4 A at -3.4 A of q current
/// while braking), and the window check's reference (i_d = 0) wanted
/// -1.32 A in phase b while the MPDTC held it at -0.04 A for the window:
/// a false `PHASE_OPEN` at 3 of the 40 instants.
#[test]
fn an_mpdtc_move_on_a_heavy_load_trips_nothing() {
    for delay_ms in (0..120u64).step_by(3) {
        let sims = [("j", 8.1e-4), ("coulomb", 0.05)];
        let (mut s, mut sim, period) = running_with(Mode::Mpdtc, 0.0, false, &sims, |_, k| k > 0);
        let per_ms = 100_000 / period;
        for _ in 0..delay_ms * per_ms {
            step(&mut s, &mut sim, period);
        }
        s.begin_move(&mut sim, 1.0, 0.3).unwrap();
        let mut k = 0;
        while s.move_pending() {
            step(&mut s, &mut sim, period);
            let f = s.faults(&mut sim).unwrap().0;
            assert_eq!(
                f,
                0,
                "+{delay_ms} ms: trip {f:#x} at step {k}: {:?}",
                s.measured()
            );
            k += 1;
            assert!(
                k < 1000 * per_ms,
                "+{delay_ms} ms: the move does not end in 1 s"
            );
        }
        let r = s.move_result().expect("a result");
        assert!(r.final_error_counts.abs() <= 2.0, "+{delay_ms} ms: {r:?}");
    }
}
