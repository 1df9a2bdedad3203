//! Hand-computed cases of the simulated PL and of the simulated motor
//! behind it.

use super::pl::{Events, SimPl};
use super::{SimConfig, SimDrive};
use drive::pl::enc::Encoder;
use drive::pl::pwm::Pwm;
use drive::pl::top::{Mode, Top};
use regmap::bus::{BusError, RegisterBus};
use regmap::{self as rm, mode, Block, Register};
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
    control_boundary: false,
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
/// is 0 in cycle h + 1 and reaches 1000 in cycle h + 1001; the registered
/// comparison holds in cycle h + 1002, whose edge latches WATCHDOG and
/// turns the gates off: both seen from cycle h + 1003.
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
    pl.run(h + 1002 - pl.cycles(), &Events::default());
    assert_eq!(peek(&pl, &rm::FAULT, &rm::FAULT_STATUS), 0, "not yet");
    let e = edges(&mut pl, 10);
    assert_eq!(e, [(h + 1003, 0, 0)]);
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
    // Heartbeat, then the clear sticks (from the second cycle after the
    // heartbeat: the registered comparison still holds in the first);
    // gates stay off until GATE_EN.
    w(&mut pl, &rm::TOP, &rm::HEARTBEAT, 0);
    pl.run_cycle_by_cycle(1);
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
    assert_eq!(pl.read(rm::BASE_ADDR + 0x2044).0, Err(BusError::SlaveError));
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
        pl.pins.adc_word = crate::adc::adc_word([100, -40, -60]);
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

// ------------------------------------------------- the simulated motor
// (the closed loops through the drive's own code are in `simpl`'s test `tests/servo.rs`)

fn wr<B: RegisterBus>(bus: &mut B, b: &Block, r: &Register, v: u32) {
    assert_eq!(bus.write(b.addr(r), v), Ok(()), "{}", r.name);
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
    let e = Encoder(&mut sim).read().unwrap();
    let (theta_e, omega_e) = (e.theta_e_rad(7, 0), e.omega_e_rad_s(7));
    let tr = sim.truth();
    // One count is 2 pi 7 / 4096 = 0.0107 rad electrical.
    let d = models::pmsm::measure::wrap_pi(theta_e - tr.theta_e_rad);
    assert!(
        d.abs() < 0.011 && d <= 1e-9,
        "angle {theta_e} vs {}",
        tr.theta_e_rad
    );
    assert!((omega_e - 300.0).abs() < 300.0 / counts_per_ms, "{omega_e}");
    // Index pulses: one per mechanical turn (4.286 turns in 0.1 s... of
    // simulated time, plus the one at count 0 right after reset).
    let idx = sim.read(rm::ENC.addr(&rm::ENC_INDEX)).unwrap();
    let turns = tr.theta_m_rad / (2.0 * std::f64::consts::PI);
    assert_eq!(idx, turns.floor() as u32 + 1, "turns {turns}");
    // Open circuit with the gates off: no current, no torque.
    assert_eq!(tr.i_abc_a, [0.0; 3]);
}

/// The simulated motor's own parameters: a coasting rotor under viscous
/// friction slows as `exp(-b t / J)`, a negative encoder direction counts
/// down, locking stops it, and a refused `sim_set` changes nothing.
#[test]
fn sim_motor_parameters_move_the_rotor_and_the_encoder() {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    wr(&mut sim, &rm::FAULT, &rm::WDG_TIMEOUT, u32::MAX);
    assert!(sim.sim_motor().locked);
    sim.sim_set("locked", 0.0).unwrap();
    sim.sim_set("b", 8.1e-4).unwrap(); // J / b = 0.1 s
    sim.sim_set("enc_dir", -1.0).unwrap();
    let before = sim.sim_motor();
    for (n, v) in [("j", 0.0), ("b", -1.0), ("enc_dir", 0.5), ("nope", 1.0)] {
        assert!(sim.sim_set(n, v).is_err(), "{n} {v}");
    }
    assert_eq!(sim.sim_motor(), before);
    // Start it at 100 rad/s mechanical (the plant's state, open circuit).
    let plant_speed = |sim: &mut SimDrive| sim.truth().omega_e_rad_s / 7.0;
    assert_eq!(plant_speed(&mut sim), 0.0);
    sim.plant_mut_for_tests()
        .set_state(0.0, 0.0, 0.0, 700.0)
        .unwrap();
    sim.advance(10_000_000); // 0.1 s: one time constant
    let w = plant_speed(&mut sim);
    assert!((w / (100.0 * (-1.0f64).exp()) - 1.0).abs() < 2e-3, "{w}");
    // The rotor turned forward by w0 J/b (1 - 1/e) = 6.32 rad; the encoder
    // counted down by as much.
    let turned = sim.truth().theta_m_rad;
    assert!(
        (turned - 10.0 * (1.0 - (-1.0f64).exp())).abs() < 0.02,
        "{turned}"
    );
    let pos = Encoder(&mut sim).read().unwrap().pos;
    let counts = (turned / (2.0 * std::f64::consts::PI) * 4096.0).floor() as i64;
    assert_eq!(i64::from(pos), (-counts).rem_euclid(4096), "{turned} rad");
    sim.sim_set("locked", 1.0).unwrap();
    sim.advance(100_000);
    assert_eq!(plant_speed(&mut sim), 0.0);
}

/// The simulated PL's time comes from `advance` alone: with a control loop
/// that stops feeding HEARTBEAT, the watchdog trips after WDG_TIMEOUT and
/// the gates go off, and the plant's current decays through the diodes.
#[test]
fn stalled_control_lets_the_watchdog_trip() {
    let cfg = SimConfig::default();
    let mut sim = SimDrive::new(&cfg).unwrap();
    // FOC-PWM at 15.985 kHz (half period 3128 cycles), 100 ns dead time.
    let mut pwm = Pwm(&mut sim);
    pwm.set_half_period(3128).unwrap();
    pwm.set_dead_time(10).unwrap();
    pwm.set_duties([0.6, 0.45, 0.45], 3128).unwrap();
    Top(&mut sim).set_mode(Mode::Foc).unwrap();
    wr(&mut sim, &rm::FAULT, &rm::WDG_TIMEOUT, 100_000); // 1 ms
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
/// under QEMU): at most 2 KiB besides the capture ring, which holds what
/// the PL's BRAM holds (163 bits per sample, 24 bytes in the Rust struct).
#[test]
fn state_is_small() {
    use super::capture::{Sample, DEPTH};
    let n = core::mem::size_of::<SimDrive>();
    let ring = core::mem::size_of::<[Sample; DEPTH]>();
    std::println!("size_of::<SimDrive>() = {n} bytes, of which the capture ring {ring}");
    assert!(ring <= 24 * DEPTH, "{ring} bytes");
    assert!(n - ring <= 2048, "{n} bytes");
}

/// A write of `CTRL.MODE` changes which event is the control-period
/// boundary from the cycle after its strobe; a PWM bottom in the cycles
/// of that write belongs to the mode before it. The drive counts as
/// boundaries exactly the cycles the PL flags in `IRQ_STATUS.BOUNDARY`,
/// whatever the phase of a mode change against the PWM bottom (the
/// co-simulation bridge counted the bottom in the cycles of a write to
/// FOC-PWM by the mode after it: the control interrupt was raised for a
/// boundary the PL never flagged).
#[test]
fn boundaries_counted_are_the_ones_flagged_across_mode_changes() {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    wr(&mut sim, &rm::FAULT, &rm::WDG_TIMEOUT, u32::MAX);
    Pwm(&mut sim).set_half_period(3128).unwrap();
    wr(&mut sim, &rm::ADC, &rm::ADC_PERIOD, 391);
    wr(&mut sim, &rm::ADC, &rm::ADC_CTRL, 1);
    wr(&mut sim, &rm::TOP, &rm::IRQ_EN, 1);
    let status = rm::TOP.addr(&rm::IRQ_STATUS);
    let mut checked = 0;
    // Counted against flagged for a mode change `d` cycles before a PWM
    // bottom (the cycles around it: the write's strobe, its edge, after).
    let mut change = |sim: &mut SimDrive, m: Mode, d: u64| {
        sim.write(status, 0b111).unwrap();
        Top(&mut *sim).set_mode(m).unwrap();
        let counted = sim.boundaries_crossed();
        let flagged = sim.read(status).unwrap() & 1;
        // A boundary in the read's own cycle is the next check's.
        if sim.boundaries_crossed() == counted {
            assert_eq!(counted, flagged, "to {m:?}, {d} cycles before a PWM bottom");
            checked += 1;
        }
        sim.advance(0);
    };
    for other in [Mode::Off, Mode::Mpdtc] {
        for d in 0..24 {
            // Just after a PWM bottom, in FOC-PWM.
            Top(&mut sim).set_mode(Mode::Foc).unwrap();
            sim.advance_to_boundary(2 * 6256);
            sim.advance(6256 - d);
            change(&mut sim, other, d);
            Top(&mut sim).set_mode(Mode::Foc).unwrap();
            sim.advance_to_boundary(2 * 6256);
            Top(&mut sim).set_mode(other).unwrap();
            sim.advance(6256 - d);
            change(&mut sim, Mode::Foc, d);
        }
    }
    assert!(checked >= 90, "{checked} of 96 checked");
}
