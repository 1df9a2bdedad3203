//! The servo's fault checks on the simulated PL: the gates-off time of
//! every fault, and no false fault on mode changes.
use drive::pl::adc::Adc;
use drive::pl::fault::Faults;
use drive::pl::top::Mode;
use drive::servo::{Servo, ServoConfig};
use simpl::{SimConfig, SimDrive};

/// Gates-off time on the simulated PL, PL clock cycles from the fault's
/// cause to all six gate outputs low, for the PL's faults (its own logic)
/// and the PS's (the control step that sees them). Every one within one
/// control period.
#[test]
fn gates_go_off_within_one_control_period_on_the_simulated_pl() {
    fn setup(mode: Mode) -> (Servo, SimDrive, u64) {
        let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
        let mut s = Servo::new(&ServoConfig::for_plant(
            sim.config().motor,
            sim.config().adc_amps_per_count,
        ))
        .unwrap();
        s.init(&mut sim).unwrap();
        s.set_mode(&mut sim, mode).unwrap();
        s.enable(&mut sim).unwrap();
        s.set_torque_ref(0.3).unwrap();
        // Past the MPDTC's alignment, then 200 periods.
        while !s.controlling() {
            sim.advance_to_boundary(20_000);
            s.control_step(&mut sim).unwrap();
        }
        for _ in 0..200 {
            sim.advance_to_boundary(20_000);
            s.control_step(&mut sim).unwrap();
        }
        let period = libm::round(f64::from(regmap::PL_CLOCK_HZ) / s.control_rate_hz()) as u64;
        (s, sim, period)
    }
    let off = |sim: &SimDrive| {
        let g = sim.gates();
        g.hi == 0 && g.lo == 0
    };
    for mode in [Mode::Foc, Mode::Mpdtc] {
        // External: the pin, through its 2-flop synchroniser.
        let (_, mut sim, period) = setup(mode);
        assert!(!off(&sim));
        sim.set_external_fault(true);
        let mut n = 0;
        while !off(&sim) {
            sim.advance(1);
            n += 1;
            assert!(n < period, "{mode:?}: external");
        }
        std::println!("{mode:?}: EXTERNAL gates off after {n} cycles");
        assert!(n <= 4, "{mode:?}: {n}");

        // ADC stuck: the conversions stop; the PS sees it at the second
        // control step without a new result (FOC: a PWM period holds 4 ADC
        // periods) or when no period boundary comes in two periods (MPDTC).
        let (mut s, mut sim, period) = setup(mode);
        Adc(&mut sim).set_enabled(false).unwrap();
        let t0 = sim.pl_cycles();
        let mut k = 0;
        while !off(&sim) {
            let a = sim.advance_to_boundary(2 * period);
            if a.control_periods == 0 {
                s.note_no_boundary(&mut sim, 2).unwrap();
            } else {
                s.control_step(&mut sim).unwrap();
            }
            k += 1;
            assert!(k < 10, "{mode:?}: adc");
        }
        let n = sim.pl_cycles() - t0;
        std::println!(
            "{mode:?}: ADC_STUCK gates off {n} cycles after the ADC stopped ({:.2} periods)",
            n as f64 / period as f64
        );
        // The first missing result is due one period after the stop (FOC:
        // the first step after it may still read the last one); the check
        // gives up on it one period later.
        let due = period;
        // (plus the cycles of the register accesses that turn them off).
        assert!(n - due <= period + 8, "{mode:?}: {n}");
        assert_eq!(
            s.faults(&mut sim).unwrap().0 & Faults::ADC_STUCK,
            Faults::ADC_STUCK
        );
    }
}

/// Mode changes move the control-period boundary (the first FOC boundary
/// may come before the next ADC result): no false ADC_STUCK, in either
/// direction, with the gates on and off.
#[test]
fn mode_changes_on_the_simulated_pl_raise_no_fault() {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    let mut s = Servo::new(&ServoConfig::for_plant(
        sim.config().motor,
        sim.config().adc_amps_per_count,
    ))
    .unwrap();
    s.init(&mut sim).unwrap();
    for (k, mode) in [Mode::Mpdtc, Mode::Foc, Mode::Off, Mode::Foc, Mode::Mpdtc]
        .into_iter()
        .cycle()
        .take(12)
        .enumerate()
    {
        s.set_mode(&mut sim, mode).unwrap();
        if mode != Mode::Off && k % 2 == 0 {
            s.enable(&mut sim).unwrap();
        }
        for _ in 0..(50 + 37 * k) {
            let a = sim.advance_to_boundary(20_000);
            assert_eq!(a.control_periods, 1);
            s.control_step(&mut sim).unwrap();
        }
        assert!(s.faults(&mut sim).unwrap().none(), "{k} {mode:?}");
    }
    assert_eq!(s.fault_history().total, 0);
}

/// The snapshot of a PL fault holds the torque reference the drive was
/// following, not the 0 N m the fault's gates-off sets afterwards: the
/// last sample's reference matches its measured torque.
#[test]
fn a_pl_fault_snapshot_keeps_the_reference_before_the_gates_went_off() {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    let mut s = Servo::new(&ServoConfig::for_plant(
        sim.config().motor,
        sim.config().adc_amps_per_count,
    ))
    .unwrap();
    s.init(&mut sim).unwrap();
    s.set_mode(&mut sim, Mode::Mpdtc).unwrap();
    s.enable(&mut sim).unwrap();
    s.set_torque_ref(0.4).unwrap();
    // Past the MPDTC's alignment and the torque's rise.
    while !s.controlling() {
        sim.advance_to_boundary(20_000);
        s.control_step(&mut sim).unwrap();
    }
    for _ in 0..400 {
        sim.advance_to_boundary(20_000);
        s.control_step(&mut sim).unwrap();
    }
    sim.set_external_fault(true);
    sim.advance(10);
    sim.advance_to_boundary(20_000);
    s.control_step(&mut sim).unwrap();
    // EXTERNAL is bit 1, code 2.
    let codes: Vec<u32> = s.fault_history().records().map(|r| r.code()).collect();
    assert_eq!(codes, [2]);
    let r = s.fault_history().records().next().unwrap();
    let last = r.snapshot.samples().last().unwrap();
    assert_eq!(last.torque_ref_nm, 0.4, "{r:?}");
    assert!((last.measured.torque_nm - 0.4).abs() < 0.1, "{r:?}");
    let mut line = std::string::String::new();
    r.write_summary(&mut line).unwrap();
    assert!(line.ends_with("(ref 0.4000 Nm)"), "{line}");
    // The drive itself is back at 0 N m for the next run.
    assert_eq!(s.torque_ref_nm(), 0.0);
}
