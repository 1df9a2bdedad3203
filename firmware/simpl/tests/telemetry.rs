//! The telemetry stream of the servo in closed loop on the simulated PL.
use drive::pl::top::Mode;
use drive::servo::{Servo, ServoConfig};
use drive::telemetry::{channel, StreamSpec, Telemetry};
use simpl::{SimConfig, SimDrive};

/// FOC on the simulated PL at 0.3 N m: the stream's torque follows the
/// reference, its duties are the FOC's (strictly inside (0, 1)), the
/// position of a rotor held at standstill stays put, and 1 kHz of
/// 50 ms of drive time gives 50 samples spaced by 1 ms.
#[test]
fn foc_stream_on_the_simulated_pl() {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    let cfg = ServoConfig::for_plant(sim.config().motor, sim.config().adc_amps_per_count);
    let mut servo = Servo::new(&cfg).unwrap();
    servo.init(&mut sim).unwrap();
    servo.set_mode(&mut sim, Mode::Foc).unwrap();
    servo.enable(&mut sim).unwrap();
    servo.set_torque_ref(0.3).unwrap();
    let period = (f64::from(regmap::PL_CLOCK_HZ) / servo.control_rate_hz()) as u64;
    // Settle 10 ms first.
    let settle = (10e-3 * servo.control_rate_hz()) as usize;
    for _ in 0..settle {
        sim.advance_to_boundary(2 * period);
        servo.control_step(&mut sim).unwrap();
    }
    let mut t = Telemetry::<256>::new();
    t.start(StreamSpec::parse("1000", "torque,torque_ref,duty_a,position,faults").unwrap());
    let (mut times, mut torque) = (Vec::new(), Vec::new());
    let t0 = servo.time_s();
    while servo.time_s() < t0 + 50e-3 - 1e-9 {
        sim.advance_to_boundary(2 * period);
        servo.control_step(&mut sim).unwrap();
        t.on_step(&servo.tel_point(1.0));
        while let Some(s) = t.pop() {
            times.push(f64::from(s.time_us) * 1e-6);
            torque.push(s.values[0]);
            assert_eq!(s.values[1], 0.3);
            assert!(
                s.values[2] > 0.0 && s.values[2] < 1.0,
                "duty {}",
                s.values[2]
            );
            assert_eq!(s.values[4], 0.0, "no fault");
        }
    }
    assert_eq!(times.len(), 50);
    for w in times.windows(2) {
        assert!((w[1] - w[0] - 1e-3).abs() < 70e-6, "{w:?}");
    }
    let mean = torque.iter().map(|&x| f64::from(x)).sum::<f64>() / torque.len() as f64;
    assert!((mean - 0.3).abs() < 0.03, "mean torque {mean}");
    assert!(channel("position").is_some());
}

/// The stream's position, velocity and speed in the units of `status`:
/// a rotor turned by the simulated motor at a fixed electrical speed w_e
/// (gates off, nothing drives it) turns at w_e / p rad/s mechanical, that
/// is w_e / (2 pi p) rev/s, and its multi-turn position grows by that
/// times the time, beyond one turn (an angle in [0, 2 pi) or in rad would
/// not match).
#[test]
fn position_velocity_and_speed_are_in_rev_rev_per_s_and_rad_per_s() {
    let w_e = 600.0;
    let mut sim = SimDrive::new(&SimConfig {
        omega_e_rad_s: w_e,
        ..SimConfig::default()
    })
    .unwrap();
    let cfg = ServoConfig::for_plant(sim.config().motor, sim.config().adc_amps_per_count);
    let mut servo = Servo::new(&cfg).unwrap();
    servo.init(&mut sim).unwrap();
    servo.set_mode(&mut sim, Mode::Foc).unwrap();
    let p = f64::from(sim.config().motor.pole_pairs);
    let rev_s = w_e / (core::f64::consts::TAU * p);
    let period = (f64::from(regmap::PL_CLOCK_HZ) / servo.control_rate_hz()) as u64;
    let step = |servo: &mut Servo, sim: &mut SimDrive| {
        sim.advance_to_boundary(2 * period);
        servo.control_step(sim).unwrap();
        // Nothing drives the rotor: the spin's missing heartbeat is all.
        let _ = servo.clear_faults(sim);
    };
    // The speed window fills first.
    for _ in 0..(20e-3 * servo.control_rate_hz()) as usize {
        step(&mut servo, &mut sim);
    }
    let (pos, vel, speed) = (
        channel("position").unwrap(),
        channel("velocity").unwrap(),
        channel("speed").unwrap(),
    );
    let a = servo.tel_point(1.0);
    let t0 = servo.time_s();
    // Long enough for more than one turn.
    let span_s = 1.5 / rev_s;
    while servo.time_s() < t0 + span_s {
        step(&mut servo, &mut sim);
    }
    let b = servo.tel_point(1.0);
    let dt = servo.time_s() - t0;
    for x in [&a, &b] {
        let v = f64::from(x.values[vel]);
        assert!(
            (v / rev_s - 1.0).abs() < 0.01,
            "velocity {v} rev/s, want {rev_s}"
        );
        let w = f64::from(x.values[speed]);
        assert!((w / w_e - 1.0).abs() < 0.01, "speed {w} rad/s, want {w_e}");
    }
    let moved = f64::from(b.values[pos]) - f64::from(a.values[pos]);
    assert!(
        (moved / (rev_s * dt) - 1.0).abs() < 0.01,
        "moved {moved} rev in {dt} s, want {}",
        rev_s * dt
    );
    // And `status` reads the same numbers.
    let st = servo.motion_status();
    assert_eq!(b.values[pos], st.position_rev as f32);
    assert_eq!(b.values[vel], st.velocity_rev_s as f32);
}
