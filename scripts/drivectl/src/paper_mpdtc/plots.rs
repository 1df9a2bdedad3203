//! SVG plots of the experiments (plotters, svg backend).

use super::experiments::Results;
use super::runs::Trace;
use anyhow::{anyhow, Result};
use plotters::prelude::*;
use std::path::Path;

fn err<E: std::fmt::Display>(e: E) -> anyhow::Error {
    anyhow!("plot: {e}")
}

/// Writes `fig8_tolerance.svg`, `fig10_step.svg`, `fig11_bode.svg`.
pub fn all(dir: &Path, r: &Results) -> Result<()> {
    fig8(&dir.join("fig8_tolerance.svg"), &r.table3_traces)?;
    fig10(&dir.join("fig10_step.svg"), &r.toggle_mpdtc, &r.toggle_foc)?;
    fig11(&dir.join("fig11_bode.svg"), r)?;
    Ok(())
}

const COLORS: [RGBColor; 4] = [BLUE, RED, GREEN, MAGENTA];

fn fig8(path: &Path, traces: &[(f64, Trace)]) -> Result<()> {
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let mut ch = ChartBuilder::on(&root)
        .caption(
            "Fig. 8: i_q (solid) and i_d (thin) after a 0.4 Nm step, by T_tol",
            ("sans-serif", 18),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(0.0f64..1.0, -8.0f64..8.0)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("t [ms]")
        .y_desc("current [A]")
        .draw()
        .map_err(err)?;
    for (i, (tt, tr)) in traces.iter().enumerate() {
        let c = COLORS[i % 4];
        let pts = tr.windows.iter().filter(|w| w.t_s <= 1e-3);
        ch.draw_series(LineSeries::new(
            pts.clone().map(|w| (w.t_s * 1e3, w.i_q_a)),
            c.stroke_width(2),
        ))
        .map_err(err)?
        .label(format!("T_tol = {tt} Nm"))
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
        ch.draw_series(LineSeries::new(
            pts.map(|w| (w.t_s * 1e3, w.i_d_a)),
            c.stroke_width(1),
        ))
        .map_err(err)?;
    }
    ch.configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

fn fig10(path: &Path, m: &Trace, f: &Trace) -> Result<()> {
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let (t0, t1) = (9.8e-3, 10.8e-3);
    let mut ch = ChartBuilder::on(&root)
        .caption(
            "Fig. 10: torque step -0.4 -> +0.4 Nm at 10 ms (15.6 us window means)",
            ("sans-serif", 18),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(t0 * 1e3..t1 * 1e3, -0.6f64..0.6)
        .map_err(err)?;
    ch.configure_mesh()
        .x_desc("t [ms]")
        .y_desc("torque [Nm]")
        .draw()
        .map_err(err)?;
    for (name, tr, c) in [("MPDTC 64 kHz", m, BLUE), ("FOC 16 kHz", f, RED)] {
        let pts = tr
            .windows
            .iter()
            .filter(|w| w.t_s >= t0 && w.t_s <= t1)
            .map(|w| (w.t_s * 1e3, w.torque_nm));
        ch.draw_series(LineSeries::new(pts, c.stroke_width(2)))
            .map_err(err)?
            .label(name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
    }
    let rf = m
        .windows
        .iter()
        .filter(|w| w.t_s >= t0 && w.t_s <= t1)
        .map(|w| (w.t_s * 1e3, w.torque_ref_nm));
    ch.draw_series(LineSeries::new(rf, BLACK))
        .map_err(err)?
        .label("reference")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    ch.configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}

fn fig11(path: &Path, r: &Results) -> Result<()> {
    let root = SVGBackend::new(path, (900, 700)).into_drawing_area();
    root.fill(&WHITE).map_err(err)?;
    let (top, bot) = root.split_vertically(350);
    let lf = |x: f64| x.log10();
    let mut g = ChartBuilder::on(&top)
        .caption(
            "Fig. 11: torque loop Bode plot, 0.3 Nm sine",
            ("sans-serif", 18),
        )
        .margin(10)
        .x_label_area_size(30)
        .y_label_area_size(50)
        .build_cartesian_2d(2.0f64..3.95, -12.0f64..3.0)
        .map_err(err)?;
    g.configure_mesh()
        .x_desc("log10(f / Hz)")
        .y_desc("gain [dB]")
        .draw()
        .map_err(err)?;
    let mut p = ChartBuilder::on(&bot)
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(2.0f64..3.95, -360.0f64..30.0)
        .map_err(err)?;
    p.configure_mesh()
        .x_desc("log10(f / Hz)")
        .y_desc("phase [deg]")
        .draw()
        .map_err(err)?;
    for (name, b, c) in [("MPDTC", &r.bode_mpdtc, BLUE), ("FOC", &r.bode_foc, RED)] {
        g.draw_series(LineSeries::new(
            b.points.iter().map(|x| (lf(x.freq_hz), x.gain_db)),
            c.stroke_width(2),
        ))
        .map_err(err)?
        .label(name)
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
        g.draw_series(
            b.points
                .iter()
                .map(|x| Circle::new((lf(x.freq_hz), x.gain_db), 3, c.filled())),
        )
        .map_err(err)?;
        p.draw_series(LineSeries::new(
            b.points.iter().map(|x| (lf(x.freq_hz), x.phase_deg)),
            c.stroke_width(2),
        ))
        .map_err(err)?;
    }
    g.draw_series(LineSeries::new([(2.0, -3.0), (3.95, -3.0)], BLACK.mix(0.5)))
        .map_err(err)?;
    g.configure_series_labels()
        .position(SeriesLabelPosition::LowerLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)?;
    Ok(())
}
