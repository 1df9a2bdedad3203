//! The reference frames of both papers: the amplitude-invariant Clarke
//! transform (paper 000 eq. (1)'s frame, paper 001's `K` of eq. (1)) and the
//! Park rotation, with their inverses.
//!
//! - Clarke: `x_alpha = (2/3)(a - (b+c)/2)`, `x_beta = (b - c)/sqrt(3)`; a
//!   balanced set of amplitude X gives |x_ab| = X; a zero-sequence
//!   component is discarded.
//! - Park: `theta_e` is the electrical angle from the alpha axis (phase a)
//!   to the d axis, so `x_d = cos(th) x_alpha + sin(th) x_beta`,
//!   `x_q = -sin(th) x_alpha + cos(th) x_beta`.

/// `sqrt(3)`.
pub const SQRT3: f64 = 1.732_050_807_568_877_2;

/// Amplitude-invariant Clarke transform, `[a, b, c] -> (alpha, beta)`.
/// A zero-sequence component is discarded.
pub fn clarke(abc: [f64; 3]) -> (f64, f64) {
    let [a, b, c] = abc;
    ((2.0 * a - b - c) / 3.0, (b - c) / SQRT3)
}

/// Inverse amplitude-invariant Clarke transform (zero-sequence free).
pub fn inv_clarke(alpha: f64, beta: f64) -> [f64; 3] {
    [
        alpha,
        -0.5 * alpha + 0.5 * SQRT3 * beta,
        -0.5 * alpha - 0.5 * SQRT3 * beta,
    ]
}

/// Park transform `(alpha, beta) -> (d, q)` at electrical angle `theta_e_rad`.
pub fn park(alpha: f64, beta: f64, theta_e_rad: f64) -> (f64, f64) {
    park_sc(alpha, beta, libm::sincos(theta_e_rad))
}

/// [`park`] with `(sin, cos)` of the angle given.
pub fn park_sc(alpha: f64, beta: f64, (s, c): (f64, f64)) -> (f64, f64) {
    (c * alpha + s * beta, -s * alpha + c * beta)
}

/// Inverse Park transform `(d, q) -> (alpha, beta)` at electrical angle `theta_e_rad`.
pub fn inv_park(d: f64, q: f64, theta_e_rad: f64) -> (f64, f64) {
    inv_park_sc(d, q, libm::sincos(theta_e_rad))
}

/// [`inv_park`] with `(sin, cos)` of the angle given.
pub fn inv_park_sc(d: f64, q: f64, (s, c): (f64, f64)) -> (f64, f64) {
    (c * d - s * q, s * d + c * q)
}

/// `(sin, cos)` of `a + b` from `(sin, cos)` of `a` and of `b` (angle
/// addition: no transcendental call).
pub fn sc_add((sa, ca): (f64, f64), (sb, cb): (f64, f64)) -> (f64, f64) {
    (sa * cb + ca * sb, ca * cb - sa * sb)
}
