//! `drivectl paper mpdcc`: reproduces paper 001's experiments (Fig. 5, the
//! FPGA-vs-reference decision mismatch, Table II) and `drivectl bench mpdcc`
//! (closed-loop decisions per second of both implementations).
//!
//! Definitions used by every number printed here (docs/mpdcc.md):
//! - switching frequency: device turn-ons per semiconductor per second
//!   (24 devices), THD: rms of `i - i_1` over rms of `i_1`, pooled over the
//!   three phases, over a whole number of periods ([`models::mpdcc::metrics`]);
//! - decision mismatch: share of all steps where the FPGA model, fed the
//!   reference's closed-loop state, returns another position than the
//!   reference (the reference drives the plant);
//! - fsw / THD differences: `|FPGA - reference| / reference` of the two
//!   independent closed-loop runs, in percent; the headline is the maximum
//!   over the sweep (the paper's "below 8 % and 2 %" covers its sweep).
//!
//! Layout (as `paper_mpdtc`): setup and runs in `paper_mpdcc/experiments.rs`
//! and `paper_mpdcc/runs.rs`, definitions in `paper_mpdcc/metrics.rs`, plots
//! in `paper_mpdcc/plots.rs`, the mismatch anatomy in
//! `paper_mpdcc/anatomy.rs`; write-up: `docs/mpdcc.md`.
use anyhow::{anyhow, Context, Result};
use models::mpdcc::closed_loop::LoopConfig;
use models::mpdcc::controller::Controller;
use models::mpdcc::mpdcc_ref::MpdccRef;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

mod anatomy;
mod experiments;
mod metrics;
mod plots;
mod runs;

use experiments::{Report, Trace};
pub use runs::load_params;
use runs::{fpga_for, run_loop};

#[derive(clap::Args)]
pub struct Args {
    /// Print one JSON object instead of tables.
    #[arg(long)]
    pub json: bool,
    /// Directory for CSV files and plots.
    #[arg(long)]
    pub out: Option<std::path::PathBuf>,
    /// Drive parameter file (TOML, layout of examples/mpdcc-machine.toml).
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Measurement window per closed-loop run, fundamental periods (after the warm-up).
    #[arg(long, default_value_t = 100, value_parser = clap::value_parser!(u32).range(1..=500))]
    pub periods: u32,
}

#[derive(clap::Args)]
pub struct BenchArgs {
    /// Simulated fundamental periods per implementation.
    #[arg(long, default_value_t = 10, value_parser = clap::value_parser!(u32).range(1..=500))]
    pub periods: u32,
    /// Drive parameter file (TOML).
    #[arg(long)]
    pub params: Option<PathBuf>,
    /// Print one JSON object.
    #[arg(long)]
    pub json: bool,
}

pub fn run(a: Args) -> Result<()> {
    if let Some(d) = &a.out {
        std::fs::create_dir_all(d).with_context(|| format!("creating {}", d.display()))?;
    }
    let (report, traces) = experiments::all(&a)?;
    if let Some(d) = &a.out {
        write_csv(d, &report, &traces)?;
        plots::all(d, &report, &traces)?;
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print!("{}", markdown(&report));
    }
    Ok(())
}

/// The tables printed without `--json`.
pub fn markdown(r: &Report) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "Paper 001, Fig. 5: switching frequency per semiconductor and stator current THD vs delta_i\n\
         ({} periods per run at rated current and frequency, T_s = {} us; the paper's Fig. 5 values are only plotted, not tabulated)\n",
        r.measure_periods,
        r.params.controller.ts_s * 1e6
    );
    let _ = writeln!(o, "| delta_i (pu) | fsw ref (Hz) | fsw FPGA (Hz) | diff (%) | THD ref (%) | THD FPGA (%) | diff (%) | decision mismatch (%) |");
    let _ = writeln!(o, "|---|---|---|---|---|---|---|---|");
    for f in &r.fig5 {
        let _ = writeln!(
            o,
            "| {:.2} | {:.1} | {:.1} | {:.1} | {:.2} | {:.2} | {:.1} | {:.2} |",
            f.delta_i_pu,
            f.reference.fsw_hz,
            f.fpga.fsw_hz,
            f.fsw_diff_percent,
            f.reference.thd_percent,
            f.fpga.thd_percent,
            f.thd_diff_percent,
            f.decision_mismatch_percent
        );
    }
    let m = &r.mismatch;
    let _ = writeln!(
        o,
        "\nFPGA model vs idealized reference (paper Sec. VII-B)\n"
    );
    let _ = writeln!(o, "| quantity | paper | ours |");
    let _ = writeln!(o, "|---|---|---|");
    let _ = writeln!(
        o,
        "| decision mismatch, % of steps | {:.1} | {:.2} |",
        m.paper_decision_mismatch_percent, m.decision_mismatch_percent
    );
    let _ = writeln!(
        o,
        "| decision mismatch, % of switching steps | - | {:.1} |",
        m.decision_mismatch_switching_percent
    );
    let _ = writeln!(
        o,
        "| max fsw difference over sweep, % | < {:.0} | {:.1} |",
        m.paper_fsw_diff_max_percent, m.fsw_diff_percent
    );
    let _ = writeln!(
        o,
        "| max THD difference over sweep, % (relative) | < {:.0} | {:.1} |",
        m.paper_thd_diff_max_percent, m.thd_diff_percent
    );
    let _ = writeln!(
        o,
        "| max THD difference over sweep, percentage points | - | {:.2} |",
        m.thd_diff_points
    );
    let _ = writeln!(
        o,
        "| mean fsw / THD difference, % | - | {:.1} / {:.1} |",
        m.fsw_diff_mean_percent, m.thd_diff_mean_percent
    );
    let _ = writeln!(
        o,
        "| mismatches where only one kept s(k-1), % of mismatches | - | {:.1} |",
        m.mismatch_lazy_share_percent
    );
    let _ = writeln!(
        o,
        "\nSame experiment vs the extrapolation point L (FPGA model), fewer periods per run\n"
    );
    let _ = writeln!(o, "| L (steps) | periods | decision mismatch (%) | max fsw diff (%) | max THD diff (%) | mean fsw diff (%) | mean THD diff (%) |");
    let _ = writeln!(o, "|---|---|---|---|---|---|---|");
    for l in &r.extrapolation_sweep {
        let m = &l.mismatch;
        let _ = writeln!(
            o,
            "| {} | {} | {:.2} | {:.1} | {:.1} | {:.1} | {:.1} |",
            l.extrapolation_steps,
            l.measure_periods,
            m.decision_mismatch_percent,
            m.fsw_diff_percent,
            m.thd_diff_percent,
            m.fsw_diff_mean_percent,
            m.thd_diff_mean_percent
        );
    }
    let _ = writeln!(o, "\nAnatomy of the mismatch (reference drives, FPGA model fed the same state; warm-up included)\n");
    let _ = writeln!(o, "| delta_i (pu) | mismatch (%) | only FPGA switched (% of mm) | only ref switched (% of mm) | both, differently (% of mm) | FPGA L* exact (%) | within 1 step (%) | over-predicted (%) | mean abs L* error (steps) | J_ref(FPGA choice)/J_ref(ref choice) |");
    let _ = writeln!(o, "|---|---|---|---|---|---|---|---|---|---|");
    for a in &r.mismatch_anatomy {
        let _ = writeln!(
            o,
            "| {:.2} | {:.2} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.1} | {:.2} | {:.2} |",
            a.delta_i_pu,
            a.decision_mismatch_percent,
            a.only_fpga_switched_percent_of_mismatches,
            a.only_reference_switched_percent_of_mismatches,
            a.both_switched_differently_percent_of_mismatches,
            a.l_star_prediction_exact_percent,
            a.l_star_prediction_within_one_step_percent,
            a.l_star_prediction_over_percent,
            a.l_star_prediction_mean_abs_error_steps,
            a.cost_ratio_when_different
        );
    }
    let _ = writeln!(o, "\nReference with the reduced 64-candidate set (stay, partner, one up, one down per phase) vs the full set\n");
    let _ = writeln!(
        o,
        "| delta_i (pu) | fsw (Hz) | THD (%) | deadlocks | fsw vs full (%) | THD vs full (%) |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|");
    for x in &r.reference_reduced_candidates {
        let _ = writeln!(
            o,
            "| {:.2} | {:.1} | {:.2} | {} | {:+.1} | {:+.1} |",
            x.delta_i_pu,
            x.fsw_hz,
            x.thd_percent,
            x.deadlocks,
            x.fsw_diff_vs_full_percent,
            x.thd_diff_vs_full_percent
        );
    }
    let _ = writeln!(o, "\nTable II: worst-case clock cycles per decision\n");
    let _ = writeln!(
        o,
        "| explorers | paper Table II | paper 47 + 2176/n | ours: paper structure, 64 candidates | ours: paper structure, 216 candidates | ours: default core, 216 candidates (model_cycles) |"
    );
    let _ = writeln!(o, "|---|---|---|---|---|---|");
    for c in &r.cycles {
        let _ = writeln!(
            o,
            "| {} | {} | {:.1} | {} | {} | {} |",
            c.explorers,
            c.paper_cycles,
            c.paper_formula_cycles,
            c.model_cycles_64,
            c.model_cycles_paper_core,
            c.model_cycles
        );
    }
    let _ = writeln!(o, "\nruntime {:.1} s", r.runtime_s);
    o
}

/// Writes `fig5.csv`, `table2_cycles.csv`, `mismatch.csv`, `trace_reference.csv`.
fn write_csv(dir: &Path, r: &Report, traces: &[Trace]) -> Result<()> {
    let w = |name: &str, text: String| -> Result<()> {
        let f = dir.join(name);
        std::fs::write(&f, text).with_context(|| format!("writing {}", f.display()))
    };
    let mut csv = String::from("delta_i_pu,ref_fsw_hz,ref_thd_percent,fpga_fsw_hz,fpga_thd_percent,decision_mismatch_percent,ref_deadlocks,fpga_deadlocks\n");
    for f in &r.fig5 {
        let _ = writeln!(
            csv,
            "{},{:.4},{:.4},{:.4},{:.4},{:.4},{},{}",
            f.delta_i_pu,
            f.reference.fsw_hz,
            f.reference.thd_percent,
            f.fpga.fsw_hz,
            f.fpga.thd_percent,
            f.decision_mismatch_percent,
            f.reference.deadlocks,
            f.fpga.deadlocks
        );
    }
    w("fig5.csv", csv)?;
    let mut csv = String::from(
        "explorers,paper_cycles,paper_formula_cycles,model_cycles_64,model_cycles_paper_core,model_cycles\n",
    );
    for c in &r.cycles {
        let _ = writeln!(
            csv,
            "{},{},{:.2},{},{},{}",
            c.explorers,
            c.paper_cycles,
            c.paper_formula_cycles,
            c.model_cycles_64,
            c.model_cycles_paper_core,
            c.model_cycles
        );
    }
    w("table2_cycles.csv", csv)?;
    let m = &r.mismatch;
    w(
        "mismatch.csv",
        format!(
            "quantity,paper,ours\ndecision_mismatch_percent,{},{:.4}\nfsw_diff_percent,{},{:.4}\nthd_diff_percent,{},{:.4}\n",
            m.paper_decision_mismatch_percent,
            m.decision_mismatch_percent,
            m.paper_fsw_diff_max_percent,
            m.fsw_diff_percent,
            m.paper_thd_diff_max_percent,
            m.thd_diff_percent
        ),
    )?;
    for (_, tr) in traces {
        let t0 = tr.first().map(|s| s.t_s).unwrap_or(0.0);
        let mut csv = String::from("t_ms,i_a_pu,i_b_pu,i_c_pu,i_ref_a_pu,v_n_pu,v_ph_a_pu,v_ph_b_pu,v_ph_c_pu,s_a,s_b,s_c\n");
        for s in tr {
            let _ = writeln!(
                csv,
                "{:.4},{:.5},{:.5},{:.5},{:.5},{:.5},{:.5},{:.5},{:.5},{},{},{}",
                (s.t_s - t0) * 1e3,
                s.i_abc_pu[0],
                s.i_abc_pu[1],
                s.i_abc_pu[2],
                s.i_ref_abc_pu[0],
                s.v_n_pu,
                s.v_ph_pu[0],
                s.v_ph_pu[1],
                s.v_ph_pu[2],
                s.s[0],
                s.s[1],
                s.s[2]
            );
        }
        w("trace_reference.csv", csv)?;
    }
    Ok(())
}

#[derive(Serialize)]
struct BenchRow {
    implementation: &'static str,
    steps: u64,
    switching_decisions: u64,
    wall_s: f64,
    decisions_per_s: f64,
    switching_decisions_per_s: f64,
}

pub fn bench(a: BenchArgs) -> Result<()> {
    let p = load_params(a.params.as_deref())?;
    let cfg = LoopConfig {
        warmup_periods: 0,
        measure_periods: a.periods,
    };
    let mut rows = Vec::new();
    let mut reference = MpdccRef::new(&p).map_err(|e| anyhow!("{e}"))?;
    let mut fpga = fpga_for(&p)?;
    let ctrls: [&mut dyn Controller; 2] = [&mut reference, &mut fpga];
    for c in ctrls {
        let name = c.name();
        let t = Instant::now();
        let r = run_loop(&p, &cfg, c, None, &mut |_| {})?;
        let wall = t.elapsed().as_secs_f64();
        rows.push(BenchRow {
            implementation: name,
            steps: r.steps,
            switching_decisions: r.switching_decisions,
            wall_s: wall,
            decisions_per_s: r.steps as f64 / wall,
            switching_decisions_per_s: r.switching_decisions as f64 / wall,
        });
    }
    if a.json {
        println!("{}", serde_json::to_string_pretty(&rows)?);
    } else {
        println!(
            "MPDCC closed loop ({} periods, plant included), delta_i = {} pu",
            a.periods, p.controller.delta_i_pu
        );
        println!("| implementation | steps | switching decisions | wall (s) | decisions/s | switching decisions/s |");
        println!("|---|---|---|---|---|---|");
        for r in &rows {
            println!(
                "| {} | {} | {} | {:.3} | {:.0} | {:.0} |",
                r.implementation,
                r.steps,
                r.switching_decisions,
                r.wall_s,
                r.decisions_per_s,
                r.switching_decisions_per_s
            );
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::experiments::table2_for_params;
    use super::*;
    use models::mpdcc::cycles;
    use models::mpdcc::params::DriveParams;

    /// The example parameter file equals the built-in defaults (so the docs,
    /// the file and the code cannot drift apart).
    #[test]
    fn example_toml_equals_defaults() {
        let f = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/mpdcc-machine.toml");
        let p = load_params(Some(&f)).unwrap();
        assert_eq!(p, DriveParams::default());
    }

    /// `--json` carries the documented keys (short windows).
    #[test]
    fn json_report_has_the_documented_keys() {
        let a = Args {
            json: true,
            out: None,
            params: None,
            periods: 1,
        };
        let (r, traces) = experiments::all(&a).unwrap();
        let v = serde_json::to_value(&r).unwrap();
        let fig5 = v["fig5"].as_array().unwrap();
        assert!(fig5.len() >= 6);
        for f in fig5 {
            assert!(f["delta_i_pu"].is_f64());
            for imp in ["reference", "fpga"] {
                assert!(f[imp]["fsw_hz"].as_f64().unwrap() > 0.0);
                assert!(f[imp]["thd_percent"].as_f64().unwrap() > 0.0);
            }
        }
        for k in [
            "decision_mismatch_percent",
            "fsw_diff_percent",
            "thd_diff_percent",
        ] {
            assert!(v["mismatch"][k].is_f64(), "{k}");
        }
        let c = v["cycles"].as_array().unwrap();
        assert_eq!(c.len(), 6);
        for (n, row) in c.iter().enumerate() {
            assert_eq!(row["explorers"].as_u64().unwrap(), n as u64 + 1);
            assert!(row["paper_cycles"].as_u64().unwrap() > 0);
            assert!(row["model_cycles"].as_u64().unwrap() > 0);
        }
        assert_eq!(v["cycles"][0]["paper_cycles"].as_u64(), Some(2223));
        assert_eq!(traces.len(), 1);
    }

    /// Table II follows the parameter file's extrapolation point: with
    /// `L = 16` the default core's lanes search pieces of 16, 16, 32 and 64
    /// steps (5 + 5 + 6 + 7 = 23 cycles worst case, not 21 as at `L = 8`).
    #[test]
    fn table2_uses_the_files_extrapolation_point() {
        let mut p = DriveParams::default();
        let t8 = table2_for_params(&p);
        p.controller.extrapolation_steps = 16;
        let t16 = table2_for_params(&p);
        assert_eq!(cycles::worst_lane_cycles(4, 4, 7), 23);
        assert_eq!(t16[0].model_per_candidate, t8[0].model_per_candidate + 2);
        assert_eq!(t16, cycles::table2_for(7, 4).to_vec());
    }

    #[test]
    fn bad_toml_is_rejected_with_reason() {
        let dir = std::env::temp_dir().join(format!("mpdcc-toml-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let f = dir.join("bad.toml");
        std::fs::write(&f, "[machine]\nr_s_pu = -1.0\n").unwrap();
        let e = load_params(Some(&f)).unwrap_err().to_string();
        assert!(e.contains("r_s_pu") && e.contains("bad.toml"), "{e}");
        std::fs::write(&f, "[machine]\nr_s = 0.01\n").unwrap();
        assert!(load_params(Some(&f)).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
