//! Hand-computed cases of the simulated PL and the closed loops through
//! `SimDrive`'s registers.

use super::pl::{Events, SimPl};
use super::{SimConfig, SimDrive};
use crate::bus::{BusError, RegisterBus};
use crate::pmsm::foc::{Foc, FocParams};
use crate::pmsm::metrics::{overshoot_percent, settling_band, settling_time_s};
use crate::pmsm::mpdtc_fixed::FixedParams;
use crate::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use crate::pmsm::params::MotorParams;
use crate::pmsm::pl_loop::{self, PlScaling, PlTiming};
use crate::pmsm::sim::{Actuation, Controller};
use crate::regmap::{self as rm, mode, seq_state, Block, Register};
use std::vec::Vec;

fn a(b: &Block, r: &Register) -> usize {
    b.addr(r)
}

fn w(pl: &mut SimPl, b: &Block, r: &Register, v: u32) {
    assert_eq!(pl.write(a(b, r), v).0, Ok(()), "{}", r.name);
}

fn peek(pl: &SimPl, b: &Block, r: &Register) -> u32 {
    pl.peek(a(b, r)).unwrap()
}

const GATES: Events = Events {
    gates: true,
    adc_convert: false,
    adc_average: false,
    pwm_period: false,
};

/// Gate edges (cycle first showing the new levels, hi, lo) over `n` cycles.
fn edges(pl: &mut SimPl, n: u64) -> Vec<(u64, u8, u8)> {
    let mut v = Vec::new();
    let end = pl.cycles() + n;
    while pl.cycles() < end {
        let (_, ev) = pl.run(end - pl.cycles(), &GATES);
        if ev.gates {
            let g = pl.gates();
            v.push((pl.cycles(), g.hi, g.lo));
        }
    }
    v
}

/// PWM_PERIOD 10, DUTY_A 4, dead time 3: per 20-cycle period the upper
/// switch of leg a is requested for 2 x 4 = 8 cycles and the lower for 12;
/// each turn-on waits 3 dead cycles, so the upper gate is on 8 - 3 = 5
/// cycles and the lower 12 - 3 = 9, with 3 cycles both off in between.
#[test]
fn pwm_period_and_dead_time_by_hand() {
    let mut pl = SimPl::new(10);
    w(&mut pl, &rm::PWM, &rm::PWM_PERIOD, 10);
    w(&mut pl, &rm::PWM, &rm::DUTY_A, 4);
    w(&mut pl, &rm::PWM, &rm::DUTY_B, 0);
    w(&mut pl, &rm::PWM, &rm::DUTY_C, 10);
    w(&mut pl, &rm::PWM, &rm::DEAD_TIME, 3);
    w(&mut pl, &rm::FAULT, &rm::WDG_TIMEOUT, u32::MAX);
    w(&mut pl, &rm::TOP, &rm::CTRL, mode::FOC_PWM);
    w(&mut pl, &rm::PWM, &rm::GATE_CTRL, 1);
    // The reset period (2 x 2500 cycles) runs out before PWM_PERIOD loads.
    pl.run(5200, &Events::default());
    assert_eq!(
        peek(&pl, &rm::TOP, &rm::STATUS),
        0b0101,
        "FOC-PWM, gates active"
    );
    let e: Vec<(u64, bool, bool)> = edges(&mut pl, 200)
        .into_iter()
        .map(|(t, hi, lo)| (t, hi & 4 != 0, lo & 4 != 0))
        .collect();
    // Only leg a switches (b always lower, c always upper).
    let mut on_hi = Vec::new();
    let mut on_lo = Vec::new();
    let mut gaps = Vec::new();
    for p in e.windows(2) {
        let ((t0, hi, lo), (t1, _, _)) = (p[0], p[1]);
        match (hi, lo) {
            (true, false) => on_hi.push(t1 - t0),
            (false, true) => on_lo.push(t1 - t0),
            (false, false) => gaps.push(t1 - t0),
            _ => panic!("both gates on"),
        }
    }
    assert!(on_hi.len() >= 8, "{e:?}");
    assert!(on_hi.iter().all(|&d| d == 5), "{on_hi:?}");
    assert!(on_lo.iter().all(|&d| d == 9), "{on_lo:?}");
    assert!(gaps.iter().all(|&d| d == 3), "{gaps:?}");
    // Upper turn-ons 20 cycles apart (the PWM period 2 x PWM_PERIOD).
    let ups: Vec<u64> = e.iter().filter(|x| x.1).map(|x| x.0).collect();
    assert!(ups.windows(2).all(|p| p[1] - p[0] == 20), "{ups:?}");
    let g = pl.gates();
    assert_eq!((g.hi & 3, g.lo & 3), (0b01, 0b10), "legs b, c");
}

/// HEARTBEAT written in cycle h (its strobe), WDG_TIMEOUT 1000: the counter
/// is 0 in cycle h + 1 and reaches 1000 in cycle h + 1001, whose edge
/// latches WATCHDOG and turns the gates off: both seen from cycle h + 1002.
#[test]
fn watchdog_trips_after_wdg_timeout() {
    let mut pl = SimPl::new(10);
    w(&mut pl, &rm::FAULT, &rm::WDG_TIMEOUT, 1000);
    w(&mut pl, &rm::PWM, &rm::SW_STATE, 0b100);
    w(&mut pl, &rm::PWM, &rm::DEAD_TIME, 2);
    w(&mut pl, &rm::TOP, &rm::CTRL, mode::MPDTC);
    w(&mut pl, &rm::PWM, &rm::GATE_CTRL, 1);
    let h = pl.cycles();
    w(&mut pl, &rm::TOP, &rm::HEARTBEAT, 0x1234);
    pl.run(100, &Events::default());
    assert_eq!((pl.gates().hi, pl.gates().lo), (0b100, 0b011));
    pl.run(h + 1001 - pl.cycles(), &Events::default());
    assert_eq!(peek(&pl, &rm::FAULT, &rm::FAULT_STATUS), 0, "not yet");
    let e = edges(&mut pl, 10);
    assert_eq!(e, [(h + 1002, 0, 0)]);
    assert_eq!(peek(&pl, &rm::FAULT, &rm::FAULT_STATUS), 4);
    assert_eq!(peek(&pl, &rm::FAULT, &rm::FAULT_RAW), 4);
    assert_eq!(peek(&pl, &rm::PWM, &rm::GATE_CTRL), 0, "GATE_EN dropped");
    assert_eq!(
        peek(&pl, &rm::TOP, &rm::STATUS),
        0b1010,
        "FAULT, mode MPDTC"
    );
    // W1C while the watchdog is still expired: set wins.
    w(&mut pl, &rm::FAULT, &rm::FAULT_STATUS, 4);
    assert_eq!(peek(&pl, &rm::FAULT, &rm::FAULT_STATUS), 4);
    // Heartbeat, then the clear sticks; gates stay off until GATE_EN.
    w(&mut pl, &rm::TOP, &rm::HEARTBEAT, 0);
    w(&mut pl, &rm::FAULT, &rm::FAULT_STATUS, 4);
    assert_eq!(peek(&pl, &rm::FAULT, &rm::FAULT_STATUS), 0);
    pl.run(20, &Events::default());
    assert_eq!((pl.gates().hi, pl.gates().lo), (0, 0));
    w(&mut pl, &rm::PWM, &rm::GATE_CTRL, 1);
    pl.run(20, &Events::default());
    assert_eq!((pl.gates().hi, pl.gates().lo), (0b100, 0b011));
}

#[test]
fn register_rules_mask_clamp_reject_w1c_slverr() {
    let mut pl = SimPl::new(10);
    // Clamp: the whole word, not wrapped.
    w(&mut pl, &rm::PWM, &rm::DEAD_TIME, 5000);
    assert_eq!(peek(&pl, &rm::PWM, &rm::DEAD_TIME), 1023);
    w(&mut pl, &rm::FAULT, &rm::WDG_TIMEOUT, 0);
    assert_eq!(peek(&pl, &rm::FAULT, &rm::WDG_TIMEOUT), 1000);
    // Mask.
    w(&mut pl, &rm::PWM, &rm::SW_STATE, 0xF);
    assert_eq!(peek(&pl, &rm::PWM, &rm::SW_STATE), 7);
    // Reject: OKAY, unchanged, ERR.BAD_VALUE.
    w(&mut pl, &rm::TOP, &rm::CTRL, 1);
    w(&mut pl, &rm::TOP, &rm::CTRL, 3);
    assert_eq!(peek(&pl, &rm::TOP, &rm::CTRL), 1);
    assert_eq!(peek(&pl, &rm::TOP, &rm::ERR), 1);
    // Read-only and unmapped: SLVERR, ERR.BAD_ADDR, nothing changes.
    assert_eq!(
        pl.write(a(&rm::TOP, &rm::ID), 0).0,
        Err(BusError::SlaveError)
    );
    assert_eq!(peek(&pl, &rm::TOP, &rm::ID), rm::ID_VALUE);
    assert_eq!(peek(&pl, &rm::TOP, &rm::ERR), 3);
    // W1C: ERR bits clear on a written one.
    w(&mut pl, &rm::TOP, &rm::ERR, 1);
    assert_eq!(peek(&pl, &rm::TOP, &rm::ERR), 2);
    assert_eq!(pl.read(rm::BASE_ADDR + 0x2000).0, Err(BusError::SlaveError));
    assert_eq!(pl.read(rm::BASE_ADDR + 0x3002).0, Err(BusError::SlaveError));
    w(&mut pl, &rm::TOP, &rm::ERR, 2);
    assert_eq!(peek(&pl, &rm::TOP, &rm::ERR), 0);
    // Every access is one PL cycle.
    let c = pl.cycles();
    let _ = pl.read(a(&rm::TOP, &rm::SCRATCH));
    assert_eq!(pl.cycles(), c + 1);
}

/// The event-driven run equals the cycle-by-cycle one (every register and
/// the gates), in FOC-PWM and in MPDTC with the sequence.
#[test]
fn event_driven_equals_cycle_by_cycle() {
    for m in [mode::FOC_PWM, mode::MPDTC] {
        let mut pl = SimPl::new(7);
        w(&mut pl, &rm::ADC, &rm::ADC_PERIOD, 40);
        w(&mut pl, &rm::PWM, &rm::PWM_PERIOD, 37);
        w(&mut pl, &rm::PWM, &rm::DUTY_A, 11);
        w(&mut pl, &rm::PWM, &rm::DUTY_B, 30);
        w(&mut pl, &rm::PWM, &rm::DEAD_TIME, 4);
        w(&mut pl, &rm::MPDTC, &rm::MPDTC_ALIGN_TIME, 500);
        w(&mut pl, &rm::MPDTC, &rm::MPDTC_ALIGN_PERIOD, 60);
        w(&mut pl, &rm::MPDTC, &rm::MPDTC_ALIGN_ON, 13);
        w(&mut pl, &rm::MPDTC, &rm::MPDTC_CTRL, 0);
        w(&mut pl, &rm::FAULT, &rm::WDG_TIMEOUT, 3000);
        w(&mut pl, &rm::TOP, &rm::CTRL, m);
        w(&mut pl, &rm::PWM, &rm::GATE_CTRL, 1);
        pl.pins.adc_word = crate::simpl::adc::adc_word([100, -40, -60]);
        let mut slow = pl.clone();
        for n in [1u64, 17, 250, 999, 4000] {
            pl.run(n, &Events::default());
            slow.run_cycle_by_cycle(n);
            assert_eq!(pl.cycles(), slow.cycles());
            assert_eq!(pl.gates(), slow.gates(), "mode {m}, after {n}");
            for blk in rm::BLOCKS {
                for r in blk.registers {
                    let ad = blk.addr(r);
                    assert_eq!(pl.peek(ad), slow.peek(ad), "mode {m}: {}", r.name);
                }
            }
            w(&mut pl, &rm::MPDTC, &rm::MPDTC_START, 1);
            w(&mut slow, &rm::MPDTC, &rm::MPDTC_START, 1);
        }
    }
}

// ------------------------------------------------------------ closed loops

fn scaling(cfg: &SimConfig) -> PlScaling {
    PlScaling {
        adc_amps_per_count: cfg.adc_amps_per_count,
        encoder_cpr: cfg.encoder_cpr,
        pole_pairs: cfg.motor.pole_pairs,
    }
}

fn wr<B: RegisterBus>(bus: &mut B, b: &Block, r: &Register, v: u32) {
    assert_eq!(bus.write(b.addr(r), v), Ok(()), "{}", r.name);
}

/// Torque sampling period of the closed loops, cycles (the ADC period).
const ADC_PERIOD: u32 = 391;

/// Torque trace of a 0 -> 0.4 N m step at `t_step` (s after the loop
/// starts): plant torque every ADC period, averaged over windows of 4
/// (as `drivectl paper mpdtc` evaluates it), time-stamped at the window end.
struct StepRun {
    windows: Vec<(f64, f64)>,
    t_step: f64,
    y0: f64,
    transitions: ([u64; 3], [u64; 3]),
    duration: f64,
}

impl StepRun {
    fn settling_s(&self) -> Option<f64> {
        settling_time_s(
            self.windows.iter().copied(),
            self.t_step,
            self.t_step + 2e-3,
            0.4,
            settling_band(self.y0, 0.4),
        )
    }
    fn overshoot(&self) -> f64 {
        overshoot_percent(
            self.windows.iter().copied(),
            self.t_step,
            self.t_step + 2e-3,
            0.0,
            0.4,
        )
    }
    fn final_nm(&self) -> f64 {
        let tail = &self.windows[self.windows.len() - 32..];
        tail.iter().map(|w| w.1).sum::<f64>() / tail.len() as f64
    }
    fn fsw_hz(&self) -> f64 {
        crate::pmsm::metrics::transitions_per_leg_per_s(
            self.transitions.0,
            self.transitions.1,
            self.duration,
        )
    }
}

/// Runs `periods` control periods: `control(sim, k)` at each boundary;
/// the torque sampled every ADC period.
fn run_loop(
    sim: &mut SimDrive,
    periods: u32,
    t_step: f64,
    y0: f64,
    mut control: impl FnMut(&mut SimDrive, f64),
) -> StepRun {
    let t0 = sim.time_s();
    let tr0 = sim.truth().transitions;
    let mut samples = Vec::new();
    let mut done = 0;
    let mut next_sample = sim.pl_cycles() + u64::from(ADC_PERIOD);
    while done < periods {
        let max = next_sample.saturating_sub(sim.pl_cycles()).max(1);
        let adv = sim.advance_to_boundary(max);
        if sim.pl_cycles() >= next_sample {
            samples.push((sim.time_s() - t0, sim.truth().torque_nm));
            next_sample += u64::from(ADC_PERIOD);
        }
        if adv.control_periods > 0 {
            let t = sim.time_s() - t0;
            let r = if t >= t_step { 0.4 } else { y0 };
            control(sim, r);
            done += 1;
        }
    }
    let windows = samples
        .chunks_exact(4)
        .map(|c| (c[3].0, c.iter().map(|x| x.1).sum::<f64>() / 4.0))
        .collect();
    StepRun {
        windows,
        t_step,
        y0,
        transitions: (tr0, sim.truth().transitions),
        duration: sim.time_s() - t0,
    }
}

fn mpdtc_step(y0: f64) -> StepRun {
    let cfg = SimConfig::default();
    let mut sim = SimDrive::new(&cfg).unwrap();
    let t = PlTiming::default();
    let mc = MpdtcConfig::new(
        MotorParams::default(),
        MpdtcParams {
            control_period_s: t.mpdtc_period_s(),
            ..MpdtcParams::default()
        },
    )
    .unwrap();
    let p = FixedParams::from_config(&mc).unwrap();
    pl_loop::setup_mpdtc(&mut sim, &p, &t, 10_000).unwrap();
    wr(&mut sim, &rm::TOP, &rm::HEARTBEAT, 0);
    wr(&mut sim, &rm::PWM, &rm::GATE_CTRL, 1);
    // Alignment (INITIAL), then the first SAMPLE.
    sim.advance(20_000);
    let st = sim.read(rm::MPDTC.addr(&rm::MPDTC_SEQ_STATUS)).unwrap();
    assert_eq!(st & 7, seq_state::SAMPLE, "sequence in SAMPLE");
    let sc = scaling(&cfg);
    let align = sim.read(rm::MPDTC.addr(&rm::MPDTC_ALIGN_POS)).unwrap();
    let overruns0 = st >> 8 & 0xFF;
    // This period's sample is in: its decision now (then one per boundary).
    let m = pl_loop::read_measurement(&mut sim, &sc, align).unwrap();
    pl_loop::mpdtc_period(&mut sim, &m, y0, &mc).unwrap();
    let run = run_loop(&mut sim, 640, 2e-3, y0, |sim, r| {
        let m = pl_loop::read_measurement(sim, &sc, align).unwrap();
        pl_loop::mpdtc_period(sim, &m, r, &mc).unwrap();
        wr(sim, &rm::TOP, &rm::HEARTBEAT, 1);
    });
    let st = sim.read(rm::MPDTC.addr(&rm::MPDTC_SEQ_STATUS)).unwrap();
    assert_eq!(st >> 8 & 0xFF, overruns0, "no overrun in the loop");
    assert!(st >> 16 >= 640, "periods {}", st >> 16);
    assert_eq!(sim.read(rm::FAULT.addr(&rm::FAULT_STATUS)), Ok(0));
    run
}

fn foc_step(y0: f64) -> StepRun {
    let cfg = SimConfig::default();
    let mut sim = SimDrive::new(&cfg).unwrap();
    let t = PlTiming::default();
    let fp = FocParams {
        period_s: t.foc_period_s(),
        measurement_lag_s: t.foc_measurement_lag_s(),
        ..FocParams::default()
    };
    let mut foc = Foc::new(&cfg.motor, &fp).unwrap();
    pl_loop::setup_foc(&mut sim, &t).unwrap();
    wr(&mut sim, &rm::TOP, &rm::HEARTBEAT, 0);
    // Two period starts (the new PWM_PERIOD loads at the first), then the
    // ADC's phase.
    sim.advance_to_boundary(100_000);
    sim.advance_to_boundary(100_000);
    pl_loop::restart_adc_timer(&mut sim).unwrap();
    wr(&mut sim, &rm::PWM, &rm::GATE_CTRL, 1);
    let sc = scaling(&cfg);
    let run = run_loop(&mut sim, 160, 2e-3, y0, |sim, r| {
        let m = pl_loop::read_measurement(sim, &sc, 0).unwrap();
        match foc.step(&m, r) {
            Actuation::DutyAbc(d) => pl_loop::write_duties(sim, d, t.pwm_period).unwrap(),
            Actuation::SwitchState(_) => unreachable!(),
        }
        wr(sim, &rm::TOP, &rm::HEARTBEAT, 1);
    });
    assert_eq!(sim.read(rm::FAULT.addr(&rm::FAULT_STATUS)), Ok(0));
    run
}

fn report(name: &str, r: &StepRun) -> f64 {
    let ts = r.settling_s().expect("settles");
    std::println!(
        "{name} via SimDrive, {} -> 0.4 N m: settling {:.3} ms, overshoot {:.1} %, final {:.4} N m, {:.1} k transitions/leg/s",
        r.y0,
        ts * 1e3,
        r.overshoot(),
        r.final_nm(),
        r.fsw_hz() / 1e3
    );
    assert!((r.final_nm() - 0.4).abs() < 0.05, "final {}", r.final_nm());
    ts
}

/// MPDTC through the simulated PL: the PS feeds the core its inputs each
/// period (`pl_loop`), the PL's sequence decides and applies. The 0.4 N m
/// step, from rest and as the reversal from -0.4 N m (the paper's Fig. 10,
/// host experiment 0.172 ms), settles within the paper's 0.19 ms.
#[test]
fn mpdtc_step_through_simulated_pl_settles() {
    assert!(report("MPDTC", &mpdtc_step(0.0)) <= 0.19e-3);
    assert!(report("MPDTC", &mpdtc_step(-0.4)) <= 0.19e-3);
}

/// FOC on the PS through the simulated PL's PWM: within the paper's
/// 0.27 ms (host experiment, reversal: 0.245 ms).
#[test]
fn foc_step_through_simulated_pl_settles() {
    assert!(report("FOC", &foc_step(0.0)) <= 0.27e-3);
    assert!(report("FOC", &foc_step(-0.4)) <= 0.27e-3);
}

/// At a constant 300 rad/s electrical (7 pole pairs: 42.86 rad/s
/// mechanical, 27.9 counts per ms at 4096 counts per turn), ENC_SPEED over
/// the 1 ms window, ENC_POS and the PS's measurement follow the rotor.
#[test]
fn encoder_follows_the_rotor() {
    let cfg = SimConfig {
        omega_e_rad_s: 300.0,
        ..SimConfig::default()
    };
    let mut sim = SimDrive::new(&cfg).unwrap();
    wr(&mut sim, &rm::FAULT, &rm::WDG_TIMEOUT, u32::MAX);
    sim.advance(10_000_000); // 0.1 s
    let counts_per_ms = 300.0 / 7.0 / (2.0 * std::f64::consts::PI) * 4096.0 / 1000.0;
    let speed = sim.read(rm::ENC.addr(&rm::ENC_SPEED)).unwrap() as u16 as i16;
    assert!(
        (f64::from(speed) - counts_per_ms).abs() <= 1.0,
        "{speed} vs {counts_per_ms}"
    );
    let m = pl_loop::read_measurement(&mut sim, &scaling(&cfg), 0).unwrap();
    let tr = sim.truth();
    // One count is 2 pi 7 / 4096 = 0.0107 rad electrical.
    let d = crate::pmsm::measure::wrap_pi(m.theta_e_rad - tr.theta_e_rad);
    assert!(
        d.abs() < 0.011 && d <= 1e-9,
        "angle {} vs {}",
        m.theta_e_rad,
        tr.theta_e_rad
    );
    assert!(
        (m.omega_e_rad_s - 300.0).abs() < 300.0 / counts_per_ms,
        "{}",
        m.omega_e_rad_s
    );
    // Index pulses: one per mechanical turn (4.286 turns in 0.1 s... of
    // simulated time, plus the one at count 0 right after reset).
    let idx = sim.read(rm::ENC.addr(&rm::ENC_INDEX)).unwrap();
    let turns = tr.theta_m_rad / (2.0 * std::f64::consts::PI);
    assert_eq!(idx, turns.floor() as u32 + 1, "turns {turns}");
    // Open circuit with the gates off: no current, no torque.
    assert_eq!(tr.i_abc_a, [0.0; 3]);
}

/// The simulated PL's time comes from `advance` alone: with a control loop
/// that stops feeding HEARTBEAT, the watchdog trips after WDG_TIMEOUT and
/// the gates go off, and the plant's current decays through the diodes.
#[test]
fn stalled_control_lets_the_watchdog_trip() {
    let cfg = SimConfig::default();
    let mut sim = SimDrive::new(&cfg).unwrap();
    let t = PlTiming::default();
    pl_loop::setup_foc(&mut sim, &t).unwrap();
    wr(&mut sim, &rm::FAULT, &rm::WDG_TIMEOUT, 100_000); // 1 ms
    pl_loop::write_duties(&mut sim, [0.6, 0.45, 0.45], t.pwm_period).unwrap();
    wr(&mut sim, &rm::TOP, &rm::HEARTBEAT, 0);
    wr(&mut sim, &rm::PWM, &rm::GATE_CTRL, 1);
    for _ in 0..10 {
        sim.advance(50_000);
        wr(&mut sim, &rm::TOP, &rm::HEARTBEAT, 1);
    }
    let i_a = sim.truth().i_abc_a[0];
    assert!(i_a > 1.0, "current flows: {i_a}");
    assert_eq!(sim.read(rm::FAULT.addr(&rm::FAULT_STATUS)), Ok(0));
    // The loop stalls: 0.99 ms is fine, 1.01 ms trips.
    sim.advance(99_000);
    assert_eq!(sim.read(rm::FAULT.addr(&rm::FAULT_STATUS)), Ok(0));
    sim.advance(2_000);
    assert_eq!(sim.read(rm::FAULT.addr(&rm::FAULT_STATUS)), Ok(4));
    assert_eq!((sim.gates().hi, sim.gates().lo), (0, 0));
    sim.advance(100_000);
    assert_eq!(sim.truth().i_abc_a, [0.0; 3], "current decayed");
}

/// The whole simulated drive stays small (it lives in the firmware's RAM
/// under QEMU).
#[test]
fn state_is_small() {
    let n = core::mem::size_of::<SimDrive>();
    std::println!("size_of::<SimDrive>() = {n} bytes");
    assert!(n <= 2048, "{n} bytes");
}
