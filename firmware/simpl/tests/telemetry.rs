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
