//! Functional tests of the PL blocks through the Verilated `pl_top` and its
//! AXI-Lite port, against hand-computed expectations: fault trip timing and
//! latching, watchdog, over-current, ADC rate and averaging, PWM on-times
//! with dead time, encoder position, index and speed.
use regmap::{self, mode};
use rtl_sim::pl_top::{axi_addr, PlTopSim, OKAY};
use simpl::adc::Converter;

fn a(b: &regmap::Block, r: &regmap::Register) -> u16 {
    axi_addr(b, r)
}

fn w(sim: &mut PlTopSim, b: &regmap::Block, r: &regmap::Register, v: u32) {
    assert_eq!(sim.write(a(b, r), v), OKAY, "write {}", r.name);
}

fn r(sim: &mut PlTopSim, b: &regmap::Block, reg: &regmap::Register) -> u32 {
    sim.read_ok(a(b, reg))
}

/// Mode MPDTC with SW_STATE = 0b100 (leg a upper, b and c lower), dead
/// time 2, gates enabled; waits until the gates are on.
fn drive_on(sim: &mut PlTopSim) {
    w(sim, &regmap::PWM, &regmap::DEAD_TIME, 2);
    w(sim, &regmap::PWM, &regmap::SW_STATE, 0b100);
    w(sim, &regmap::TOP, &regmap::CTRL, mode::MPDTC);
    w(sim, &regmap::PWM, &regmap::GATE_CTRL, 1);
    sim.idle(4);
    let o = sim.peek();
    assert_eq!((o.gate_hi, o.gate_lo), (0b100, 0b011), "gates on");
}

fn gates_off(sim: &PlTopSim) -> bool {
    let o = sim.peek();
    o.gate_hi == 0 && o.gate_lo == 0
}

#[test]
fn external_fault_trips_in_three_clocks_and_latches() {
    let mut sim = PlTopSim::new();
    drive_on(&mut sim);
    sim.inp.fault_ext_n = 0;
    // 2 synchroniser flops, then the gate flops: off at the 3rd edge.
    sim.step();
    sim.step();
    assert!(!gates_off(&sim), "off too early (only 2 edges)");
    sim.step();
    assert!(gates_off(&sim), "not off at the 3rd edge");
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0b010);
    assert_eq!(
        r(&mut sim, &regmap::PWM, &regmap::GATE_CTRL),
        0,
        "GATE_EN held at 0"
    );
    assert_eq!(
        r(&mut sim, &regmap::TOP, &regmap::STATUS) >> 3 & 1,
        1,
        "STATUS.FAULT"
    );
    // Clearing while the pin is still low does not clear.
    w(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS, 0b010);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0b010);
    // Pin released: still latched, gates still off.
    sim.inp.fault_ext_n = 1;
    sim.idle(10);
    assert!(gates_off(&sim));
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0b010);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_RAW), 0);
    // Clear, then gates stay off until GATE_EN is written again.
    w(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS, 0b111);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0);
    sim.idle(10);
    assert!(gates_off(&sim));
    w(&mut sim, &regmap::PWM, &regmap::GATE_CTRL, 1);
    sim.idle(4);
    assert!(!gates_off(&sim));
}

#[test]
fn watchdog_trips_without_heartbeat() {
    let mut sim = PlTopSim::new();
    // A converter answering every convert pulse: no ADC_STUCK.
    sim.adc = Some(Converter::new(10));
    w(&mut sim, &regmap::FAULT, &regmap::WDG_TIMEOUT, 0); // clamped to 1000
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::WDG_TIMEOUT), 1000);
    drive_on(&mut sim);
    let hb = a(&regmap::TOP, &regmap::HEARTBEAT);
    for i in 0..10 {
        assert_eq!(sim.write(hb, i), OKAY);
        sim.idle(500);
        assert!(!gates_off(&sim), "tripped with heartbeats");
    }
    assert_eq!(sim.write(hb, 99), OKAY);
    let t0 = sim.cycles;
    while !gates_off(&sim) {
        sim.step();
        assert!(sim.cycles - t0 < 2000, "watchdog never tripped");
    }
    // Trips 1000 cycles after the heartbeat (the write response came one
    // cycle after the write): within a couple of cycles of bookkeeping.
    let dt = sim.cycles - t0;
    assert!((999..=1002).contains(&dt), "tripped after {dt} cycles");
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0b100);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_RAW), 0b100);
}

/// The modelled ADC: answers a convert pulse after `conv` cycles.
struct Adc {
    pending: Option<u32>,
    conv: u32,
    samples: Vec<[i16; 3]>,
    next: usize,
}

impl Adc {
    fn new(samples: Vec<[i16; 3]>) -> Self {
        Self {
            pending: None,
            conv: 10,
            samples,
            next: 0,
        }
    }
    /// One cycle of the converter around `sim.step()`; returns the pre-edge outputs.
    fn step(&mut self, sim: &mut PlTopSim) -> rtl_sim::pl_top::PtOut {
        sim.inp.adc_drdy = 0;
        if let Some(t) = self.pending {
            if t == 0 {
                let s = self.samples[self.next % self.samples.len()];
                self.next += 1;
                let f = |x: i16| (x as u64) & 0xFFF;
                sim.inp.adc_data = f(s[0]) << 24 | f(s[1]) << 12 | f(s[2]);
                sim.inp.adc_drdy = 1;
                self.pending = None;
            } else {
                self.pending = Some(t - 1);
            }
        }
        let o = sim.step();
        if o.adc_cnv == 1 {
            assert!(self.pending.is_none(), "convert while converting");
            self.pending = Some(self.conv);
        }
        o
    }
}

#[test]
fn adc_rate_and_average_of_four() {
    let mut sim = PlTopSim::new();
    let mut adc = Adc::new(vec![
        [100, -1, -2048],
        [101, -2, -2048],
        [102, -2, -2048],
        [104, -2, -2048],
    ]);
    // -2048 would trip the over-current fault: irrelevant here (gates off).
    let mut starts = Vec::new();
    while starts.len() < 9 {
        let o = adc.step(&mut sim);
        if o.adc_cnv == 1 {
            starts.push(sim.cycles);
        }
    }
    // Default 391 cycles = 255.75 kHz.
    for p in starts.windows(2) {
        assert_eq!(p[1] - p[0], 391);
    }
    sim.idle(20);
    // floor(407 / 4) = 101; floor(-7 / 4) = -2; -2048.
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_IA), 101);
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_IB), 0xFFFE);
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_IC), 0xF800);
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_COUNT), 2);
    // A new period takes effect.
    w(&mut sim, &regmap::ADC, &regmap::ADC_PERIOD, 100);
    let mut starts = Vec::new();
    while starts.len() < 4 {
        let o = adc.step(&mut sim);
        if o.adc_cnv == 1 {
            starts.push(sim.cycles);
        }
    }
    assert_eq!(starts[3] - starts[2], 100);
}

#[test]
fn over_current_trips_above_the_limit_only() {
    let mut sim = PlTopSim::new();
    drive_on(&mut sim);
    // |1800| = OC_LIMIT is not over the limit.
    let mut adc = Adc::new(vec![[1800, -1800, 0]]);
    for _ in 0..2000 {
        adc.step(&mut sim);
    }
    assert!(!gates_off(&sim));
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0);
    adc.samples = vec![[0, 0, -1801]];
    adc.next = 0;
    let mut trip_at = None;
    let mut drdy_at = None;
    for _ in 0..1000 {
        adc.step(&mut sim);
        if sim.inp.adc_drdy == 1 && drdy_at.is_none() {
            drdy_at = Some(sim.cycles);
        }
        if trip_at.is_none() && gates_off(&sim) {
            trip_at = Some(sim.cycles);
        }
    }
    // The data-ready pin passes two synchroniser flops, the sample register
    // loads at the next edge, the registered over-current comparison at the
    // one after, the gates turn off at the next: the first edge that sees
    // the pin high plus four.
    assert_eq!(trip_at.unwrap() - drdy_at.unwrap(), 4);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0b001);
}

/// An asynchronous converter: data-ready rises at a random edge (random
/// phase and jitter against the PL clock, in whole cycles: a real edge of
/// any phase is first seen at one of two edges) and stays high a random
/// number of cycles; the data bus holds the result from the rising edge
/// until the next conversion. Every pulse must give exactly one sample,
/// the one on the bus, whatever its width.
#[test]
fn asynchronous_data_ready_gives_one_sample_per_edge() {
    let mut sim = PlTopSim::new();
    w(&mut sim, &regmap::ADC, &regmap::ADC_AVG_LOG2, 0);
    let mut rng = rtl_sim::mpdtc_vectors::Rng(0xADC0_0027);
    let mut sent: Vec<[i32; 3]> = Vec::new();
    let mut got: Vec<[i32; 3]> = Vec::new();
    let rd = |sim: &mut PlTopSim, reg: &regmap::Register| {
        (r(sim, &regmap::ADC, reg) as u16 as i16) as i32
    };
    let count0 = r(&mut sim, &regmap::ADC, &regmap::ADC_COUNT);
    for _ in 0..60 {
        // Wait for the convert pulse, then the conversion time plus a
        // random delay, then a pulse 1..8 cycles wide with new data.
        while sim.step().adc_cnv == 0 {}
        sim.idle(40 + (rng.next_u64() % 24) as u32);
        let s = [0, 1, 2].map(|_| rng.range(-2048, 2047));
        sent.push(s);
        sim.inp.adc_data = simpl::adc::adc_word(s);
        sim.inp.adc_drdy = 1;
        sim.idle(1 + (rng.next_u64() % 8) as u32);
        sim.inp.adc_drdy = 0;
        // Data held until after the capture, then garbage on the bus.
        sim.idle(4);
        sim.inp.adc_data = rng.next_u64() & 0xF_FFFF_FFFF;
        got.push([
            rd(&mut sim, &regmap::ADC_IA),
            rd(&mut sim, &regmap::ADC_IB),
            rd(&mut sim, &regmap::ADC_IC),
        ]);
    }
    assert_eq!(got, sent);
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_COUNT) - count0, 60);
}

/// No converter card: the pull-downs hold data-ready and the data low. No
/// sample is taken, `ADC_COUNT` stays at 0, the over-current trip stays
/// quiet, and the ADC result timer latches `ADC_STUCK` ADC_PERIOD + 16
/// cycles after `GATE_EN` (the timer holds at 0 while it is 0); a
/// data-ready held high through reset is not a result either.
#[test]
fn missing_converter_gives_no_samples() {
    let mut sim = PlTopSim::new();
    w(&mut sim, &regmap::PWM, &regmap::DEAD_TIME, 2);
    w(&mut sim, &regmap::PWM, &regmap::SW_STATE, 0b100);
    w(&mut sim, &regmap::TOP, &regmap::CTRL, mode::MPDTC);
    sim.idle(1000);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0);
    w(&mut sim, &regmap::PWM, &regmap::GATE_CTRL, 1);
    // The write's strobe is one cycle before its response.
    let t0 = sim.cycles - 1;
    while sim.peek().gate_hi == 0 {
        sim.step();
        assert!(sim.cycles - t0 < 20, "gates never on");
    }
    while !gates_off(&sim) {
        sim.step();
        assert!(sim.cycles - t0 < 2000, "ADC_STUCK never tripped");
    }
    // GATE_EN = 1 from the edge ending the strobe cycle t0; the age
    // counts from 0 at the next edge and reaches 391 + 16 = 407 in cycle
    // t0 + 408, whose edge turns the gates off.
    let dt = sim.cycles - t0;
    let limit = u64::from(regmap::ADC_PERIOD.reset + regmap::ADC_STUCK_MARGIN_CYCLES);
    assert_eq!(dt, limit + 1, "tripped after {dt} cycles");
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0b1_0000);
    assert_eq!(r(&mut sim, &regmap::PWM, &regmap::GATE_CTRL), 0);
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_COUNT), 0);
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_IA), 0);
    let mut sim = PlTopSim::new();
    sim.inp.adc_drdy = 1;
    sim.inp.aresetn = 0;
    sim.idle(10);
    sim.inp.aresetn = 1;
    sim.idle(5000);
    assert_eq!(r(&mut sim, &regmap::ADC, &regmap::ADC_COUNT), 0);
}

#[test]
fn centre_aligned_pwm_on_times_with_dead_time() {
    let mut sim = PlTopSim::new();
    sim.adc = Some(Converter::new(10));
    w(&mut sim, &regmap::PWM, &regmap::PWM_PERIOD, 100);
    w(&mut sim, &regmap::PWM, &regmap::DUTY_A, 25);
    w(&mut sim, &regmap::PWM, &regmap::DUTY_B, 50);
    w(&mut sim, &regmap::PWM, &regmap::DUTY_C, 100);
    w(&mut sim, &regmap::PWM, &regmap::DEAD_TIME, 3);
    w(&mut sim, &regmap::TOP, &regmap::CTRL, mode::FOC_PWM);
    w(&mut sim, &regmap::PWM, &regmap::GATE_CTRL, 1);
    // The new period and duties load at the end of the current period of
    // the reset period (2 x 2500 cycles).
    sim.idle(5200);
    let (mut hi, mut lo) = ([0u32; 3], [0u32; 3]);
    for _ in 0..200 * 5 {
        sim.step();
        let o = sim.peek();
        assert_eq!(o.gate_hi & o.gate_lo, 0, "shoot-through");
        for leg in 0..3 {
            hi[leg] += u32::from(o.gate_hi >> (2 - leg) & 1);
            lo[leg] += u32::from(o.gate_lo >> (2 - leg) & 1);
        }
    }
    // Per 200-cycle period: upper 2 D - dt, lower 2 (P - D) - dt; 100 %
    // has no transitions, so no dead time.
    assert_eq!(hi.map(|x| x / 5), [47, 97, 200]);
    assert_eq!(lo.map(|x| x / 5), [147, 97, 0]);
    assert_eq!(hi.map(|x| x % 5), [0, 0, 0]);
    let pc = r(&mut sim, &regmap::PWM, &regmap::PWM_COUNT);
    assert!(pc & 0xFFFF < 100);
}

/// An illegal quadrature step (A and B change together) with the gates on
/// latches `ENCODER_LOSS` and turns the gates off 3 edges after the pins
/// change (2 synchroniser flops, then the gate flops); with `GATE_EN` = 0
/// it latches nothing. The count ignores the step either way.
#[test]
fn illegal_encoder_step_is_encoder_loss_while_running() {
    let mut sim = PlTopSim::new();
    sim.adc = Some(Converter::new(10));
    sim.idle(10);
    // Gates off: no fault.
    (sim.inp.enc_a, sim.inp.enc_b) = (1, 1);
    sim.idle(10);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0);
    assert_eq!(r(&mut sim, &regmap::ENC, &regmap::ENC_POS), 0);
    drive_on(&mut sim);
    // A legal step: no fault.
    sim.inp.enc_a = 0;
    sim.idle(10);
    assert!(!gates_off(&sim));
    let pos = r(&mut sim, &regmap::ENC, &regmap::ENC_POS);
    // (0, 1) to (1, 0): both lines change.
    (sim.inp.enc_a, sim.inp.enc_b) = (1, 0);
    sim.step();
    sim.step();
    assert!(!gates_off(&sim), "off too early (only 2 edges)");
    sim.step();
    assert!(gates_off(&sim), "not off at the 3rd edge");
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0b0_1000);
    assert_eq!(r(&mut sim, &regmap::ENC, &regmap::ENC_POS), pos);
    // A one-cycle condition: cleared by a written 1.
    w(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS, 0b1_1111);
    assert_eq!(r(&mut sim, &regmap::FAULT, &regmap::FAULT_STATUS), 0);
}

/// Encoder phases (a, b) in counting-up order.
const QUAD: [(u8, u8); 4] = [(0, 0), (1, 0), (1, 1), (0, 1)];

fn enc_move(sim: &mut PlTopSim, phase: &mut usize, counts: i32, hold: u32) {
    for _ in 0..counts.unsigned_abs() {
        *phase = if counts > 0 {
            (*phase + 1) % 4
        } else {
            (*phase + 3) % 4
        };
        (sim.inp.enc_a, sim.inp.enc_b) = QUAD[*phase];
        sim.idle(hold);
    }
}

#[test]
fn encoder_position_index_and_speed() {
    let mut sim = PlTopSim::new();
    let mut ph = 0;
    sim.idle(5);
    enc_move(&mut sim, &mut ph, 40, 3);
    sim.idle(5);
    assert_eq!(r(&mut sim, &regmap::ENC, &regmap::ENC_POS), 40);
    enc_move(&mut sim, &mut ph, -50, 3);
    sim.idle(5);
    assert_eq!(r(&mut sim, &regmap::ENC, &regmap::ENC_POS), 4096 - 10);
    w(&mut sim, &regmap::ENC, &regmap::ENC_CPR, 1000);
    enc_move(&mut sim, &mut ph, 20, 3);
    sim.idle(5);
    // 4086 >= 1000 - 1: the next up-count wraps to 0, then 19 more.
    assert_eq!(r(&mut sim, &regmap::ENC, &regmap::ENC_POS), 19);
    sim.inp.enc_z = 1;
    sim.idle(5);
    sim.inp.enc_z = 0;
    sim.idle(5);
    assert_eq!(r(&mut sim, &regmap::ENC, &regmap::ENC_POS), 0);
    assert_eq!(r(&mut sim, &regmap::ENC, &regmap::ENC_INDEX), 1);
    // Speed: one count every 10 cycles, window 1000 cycles -> 100 counts.
    w(&mut sim, &regmap::ENC, &regmap::ENC_WINDOW, 1000);
    enc_move(&mut sim, &mut ph, 400, 10);
    let s = r(&mut sim, &regmap::ENC, &regmap::ENC_SPEED);
    assert!((99..=101).contains(&s), "speed {s}");
    enc_move(&mut sim, &mut ph, -400, 10);
    let s = r(&mut sim, &regmap::ENC, &regmap::ENC_SPEED) as u16 as i16;
    assert!((-101..=-99).contains(&s), "speed {s}");
}
