//! Centre-aligned space-vector PWM by min-max (zero-sequence) injection.
//!
//! The reference `(u_alpha, u_beta)` is turned into phase references, the mean
//! of their maximum and minimum is subtracted (this centres the active vectors
//! in the period, which is exactly symmetric SVPWM) and the result is mapped to
//! duties `d_x = 1/2 + u_x' / U_dc`. The average leg voltages over the period
//! then reproduce the reference exactly while `max - min <= U_dc`, i.e. for
//! every direction while `|u| <= U_dc / sqrt(3)` (the linear range: the circle
//! inscribed in the hexagon of radius `2/3 U_dc`). Beyond the hexagon the
//! vector is shrunk towards zero, keeping its angle, onto the hexagon boundary
//! (so duties stay in `[0, 1]` and the direction is kept).

use super::frames::inv_clarke;

/// Radius of the linear range of SVPWM for DC-link `u_dc_v`, V: `U_dc / sqrt(3)`.
pub fn linear_limit_v(u_dc_v: f64) -> f64 {
    u_dc_v / 1.732_050_807_568_877_2
}

/// Duties of legs a, b, c (each in `[0, 1]`) for the stator voltage reference
/// `(u_alpha_v, u_beta_v)` and the flag "the reference was outside the hexagon
/// and was shrunk". Non-finite inputs give duties 0.5 (zero voltage) and `true`.
pub fn duties(u_alpha_v: f64, u_beta_v: f64, u_dc_v: f64) -> ([f64; 3], bool) {
    if !(u_alpha_v.is_finite() && u_beta_v.is_finite() && u_dc_v.is_finite() && u_dc_v > 0.0) {
        return ([0.5; 3], true);
    }
    let u = inv_clarke(u_alpha_v, u_beta_v);
    let max = u[0].max(u[1]).max(u[2]);
    let min = u[0].min(u[1]).min(u[2]);
    let span = max - min;
    let (scale, sat) = if span > u_dc_v {
        (u_dc_v / span, true)
    } else {
        (1.0, false)
    };
    let mid = 0.5 * (max + min);
    let mut d = [0.0; 3];
    for (dx, ux) in d.iter_mut().zip(u) {
        *dx = (0.5 + (ux - mid) * scale / u_dc_v).clamp(0.0, 1.0);
    }
    (d, sat)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pmsm::frames::leg_voltage_alpha_beta;
    use core::f64::consts::PI;

    #[test]
    fn duties_stay_in_range_and_reproduce_the_reference_in_the_linear_range() {
        let udc = 48.0;
        let lim = linear_limit_v(udc);
        assert!((lim - 27.712_812_921).abs() < 1e-6);
        for k in 0..360 {
            let th = k as f64 * PI / 180.0;
            for &mag in &[0.0, 1.0, 10.0, 0.999 * lim, lim] {
                let (ua, ub) = (mag * th.cos(), mag * th.sin());
                let (d, sat) = duties(ua, ub, udc);
                assert!(!sat, "{k} {mag}");
                assert!(d.iter().all(|&x| (0.0..=1.0).contains(&x)));
                let (a, b) = leg_voltage_alpha_beta(d, udc);
                assert!((a - ua).abs() < 1e-9 && (b - ub).abs() < 1e-9, "{k} {mag}");
                // Min-max injection centres the vectors: max + min duty = 1.
                let mx = d[0].max(d[1]).max(d[2]);
                let mn = d[0].min(d[1]).min(d[2]);
                assert!((mx + mn - 1.0).abs() < 1e-12);
            }
            // Beyond the hexagon: duties clamp, angle kept, magnitude = hexagon.
            let (d, sat) = duties(100.0 * th.cos(), 100.0 * th.sin(), udc);
            assert!(sat && d.iter().all(|&x| (0.0..=1.0).contains(&x)));
            let (a, b) = leg_voltage_alpha_beta(d, udc);
            let mag = a.hypot(b);
            // Hexagon radius in direction th: (U_dc/sqrt3) / cos(angle to nearest edge normal).
            let rel = th.rem_euclid(PI / 3.0) - PI / 6.0;
            let hex = lim / rel.cos();
            assert!((mag - hex).abs() < 1e-9, "{k}: {mag} vs {hex}");
            assert!((b.atan2(a) - th.sin().atan2(th.cos())).abs() < 1e-9);
        }
        // Just outside the circle at 30 deg (an edge normal) is saturated.
        let th = PI / 6.0;
        let (_, sat) = duties(1.001 * lim * th.cos(), 1.001 * lim * th.sin(), udc);
        assert!(sat);
        // At an active-vector direction the linear range extends to 2/3 U_dc.
        let (d, sat) = duties(0.999 * 2.0 / 3.0 * udc, 0.0, udc);
        assert!(!sat && d.iter().all(|&x| (0.0..=1.0).contains(&x)));
        assert_eq!(duties(f64::NAN, 0.0, udc), ([0.5; 3], true));
    }
}
