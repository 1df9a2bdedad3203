//! SVG plots of the paper-001 experiments (`crate::plot`, plotters).
use super::experiments::{Report, Trace};
use crate::plot::{line_plot, Series};
use anyhow::{Context, Result};
use models::mpdcc::closed_loop::TraceSample;
use std::path::Path;

/// Writes `fig5_fsw.svg`, `fig5_thd.svg`, `table2_cycles.svg` and, for the
/// kept trace, `currents_reference.svg` and `capacitors_reference.svg`.
pub fn all(dir: &Path, r: &Report, traces: &[Trace]) -> Result<()> {
    let w = |name: &str, text: String| -> Result<()> {
        let f = dir.join(name);
        std::fs::write(&f, text).with_context(|| format!("writing {}", f.display()))
    };
    let series = |name: &str, pts: Vec<(f64, f64)>, color: &'static str, dashed: bool| Series {
        name: name.into(),
        points: pts,
        color,
        dashed,
        markers: true,
    };
    let fsw = vec![
        series(
            "reference (f64)",
            r.fig5
                .iter()
                .map(|f| (f.delta_i_pu, f.reference.fsw_hz))
                .collect(),
            "#1f77b4",
            true,
        ),
        series(
            "FPGA model (16 bit)",
            r.fig5
                .iter()
                .map(|f| (f.delta_i_pu, f.fpga.fsw_hz))
                .collect(),
            "#d62728",
            false,
        ),
    ];
    w(
        "fig5_fsw.svg",
        line_plot(
            "Fig. 5: switching frequency per semiconductor",
            "current bound delta_i (pu)",
            "f_sw (Hz)",
            &fsw,
            true,
        )?,
    )?;
    let thd = vec![
        series(
            "reference (f64)",
            r.fig5
                .iter()
                .map(|f| (f.delta_i_pu, f.reference.thd_percent))
                .collect(),
            "#1f77b4",
            true,
        ),
        series(
            "FPGA model (16 bit)",
            r.fig5
                .iter()
                .map(|f| (f.delta_i_pu, f.fpga.thd_percent))
                .collect(),
            "#d62728",
            false,
        ),
    ];
    w(
        "fig5_thd.svg",
        line_plot(
            "Fig. 5: stator current THD",
            "current bound delta_i (pu)",
            "THD (%)",
            &thd,
            true,
        )?,
    )?;
    let cyc = vec![
        series(
            "paper Table II",
            r.cycles
                .iter()
                .map(|c| (c.explorers as f64, c.paper_cycles as f64))
                .collect(),
            "#1f77b4",
            true,
        ),
        series(
            "ours, paper structure, 64 cand.",
            r.cycles
                .iter()
                .map(|c| (c.explorers as f64, c.model_cycles_64 as f64))
                .collect(),
            "#2ca02c",
            false,
        ),
        series(
            "ours, default core, 216 cand.",
            r.cycles
                .iter()
                .map(|c| (c.explorers as f64, c.model_cycles as f64))
                .collect(),
            "#d62728",
            false,
        ),
    ];
    w(
        "table2_cycles.svg",
        line_plot(
            "Table II: worst-case cycles per decision",
            "explorer units n",
            "clock cycles",
            &cyc,
            true,
        )?,
    )?;
    for (di, tr) in traces {
        let t0 = tr.first().map(|s| s.t_s).unwrap_or(0.0);
        let ms = |s: &TraceSample| (s.t_s - t0) * 1e3;
        let colors = ["#1f77b4", "#2ca02c", "#d62728"];
        let mut cur: Vec<Series> = (0..3)
            .map(|x| Series {
                name: format!("i_{}", ["a", "b", "c"][x]),
                points: tr.iter().map(|s| (ms(s), s.i_abc_pu[x])).collect(),
                color: colors[x],
                dashed: false,
                markers: false,
            })
            .collect();
        cur.push(Series {
            name: "i*_a".into(),
            points: tr.iter().map(|s| (ms(s), s.i_ref_abc_pu[0])).collect(),
            color: "#555555",
            dashed: true,
            markers: false,
        });
        let title = format!("Stator currents, reference MPDCC, delta_i = {di} pu (one period)");
        w(
            "currents_reference.svg",
            line_plot(&title, "t (ms)", "i (pu)", &cur, false)?,
        )?;
        let mut caps: Vec<Series> = (0..3)
            .map(|x| Series {
                name: format!("v_ph,{} - V_dc/4", ["a", "b", "c"][x]),
                points: tr
                    .iter()
                    .map(|s| (ms(s), s.v_ph_pu[x] - r.params.inverter.v_ph_ref_pu()))
                    .collect(),
                color: colors[x],
                dashed: false,
                markers: false,
            })
            .collect();
        caps.push(Series {
            name: "v_n".into(),
            points: tr.iter().map(|s| (ms(s), s.v_n_pu)).collect(),
            color: "#555555",
            dashed: true,
            markers: false,
        });
        let c = &r.params.controller;
        let title = format!(
            "Neutral point and phase capacitor voltages (bounds +-{} / +-{} pu)",
            c.v_n_bound_pu, c.v_ph_bound_pu
        );
        w(
            "capacitors_reference.svg",
            line_plot(&title, "t (ms)", "v (pu)", &caps, false)?,
        )?;
    }
    Ok(())
}
