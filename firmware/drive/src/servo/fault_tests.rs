//! The PS's fault checks against the fake PL (the gates-off time of every
//! fault on the simulated PL is a test of the `simpl` crate).
use super::*;
use crate::pl::fake::FakePl;
use regmap::{ENC, FAULT_STATUS_ADDR, GATE_CTRL_ADDR, HEARTBEAT_ADDR};

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
fn adc_stuck_latches_at_the_first_foc_step_without_a_result_and_clear_restarts_the_adc() {
    let (mut s, mut pl) = running(Mode::Foc);
    // Not known how late the step before was: one stale step tolerated.
    assert_eq!(s.adc_stale_limit(), 2);
    // The paper's timing: four averaged results in a PWM period; a step
    // before served up to three result periods late leaves this one a new
    // result, later it may not.
    s.note_step_age(4692);
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.adc_stale_limit(), 1);
    s.note_step_age(4693);
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.adc_stale_limit(), 2);
    s.note_step_age(20);
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.adc_stale_limit(), 1);
    Adc(&mut pl).set_enabled(false).unwrap();
    s.note_step_age(20);
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.faults(&mut pl).unwrap(), Faults(Faults::ADC_STUCK));
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    assert_eq!(codes(&s), [5]);
    let r = s.fault_history().records().next().unwrap();
    assert_eq!(r.snapshot.len(), faults::SNAPSHOT_LEN);
    // 14 FOC periods of 6256 cycles at 100 MHz.
    assert!((r.time_s - 14.0 * 62.56e-6).abs() < 1e-9, "{r:?}");
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
    let pos = ENC.addr(&regmap::ENC_POS_SAMPLE);
    let loss = |s: &mut Servo, pl: &mut FakePl| s.faults(pl).unwrap().0 & Faults::ENCODER_LOSS;
    // 4096 counts per turn: 512 (an eighth) is the most per period,
    // either way and across zero. (At 2,000 rev/s such jumps latch
    // OVERSPEED; the encoder check is what is tested here.)
    for p in [512, 0, 3584] {
        pl.set(pos, p);
        s.control_step(&mut pl).unwrap();
        assert_eq!(loss(&mut s, &mut pl), 0, "{p}");
    }
    pl.set(pos, 3584 - 513);
    s.control_step(&mut pl).unwrap();
    assert_ne!(loss(&mut s, &mut pl), 0);
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    assert_eq!(codes(&s).last(), Some(&4), "the newest record");
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
    // With the gates off (mode off: no ADC card) nothing runs to protect.
    let (mut s, mut pl) = running(Mode::Mpdtc);
    s.disable(&mut pl).unwrap();
    s.note_no_boundary(&mut pl, 4).unwrap();
    assert!(s.faults(&mut pl).unwrap().none());
}

/// The heartbeat without a control step only with the gates off.
#[test]
fn keep_alive_writes_the_heartbeat_only_with_the_gates_off() {
    let (mut s, mut pl) = running(Mode::Foc);
    let beat = pl.get(HEARTBEAT_ADDR);
    assert!(!s.keep_alive(&mut pl).unwrap());
    assert_eq!(pl.get(HEARTBEAT_ADDR), beat);
    s.disable(&mut pl).unwrap();
    assert!(s.keep_alive(&mut pl).unwrap());
    assert_ne!(pl.get(HEARTBEAT_ADDR), beat);
}

/// `debug fault position-limit`: the next step latches `POSITION_LIMIT`;
/// `fault clear` restores the limits (the next run is clean).
#[test]
fn a_limit_moved_behind_the_position_trips_at_the_next_step_and_clear_restores_it() {
    let (mut s, mut pl) = running(Mode::Foc);
    let before = s.config().motion;
    s.tighten_limit(false).unwrap();
    s.control_step(&mut pl).unwrap();
    assert_eq!(s.faults(&mut pl).unwrap(), Faults(Faults::POSITION_LIMIT));
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    // With the gates off: refused, nothing changed.
    let latched = s.config().motion;
    assert_eq!(s.tighten_limit(true), Err(ServoError::GatesOff));
    assert_eq!(s.config().motion, latched);
    assert!(s.clear_faults(&mut pl).unwrap().none());
    assert_eq!(s.config().motion, before);
    s.enable(&mut pl).unwrap();
    for _ in 0..5 {
        s.control_step(&mut pl).unwrap();
    }
    assert!(s.faults(&mut pl).unwrap().none());
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
