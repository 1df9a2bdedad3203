//! `drivectl explore mpdcc --horizon ...`: the switching-horizon trade-off
//! (docs/mpdcc-horizons.md). For each horizon and current bound `delta_i`:
//! the horizon reference drives the loop with the 16-bit model as shadow
//! (decision mismatch), then the 16-bit model drives its own loop; f_sw per
//! semiconductor and current THD of both, candidate extensions per search
//! (mean, worst) and the core cycles per decision from the cycle model for
//! N = 1, 2, 4 explorers. Writes `horizons.csv`, `horizons_equal_thd.csv`,
//! `horizons_cycles.csv` and `horizons_fsw_thd.svg` to `--out`.
use crate::plot;
use anyhow::{anyhow, bail, Context, Result};
use models::mpdcc::closed_loop::{self, LoopConfig};
use models::mpdcc::horizon_fixed::{self, HorizonFixed, ADVANCE_CYCLES};
use models::mpdcc::horizon_ref::{Horizon, HorizonRef, SearchOptions, STATS_EXPLORERS};
use models::mpdcc::mpdcc_fixed::FpgaConfig;
use models::mpdcc::params::DriveParams;
use std::fmt::Write as _;
use std::path::Path;

/// Cycle budget of one decision: 25 us at 100 MHz.
pub const BUDGET_CYCLES: u32 = 2500;

/// One (horizon, delta_i) point of the sweep.
#[derive(Debug, Clone)]
pub struct Point {
    /// Horizon.
    pub horizon: Horizon,
    /// Current bound, pu.
    pub delta_i: f64,
    /// Reference-driven run: f_sw (Hz), THD (%).
    pub ref_fsw: f64,
    /// Reference THD, %.
    pub ref_thd: f64,
    /// FPGA-driven run: f_sw, Hz.
    pub fpga_fsw: f64,
    /// FPGA THD, %.
    pub fpga_thd: f64,
    /// Decision mismatch of the shadow run, % of steps.
    pub mismatch: f64,
    /// Mean / worst candidate extensions per search (reference, FPGA).
    pub cand: [(f64, u32); 2],
    /// Mean / worst core cycles per decision for N = 1, 2, 4 (FPGA-driven run).
    pub cycles: [(f64, u32); 3],
    /// Searches stopped by the expansion budget / fallbacks to SE, % of searches (FPGA run).
    pub budget_hits: f64,
    /// Fallbacks to SE, % of searches (FPGA run).
    pub fallbacks: f64,
    /// Searches whose position differs from SE's on the same state, % (reference run).
    pub differs: f64,
    /// Steps outside a bound (FPGA-driven run).
    pub outside: u64,
}

/// Parses the `--horizon` list.
pub fn parse_horizons(v: &[String]) -> Result<Vec<Horizon>> {
    v.iter()
        .map(|s| {
            Horizon::parse(s).ok_or_else(|| {
                anyhow!("unknown horizon `{s}` (implemented: SE, SSE, SESE, SESESE; eSESE = SESE)")
            })
        })
        .collect()
}

/// Runs one point.
pub fn run_point(
    base: &DriveParams,
    h: Horizon,
    delta_i: f64,
    periods: u32,
    opt: SearchOptions,
) -> Result<Point> {
    let mut p = *base;
    p.controller.delta_i_pu = delta_i;
    p.validate()
        .map_err(|e| anyhow!("delta_i {delta_i}: {e}"))?;
    let cfg = LoopConfig {
        warmup_periods: 1,
        measure_periods: periods,
    };
    let fc = FpgaConfig::core(&p.machine);
    let mk_f = || HorizonFixed::new(&p, fc, h, opt).map_err(|e| anyhow!("{e}"));
    let mut r = HorizonRef::with_options(&p, h, opt).map_err(|e| anyhow!("{e:?}"))?;
    let mut shadow = mk_f()?;
    let rr = closed_loop::run(&p, &cfg, &mut r, Some(&mut shadow), &mut |_| {})
        .map_err(|e| anyhow!("{e:?}"))?;
    let mut f = mk_f()?;
    let rf = closed_loop::run(&p, &cfg, &mut f, None, &mut |_| {}).map_err(|e| anyhow!("{e:?}"))?;
    let rs = r.stats();
    let fs = f.stats();
    let pct = |a: u64| 100.0 * a as f64 / fs.searches.max(1) as f64;
    Ok(Point {
        horizon: h,
        delta_i,
        ref_fsw: rr.fsw_hz,
        ref_thd: rr.thd_percent,
        fpga_fsw: rf.fsw_hz,
        fpga_thd: rf.thd_percent,
        mismatch: rr.mismatch_percent(),
        cand: [
            (rs.mean_evaluations(), rs.max_evaluations),
            (fs.mean_evaluations(), fs.max_evaluations),
        ],
        cycles: core::array::from_fn(|i| (fs.mean_cycles(i), fs.max_cycles[i])),
        budget_hits: pct(fs.budget_hits),
        fallbacks: pct(fs.fallbacks),
        differs: 100.0 * rs.differs_from_se as f64 / rs.searches.max(1) as f64,
        outside: rf.steps_outside_bounds,
    })
}

/// f_sw at `thd` by linear interpolation of a (THD, f_sw) curve; `None`
/// outside the measured THD range.
pub fn fsw_at_thd(curve: &[(f64, f64)], thd: f64) -> Option<f64> {
    let mut c: Vec<(f64, f64)> = curve.to_vec();
    c.sort_by(|a, b| a.0.total_cmp(&b.0));
    c.windows(2).find_map(|w| {
        let ((t0, f0), (t1, f1)) = (w[0], w[1]);
        if t0 <= thd && thd <= t1 && t1 > t0 {
            Some(f0 + (f1 - f0) * (thd - t0) / (t1 - t0))
        } else if t0 == thd {
            Some(f0)
        } else {
            None
        }
    })
}

/// The sweep, the tables on stdout and the files in `out`.
pub fn run(
    horizons: &[Horizon],
    delta_i: &[f64],
    periods: u32,
    target_delta_i: f64,
    opt: SearchOptions,
    out: &Path,
) -> Result<()> {
    if horizons.is_empty() || delta_i.is_empty() {
        bail!("need at least one horizon and one delta_i");
    }
    let base = DriveParams::default();
    std::fs::create_dir_all(out).with_context(|| format!("creating {}", out.display()))?;
    let mut pts = Vec::new();
    println!("| horizon | delta_i (pu) | f_sw ref (Hz) | THD ref (%) | f_sw FPGA (Hz) | THD FPGA (%) | mismatch (%) | candidates ref mean / max | candidates FPGA mean / max | cycles N=1 mean / max | N=2 | N=4 | budget hits (%) | SE fallbacks (%) | differs from SE (%) | FPGA steps outside |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for &h in horizons {
        for &di in delta_i {
            let pt = run_point(&base, h, di, periods, opt)?;
            println!(
                "| {} | {:.3} | {:.1} | {:.2} | {:.1} | {:.2} | {:.2} | {:.0} / {} | {:.0} / {} | {:.0} / {} | {:.0} / {} | {:.0} / {} | {:.1} | {:.1} | {:.1} | {} |",
                h.name(),
                di,
                pt.ref_fsw,
                pt.ref_thd,
                pt.fpga_fsw,
                pt.fpga_thd,
                pt.mismatch,
                pt.cand[0].0,
                pt.cand[0].1,
                pt.cand[1].0,
                pt.cand[1].1,
                pt.cycles[0].0,
                pt.cycles[0].1,
                pt.cycles[1].0,
                pt.cycles[1].1,
                pt.cycles[2].0,
                pt.cycles[2].1,
                pt.budget_hits,
                pt.fallbacks,
                pt.differs,
                pt.outside
            );
            pts.push(pt);
        }
    }
    let mut csv = String::from("horizon,delta_i_pu,ref_fsw_hz,ref_thd_percent,fpga_fsw_hz,fpga_thd_percent,mismatch_percent,ref_candidates_mean,ref_candidates_max,fpga_candidates_mean,fpga_candidates_max,cycles_mean_n1,cycles_max_n1,cycles_mean_n2,cycles_max_n2,cycles_mean_n4,cycles_max_n4,budget_hits_percent,se_fallbacks_percent,differs_from_se_percent,fpga_steps_outside\n");
    for p in &pts {
        let _ = writeln!(
            csv,
            "{},{},{:.3},{:.4},{:.3},{:.4},{:.4},{:.2},{},{:.2},{},{:.2},{},{:.2},{},{:.2},{},{:.3},{:.3},{:.3},{}",
            p.horizon.name(),
            p.delta_i,
            p.ref_fsw,
            p.ref_thd,
            p.fpga_fsw,
            p.fpga_thd,
            p.mismatch,
            p.cand[0].0,
            p.cand[0].1,
            p.cand[1].0,
            p.cand[1].1,
            p.cycles[0].0,
            p.cycles[0].1,
            p.cycles[1].0,
            p.cycles[1].1,
            p.cycles[2].0,
            p.cycles[2].1,
            p.budget_hits,
            p.fallbacks,
            p.differs,
            p.outside
        );
    }
    write(out, "horizons.csv", csv)?;
    // Equal THD: the SE reference's THD at the paper's operating point.
    let se = pts
        .iter()
        .find(|p| p.horizon == Horizon::Se && (p.delta_i - target_delta_i).abs() < 1e-9);
    let curve = |h: Horizon, fpga: bool| -> Vec<(f64, f64)> {
        pts.iter()
            .filter(|p| p.horizon == h)
            .map(|p| {
                if fpga {
                    (p.fpga_thd, p.fpga_fsw)
                } else {
                    (p.ref_thd, p.ref_fsw)
                }
            })
            .collect()
    };
    let mut eq = String::from("horizon,target_thd_percent,ref_fsw_hz,ref_reduction_vs_se_percent,fpga_fsw_hz,fpga_reduction_vs_se_percent\n");
    if let Some(se) = se {
        let target = se.ref_thd;
        println!(
            "\nAt equal THD = {target:.2} % (SE reference at delta_i = {target_delta_i} pu):\n"
        );
        println!("| horizon | f_sw ref (Hz) | vs SE ref (%) | f_sw FPGA (Hz) | vs SE FPGA (%) |");
        println!("|---|---|---|---|---|");
        let se_r = fsw_at_thd(&curve(Horizon::Se, false), target);
        let se_f = fsw_at_thd(&curve(Horizon::Se, true), target);
        for &h in horizons {
            let r = fsw_at_thd(&curve(h, false), target);
            let f = fsw_at_thd(&curve(h, true), target);
            let red = |a: Option<f64>, b: Option<f64>| match (a, b) {
                (Some(a), Some(b)) => format!("{:+.1}", 100.0 * (a / b - 1.0)),
                _ => "-".into(),
            };
            let fmt = |a: Option<f64>| a.map_or("-".into(), |v| format!("{v:.1}"));
            println!(
                "| {} | {} | {} | {} | {} |",
                h.name(),
                fmt(r),
                red(r, se_r),
                fmt(f),
                red(f, se_f)
            );
            let _ = writeln!(
                eq,
                "{},{target:.4},{},{},{},{}",
                h.name(),
                fmt(r),
                red(r, se_r),
                fmt(f),
                red(f, se_f)
            );
        }
    } else {
        println!("\n(no SE point at delta_i = {target_delta_i}: no equal-THD table)");
    }
    write(out, "horizons_equal_thd.csv", eq)?;
    // Cycles against the budget.
    println!("\nCore cycles per decision vs the {BUDGET_CYCLES}-cycle budget (advance {ADVANCE_CYCLES} cycles, budget of {} expansions):\n", opt.max_expansions);
    println!("| horizon | N | worst case (model, full budget) | worst seen | mean seen | fits |");
    println!("|---|---|---|---|---|---|");
    let mut cyc =
        String::from("horizon,explorers,worst_case_model,worst_seen,mean_seen,fits_budget\n");
    for &h in horizons {
        for (i, &n) in STATS_EXPLORERS.iter().enumerate() {
            let wc = horizon_fixed::worst_case_cycles(h, n, opt.max_expansions);
            let seen = pts
                .iter()
                .filter(|p| p.horizon == h)
                .map(|p| p.cycles[i].1)
                .max()
                .unwrap_or(0);
            let mean = pts
                .iter()
                .filter(|p| p.horizon == h)
                .map(|p| p.cycles[i].0)
                .fold(0.0, f64::max);
            let fits = if wc <= BUDGET_CYCLES { "yes" } else { "no" };
            println!(
                "| {} | {n} | {wc} | {seen} | {mean:.0} | {fits} |",
                h.name()
            );
            let _ = writeln!(cyc, "{},{n},{wc},{seen},{mean:.1},{fits}", h.name());
        }
    }
    write(out, "horizons_cycles.csv", cyc)?;
    // Trade-off plot.
    const COLORS: [&str; 4] = ["#1f77b4", "#2ca02c", "#d62728", "#9467bd"];
    let mut series = Vec::new();
    for (i, &h) in horizons.iter().enumerate() {
        for fpga in [false, true] {
            let mut c = curve(h, fpga);
            c.sort_by(|a, b| a.0.total_cmp(&b.0));
            series.push(plot::Series {
                name: format!(
                    "{} {}",
                    h.name(),
                    if fpga {
                        "FPGA (16 bit)"
                    } else {
                        "reference (f64)"
                    }
                ),
                points: c,
                color: COLORS[i % COLORS.len()],
                dashed: !fpga,
                markers: true,
            });
        }
    }
    write(
        out,
        "horizons_fsw_thd.svg",
        plot::line_plot(
            "MPDCC switching horizons: f_sw per semiconductor vs current THD",
            "current THD (%)",
            "f_sw (Hz)",
            &series,
            true,
        )?,
    )?;
    println!("\nwrote {}/horizons.csv, horizons_equal_thd.csv, horizons_cycles.csv, horizons_fsw_thd.svg", out.display());
    Ok(())
}

fn write(dir: &Path, name: &str, text: String) -> Result<()> {
    let f = dir.join(name);
    std::fs::write(&f, text).with_context(|| format!("writing {}", f.display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use models::mpdcc::cycles;

    #[test]
    fn interpolation_at_equal_thd() {
        let c = [(4.0, 200.0), (8.0, 120.0), (6.0, 150.0)];
        assert_eq!(fsw_at_thd(&c, 7.0), Some(135.0));
        assert_eq!(fsw_at_thd(&c, 4.0), Some(200.0));
        assert_eq!(fsw_at_thd(&c, 9.0), None);
        assert_eq!(fsw_at_thd(&c, 3.0), None);
    }

    #[test]
    fn horizon_names_are_checked() {
        let v = parse_horizons(&["SE".into(), "sese".into(), "eSESE".into()]).unwrap();
        assert_eq!(v, vec![Horizon::Se, Horizon::Sese, Horizon::Sese]);
        assert!(parse_horizons(&["SEX".into()]).is_err());
    }

    /// A short point runs end to end with bounded work and the SE point's
    /// FPGA cycles are the frozen core's.
    #[test]
    fn short_point_runs() {
        let p = run_point(
            &DriveParams::default(),
            Horizon::Sese,
            0.12,
            1,
            SearchOptions::default(),
        )
        .unwrap();
        assert!(p.ref_fsw > 0.0 && p.fpga_thd > 0.0);
        assert!(p.cand[1].1 <= 216 * (1 + SearchOptions::default().max_expansions));
        let se = run_point(
            &DriveParams::default(),
            Horizon::Se,
            0.12,
            1,
            SearchOptions::default(),
        )
        .unwrap();
        assert!(se.cycles[1].1 <= cycles::pipelined_core_cycles(2, 216));
    }
}
