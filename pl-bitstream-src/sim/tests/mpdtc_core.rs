//! `mpdtc_core` against `mpdtc_fixed::decide`: bit-exact on every output
//! (switch state, debug values, next state), fixed latency.
use models::pmsm::mpdtc_fixed;
use rtl_sim::mpdtc_core::MpdtcCoreSim;
use rtl_sim::mpdtc_vectors::{check, paper_params, vector, Rng};

#[test]
fn random_and_corner_vectors_are_bit_exact() {
    let s = check(1, 20_000);
    assert_eq!(s.mismatches, 0, "{s:?}");
    // The capture edge, then the ten stages' windows of 5, 5, 4, 4, 3, 4,
    // 2, 3, 5 and 3 cycles (their register levels, mpdtc_core.v).
    assert_eq!(s.latency_cycles, Some(39), "{s:?}");
    // The register the PS reads says the same.
    assert_eq!(regmap::MPDTC_LATENCY_CYCLES, 39);
    // Both band outcomes are exercised.
    assert!(
        s.in_band_decisions > 1000 && s.in_band_decisions < 19_000,
        "{s:?}"
    );
}

/// A mismatch is reported with its fields (and the harness can fail: a
/// perturbed model output is detected).
#[test]
fn first_vectors_in_detail() {
    let base = paper_params();
    let mut rng = Rng(99);
    let mut sim = MpdtcCoreSim::new();
    for idx in 0..200 {
        let (st, inp, p) = vector(&mut rng, &base, idx);
        let want = mpdtc_fixed::decide(&st, &inp, &p);
        let got = sim.decide(&st, &inp, &p).out;
        assert_eq!(got.s_next, want.s_next, "vector {idx}: s_next");
        assert_eq!(got.i1, want.i1, "vector {idx}: i1");
        assert_eq!(got.eta, want.eta, "vector {idx}: eta");
        assert_eq!(got.iq_ref, want.iq_ref, "vector {idx}: iq_ref");
        assert_eq!(got.i2, want.i2, "vector {idx}: i2");
        assert_eq!(got.err, want.err, "vector {idx}: err");
        assert_eq!(got.cost2, want.cost2, "vector {idx}: cost2");
        assert_eq!(got.next, want.next, "vector {idx}: next state");
        let mut bad = want;
        bad.cost2[3] += 1;
        assert_ne!(got, bad);
    }
}

/// Closed loop on the core's own state: the RTL keeps its state between
/// decisions exactly as the model does.
#[test]
fn state_carries_over_between_decisions() {
    let base = paper_params();
    let mut rng = Rng(5);
    let mut sim = MpdtcCoreSim::new();
    let mut st = mpdtc_fixed::FixedState::default();
    for idx in 0..500 {
        let (_, inp, _) = vector(&mut rng, &base, idx * 4);
        let want = mpdtc_fixed::decide(&st, &inp, &base);
        let got = sim.decide(&st, &inp, &base).out;
        assert_eq!(got, want, "decision {idx}");
        st = want.next;
    }
}
