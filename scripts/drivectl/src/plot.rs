//! Line plots for the SVG files the tool writes from point series (paper 001's
//! Fig. 5, Table II and traces, the horizon study): plotters with its SVG
//! backend, the library of every plot of the tool. Axes cover all finite
//! points; NaN and infinite points are left out (a gap, never a NaN in the
//! file).
use anyhow::{anyhow, Result};
use plotters::prelude::*;

/// One curve.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    /// `#rrggbb`.
    pub color: &'static str,
    pub dashed: bool,
    pub markers: bool,
}

const SIZE: (u32, u32) = (640, 400);

fn err<E: std::fmt::Display>(e: E) -> anyhow::Error {
    anyhow!("plot: {e}")
}

/// `#rrggbb` -> colour; anything else is an error (a programming error in a
/// caller's constant, reported rather than drawn black).
fn rgb(hex: &str) -> Result<RGBColor> {
    let h = hex.strip_prefix('#').filter(|h| h.len() == 6);
    let byte = |i: usize| h.and_then(|h| u8::from_str_radix(&h[i..i + 2], 16).ok());
    match (byte(0), byte(2), byte(4)) {
        (Some(r), Some(g), Some(b)) => Ok(RGBColor(r, g, b)),
        _ => Err(anyhow!("plot: colour {hex:?} is not #rrggbb")),
    }
}

/// The axis range of `v` with 5 % headroom; from zero if `from_zero` and all
/// values are positive; a unit span around a single value.
fn span(v: impl Iterator<Item = f64>, from_zero: bool) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for x in v {
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    if from_zero && lo > 0.0 {
        lo = 0.0;
    }
    if hi - lo < 1e-12 {
        return (lo - 0.5, hi + 0.5);
    }
    let pad = 0.05 * (hi - lo);
    (
        if from_zero && lo == 0.0 {
            0.0
        } else {
            lo - pad
        },
        hi + pad,
    )
}

/// Renders the plot as an SVG document. Ranges cover all finite points (y
/// from 0 if `y_from_zero`).
pub fn line_plot(
    title: &str,
    xlabel: &str,
    ylabel: &str,
    series: &[Series],
    y_from_zero: bool,
) -> Result<String> {
    let finite = |s: &Series| -> Vec<(f64, f64)> {
        s.points
            .iter()
            .copied()
            .filter(|p| p.0.is_finite() && p.1.is_finite())
            .collect()
    };
    let all: Vec<(f64, f64)> = series.iter().flat_map(finite).collect();
    let (x0, x1) = span(all.iter().map(|p| p.0), false);
    let (y0, y1) = span(all.iter().map(|p| p.1), y_from_zero);
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(err)?;
        let mut ch = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(err)?;
        ch.configure_mesh()
            .x_desc(xlabel)
            .y_desc(ylabel)
            .draw()
            .map_err(err)?;
        for s in series {
            let c = rgb(s.color)?;
            let pts = finite(s);
            let style = c.stroke_width(2);
            let legend = move |(x, y): (i32, i32)| {
                PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
            };
            if s.dashed {
                ch.draw_series(DashedLineSeries::new(pts.clone(), 6, 4, style))
                    .map_err(err)?
                    .label(s.name.as_str())
                    .legend(legend);
            } else {
                ch.draw_series(LineSeries::new(pts.clone(), style))
                    .map_err(err)?
                    .label(s.name.as_str())
                    .legend(legend);
            }
            if s.markers {
                ch.draw_series(pts.iter().map(|&p| Circle::new(p, 3, c.filled())))
                    .map_err(err)?;
            }
        }
        ch.configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
        root.present().map_err(err)?;
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spans_cover_the_points() {
        assert_eq!(span([1.0, 3.0].into_iter(), true), (0.0, 3.15));
        assert_eq!(span([2.0].into_iter(), false), (1.5, 2.5));
        assert_eq!(span(std::iter::empty(), false), (0.0, 1.0));
        let (lo, hi) = span([-1.0, 1.0].into_iter(), true);
        assert!((lo + 1.1).abs() < 1e-12 && (hi - 1.1).abs() < 1e-12);
    }

    #[test]
    fn colours_parse_or_fail() {
        assert_eq!(rgb("#1f77b4").unwrap(), RGBColor(0x1f, 0x77, 0xb4));
        assert!(rgb("red").is_err());
        assert!(rgb("#12345").is_err());
    }

    /// One path per series, the legend's names escaped, no NaN in the file.
    #[test]
    fn plot_has_every_series_and_no_nan() {
        let s = vec![
            Series {
                name: "a<b".into(),
                points: vec![(0.0, 1.0), (1.0, 2.0)],
                color: "#d62728",
                dashed: false,
                markers: true,
            },
            Series {
                name: "c".into(),
                points: vec![(0.0, 0.5), (0.5, 0.7), (1.0, f64::NAN)],
                color: "#1f77b4",
                dashed: true,
                markers: false,
            },
        ];
        let svg = line_plot("t", "x", "y", &s, true).unwrap();
        assert!(svg.starts_with("<svg"));
        assert!(svg.contains("a&lt;b"));
        assert!(!svg.contains("NaN"));
        assert!(
            svg.contains("stroke=\"#D62728\"")
                || svg.contains("#D62728")
                || svg.contains("rgb(214,39,40)")
        );
        // Two markers of the first series.
        assert_eq!(svg.matches("<circle").count(), 2);
    }
}
