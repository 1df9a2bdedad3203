//! The checks over a window (`drive::servo::evidence`) on the simulated PL,
//! at many instants of the cause: a dead encoder on a turning rotor and an
//! open phase on a held one close within the window plus one control
//! period in FOC and MPDTC, whatever the instant (the dead encoder at the
//! window exactly: no period of the window is lost to a zero crossing that
//! looks like an open phase).
use drive::pl::fault::Faults;
use drive::pl::top::Mode;
use drive::servo::{evidence, Servo, ServoConfig};
use simpl::{SimConfig, SimDrive};

/// A running drive in `mode` at `torque` N m, `locked` or free, stepped
/// until `ready` (or 20 000 steps).
fn running(
    mode: Mode,
    torque: f64,
    locked: bool,
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
    s.set_mode(&mut sim, mode).unwrap();
    s.enable(&mut sim).unwrap();
    s.set_torque_ref(torque).unwrap();
    let period = libm::round(f64::from(regmap::PL_CLOCK_HZ) / s.control_rate_hz()) as u64;
    let mut k = 0;
    while !(s.controlling() && ready(&s, k)) {
        sim.advance_to_boundary(2 * period);
        s.control_step(&mut sim).unwrap();
        k += 1;
        assert!(k < 20_000, "{mode:?}: not ready");
    }
    (s, sim, period)
}

/// Control steps from the cause (right after a step) to the one that
/// turns the gates off, and the faults then latched.
fn steps_to_gates_off(s: &mut Servo, sim: &mut SimDrive, period: u64) -> (u32, u32) {
    let mut j = 0;
    while s.gates_on(sim).unwrap() {
        sim.advance_to_boundary(2 * period);
        s.control_step(sim).unwrap();
        j += 1;
        assert!(j < 1000, "no trip");
    }
    (j, s.faults(sim).unwrap().0)
}

#[test]
fn a_dead_encoder_trips_at_the_window_at_any_instant() {
    for mode in [Mode::Foc, Mode::Mpdtc] {
        for extra in (0..300).step_by(11) {
            // Free rotor at 0.5 N m; above 900 rad/s (5.6x the threshold,
            // more than one count per control period) the encoder dies at
            // a boundary, `extra` steps later each time: the count stands
            // still from that step on, the window closes `win` steps later.
            let (mut s, mut sim, period) = running(mode, 0.5, false, |s, k| {
                k > extra && s.measured().omega_e_rad_s.abs() > 900.0
            });
            let win = evidence::window_periods(period as f64 / f64::from(regmap::PL_CLOCK_HZ));
            sim.advance_to_boundary(2 * period);
            sim.sim_set("enc_dead", 1.0).unwrap();
            let cause = sim.pl_cycles();
            s.control_step(&mut sim).unwrap();
            let (j, f) = steps_to_gates_off(&mut s, &mut sim, period);
            assert_eq!(
                f,
                Faults::ENCODER_DEAD,
                "{mode:?} +{extra}: after {j} steps"
            );
            assert_eq!(j, win, "{mode:?} +{extra}");
            let off = sim.gates_off_since().unwrap() - cause;
            assert!(
                off <= (u64::from(win) + 1) * period,
                "{mode:?} +{extra}: {off} cycles"
            );
        }
    }
}

#[test]
fn an_open_phase_trips_within_the_window_at_any_instant() {
    for mode in [Mode::Foc, Mode::Mpdtc] {
        for extra in (0..100).step_by(11) {
            let (mut s, mut sim, period) = running(mode, 0.2, true, |_, k| k > 200 + extra);
            let win = evidence::window_periods(period as f64 / f64::from(regmap::PL_CLOCK_HZ));
            sim.sim_set("phase_open", 2.0).unwrap();
            let (j, f) = steps_to_gates_off(&mut s, &mut sim, period);
            assert_eq!(f, Faults::PHASE_OPEN, "{mode:?} +{extra}: after {j} steps");
            assert!(j <= win + 1, "{mode:?} +{extra}: {j} steps, window {win}");
        }
    }
}
