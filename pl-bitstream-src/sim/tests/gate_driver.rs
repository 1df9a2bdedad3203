//! The Verilated gate driver against the Rust model `simpl::gates`,
//! bit-exact on every output of every cycle, plus directed cases checked
//! against hand-computed expectations (independent of the model).
use rtl_sim::gate_driver::GateDriverSim;
use rtl_sim::mpdtc_vectors::Rng;
use simpl::gates::{DeadTime, GateDriver, GateInputs, GateOutputs};

fn inp(rst: bool, en: bool, fault: bool, state: u8, dt: u16) -> GateInputs {
    GateInputs {
        rst,
        en,
        fault,
        state,
        dead_time: DeadTime::new(dt).unwrap(),
    }
}

/// Runs `cycles` random cycles; returns the number of cycles in which a gate
/// turned on (so the test can check the run exercised switching).
fn random_run(seed: u64, cycles: usize) -> usize {
    let mut rng = Rng(seed);
    let mut rtl = GateDriverSim::new();
    let mut model = GateDriver::default();
    let mut cur = inp(true, false, false, 0, 0);
    let mut turn_ons = 0;
    let mut prev = GateOutputs::default();
    for cycle in 0..cycles {
        // Inputs change rarely enough that dead times complete, often
        // enough to hit every interleaving.
        cur.rst = rng.next_u64() % 2000 == 0;
        cur.fault = rng.next_u64() % 300 == 0;
        if rng.next_u64() % 500 == 0 {
            cur.en = !cur.en;
        }
        if rng.next_u64() % 6 == 0 {
            cur.state = (rng.next_u64() & 7) as u8;
        }
        if rng.next_u64() % 400 == 0 {
            let dt = match rng.next_u64() % 8 {
                0 => 0,
                1 => 1023,
                2 => (rng.next_u64() % 1024) as u16,
                _ => (rng.next_u64() % 12) as u16,
            };
            cur.dead_time = DeadTime::new(dt).unwrap();
        }
        let want = model.step(&cur).unwrap();
        let got = rtl.step(&cur);
        assert_eq!(
            got, want,
            "seed {seed} cycle {cycle}: inputs {cur:?}, RTL {got:?}, model {want:?}"
        );
        turn_ons += ((want.hi & !prev.hi) | (want.lo & !prev.lo)).count_ones() as usize;
        prev = want;
    }
    turn_ons
}

#[test]
fn random_sequences_match_model_bit_exact() {
    let mut turn_ons = 0;
    for seed in 1..=4u64 {
        turn_ons += random_run(seed, 250_000);
    }
    // The run must actually switch the gates a lot, or it proves little.
    assert!(turn_ons > 50_000, "only {turn_ons} gate turn-ons");
}

/// Hand-computed: dt = 5, leg a from upper to lower. The upper gate goes
/// off at the first edge after the command, both stay off for exactly 5
/// cycles, the lower gate is on from the 6th edge.
#[test]
fn directed_dead_time_exact() {
    let mut rtl = GateDriverSim::new();
    rtl.step(&inp(true, false, false, 0, 5));
    for _ in 0..10 {
        rtl.step(&inp(false, true, false, 0b100, 5));
    }
    assert_eq!(
        rtl.outputs(),
        GateOutputs {
            hi: 0b100,
            lo: 0b011
        }
    );
    let trace: Vec<u8> = (0..8)
        .map(|_| {
            let o = rtl.step(&inp(false, true, false, 0b000, 5));
            (o.hi >> 2 & 1) | ((o.lo >> 2 & 1) << 1)
        })
        .collect();
    // (hi, lo) of leg a as 2 bits: off x5 after the upper went off, then lower.
    assert_eq!(trace, [0, 0, 0, 0, 0, 2, 2, 2]);
}

#[test]
fn directed_zero_dead_time_is_one_cycle() {
    let mut rtl = GateDriverSim::new();
    rtl.step(&inp(true, false, false, 0, 0));
    for _ in 0..4 {
        rtl.step(&inp(false, true, false, 0b111, 0));
    }
    assert_eq!(rtl.outputs(), GateOutputs { hi: 7, lo: 0 });
    assert_eq!(
        rtl.step(&inp(false, true, false, 0, 0)),
        GateOutputs::default()
    );
    assert_eq!(
        rtl.step(&inp(false, true, false, 0, 0)),
        GateOutputs { hi: 0, lo: 7 }
    );
}

#[test]
fn directed_fault_disable_reset_turn_all_off_next_edge() {
    let mut rtl = GateDriverSim::new();
    let on = inp(false, true, false, 0b110, 2);
    for _ in 0..6 {
        rtl.step(&on);
    }
    assert_eq!(
        rtl.outputs(),
        GateOutputs {
            hi: 0b110,
            lo: 0b001
        }
    );
    for off in [
        inp(false, true, true, 0b110, 2),
        inp(false, false, false, 0b110, 2),
        inp(true, true, false, 0b110, 2),
    ] {
        assert_eq!(rtl.step(&off), GateOutputs::default(), "{off:?}");
        // Back on only after the dead time (2 cycles counted from the off edge).
        assert_eq!(rtl.step(&on), GateOutputs::default());
        if off.rst {
            // Reset also cleared the counter: one more cycle.
            assert_eq!(rtl.step(&on), GateOutputs::default());
        }
        assert_eq!(
            rtl.step(&on),
            GateOutputs {
                hi: 0b110,
                lo: 0b001
            }
        );
    }
}
