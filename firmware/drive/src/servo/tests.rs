//! Servo logic against the fake PL (register storage and write rules, no
//! dynamics); the closed loop is tested against the simulated PL.
use super::*;
use crate::pl::fake::FakePl;
use regmap::{FAULT_STATUS_ADDR, GATE_CTRL_ADDR, HEARTBEAT_ADDR, MPDTC, PWM};

fn setup() -> (Servo, FakePl) {
    let mut s = Servo::new(&ServoConfig::default()).unwrap();
    let mut pl = FakePl::new();
    s.init(&mut pl).unwrap();
    (s, pl)
}

#[test]
fn init_programs_timing_and_watchdog_with_gates_off() {
    let (_, pl) = setup();
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    assert_eq!(pl.get(PWM.addr(&regmap::PWM_PERIOD)), 3128);
    assert_eq!(pl.get(regmap::ADC.addr(&regmap::ADC_PERIOD)), 391);
    assert_eq!(pl.get(regmap::FAULT.addr(&regmap::WDG_TIMEOUT)), 200_000);
    // Core state held cleared until a run starts; the autonomous path.
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_CTRL)), 0b110);
    // The front end's registers: 7 pole pairs over 4096 counts, the ADC
    // gain of 10 mA per count in 2^-20 A (10486).
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_FE_ANG_SCALE)), 7 << 20);
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_FE_GAIN_B)), 10_486);
}

#[test]
fn control_rates_are_the_papers_within_a_permille() {
    let (mut s, mut pl) = setup();
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    assert!((s.control_rate_hz() / 16_000.0 - 1.0).abs() < 1e-3);
    s.set_mode(&mut pl, Mode::Mpdtc).unwrap();
    assert!((s.control_rate_hz() / 64_000.0 - 1.0).abs() < 1e-3);
}

#[test]
fn control_periods_in_pl_cycles_are_the_timers_whole_counts() {
    // MPDTC: 4 ADC periods of 391 cycles; FOC: 2 PWM half periods of 3,128.
    let (mut s, mut pl) = setup();
    s.set_mode(&mut pl, Mode::Mpdtc).unwrap();
    assert_eq!(s.control_period_cycles(), 4 * 391);
    // The float route that lost a cycle: 1e8 / rate truncated.
    assert_eq!(
        (f64::from(regmap::PL_CLOCK_HZ) / s.control_rate_hz()) as u64,
        1563
    );
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    assert_eq!(s.control_period_cycles(), 2 * 3128);
}

#[test]
fn enable_is_refused_in_mode_off_and_with_a_fault_latched() {
    let (mut s, mut pl) = setup();
    assert_eq!(s.enable(&mut pl), Err(ServoError::ModeOff));
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    pl.set(FAULT_STATUS_ADDR, Faults::WATCHDOG);
    assert_eq!(
        s.enable(&mut pl),
        Err(ServoError::FaultLatched(Faults(Faults::WATCHDOG)))
    );
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    assert!(s.clear_faults(&mut pl).unwrap().none());
    // Clearing leaves the gates off; enable turns them on.
    assert_eq!(pl.get(GATE_CTRL_ADDR), 0);
    s.enable(&mut pl).unwrap();
    assert_eq!(pl.get(GATE_CTRL_ADDR), 1);
}

#[test]
fn any_mode_change_turns_the_gates_off() {
    let (mut s, mut pl) = setup();
    for (from, to) in [
        (Mode::Foc, Mode::Mpdtc),
        (Mode::Mpdtc, Mode::Foc),
        (Mode::Foc, Mode::Foc),
        (Mode::Foc, Mode::Off),
    ] {
        s.set_mode(&mut pl, from).unwrap();
        s.enable(&mut pl).unwrap();
        assert_eq!(pl.get(GATE_CTRL_ADDR), 1);
        s.set_mode(&mut pl, to).unwrap();
        assert_eq!(pl.get(GATE_CTRL_ADDR), 0, "{from:?} -> {to:?}");
        assert_eq!(pl.get(regmap::CTRL_ADDR), to.reg());
    }
}

#[test]
fn bad_torque_references_change_nothing() {
    let (mut s, _) = setup();
    s.set_torque_ref(0.3).unwrap();
    for bad in [f64::NAN, f64::INFINITY, -f64::INFINITY, 1.0001, -7.0] {
        assert!(matches!(
            s.set_torque_ref(bad),
            Err(ServoError::TorqueOutOfRange(_))
        ));
        assert_eq!(s.torque_ref_nm(), 0.3);
    }
    s.set_torque_ref(-1.0).unwrap();
    assert_eq!(s.torque_ref_nm(), -1.0);
}

#[test]
fn foc_step_feeds_the_watchdog_and_writes_duties() {
    let (mut s, mut pl) = setup();
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    s.enable(&mut pl).unwrap();
    s.set_torque_ref(0.4).unwrap();
    pl.writes.clear();
    s.control_step(&mut pl).unwrap();
    s.control_step(&mut pl).unwrap();
    assert_eq!(pl.get(HEARTBEAT_ADDR), 2);
    assert_eq!(s.periods(), 2);
    // Zero current, positive torque reference at angle 0: the FOC asks for
    // a positive q voltage, i.e. duties away from 50 %.
    let d: std::vec::Vec<u32> = [&regmap::DUTY_A, &regmap::DUTY_B, &regmap::DUTY_C]
        .iter()
        .map(|r| pl.get(PWM.addr(r)))
        .collect();
    assert!(d.iter().any(|x| x.abs_diff(1564) > 100), "{d:?}");
    assert!(pl
        .writes
        .iter()
        .any(|(a, _)| *a == PWM.addr(&regmap::DUTY_A)));
}

#[test]
fn measured_torque_from_the_adc_currents() {
    let (mut s, mut pl) = setup();
    // i_a = 0, i_b = -i_c = 3.464 A at angle 0: i_q = 2 A... by Clarke:
    // beta = (i_b - i_c)/sqrt(3) = 4 A, alpha = 0 -> i_d = 0, i_q = 4 A.
    let c = (4.0 * 3f64.sqrt() / 2.0 / 0.01) as i32; // counts of 3.46 A
    pl.set(regmap::ADC.addr(&regmap::ADC_IB), c as u32 & 0xFFFF);
    pl.set(regmap::ADC.addr(&regmap::ADC_IC), (-c) as u32 & 0xFFFF);
    s.control_step(&mut pl).unwrap();
    let m = s.measured();
    let iq = f64::from(2 * c) * 0.01 / 3f64.sqrt();
    assert!(m.i_d_a.abs() < 1e-9 && (m.i_q_a - iq).abs() < 1e-9, "{m:?}");
    let t = 1.5 * 7.0 * models::pmsm::params::PSI_PM_FROM_KE_WB * iq;
    assert!((m.torque_nm - t).abs() < 1e-9);
}

#[test]
fn autonomous_mpdtc_period_writes_only_the_torque_reference() {
    let (mut s, mut pl) = setup();
    s.set_mode(&mut pl, Mode::Mpdtc).unwrap();
    s.enable(&mut pl).unwrap();
    assert_eq!(
        pl.get(MPDTC.addr(&regmap::MPDTC_CTRL)),
        0b100,
        "sequence, AUTO"
    );
    let seq = MPDTC.addr(&regmap::MPDTC_SEQ_STATUS);
    pl.set(seq, seq_state::SAMPLE | 8 | 16);
    s.set_torque_ref(0.4).unwrap();
    pl.writes.clear();
    s.control_step(&mut pl).unwrap();
    // On the MPDTC page only T_REF; besides it the heartbeat and the
    // capture channels.
    let mpdtc: std::vec::Vec<usize> = pl
        .writes
        .iter()
        .map(|(a, _)| *a)
        .filter(|a| (MPDTC.base()..MPDTC.base() + 0x1000).contains(a))
        .collect();
    assert_eq!(mpdtc, [MPDTC.addr(&regmap::MPDTC_IN_T_REF)]);
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_IN_T_REF)), 6554);
    // Gates off: the reference in the PL returns to 0.
    s.disable(&mut pl).unwrap();
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_IN_T_REF)), 0);
}

#[test]
fn mpdtc_step_writes_inputs_and_starts_only_in_sample_after_alignment() {
    let mut s = Servo::new(&ServoConfig {
        mpdtc_ps_fed: true,
        ..ServoConfig::default()
    })
    .unwrap();
    let mut pl = FakePl::new();
    s.init(&mut pl).unwrap();
    s.set_mode(&mut pl, Mode::Mpdtc).unwrap();
    s.enable(&mut pl).unwrap();
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_CTRL)), 0, "sequence runs");
    let seq = MPDTC.addr(&regmap::MPDTC_SEQ_STATUS);
    let start = MPDTC.addr(&regmap::MPDTC_START);
    // Aligning: no decision requested.
    pl.set(seq, seq_state::INITIAL);
    pl.writes.clear();
    s.control_step(&mut pl).unwrap();
    assert!(!pl.writes.iter().any(|(a, _)| *a == start));
    // Aligned, in SAMPLE with the sample: inputs, then START.
    pl.set(seq, seq_state::SAMPLE | 8 | 16);
    s.set_torque_ref(0.4).unwrap();
    s.control_step(&mut pl).unwrap();
    let pos = |a: usize| pl.writes.iter().position(|(x, _)| *x == a).unwrap();
    assert!(pos(MPDTC.addr(&regmap::MPDTC_IN_T_REF)) < pos(start));
    // T_REF in TRQ sQ3.14: 0.4 N m = round(0.4 * 16384).
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_IN_T_REF)), 6554);
}

#[test]
fn step_needs_the_gates_on_and_records_one_sample_per_period() {
    let (mut s, mut pl) = setup();
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    assert_eq!(s.begin_step(&mut pl, 0.4, 2e-3), Err(ServoError::GatesOff));
    s.enable(&mut pl).unwrap();
    assert!(matches!(
        s.begin_step(&mut pl, 2.0, 2e-3),
        Err(ServoError::TorqueOutOfRange(_))
    ));
    s.begin_step(&mut pl, 0.4, 2e-3).unwrap();
    // 2 ms at 15.985 kHz = 31.97 -> 32 periods.
    for _ in 0..31 {
        s.control_step(&mut pl).unwrap();
        assert!(s.step_pending());
    }
    assert_eq!(s.torque_ref_nm(), 0.4);
    s.control_step(&mut pl).unwrap();
    let r = s.step_result().unwrap();
    assert_eq!((r.from_nm, r.to_nm), (0.0, 0.4));
    // Nothing moves on a fake PL: the torque never settles.
    assert_eq!(r.settling_s, None);
    // At most 2 transitions per leg per period (centre-aligned PWM); fewer
    // here, because with no current ever measured the FOC saturates and
    // clamps legs at 0 or 100 %.
    let sw = r.switching_per_leg_per_s;
    assert!(sw > 0.0 && sw <= 2.0 * s.control_rate_hz() + 1.0, "{r:?}");
}

#[test]
fn a_fault_turns_the_drive_off() {
    let (mut s, mut pl) = setup();
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    s.enable(&mut pl).unwrap();
    // The PL holds GATE_EN at 0 once a fault latches.
    pl.set(FAULT_STATUS_ADDR, Faults::WATCHDOG);
    pl.set(GATE_CTRL_ADDR, 0);
    s.control_step(&mut pl).unwrap();
    assert!(!s.gates_on(&mut pl).unwrap());
    assert_eq!(s.begin_step(&mut pl, 0.4, 2e-3), Err(ServoError::GatesOff));
}

#[test]
fn foc_measurement_lag_by_hand() {
    // Restart 4 cycles after the start: conversions at 4 + 391 j; the last
    // before 6256 is j = 15 (5869), 387 cycles old; mean 1.5 x 391 older.
    let lag = foc_measurement_lag_s(&ServoConfig::default());
    assert!((lag - (387.0 + 586.5) * 1e-8).abs() < 1e-15, "{lag}");
}

#[test]
fn turning_the_gates_off_returns_the_reference_to_zero() {
    let (mut s, mut pl) = setup();
    s.set_mode(&mut pl, Mode::Foc).unwrap();
    // Set while off: kept for the run.
    s.set_torque_ref(0.3).unwrap();
    s.enable(&mut pl).unwrap();
    assert_eq!(s.torque_ref_nm(), 0.3);
    s.disable(&mut pl).unwrap();
    assert_eq!(s.torque_ref_nm(), 0.0);
    s.enable(&mut pl).unwrap();
    s.set_torque_ref(0.2).unwrap();
    s.set_mode(&mut pl, Mode::Mpdtc).unwrap();
    assert_eq!(s.torque_ref_nm(), 0.0);
}
