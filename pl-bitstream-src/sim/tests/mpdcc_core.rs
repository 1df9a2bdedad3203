//! `mpdcc_core` against `drive::mpdcc::fpga::FpgaMpdcc::decide_raw`: the
//! same decision (position, kind, `L*`, candidates, `J` and `J_dl` of the
//! chosen candidate) and the cycle count of `cycles::pipelined_core_cycles`,
//! from the raw state registers (common terms, lazy check, search).
use rtl_sim::mpdcc_vectors::check_core;

#[test]
fn decisions_are_bit_exact_at_two_explorers() {
    let s = check_core(1, 300, 2);
    assert_eq!(s.mismatches, 0, "{s:?}");
    assert!(s.kinds.iter().all(|&k| k > 5), "{s:?}");
    // 216 candidates at N = 2: common terms 16, 108 issue cycles, explorer
    // latency 41, last comparison 1.
    assert_eq!(s.worst_case_cycles, 16 + 108 + 41 + 1, "{s:?}");
}

#[test]
fn decisions_do_not_depend_on_the_explorer_count() {
    for n in [1, 3, 4, 5, 6] {
        let s = check_core(3, 60, n);
        assert_eq!(s.mismatches, 0, "{s:?}");
    }
}
