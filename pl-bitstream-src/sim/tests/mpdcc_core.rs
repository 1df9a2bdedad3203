//! `mpdcc_core` against `models::mpdcc::mpdcc_fixed::MpdccFixed::decide_raw`: the
//! same decision (position, kind, `L*`, candidates, `J` and `J_dl` of the
//! chosen candidate) and the cycle count of `cycles::pipelined_core_cycles`,
//! from the raw state registers (common terms, lazy check, search).
use models::mpdcc::cycles;
use rtl_sim::mpdcc_vectors::check_core;

#[test]
fn decisions_are_bit_exact_at_two_explorers() {
    let s = check_core(1, 300, 2);
    assert_eq!(s.mismatches, 0, "{s:?}");
    assert!(s.kinds.iter().all(|&k| k > 5), "{s:?}");
    // 216 candidates at N = 2: first issue after 20 cycles (common terms on
    // four shared multipliers), 108 issue cycles, explorer latency 41,
    // arg-min tree 3, fold 1.
    assert_eq!(s.worst_case_cycles, 20 + 108 + 41 + 3 + 1, "{s:?}");
}

#[test]
fn decisions_do_not_depend_on_the_explorer_count() {
    for n in [1, 3, 4, 5, 6] {
        let s = check_core(3, 60, n);
        assert_eq!(s.mismatches, 0, "{s:?}");
    }
}

/// The measured worst case (the vectors include 216-candidate sets) is the
/// cycle model's for N = 1..6, and both are the count by hand:
/// 20 + ceil(216 / N) + 41 + 3 + 1.
#[test]
fn worst_case_cycles_follow_the_model_for_one_to_six_explorers() {
    let by_hand = [281, 173, 137, 119, 109, 101];
    for n in 1..=6u32 {
        let s = check_core(5, 30, n);
        assert_eq!(s.mismatches, 0, "{s:?}");
        assert_eq!(
            s.worst_case_cycles,
            cycles::pipelined_core_cycles(n, 216),
            "{s:?}"
        );
        assert_eq!(s.worst_case_cycles, by_hand[n as usize - 1], "{s:?}");
    }
}
