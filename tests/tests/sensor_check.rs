//! The drive's sensor check (`drive::servo::sensors`) against the simulated
//! PL on the host: every wrong wiring of the three current channels (the
//! five other orders and each single inversion) is found and named, the
//! right one passes within a few ms of PL time, and the encoder's direction
//! is judged when the rotor turns.
use drive::pl::top::Mode;
use drive::servo::sensors::{PlTime, SensorFault};
use drive::servo::{Servo, ServoConfig, ServoError};
use regmap::bus::{BusError, RegisterBus};
use simpl::{AdcWiring, SimConfig, SimDrive};

/// The simulated PL with PL time the check may let pass.
struct Timed(SimDrive);

impl RegisterBus for Timed {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        self.0.read(addr)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.0.write(addr, value)
    }
}

impl PlTime for Timed {
    fn wait_cycles(&mut self, cycles: u64) {
        let _ = self.0.advance(cycles);
    }
}

fn drive(sim: &SimConfig, w: AdcWiring) -> (Servo, Timed) {
    let mut pl = Timed(SimDrive::new(sim).unwrap());
    pl.0.set_adc_wiring(w);
    let mut s = Servo::new(&ServoConfig::for_plant(sim.motor, sim.adc_amps_per_count)).unwrap();
    s.init(&mut pl).unwrap();
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    (s, pl)
}

#[test]
fn the_right_wiring_passes_in_a_few_ms_and_leaves_the_gates_off() {
    let (mut s, mut pl) = drive(&SimConfig::default(), AdcWiring::default());
    let r = s.check_sensors(&mut pl).unwrap();
    assert_eq!(r.result, Ok(()), "{r:?}");
    let ms = r.cycles as f64 / 1e5;
    assert!(ms < 3.0, "{ms} ms");
    eprintln!("sensor check: {ms:.3} ms of PL time, {r:?}");
    // Hand estimate (module docs): di/dt about 4.8 kA/s, 1.4 A after about
    // 0.3 ms; the vector ends at the first averaged result past the target.
    for c in r.vector_cycles {
        assert!((20_000..60_000).contains(&c), "{c} cycles");
    }
    assert!(!s.gates_on(&mut pl).unwrap());
    let g = pl.0.gates();
    assert_eq!((g.hi, g.lo), (0, 0));
    assert!(!s.sensor_check_due());
    // Enabled without a second check.
    s.enable_checked(&mut pl).unwrap();
    assert!(s.gates_on(&mut pl).unwrap());
}

#[test]
fn every_wrong_order_and_every_inversion_is_found() {
    let orders = [[0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]];
    for source in orders {
        let w = AdcWiring {
            source,
            inverted: [false; 3],
        };
        let (mut s, mut pl) = drive(&SimConfig::default(), w);
        let r = s.check_sensors(&mut pl).unwrap();
        let ch = (0..3).find(|&j| source[j] != j).unwrap();
        assert_eq!(
            r.result,
            Err(SensorFault::Order {
                ch,
                phase: source[ch]
            }),
            "{source:?}"
        );
        assert!(s.sensor_check_due());
        match s.enable_checked(&mut pl) {
            Err(ServoError::SensorCheck(SensorFault::Order { .. })) => {}
            e => panic!("{source:?}: {e:?}"),
        }
        assert!(!s.gates_on(&mut pl).unwrap());
    }
    for ch in 0..3 {
        let mut w = AdcWiring::default();
        w.inverted[ch] = true;
        let (mut s, mut pl) = drive(&SimConfig::default(), w);
        let r = s.check_sensors(&mut pl).unwrap();
        assert!(
            matches!(r.result, Err(SensorFault::Inverted { ch: c, read_a }) if c == ch && read_a < -1.0),
            "{ch}: {r:?}"
        );
    }
}

#[test]
fn the_encoder_direction_is_judged_when_the_rotor_turns() {
    // A dynamometer turning the rotor forwards (with the field's a-b-c
    // rotation) or backwards at 200 rad/s electrical (28.6 rad/s with 7
    // pole pairs): about 26 of 4096 counts over the 1.4 ms check.
    for (w, ok) in [(200.0, true), (-200.0, false)] {
        let sim = SimConfig {
            omega_e_rad_s: w,
            ..SimConfig::default()
        };
        let (mut s, mut pl) = drive(&sim, AdcWiring::default());
        let r = s.check_sensors(&mut pl).unwrap();
        assert!(r.encoder_judged(), "{r:?}");
        assert_eq!(r.result.is_ok(), ok, "{r:?}");
        if !ok {
            assert!(matches!(r.result, Err(SensorFault::EncoderReversed(n)) if n < 0));
        }
    }
}

#[test]
fn a_new_motor_or_sensor_configuration_checks_again() {
    let (mut s, mut pl) = drive(&SimConfig::default(), AdcWiring::default());
    s.check_sensors(&mut pl).unwrap().result.unwrap();
    let mut cfg = *s.config();
    cfg.torque_limit_nm *= 0.5;
    s.reconfigure(&mut pl, &cfg).unwrap();
    assert!(!s.sensor_check_due(), "a torque limit is no sensor fact");
    cfg.enc_cpr = 2048;
    s.reconfigure(&mut pl, &cfg).unwrap();
    assert!(s.sensor_check_due());
}

#[test]
fn a_period_change_then_the_check_then_enable() {
    // `config set foc_half_period 6256`, `adc_period 782`, modes FOC and
    // MPDTC, `config reset`, `current_limit 3` (the check is due), `mode
    // foc`, `enable`, with control steps in between: each period change
    // restarts the ADC's conversions (`Adc::set_period`), which moves the
    // averaged results against the PWM period. The check read the
    // previous vector (vector b's reading on phase a: "channels swapped")
    // while the PWM still had its duties; its readings are now each
    // vector's own.
    let sim = SimConfig::default();
    let (mut s, mut pl) = drive(&sim, AdcWiring::default());
    s.set_mode(&mut pl, Mode::Off).unwrap();
    let base = *s.config();
    let steps = |s: &mut Servo, pl: &mut Timed| {
        for _ in 0..50 {
            pl.0.advance_to_boundary(20_000);
            s.control_step(&mut pl.0).unwrap();
        }
    };
    let set = |s: &mut Servo, pl: &mut Timed, adc: u32, half: u32, limit_a: f64| {
        let c = ServoConfig {
            adc_period_cycles: adc,
            foc_half_period_cycles: half,
            current_limit_a: limit_a,
            ..base
        };
        s.reconfigure(&mut *pl, &c).unwrap();
        assert_eq!(drive::pl::adc::Adc(&mut *pl).period().unwrap(), adc);
    };
    let limit = base.current_limit_a;
    set(&mut s, &mut pl, 391, 6256, limit);
    steps(&mut s, &mut pl);
    let n0 = drive::pl::adc::Adc(&mut pl).count().unwrap();
    set(&mut s, &mut pl, 782, 6256, limit);
    steps(&mut s, &mut pl);
    // The conversions run at the new period: 50 MPDTC-off periods of 4
    // results each.
    assert!(drive::pl::adc::Adc(&mut pl).count().unwrap() - n0 >= 50);
    for m in [Mode::Foc, Mode::Mpdtc] {
        s.set_mode(&mut pl, m).unwrap();
        steps(&mut s, &mut pl);
    }
    set(&mut s, &mut pl, 391, 3128, limit);
    steps(&mut s, &mut pl);
    set(&mut s, &mut pl, 391, 3128, 3.0);
    steps(&mut s, &mut pl);
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    steps(&mut s, &mut pl);
    assert!(s.sensor_check_due());
    let r = s.check_sensors(&mut pl).unwrap();
    assert_eq!(r.result, Ok(()), "{r:?}");
    // Each vector's reading is its own phase's, the others about -1/2 of
    // it (module doc of `drive::servo::sensors`).
    for (k, row) in r.readings_a.iter().enumerate() {
        for (j, &x) in row.iter().enumerate() {
            if j == k {
                assert!(x >= r.target_a, "{r:?}");
            } else {
                assert!((x / row[k] + 0.5).abs() < 0.25, "{r:?}");
            }
        }
    }
    s.enable_checked(&mut pl).unwrap();
    steps(&mut s, &mut pl);
    assert!(s.gates_on(&mut pl).unwrap());
    assert!(s.faults(&mut pl).unwrap().none());
}
