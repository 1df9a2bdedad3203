//! The metrics of the paper-001 experiments: per-implementation statistics
//! of a closed-loop run (switching frequency and THD as defined in
//! `models::mpdcc::metrics`, bound violations, deadlocks) and the relative
//! differences the paper's Sec. VII-B quotes.
use models::mpdcc::closed_loop::LoopResult;
use serde::Serialize;

/// Paper 001, Sec. VII-B.
pub const PAPER_MISMATCH_PERCENT: f64 = 2.5;
pub const PAPER_FSW_DIFF_PERCENT: f64 = 8.0;
pub const PAPER_THD_DIFF_PERCENT: f64 = 2.0;

#[derive(Serialize, Clone, Copy)]
pub struct ImplStats {
    pub fsw_hz: f64,
    pub thd_percent: f64,
    switching_decisions: u64,
    pub deadlocks: u64,
    steps_outside_bounds: u64,
    max_abs_v_n_pu: f64,
    max_v_ph_dev_pu: f64,
    max_i_err_pu: f64,
    max_level_jump: u8,
}

impl From<&LoopResult> for ImplStats {
    fn from(r: &LoopResult) -> Self {
        Self {
            fsw_hz: r.fsw_hz,
            thd_percent: r.thd_percent,
            switching_decisions: r.switching_decisions,
            deadlocks: r.deadlocks,
            steps_outside_bounds: r.steps_outside_bounds,
            max_abs_v_n_pu: r.max_abs_v_n_pu,
            max_v_ph_dev_pu: r.max_v_ph_dev_pu,
            max_i_err_pu: r.max_i_err_pu,
            max_level_jump: r.max_level_jump,
        }
    }
}

/// `(a - b_ref) / b_ref` in percent (0 when `b_ref` is 0).
pub fn signed_diff_percent(a: f64, b_ref: f64) -> f64 {
    if b_ref.abs() < 1e-12 {
        0.0
    } else {
        100.0 * (a - b_ref) / b_ref.abs()
    }
}

/// `|a - b_ref| / |b_ref|` in percent (0 when `b_ref` is 0).
pub fn rel_diff_percent(a: f64, b_ref: f64) -> f64 {
    signed_diff_percent(a, b_ref).abs()
}
