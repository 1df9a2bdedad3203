//! The metrics of the paper-000 experiments: the definitions of
//! `models::pmsm::metrics` (one place, band included), applied to window means.
//!
//! Signals are evaluated as the paper measures them: the plant value averaged
//! over consecutive windows of one MPDTC period (the mean of 4 ADC samples at
//! 256 kHz, 15.625 us, "each four sampled phase currents are averaged"),
//! identically for MPDTC and FOC, and time-stamped at the window end.
//!
//! **Settling time** (`models::pmsm::metrics::settling_time_s`): from the step
//! to the end of the first window inside the band `y1 +- SETTLING_BAND
//! |y1 - y0|` after which no window within the evaluation interval (2 ms
//! after the step) leaves it; `None` if still outside at its end. Band 10 %
//! (`models::pmsm::metrics::SETTLING_BAND_FRACTION`, reason there), the same
//! for both controllers and every table.
//!
//! **Overshoot**, **switching frequency** (transitions per leg per second):
//! `models::pmsm::metrics`.

use super::runs::Window;
use models::pmsm::metrics as m;

/// Relative half-width of the settling band (the library's definition).
pub const SETTLING_BAND: f64 = m::SETTLING_BAND_FRACTION;

/// Settling time, s (see module doc).
pub fn settling(
    w: &[Window],
    signal: impl Fn(&Window) -> f64,
    t0_s: f64,
    t_end_s: f64,
    y0: f64,
    y1: f64,
) -> Option<f64> {
    let band = m::settling_band(y0, y1);
    m::settling_time_s(
        w.iter().map(|x| (x.t_s, signal(x))),
        t0_s,
        t_end_s,
        y1,
        band,
    )
}

/// Overshoot, percent of the step.
pub fn overshoot(
    w: &[Window],
    signal: impl Fn(&Window) -> f64,
    t0_s: f64,
    t_end_s: f64,
    y0: f64,
    y1: f64,
) -> f64 {
    m::overshoot_percent(w.iter().map(|x| (x.t_s, signal(x))), t0_s, t_end_s, y0, y1)
}

/// Mean transitions per leg per second.
pub fn fsw_hz(transitions: [u64; 3], duration_s: f64) -> f64 {
    m::transitions_per_leg_per_s([0; 3], transitions, duration_s)
}

/// Carrier-equivalent switching frequency (half of [`fsw_hz`]), Hz.
pub fn fsw_carrier_equiv_hz(transitions: [u64; 3], duration_s: f64) -> f64 {
    m::equivalent_carrier_hz([0; 3], transitions, duration_s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_is_ten_percent_of_the_step() {
        // First order, tau = 10 us, windows every 1 us: enters the 10 % band
        // at tau ln 10 = 23.03 us -> first window inside: 24 us.
        let w: Vec<Window> = (0..400)
            .map(|k| {
                let t = k as f64 * 1e-6;
                Window {
                    t_s: t,
                    torque_nm: 1.0 - (-t / 10e-6).exp(),
                    ..Default::default()
                }
            })
            .collect();
        let ts = settling(&w, |x| x.torque_nm, 0.0, 1.0, 0.0, 1.0).unwrap();
        assert!((ts - 24e-6).abs() < 1e-12, "{ts}");
        assert_eq!(fsw_hz([30, 30, 30], 1e-3), 30e3);
        assert_eq!(fsw_carrier_equiv_hz([30, 30, 30], 1e-3), 15e3);
    }
}
