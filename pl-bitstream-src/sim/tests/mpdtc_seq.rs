//! The control sequence (`mpdtc_seq` in `pl_top`, paper 000 section 3)
//! stepped through cycle by cycle via the AXI-Lite port, against
//! hand-computed timings: IDLE until the run condition, INITIAL = chopped
//! alignment vector (period, on-time, dead time, the 50 % cap, duration) and
//! the latched encoder reference, SAMPLE waiting for the averaged ADC sample
//! and the START hand-shake, MPDTC (the core latency), PWM applying S[k+1] only at
//! the next ADC average strobe, overruns, ignored starts, and the aborts to
//! IDLE (fault, GATE_EN = 0, mode change, MANUAL).
use regmap::{self as rm, mode, seq_state, Block, Register};
use rtl_sim::pl_top::{axi_addr, PlTopSim, PtOut, OKAY};

fn w(sim: &mut PlTopSim, b: &Block, r: &Register, v: u32) {
    assert_eq!(sim.write(axi_addr(b, r), v), OKAY, "write {}", r.name);
}

fn r(sim: &mut PlTopSim, b: &Block, reg: &Register) -> u32 {
    sim.read_ok(axi_addr(b, reg))
}

fn status(sim: &mut PlTopSim) -> u32 {
    r(sim, &rm::MPDTC, &rm::MPDTC_SEQ_STATUS)
}

fn state(sim: &mut PlTopSim) -> u32 {
    status(sim) & 7
}

fn done_count(sim: &mut PlTopSim) -> u32 {
    r(sim, &rm::MPDTC, &rm::MPDTC_STATUS) >> 16
}

fn gates(o: &PtOut) -> (u8, u8) {
    (o.gate_hi, o.gate_lo)
}

const DT: u32 = 2;
const ALIGN_PERIOD: u32 = 100;
const ALIGN_ON: u32 = 30;
/// 10 whole chopper periods and 15 cycles of the 11th.
const ALIGN_TIME: u32 = 1015;
/// ADC period: one averaged sample (control period) every 4 x 50 cycles.
const ADC_PERIOD: u32 = 50;

/// Upper-gate pulses of leg a in a recorded run: (first cycle, length).
fn pulses_a(trace: &[PtOut]) -> Vec<(usize, usize)> {
    let mut v = Vec::new();
    let mut start = None;
    for (t, o) in trace.iter().enumerate() {
        let on = o.gate_hi & 0b100 != 0;
        match (on, start) {
            (true, None) => start = Some(t),
            (false, Some(s)) => {
                v.push((s, t - s));
                start = None;
            }
            _ => {}
        }
    }
    v
}

/// Encoder phases (a, b) in counting-up order.
const QUAD: [(u8, u8); 4] = [(0, 0), (1, 0), (1, 1), (0, 1)];

/// A configured drive: sequence registers, ADC answering every conversion,
/// dead time, mode MPDTC with MANUAL = 0 and STATE_CLR = 0; GATE_EN still 0.
fn setup() -> PlTopSim {
    let mut sim = PlTopSim::new();
    sim.adc = Some(simpl::adc::Converter::new(10));
    w(&mut sim, &rm::ADC, &rm::ADC_PERIOD, ADC_PERIOD);
    // The new pace at once (the sample timer's countdown of the reset
    // period would outlast the ADC result timer's new limit).
    w(&mut sim, &rm::ADC, &rm::ADC_CTRL, 0);
    w(&mut sim, &rm::ADC, &rm::ADC_CTRL, 1);
    w(&mut sim, &rm::PWM, &rm::DEAD_TIME, DT);
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_PERIOD, ALIGN_PERIOD);
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_ON, ALIGN_ON);
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_TIME, ALIGN_TIME);
    assert_eq!(
        r(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_VEC),
        0b100,
        "reset vector"
    );
    // Parameters and inputs of a decision that picks an active vector:
    // zero currents, angle 0 (cos 1.0 = 65536 in COEF sQ1.16), T* = 0.4 N m
    // (TRQ sQ3.14: 6554), the default drive's fixed-point parameters.
    let cfg = models::pmsm::mpdtc_ref::MpdtcConfig::new(
        models::pmsm::params::MotorParams::default(),
        models::pmsm::mpdtc_ref::MpdtcParams::default(),
    )
    .unwrap();
    let p = models::pmsm::mpdtc_fixed::FixedParams::from_config(&cfg).unwrap();
    let m = &rm::MPDTC;
    for (reg, v) in [
        (&rm::MPDTC_P_A, p.a),
        (&rm::MPDTC_P_LAMBDA, p.lambda),
        (&rm::MPDTC_P_U0, p.u0),
        (&rm::MPDTC_P_U0_HALF, p.u0_half),
        (&rm::MPDTC_P_U0_H, p.u0_h),
        (&rm::MPDTC_P_PSI_L, p.psi_l),
        (&rm::MPDTC_P_KINV_T, p.kinv_t),
        (&rm::MPDTC_P_TOL, p.tol),
        (&rm::MPDTC_P_W2_0, p.w2[0]),
        (&rm::MPDTC_P_W2_1, p.w2[1]),
        (&rm::MPDTC_P_W2_2, p.w2[2]),
        (&rm::MPDTC_P_W2_3, p.w2[3]),
        (&rm::MPDTC_IN_COS0, 65536),
        (&rm::MPDTC_IN_COS1, 65536),
        (&rm::MPDTC_IN_COS2, 65536),
        (&rm::MPDTC_IN_T_REF, 6554),
    ] {
        w(&mut sim, m, reg, v as u32 & reg.mask());
    }
    w(&mut sim, m, &rm::MPDTC_CTRL, 0);
    w(&mut sim, &rm::TOP, &rm::CTRL, mode::MPDTC);
    sim
}

/// Runs until the sequence is in SAMPLE with its sample (SAMPLED = 1).
fn until_sampled(sim: &mut PlTopSim) {
    let mut n = 0;
    while status(sim) & 0xF != seq_state::SAMPLE | 8 {
        n += 1;
        assert!(
            n < 1000,
            "no sample in SAMPLE (FAULT_STATUS {:#x})",
            r(sim, &rm::FAULT, &rm::FAULT_STATUS)
        );
    }
}

/// Steps until the ADC average strobe (the control-period boundary); returns
/// the cycles stepped before the strobe cycle and the outputs seen.
fn until_boundary(sim: &mut PlTopSim) -> Vec<PtOut> {
    let mut seen = Vec::new();
    loop {
        let o = sim.step();
        if o.adc_avg_valid == 1 {
            return seen;
        }
        seen.push(o);
        assert!(seen.len() <= 4 * ADC_PERIOD as usize, "no boundary");
    }
}

#[test]
fn idle_alignment_then_sample() {
    let mut sim = setup();
    // IDLE: mode MPDTC and MANUAL = 0, but GATE_EN = 0: gates off.
    sim.idle(50);
    assert_eq!(status(&mut sim), 0, "IDLE, nothing counted");
    assert_eq!(gates(&sim.peek()), (0, 0));
    // Encoder at 3 counts before the alignment.
    let mut ph = 0;
    for _ in 0..3 {
        ph += 1;
        (sim.inp.enc_a, sim.inp.enc_b) = QUAD[ph];
        sim.idle(4);
    }
    w(&mut sim, &rm::PWM, &rm::GATE_CTRL, 1);
    assert_eq!(state(&mut sim), seq_state::INITIAL);
    // Record the gates (after each edge) through the whole alignment.
    let mut trace = Vec::new();
    for _ in 0..1100 {
        sim.step();
        trace.push(sim.peek());
    }
    let p = pulses_a(&trace);
    // 11 pulses of the vector 100: the first may be cut by the AXI reads
    // above; then 9 whole ones of ON - DT = 28 cycles (the lower gate of leg
    // a must be off DT cycles before the upper one turns on), one chopper
    // period (100 cycles) apart, and the last one cut after 15 requested
    // cycles by the end of INITIAL (ALIGN_TIME = 10 x 100 + 15): 15 - DT.
    assert_eq!(p.len(), 11, "pulses {p:?}");
    for i in 1..10 {
        assert_eq!(p[i].1, (ALIGN_ON - DT) as usize, "pulse {i}: {p:?}");
        assert_eq!(p[i + 1].0 - p[i].0, ALIGN_PERIOD as usize, "{p:?}");
    }
    assert_eq!(p[10].1, (15 - DT) as usize, "truncated last pulse: {p:?}");
    // Legs b and c: lower gate on the whole time, upper never.
    assert!(trace.iter().all(|o| o.gate_hi & 0b011 == 0));
    assert!(trace[p[1].0..].iter().all(|o| o.gate_lo & 0b011 == 0b011));
    // After the alignment: the zero vector 000 (the core's cleared S[k]).
    assert_eq!(gates(trace.last().unwrap()), (0, 0b111));
    let st = status(&mut sim);
    assert_eq!(st & 7, seq_state::SAMPLE);
    assert_eq!(st >> 4 & 1, 1, "ALIGNED");
    assert_eq!(r(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_POS), 3);
    // The encoder itself is not zeroed; later moves do not change the reference.
    ph += 1;
    (sim.inp.enc_a, sim.inp.enc_b) = QUAD[ph % 4];
    sim.idle(4);
    assert_eq!(r(&mut sim, &rm::ENC, &rm::ENC_POS), 4);
    assert_eq!(r(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_POS), 3);

    // The 50 % cap: ALIGN_ON = 80 of 100 gives 50 - DT cycles of upper gate.
    w(&mut sim, &rm::PWM, &rm::GATE_CTRL, 0);
    assert_eq!(state(&mut sim), seq_state::IDLE, "GATE_EN = 0 -> IDLE");
    assert_eq!(gates(&sim.peek()), (0, 0));
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_ON, 80);
    w(&mut sim, &rm::PWM, &rm::GATE_CTRL, 1);
    assert_eq!(
        status(&mut sim) & 0x1F,
        seq_state::INITIAL,
        "again, ALIGNED = 0"
    );
    let mut trace = Vec::new();
    for _ in 0..500 {
        sim.step();
        trace.push(sim.peek());
    }
    let p = pulses_a(&trace);
    for i in 1..4 {
        assert_eq!(p[i].1, (50 - DT) as usize, "capped pulse {i}: {p:?}");
        assert_eq!(p[i + 1].0 - p[i].0, ALIGN_PERIOD as usize);
    }
}

#[test]
fn sample_mpdtc_pwm_cycle_and_aborts() {
    let mut sim = setup();
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_ALIGN_TIME, 200);
    // No averaged ADC results: the sequence waits in SAMPLE, a START is
    // ignored. (A slow ADC, not a stopped one: with the gates on, the PL's
    // ADC result timer trips ADC_STUCK ADC_PERIOD + 16 cycles after the
    // last raw sample.)
    w(&mut sim, &rm::ADC, &rm::ADC_PERIOD, 1000);
    w(&mut sim, &rm::ADC, &rm::ADC_CTRL, 0);
    w(&mut sim, &rm::ADC, &rm::ADC_CTRL, 1);
    w(&mut sim, &rm::PWM, &rm::GATE_CTRL, 1);
    sim.idle(250);
    assert_eq!(
        status(&mut sim) & 0xF,
        seq_state::SAMPLE,
        "SAMPLE, no sample"
    );
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_START, 1);
    sim.idle(30);
    assert_eq!(
        done_count(&mut sim),
        0,
        "START before the sample is ignored"
    );
    assert_eq!(state(&mut sim), seq_state::SAMPLE);
    // A shorter period acts on the result timer at once: written with the
    // conversions stopped (the change of ENABLE restarts the timer).
    w(&mut sim, &rm::ADC, &rm::ADC_CTRL, 0);
    w(&mut sim, &rm::ADC, &rm::ADC_PERIOD, ADC_PERIOD);
    w(&mut sim, &rm::ADC, &rm::ADC_CTRL, 1);
    until_sampled(&mut sim);

    // START: MPDTC for the core's latency, then PWM.
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_START, 1);
    assert_eq!(state(&mut sim), seq_state::MPDTC);
    sim.idle(rm::MPDTC_LATENCY_CYCLES);
    assert_eq!(state(&mut sim), seq_state::PWM);
    let st = r(&mut sim, &rm::MPDTC, &rm::MPDTC_STATUS);
    assert_eq!(st >> 16, 1, "one decision");
    let s = (st >> 1 & 7) as u8;
    assert!(
        s != 0 && s != 7,
        "an active vector for T* = 0.4 N m, got {s:03b}"
    );
    // A START in PWM is ignored.
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_START, 1);
    sim.idle(25);
    assert_eq!(done_count(&mut sim), 1, "START in PWM ignored");
    // The gates hold 000 up to the boundary ...
    let before = until_boundary(&mut sim);
    assert!(before.iter().all(|o| gates(o) == (0, 0b111)));
    // ... and follow S[k+1] after it: the edge ending the strobe cycle t
    // changes the state (gates unchanged after it), the gate driver sees
    // S[k+1] in t+1, so the lower gates of the legs in s are off after the
    // edge ending t+1 and the upper gates on DT edges later.
    assert_eq!(gates(&sim.peek()), (0, 0b111), "after the edge ending t");
    let mut after = Vec::new();
    for _ in 0..6 {
        sim.step();
        after.push(gates(&sim.peek()));
    }
    assert_eq!(
        after[0],
        (0, !s & 7),
        "edge t+1: lower gates of the legs in s off"
    );
    assert_eq!(after[DT as usize - 1], (0, !s & 7), "dead time");
    assert_eq!(
        after[DT as usize],
        (s, !s & 7),
        "edge t+1+DT: upper gates on"
    );
    assert_eq!(after[5], (s, !s & 7));
    let st = status(&mut sim);
    assert_eq!(
        st & 0xF,
        seq_state::SAMPLE | 8,
        "SAMPLE with the boundary's sample"
    );
    assert_eq!(st >> 16, 1, "PERIODS");
    assert_eq!(st >> 8 & 0xFF, 0, "no overrun");

    // The PS skips a period: the next boundary is an overrun, S[k] stays.
    let held = until_boundary(&mut sim);
    assert!(held.iter().skip(1).all(|o| gates(o) == (s, !s & 7)));
    sim.idle(5);
    assert_eq!(gates(&sim.peek()), (s, !s & 7));
    let st = status(&mut sim);
    assert_eq!(st & 0xF, seq_state::SAMPLE | 8);
    assert_eq!(st >> 8 & 0xFF, 1, "one overrun");
    assert_eq!(st >> 16, 1, "no period completed");

    // Another period: START, then back to SAMPLE after the boundary.
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_START, 1);
    sim.idle(rm::MPDTC_LATENCY_CYCLES);
    assert_eq!(state(&mut sim), seq_state::PWM);
    until_boundary(&mut sim);
    sim.idle(2);
    assert_eq!(status(&mut sim) >> 16, 2, "PERIODS");
    assert_eq!(state(&mut sim), seq_state::SAMPLE);

    // Fault abort: external fault pin -> gates off at the 3rd edge (2
    // synchroniser flops), sequence IDLE.
    sim.inp.fault_ext_n = 0;
    sim.step();
    sim.step();
    sim.step();
    assert_eq!(gates(&sim.peek()), (0, 0), "gates off at the 3rd edge");
    assert_eq!(state(&mut sim), seq_state::IDLE, "fault -> IDLE");
    sim.inp.fault_ext_n = 1;
    sim.idle(5);
    w(&mut sim, &rm::FAULT, &rm::FAULT_STATUS, 0b111);
    sim.idle(20);
    assert_eq!(
        state(&mut sim),
        seq_state::IDLE,
        "GATE_EN was cleared by the fault"
    );
    assert_eq!(gates(&sim.peek()), (0, 0));
    // Re-enable: a new run starts with the alignment.
    w(&mut sim, &rm::PWM, &rm::GATE_CTRL, 1);
    assert_eq!(status(&mut sim) & 0x1F, seq_state::INITIAL);
    until_sampled(&mut sim);

    // Mode change away from MPDTC -> IDLE, gates off.
    w(&mut sim, &rm::TOP, &rm::CTRL, mode::OFF);
    assert_eq!(state(&mut sim), seq_state::IDLE);
    assert_eq!(gates(&sim.peek()), (0, 0));
    w(&mut sim, &rm::TOP, &rm::CTRL, mode::MPDTC);
    until_sampled(&mut sim);
    // MANUAL = 1 -> sequence IDLE, the gates follow PWM.SW_STATE.
    w(&mut sim, &rm::PWM, &rm::SW_STATE, 0b010);
    w(&mut sim, &rm::MPDTC, &rm::MPDTC_CTRL, 1);
    assert_eq!(state(&mut sim), seq_state::IDLE);
    sim.idle(DT + 2);
    assert_eq!(gates(&sim.peek()), (0b010, 0b101));
}
