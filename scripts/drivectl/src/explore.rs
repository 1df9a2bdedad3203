//! `drivectl explore mpdcc`: design exploration of the FPGA MPDCC model
//! (a research tool, not a test): for each current bound `delta_i`, the
//! reference run and its noise floor (the reference against itself with
//! `delta_i` scaled by 1 + 1e-4), then for each `L` and `p` the FPGA model's
//! decision mismatch against the reference (shadow run) and the f_sw / THD
//! of an FPGA-driven run relative to the reference. Uses the datapath
//! structures of `models`' `mpdcc-research` feature (docs/mpdcc-fpga.md).
use anyhow::{anyhow, Result};
use clap::{Args as ClapArgs, ValueEnum};
use models::mpdcc::closed_loop::{self, LoopConfig};
use models::mpdcc::mpdcc_fixed::{self, FpgaConfig, MpdccFixed, Structure, P_PAPER};
use models::mpdcc::mpdcc_ref::MpdccRef;
use models::mpdcc::params::DriveParams;

pub mod horizons;

/// Datapath structure of the explored core.
#[derive(Clone, Copy, Debug, ValueEnum)]
pub enum Which {
    /// The frozen core (what the Verilog implements).
    Core,
    /// The paper's structure (one chord, no accuracy options).
    Paper,
}

/// Arguments of `drivectl explore mpdcc`.
#[derive(ClapArgs, Debug)]
pub struct Args {
    /// Measured fundamental periods (after one warm-up period).
    #[arg(long, default_value_t = 40)]
    pub periods: u32,
    /// Current bounds `delta_i`, pu (comma-separated).
    #[arg(long, value_delimiter = ',', default_values_t = [0.06, 0.1, 0.15, 0.2])]
    pub delta_i: Vec<f64>,
    /// Extrapolation steps `L` (comma-separated powers of two).
    #[arg(long = "l", value_delimiter = ',', default_values_t = [8, 16, 32])]
    pub l: Vec<u32>,
    /// Correction factors `p` (comma-separated; default: 0, the paper's,
    /// 1 and X_m/(2D)).
    #[arg(long, value_delimiter = ',')]
    pub p: Vec<f64>,
    /// Datapath structure.
    #[arg(long, value_enum, default_value_t = Which::Core)]
    pub structure: Which,
    /// Interpolation nodes (1..=4), overriding the structure's.
    #[arg(long)]
    pub nodes: Option<u32>,
    /// Switching horizons (comma-separated: SE, SSE, SESE, SESESE; eSESE = SESE):
    /// sweep the f_sw-vs-THD trade-off of the horizons instead
    /// (docs/mpdcc-horizons.md).
    #[arg(long, value_delimiter = ',')]
    pub horizon: Vec<String>,
    /// Horizon sweep: output directory for the CSV and SVG files.
    #[arg(long, default_value = "target/explore-horizons")]
    pub out: std::path::PathBuf,
    /// Horizon sweep: the SE reference's THD at this `delta_i` (pu) is the
    /// equal-THD target.
    #[arg(long, default_value_t = 0.12)]
    pub target_delta_i: f64,
    /// Horizon sweep: nodes expanded beyond the first switching event at
    /// most (the branch-and-bound budget).
    #[arg(long, default_value_t = models::mpdcc::horizon_ref::DEFAULT_MAX_EXPANSIONS)]
    pub max_expansions: u32,
}

/// Runs the sweep and prints one line per design.
pub fn mpdcc(a: Args) -> Result<()> {
    if !a.horizon.is_empty() {
        let hs = horizons::parse_horizons(&a.horizon)?;
        if a.periods == 0 {
            return Err(anyhow!("--periods must be >= 1"));
        }
        if a.max_expansions > 512 {
            return Err(anyhow!("--max-expansions must be <= 512"));
        }
        let opt = models::mpdcc::horizon_ref::SearchOptions {
            max_expansions: a.max_expansions,
            ..Default::default()
        };
        return horizons::run(&hs, &a.delta_i, a.periods, a.target_delta_i, opt, &a.out);
    }
    let base = DriveParams::default();
    let cfg = LoopConfig {
        warmup_periods: 1,
        measure_periods: a.periods,
    };
    let pcs = if a.p.is_empty() {
        vec![0.0, P_PAPER, 1.0, mpdcc_fixed::p_taylor(&base.machine)]
    } else {
        a.p.clone()
    };
    let mut st = match a.structure {
        Which::Core => Structure::CORE,
        Which::Paper => Structure::PAPER,
    };
    if let Some(n) = a.nodes {
        st.nodes = n;
    }
    let run = |p: &DriveParams, ctrl: &mut dyn models::mpdcc::controller::Controller| {
        closed_loop::run(p, &cfg, ctrl, None, &mut |_| {}).map_err(|e| anyhow!("{e:?}"))
    };
    for &di in &a.delta_i {
        let mut p = base;
        p.controller.delta_i_pu = di;
        let rr = run(&p, &mut MpdccRef::new(&p).map_err(|e| anyhow!("{e:?}"))?)?;
        let mut pn = p;
        pn.controller.delta_i_pu = di * (1.0 + 1e-4);
        let rn = run(&pn, &mut MpdccRef::new(&pn).map_err(|e| anyhow!("{e:?}"))?)?;
        println!(
            "delta_i {di}: reference fsw {:.1} Hz THD {:.2} %; noise floor fsw {:+.1} % THD {:+.1} %",
            rr.fsw_hz,
            rr.thd_percent,
            100.0 * (rn.fsw_hz / rr.fsw_hz - 1.0),
            100.0 * (rn.thd_percent / rr.thd_percent - 1.0)
        );
        for &l in &a.l {
            for &pc in &pcs {
                let mut q = p;
                q.controller.extrapolation_steps = l;
                let fc = FpgaConfig::with_p(pc);
                let mk =
                    || MpdccFixed::research(&q, fc, st).map_err(|e| anyhow!("L {l} p {pc}: {e}"));
                let mut f = mk()?;
                let mut r = MpdccRef::new(&q).map_err(|e| anyhow!("{e:?}"))?;
                let sh = closed_loop::run(&q, &cfg, &mut r, Some(&mut f), &mut |_| {})
                    .map_err(|e| anyhow!("{e:?}"))?;
                let rf = run(&q, &mut mk()?)?;
                println!(
                    "  L {l:2} p {pc:.3}: mismatch {:.2} % ({} of {} switching), fsw {:+.1} %, THD {:+.1} %",
                    sh.mismatch_percent(),
                    sh.shadow_mismatches,
                    sh.switching_decisions,
                    100.0 * (rf.fsw_hz / rr.fsw_hz - 1.0),
                    100.0 * (rf.thd_percent / rr.thd_percent - 1.0),
                );
            }
        }
    }
    Ok(())
}
