//! The PS's fault checks against the fake PL, and the gates-off time of
//! every fault measured on the simulated PL.
use super::*;
use crate::pl::fake::FakePl;
use crate::regmap::{ENC, FAULT_STATUS_ADDR, GATE_CTRL_ADDR};
use crate::simpl::{SimConfig, SimDrive};

fn running(mode: Mode) -> (Servo, FakePl) {
    let mut s = Servo::new(&ServoConfig::default()).unwrap();
    let mut pl = FakePl::new();
    s.init(&mut pl).unwrap();
    s.set_mode(&mut pl, mode).unwrap();
    s.enable(&mut pl).unwrap();
    for _ in 0..10 {
        s.control_step(&mut pl).unwrap();
    }
    assert!(s.faults(&mut pl).unwrap().none());
    assert_eq!(pl.get(GATE_CTRL_ADDR), 1);
    (s, pl)
}

fn codes(s: &Servo) -> Vec<u32> {
    s.fault_history().records().map(|r| r.code()).collect()
}

#[test]
fn adc_stuck_latches_at_the_second_step_without_a_result_and_clear_restarts_the_adc() {
    let (mut s, mut pl) = running(Mode::Foc);
    Adc(&mut pl).set_enabled(false).unwrap();
    // One stale step is tolerated (a late step may have read its result).
    s.control_step(&mut pl).unwrap();
    assert!(s.faults(&mut pl).unwrap().none());
    assert_eq!(pl.get(GATE_CTRL_ADDR), 1);
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.faults(&mut pl).unwrap(), Faults(Faults::ADC_STUCK));
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    assert_eq!(codes(&s), [5]);
    let r = s.fault_history().records().next().unwrap();
    assert_eq!(r.snapshot.len(), faults::SNAPSHOT_LEN);
    // 12 FOC periods of 6256 cycles at 100 MHz.
    assert!((r.time_s - 12.0 * 62.56e-6).abs() < 1e-9, "{r:?}");
    assert!(matches!(
        s.enable(&mut pl),
        Err(ServoError::FaultLatched(_))
    ));
    // Still latched and recorded once.
    s.control_step(&mut pl).unwrap();
    assert_eq!(codes(&s), [5]);
    assert!(s.clear_faults(&mut pl).unwrap().none());
    assert_eq!(pl.get(regmap::ADC.addr(&regmap::ADC_CTRL)), 1);
    s.enable(&mut pl).unwrap();
    for _ in 0..5 {
        s.control_step(&mut pl).unwrap();
    }
    assert!(s.faults(&mut pl).unwrap().none());
}

#[test]
fn an_impossible_encoder_jump_is_encoder_loss() {
    let (mut s, mut pl) = running(Mode::Foc);
    let pos = ENC.addr(&regmap::ENC_POS);
    // 4096 counts per turn: 512 (an eighth) is the most per period,
    // either way and across zero.
    for p in [512, 0, 3584] {
        pl.set(pos, p);
        s.control_step(&mut pl).unwrap();
        assert!(s.faults(&mut pl).unwrap().none(), "{p}");
    }
    pl.set(pos, 3584 - 513);
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.faults(&mut pl).unwrap(), Faults(Faults::ENCODER_LOSS));
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    assert_eq!(codes(&s), [4]);
}

#[test]
fn two_missed_periods_are_an_overrun() {
    let (mut s, mut pl) = running(Mode::Mpdtc);
    s.note_overruns(1);
    s.control_step(&mut pl).unwrap();
    assert!(s.faults(&mut pl).unwrap().none());
    s.note_overruns(2);
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.faults(&mut pl).unwrap(), Faults(Faults::CONTROL_OVERRUN));
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    assert_eq!(s.overruns(), 3);
    assert_eq!(codes(&s), [6]);
}

#[test]
fn pl_faults_are_recorded_once_each() {
    let (mut s, mut pl) = running(Mode::Foc);
    pl.set(FAULT_STATUS_ADDR, 0b010);
    s.control_step(&mut pl).unwrap();
    s.control_step(&mut pl).unwrap();
    pl.set(FAULT_STATUS_ADDR, 0b011);
    s.control_step(&mut pl).unwrap();
    assert_eq!(codes(&s), [2, 1]);
    assert!(s.clear_faults(&mut pl).unwrap().none());
    pl.set(FAULT_STATUS_ADDR, 0b010);
    s.control_step(&mut pl).unwrap();
    assert_eq!(codes(&s), [2, 1, 2]);
    assert_eq!(s.fault_history().total, 3);
}

#[test]
fn no_boundary_in_mpdtc_is_a_stuck_adc() {
    let (mut s, mut pl) = running(Mode::Mpdtc);
    s.note_no_boundary(&mut pl, 1).unwrap();
    assert!(s.faults(&mut pl).unwrap().none());
    s.note_no_boundary(&mut pl, 1).unwrap();
    assert_eq!(s.faults(&mut pl).unwrap(), Faults(Faults::ADC_STUCK));
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    // FOC is paced by the PWM: a missing boundary there is no ADC matter.
    let (mut s, mut pl) = running(Mode::Foc);
    s.note_no_boundary(&mut pl, 4).unwrap();
    assert!(s.faults(&mut pl).unwrap().none());
}

/// Gates-off time on the simulated PL, PL clock cycles from the fault's
/// cause to all six gate outputs low, for the PL's faults (its own logic)
/// and the PS's (the control step that sees them). Every one within one
/// control period.
#[test]
fn gates_go_off_within_one_control_period_on_the_simulated_pl() {
    fn setup(mode: Mode) -> (Servo, SimDrive, u64) {
        let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
        let mut s = Servo::new(&ServoConfig::for_simulated(sim.config())).unwrap();
        s.init(&mut sim).unwrap();
        s.set_mode(&mut sim, mode).unwrap();
        s.enable(&mut sim).unwrap();
        s.set_torque_ref(0.3).unwrap();
        // Past the MPDTC's 2 ms alignment.
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
    let mut s = Servo::new(&ServoConfig::for_simulated(sim.config())).unwrap();
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
    let mut s = Servo::new(&ServoConfig::for_simulated(sim.config())).unwrap();
    s.init(&mut sim).unwrap();
    s.set_mode(&mut sim, Mode::Mpdtc).unwrap();
    s.enable(&mut sim).unwrap();
    s.set_torque_ref(0.4).unwrap();
    // Past the MPDTC's 2 ms alignment and the torque's rise.
    for _ in 0..400 {
        sim.advance_to_boundary(20_000);
        s.control_step(&mut sim).unwrap();
    }
    sim.set_external_fault(true);
    sim.advance(10);
    sim.advance_to_boundary(20_000);
    s.control_step(&mut sim).unwrap();
    // EXTERNAL is bit 1, code 2.
    assert_eq!(codes(&s), [2]);
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

/// The same on the fake PL in FOC: a PL fault that cleared `GATE_EN`.
#[test]
fn a_pl_fault_snapshot_on_the_fake_pl_keeps_the_reference() {
    let (mut s, mut pl) = running(Mode::Foc);
    s.set_torque_ref(0.25).unwrap();
    s.control_step(&mut pl).unwrap();
    pl.set(FAULT_STATUS_ADDR, 0b001);
    pl.set(GATE_CTRL_ADDR, 0);
    s.control_step(&mut pl).unwrap();
    assert_eq!(codes(&s), [1]);
    let r = s.fault_history().records().next().unwrap();
    let refs: Vec<f64> = r.snapshot.samples().map(|x| x.torque_ref_nm).collect();
    assert_eq!(refs[refs.len() - 2..], [0.25, 0.25], "{r:?}");
}
