//! `mpdcc_lane` against `models::mpdcc::mpdcc_fixed::lane`: bit-exact `l_j` at one
//! input per clock (and with idle gaps), fixed latency.
use models::mpdcc::binsearch;
use rtl_sim::mpdcc_lane::{LaneInput, MpdccLaneSim};
use rtl_sim::mpdcc_vectors::{check_lane, lane_cases};

#[test]
fn closed_loop_random_and_raw_vectors_are_bit_exact() {
    let s = check_lane(1, 30_000);
    assert_eq!(s.mismatches, 0, "{s:?}");
    assert_eq!(s.latency_cycles, Some(12), "{s:?}");
    // Every outcome class is exercised: infeasible at once, a finite l_j,
    // inside over the whole horizon.
    assert!(s.classes.iter().all(|&c| c > 1000), "{s:?}");
}

/// Hand-computed cases (eq. 24 on the piece that is left, independent of the
/// model's lane): the harness sees what it is given.
#[test]
fn hand_computed_cases() {
    let mut sim = MpdccLaneSim::new();
    let v = |e0: i16, nodes: [i32; 4], bnd: i16| LaneInput {
        e0,
        nodes,
        bnd,
        idle_before: 0,
    };
    // 1. Node values 100, 200, 400, 800 at k + 8, 16, 32, 64, bound 1000:
    //    inside up to k + 64; the last piece (from 400 at k + 32, slope
    //    400 per 32 steps) reaches 1000 at 32 + floor(32 * 600 / 400) = 80.
    // 2. |e0| > bnd: 0.  3. Flat at 0: inside over the horizon, 128.
    // 4. From 900, +100 per 8 steps: on the bound at k + 8 (capped piece),
    //    then the second piece starts at 1000 moving out: 8 + 0 = 8.
    let want_eq24 = binsearch::lj_exact_eq24(400, 400, 1000, 5).unwrap();
    // floor(32 * 600 / 400)
    assert_eq!(want_eq24, 48);
    let got = sim.run(&[
        v(0, [100, 200, 400, 800], 1000),
        v(1001, [0; 4], 1000),
        v(0, [0; 4], 1000),
        v(900, [100, 200, 300, 400], 1000),
    ]);
    let lj: Vec<u32> = got.iter().map(|o| o.lj).collect();
    assert_eq!(lj, vec![32 + want_eq24 as u32, 0, 128, 8]);
}

/// The first vectors of a seed in detail, and a perturbed expectation is
/// detected (the comparison can fail).
#[test]
fn first_vectors_in_detail() {
    let cases = lane_cases(7, 3_000);
    let mut sim = MpdccLaneSim::new();
    let got = sim.run(&cases.iter().map(|c| c.input).collect::<Vec<_>>());
    assert_eq!(got.len(), cases.len());
    for (i, (g, c)) in got.iter().zip(&cases).enumerate() {
        assert_eq!(g.lj, c.want, "vector {i}: {:?}", c.input);
        assert_ne!(g.lj, c.want + 1);
    }
}
