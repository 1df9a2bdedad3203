//! Anatomy of the FPGA-vs-reference decision mismatch: the paper (Sec. VII-B)
//! attributes its 2.5 % to "an error of one time step on the predicted length
//! of the switching sequence" and to cost truncation. This measures both on
//! the reference's closed loop: the FPGA model is fed the same state every
//! step; its predicted `L*` for the candidate it picks is compared with the
//! `L*` the reference's exact extension gives that candidate, and when both
//! switch to different positions the two choices are priced with the
//! reference's cost (eqs. 10-12).
use models::mpdcc::controller::{Controller, CtrlState, Decision, DecisionKind, StateError};
use models::mpdcc::mpdcc_fixed::MpdccFixed;
use models::mpdcc::mpdcc_ref::MpdccRef;
use serde::Serialize;

/// Drives with the reference, watches the FPGA model.
pub struct Spy {
    pub reference: MpdccRef,
    pub fpga: MpdccFixed,
    pub a: Anatomy,
}

/// Counters; see [`Anatomy::finish`] for the derived percentages.
#[derive(Serialize, Default, Clone, Copy)]
pub struct Anatomy {
    pub delta_i_pu: f64,
    pub steps: u64,
    pub mismatches: u64,
    /// Reference kept `s(k-1)`, the FPGA model switched.
    pub only_fpga_switched: u64,
    /// The FPGA model kept `s(k-1)`, the reference switched.
    pub only_reference_switched: u64,
    /// Both switched, to different positions.
    pub both_switched_differently: u64,
    /// FPGA `Optimal` decisions checked for their `L*` prediction.
    pub fpga_predictions: u64,
    /// ... with predicted `L*` equal to the reference's `L*` of that candidate.
    pub prediction_exact: u64,
    /// ... within one step.
    pub prediction_within_one: u64,
    /// Sum of |predicted - true| (for the mean), steps.
    pub prediction_abs_error_sum: u64,
    /// Predictions above the truth (the FPGA model is optimistic).
    pub prediction_over: u64,
    /// Sum over `both_switched_differently` of J_ref(FPGA choice) / J_ref(reference choice).
    pub cost_ratio_sum: f64,
    /// FPGA choices that the reference finds infeasible (`L* = 0`).
    pub fpga_choice_infeasible: u64,
}

/// Derived figures, percent unless named otherwise.
#[derive(Serialize, Clone, Copy)]
pub struct AnatomyReport {
    pub delta_i_pu: f64,
    pub decision_mismatch_percent: f64,
    pub only_fpga_switched_percent_of_mismatches: f64,
    pub only_reference_switched_percent_of_mismatches: f64,
    pub both_switched_differently_percent_of_mismatches: f64,
    pub l_star_prediction_exact_percent: f64,
    pub l_star_prediction_within_one_step_percent: f64,
    pub l_star_prediction_over_percent: f64,
    pub l_star_prediction_mean_abs_error_steps: f64,
    /// Mean of J_ref(FPGA choice) / J_ref(reference choice) where both switched differently.
    pub cost_ratio_when_different: f64,
    pub fpga_choice_infeasible_count: u64,
}

impl Anatomy {
    pub fn finish(&self) -> AnatomyReport {
        let pct = |a: u64, b: u64| 100.0 * a as f64 / b.max(1) as f64;
        AnatomyReport {
            delta_i_pu: self.delta_i_pu,
            decision_mismatch_percent: pct(self.mismatches, self.steps),
            only_fpga_switched_percent_of_mismatches: pct(self.only_fpga_switched, self.mismatches),
            only_reference_switched_percent_of_mismatches: pct(
                self.only_reference_switched,
                self.mismatches,
            ),
            both_switched_differently_percent_of_mismatches: pct(
                self.both_switched_differently,
                self.mismatches,
            ),
            l_star_prediction_exact_percent: pct(self.prediction_exact, self.fpga_predictions),
            l_star_prediction_within_one_step_percent: pct(
                self.prediction_within_one,
                self.fpga_predictions,
            ),
            l_star_prediction_over_percent: pct(self.prediction_over, self.fpga_predictions),
            l_star_prediction_mean_abs_error_steps: self.prediction_abs_error_sum as f64
                / self.fpga_predictions.max(1) as f64,
            cost_ratio_when_different: self.cost_ratio_sum
                / (self.both_switched_differently - self.fpga_choice_infeasible).max(1) as f64,
            fpga_choice_infeasible_count: self.fpga_choice_infeasible,
        }
    }
}

impl Controller for Spy {
    fn name(&self) -> &'static str {
        "reference (watching the FPGA model)"
    }

    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let d = self.reference.step(st)?;
        let f = self.fpga.step(st)?;
        self.a.steps += 1;
        if f.kind == DecisionKind::Optimal {
            let t = self.reference.evaluate(st, f.s)?;
            let err = (f.horizon_steps as i64 - t.l_star as i64).unsigned_abs();
            self.a.fpga_predictions += 1;
            self.a.prediction_abs_error_sum += err;
            self.a.prediction_exact += u64::from(err == 0);
            self.a.prediction_within_one += u64::from(err <= 1);
            self.a.prediction_over += u64::from(f.horizon_steps > t.l_star);
        }
        if d.s != f.s {
            self.a.mismatches += 1;
            match (d.kind == DecisionKind::Kept, f.kind == DecisionKind::Kept) {
                (true, _) => self.a.only_fpga_switched += 1,
                (false, true) => self.a.only_reference_switched += 1,
                (false, false) => {
                    self.a.both_switched_differently += 1;
                    let tf = self.reference.evaluate(st, f.s)?;
                    let tr = self.reference.evaluate(st, d.s)?;
                    if tf.l_star == 0 {
                        self.a.fpga_choice_infeasible += 1;
                    } else if tr.l_star > 0 {
                        let jf = self.reference.cost(st.s_prev, f.s, &tf);
                        let jr = self.reference.cost(st.s_prev, d.s, &tr);
                        self.a.cost_ratio_sum += if jr > 0.0 { jf / jr } else { 1.0 };
                    } else {
                        // Reference deadlock: both are eq. (16) choices; count as equal.
                        self.a.cost_ratio_sum += 1.0;
                    }
                }
            }
        }
        Ok(d)
    }
}
