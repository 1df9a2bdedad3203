//! Hardware in the loop (paper 001, Sec. VII): the Verilated `pl_top`'s
//! `mpdcc_core`, driven through its register page by the driver
//! `drive::pl::mpdcc`, closes the loop around the Rust induction machine and
//! 5L-ANPC plant (`models::mpdcc::closed_loop`), one decision per `T_s`. It
//! must reproduce the loop of the pure-Rust FPGA model
//! (`models::mpdcc::mpdcc_fixed::MpdccFixed`) decision for decision over two
//! fundamental periods: same positions, kinds, `L*`, candidate counts, so
//! the same trajectory and the same statistics; and each decision's cycle
//! count must be the core's (`cycles::pipelined_core_cycles_ii` of pl_top's
//! `MPDCC_N` explorers and `MPDCC_II`).
use std::time::Instant;

use drive::pl::mpdcc::Mpdcc;
use models::mpdcc::closed_loop::{self, LoopConfig, LoopResult};
use models::mpdcc::controller::{candidates, Controller, CtrlState, Decision, StateError};
use models::mpdcc::cycles;
use models::mpdcc::mpdcc_fixed::{Inputs, MpdccFixed};
use models::mpdcc::params::DriveParams;
use rtl_sim::mpdcc_vectors::core;
use rtl_sim::pl_top::PlTopSim;

/// Status polls allowed per decision (2 PL cycles each; a decision takes at
/// most 927 + 2 cycles in pl_top's configuration, N = 1, II = 4).
const MAX_POLLS: u32 = 600;

/// The core on the register page of the Verilated `pl_top`.
struct Hil {
    pl: Mpdcc<PlTopSim>,
    decisions: Vec<Decision>,
    /// (core cycles read back, the cycle model's, PL cycles START to result)
    cycles: Vec<(u32, u32, u64)>,
}

impl Controller for Hil {
    fn name(&self) -> &'static str {
        "pl_top"
    }
    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let x = Inputs::quantize(st)?;
        let t0 = self.pl.0.cycles;
        let d = self.pl.decide(&x, MAX_POLLS).expect("MPDCC page");
        let model = cycles::pipelined_core_cycles_ii(
            regmap::MPDCC_EXPLORERS,
            regmap::MPDCC_II,
            candidates(x.s_prev).len() as u32,
        );
        self.cycles.push((d.cycles, model, self.pl.0.cycles - t0));
        self.decisions.push(d.decision);
        Ok(d.decision)
    }
}

/// The FPGA model, recording its decisions.
struct Model(MpdccFixed, Vec<Decision>);

impl Controller for Model {
    fn name(&self) -> &'static str {
        "fpga"
    }
    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let d = self.0.step(st)?;
        self.1.push(d);
        Ok(d)
    }
}

fn run(ctrl: &mut dyn Controller) -> LoopResult {
    let p = DriveParams::default();
    let cfg = LoopConfig {
        warmup_periods: 1,
        measure_periods: 1,
    };
    closed_loop::run(&p, &cfg, ctrl, None, &mut |_| {}).expect("closed loop")
}

#[test]
fn pl_top_reproduces_the_fpga_model_loop_over_two_periods() {
    let mut model = Model(core(), Vec::new());
    let want = run(&mut model);

    let t0 = Instant::now();
    let mut pl = Mpdcc(PlTopSim::new());
    let cfg = pl.config().expect("MPDCC_CONFIG");
    assert_eq!(cfg.explorers, regmap::MPDCC_EXPLORERS);
    pl.load_coeffs(core().coeffs()).expect("constants");
    let mut hil = Hil {
        pl,
        decisions: Vec::new(),
        cycles: Vec::new(),
    };
    let got = run(&mut hil);
    let secs = t0.elapsed().as_secs_f64();

    let n = model.1.len();
    assert_eq!(hil.decisions.len(), n);
    let first = hil.decisions.iter().zip(&model.1).position(|(a, b)| a != b);
    assert_eq!(first, None, "first differing decision");
    // Same decisions, same plant: the statistics are identical.
    assert_eq!(got, want);
    // Not a trivial loop: it switched, and searched often.
    let kinds = |k| model.1.iter().filter(|d| d.kind == k).count();
    use models::mpdcc::controller::DecisionKind::*;
    let (kept, opt, dl) = (kinds(Kept), kinds(Optimal), kinds(Deadlock));
    assert!(
        n > 1000 && opt > 50 && kept > 50,
        "{n} steps: {kept} kept, {opt} optimal"
    );
    for (i, &(core_cycles, model_cycles, _)) in hil.cycles.iter().enumerate() {
        assert_eq!(core_cycles, model_cycles, "decision {i}: core cycles");
    }
    let worst = hil.cycles.iter().map(|c| c.0).max().unwrap_or(0);
    let mean = hil.cycles.iter().map(|c| f64::from(c.0)).sum::<f64>() / n as f64;
    let bus = hil.cycles.iter().map(|c| c.2).sum::<u64>() as f64 / n as f64;
    println!(
        "mpdcc HIL: {n} decisions compared ({kept} kept, {opt} optimal, {dl} deadlock), 0 \
         differ; core cycles mean {mean:.1} worst {worst}; PL cycles per T_s with the bus \
         accesses {bus:.1}; f_sw {:.1} Hz, THD {:.2} %; {secs:.1} s",
        got.fsw_hz, got.thd_percent
    );
    assert_eq!(
        hil.pl.deadlocks().expect("MPDCC_DEADLOCKS") as usize,
        dl % 65536
    );
}
