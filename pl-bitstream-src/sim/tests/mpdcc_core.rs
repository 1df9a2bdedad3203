//! `mpdcc_core` against `models::mpdcc::mpdcc_fixed::MpdccFixed::decide_raw`: the
//! same decision (position, kind, `L*`, candidates, `J` and `J_dl` of the
//! chosen candidate) and the cycle count of `cycles::pipelined_core_cycles_ii`,
//! from the raw state registers (common terms, lazy check, search), for both
//! datapaths: full rate (`II = 1`) and `pl_top`'s shared search lanes.
use models::mpdcc::cycles;
use rtl_sim::mpdcc_core::CoreConfig;
use rtl_sim::mpdcc_vectors::check_core;

#[test]
fn decisions_are_bit_exact_at_two_explorers() {
    let s = check_core(1, 300, 2, CoreConfig::FullRate);
    assert_eq!(s.mismatches, 0, "{s:?}");
    assert!(s.kinds.iter().all(|&k| k > 5), "{s:?}");
    // 216 candidates at N = 2: first issue after 20 cycles (common terms on
    // four shared multipliers), 108 issue cycles, explorer latency 41,
    // arg-min tree 3, fold 1.
    assert_eq!(s.worst_case_cycles, 20 + 108 + 41 + 3 + 1, "{s:?}");
}

/// `pl_top`'s configuration (the default of `scripts/rtl-check mpdcc`): one
/// explorer, a candidate every 4 clocks on two shared lanes; 216
/// candidates: first issue after 20 cycles, the last 4 x 215 clocks later,
/// explorer latency 41 + 1, arg-min tree 3, fold 1 = 927 <= 1,000 cycles.
#[test]
fn pl_top_configuration_is_bit_exact_within_a_thousand_cycles() {
    assert_eq!(CoreConfig::PlTop.ii(), regmap::MPDCC_II);
    let s = check_core(1, 300, regmap::MPDCC_EXPLORERS, CoreConfig::PlTop);
    assert_eq!(s.mismatches, 0, "{s:?}");
    assert!(s.kinds.iter().all(|&k| k > 5), "{s:?}");
    assert_eq!(s.worst_case_cycles, 20 + 4 * 215 + 1 + 42 + 3 + 1, "{s:?}");
    assert!(s.worst_case_cycles <= 1000, "{s:?}");
}

#[test]
fn decisions_do_not_depend_on_the_explorer_count() {
    for config in [CoreConfig::FullRate, CoreConfig::PlTop] {
        for n in [1, 3, 4, 5, 6] {
            let s = check_core(3, 60, n, config);
            assert_eq!(s.mismatches, 0, "{config:?} {s:?}");
        }
    }
}

/// The measured worst case (the vectors include 216-candidate sets) is the
/// cycle model's for N = 1..6, and both are the count by hand:
/// 20 + ceil(216 / N) + 41 + 3 + 1 at full rate,
/// 20 + 4 (ceil(216 / N) - 1) + 1 + 42 + 3 + 1 on shared lanes.
#[test]
fn worst_case_cycles_follow_the_model_for_one_to_six_explorers() {
    let by_hand = [
        (CoreConfig::FullRate, [281, 173, 137, 119, 109, 101]),
        (CoreConfig::PlTop, [927, 495, 351, 279, 239, 207]),
    ];
    for (config, hand) in by_hand {
        for n in 1..=6u32 {
            let s = check_core(5, 30, n, config);
            assert_eq!(s.mismatches, 0, "{config:?} {s:?}");
            assert_eq!(
                s.worst_case_cycles,
                cycles::pipelined_core_cycles_ii(n, config.ii(), 216),
                "{config:?} {s:?}"
            );
            assert_eq!(
                s.worst_case_cycles,
                hand[n as usize - 1],
                "{config:?} {s:?}"
            );
        }
    }
}
