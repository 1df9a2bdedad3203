//! Induction machine model in per unit (paper 001, Sec. II-B) and its exact
//! discretization.
//!
//! State `x_m = [i_s_alpha, i_s_beta, psi_r_alpha, psi_r_beta]` (pu), input the
//! stator voltage `v_s,alpha_beta = K v_abc` (pu), rotor speed `omega_r` (pu) a
//! parameter. In normalized time (`t_pu = omega_B t`):
//!
//! ```text
//! di_s/dt   = -1/tau_s i_s + X_m/D (1/tau_r I - omega_r J) psi_r + X_r/D v_s
//! dpsi_r/dt = X_m/tau_r i_s - (1/tau_r I - omega_r J) psi_r,   J = [0 -1; 1 0]
//! ```
//!
//! which is the continuous-time matrix inside the paper's eq. (4) (its
//! forward-Euler form without the correction term) and the `B` of eq. (5).
//! The exact discretization with a zero-order-hold voltage is
//! `Phi = e^{F T}`, `Gamma = int_0^T e^{F t} dt G`, computed from the
//! exponential of the augmented matrix `[F G; 0 0]` (Taylor series with
//! scaling and squaring, enough terms for `f64` at the norms that occur).
#![allow(clippy::needless_range_loop)] // index loops mirror the matrix equations

use super::params::MachineParams;

/// Continuous-time model `dx/dt = F x + G v_s,ab` (normalized time).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Continuous {
    /// System matrix `F` (4x4), 1/pu-time.
    pub f: [[f64; 4]; 4],
    /// Input matrix `G` (4x2), `X_r/D` on the current rows.
    pub g: [[f64; 2]; 4],
}

/// Builds `F`, `G` for rotor speed `omega_r_pu`.
pub fn continuous(m: &MachineParams, omega_r_pu: f64) -> Continuous {
    let d = m.d_pu();
    let (ts, tr) = (m.tau_s_pu(), m.tau_r_pu());
    let (xm, xr) = (m.x_m_pu, m.x_r_pu());
    let w = omega_r_pu;
    let f = [
        [-1.0 / ts, 0.0, xm / (d * tr), xm / d * w],
        [0.0, -1.0 / ts, -xm / d * w, xm / (d * tr)],
        [xm / tr, 0.0, -1.0 / tr, -w],
        [0.0, xm / tr, w, -1.0 / tr],
    ];
    let g = [[xr / d, 0.0], [0.0, xr / d], [0.0, 0.0], [0.0, 0.0]];
    Continuous { f, g }
}

/// Exact (zero-order-hold) discretization `x(k+1) = Phi x(k) + Gamma v_ab(k)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Discrete {
    /// `Phi = e^{F T_s}`.
    pub phi: [[f64; 4]; 4],
    /// `Gamma = int_0^{T_s} e^{F t} dt G`.
    pub gamma: [[f64; 2]; 4],
}

impl Discrete {
    /// Exact discretization of `c` over `ts_pu` (normalized time).
    pub fn exact(c: &Continuous, ts_pu: f64) -> Self {
        let mut a = [[0.0; 6]; 6];
        for r in 0..4 {
            for k in 0..4 {
                a[r][k] = c.f[r][k] * ts_pu;
            }
            for k in 0..2 {
                a[r][4 + k] = c.g[r][k] * ts_pu;
            }
        }
        let e = expm(&a);
        let mut phi = [[0.0; 4]; 4];
        let mut gamma = [[0.0; 2]; 4];
        for r in 0..4 {
            phi[r].copy_from_slice(&e[r][..4]);
            gamma[r].copy_from_slice(&e[r][4..]);
        }
        Self { phi, gamma }
    }

    /// Forward Euler `Phi = I + T F`, `Gamma = T G` (no correction term).
    pub fn euler(c: &Continuous, ts_pu: f64) -> Self {
        let mut phi = [[0.0; 4]; 4];
        let mut gamma = [[0.0; 2]; 4];
        for r in 0..4 {
            for k in 0..4 {
                phi[r][k] = f64::from(u8::from(r == k)) + ts_pu * c.f[r][k];
            }
            for k in 0..2 {
                gamma[r][k] = ts_pu * c.g[r][k];
            }
        }
        Self { phi, gamma }
    }

    /// One step: `Phi x + Gamma v_ab`.
    #[inline]
    pub fn step(&self, x: &[f64; 4], v_ab: [f64; 2]) -> [f64; 4] {
        let mut y = [0.0; 4];
        for (r, yr) in y.iter_mut().enumerate() {
            let p = &self.phi[r];
            *yr = p[0] * x[0]
                + p[1] * x[1]
                + p[2] * x[2]
                + p[3] * x[3]
                + self.gamma[r][0] * v_ab[0]
                + self.gamma[r][1] * v_ab[1];
        }
        y
    }
}

/// Infinity norm of a square matrix.
fn norm_inf<const N: usize>(a: &[[f64; N]; N]) -> f64 {
    a.iter()
        .map(|r| r.iter().map(|v| libm::fabs(*v)).sum::<f64>())
        .fold(0.0, f64::max)
}

/// Matrix product of two square matrices.
pub fn matmul<const N: usize>(a: &[[f64; N]; N], b: &[[f64; N]; N]) -> [[f64; N]; N] {
    let mut c = [[0.0; N]; N];
    for i in 0..N {
        for k in 0..N {
            let aik = a[i][k];
            if aik == 0.0 {
                continue;
            }
            for j in 0..N {
                c[i][j] += aik * b[k][j];
            }
        }
    }
    c
}

/// Matrix exponential `e^A` by scaling and squaring with an 18-term Taylor
/// series. After scaling `||A / 2^s|| <= 0.5`, the truncation error is below
/// `0.5^19 / 19! < 1e-22` relative, far under `f64` rounding. Non-finite
/// input gives non-finite output (callers validate parameters first).
pub fn expm<const N: usize>(a: &[[f64; N]; N]) -> [[f64; N]; N] {
    let nrm = norm_inf(a);
    let mut s = 0u32;
    let mut scale = 1.0;
    while nrm * scale > 0.5 && s < 64 {
        scale *= 0.5;
        s += 1;
    }
    let mut x = *a;
    for r in x.iter_mut() {
        for v in r.iter_mut() {
            *v *= scale;
        }
    }
    // Horner: e^X ~ I + X (I + X/2 (I + X/3 (...)))
    let mut e = [[0.0; N]; N];
    for (i, r) in e.iter_mut().enumerate() {
        r[i] = 1.0;
    }
    for k in (1..=18).rev() {
        let mut t = matmul(&x, &e);
        for (i, r) in t.iter_mut().enumerate() {
            for v in r.iter_mut() {
                *v /= k as f64;
            }
            r[i] += 1.0;
        }
        e = t;
    }
    for _ in 0..s {
        e = matmul(&e, &e);
    }
    e
}

/// Steady-state rotor flux for a stator current phasor `i_s = I e^{j theta}`
/// rotating at `omega_s` with the rotor at `omega_r` (all pu):
/// `psi_r = X_m i_s / (1 + j (omega_s - omega_r) tau_r)`. Returns `[psi_a, psi_b]`
/// at the instant where `i_s,ab = i_ab`. Used to start simulations without the
/// slow (`tau_r` ~ 0.9 s) rotor flux transient.
pub fn steady_state_flux(
    m: &MachineParams,
    i_ab: [f64; 2],
    omega_s: f64,
    omega_r: f64,
) -> [f64; 2] {
    let a = (omega_s - omega_r) * m.tau_r_pu();
    let den = 1.0 + a * a;
    // X_m (1 - j a) / (1 + a^2) * (i_a + j i_b)
    let (re, im) = (m.x_m_pu / den, -m.x_m_pu * a / den);
    [re * i_ab[0] - im * i_ab[1], re * i_ab[1] + im * i_ab[0]]
}

/// Electromagnetic torque, pu: `T = X_m/X_r (psi_r x i_s)` (amplitude-invariant
/// pu, where rated torque is about 1 pu).
pub fn torque_pu(m: &MachineParams, x: &[f64; 4]) -> f64 {
    m.x_m_pu / m.x_r_pu() * (x[2] * x[1] - x[3] * x[0])
}

#[cfg(test)]
mod tests {
    use super::*;

    fn params() -> MachineParams {
        MachineParams::default()
    }

    #[test]
    fn expm_of_rotation_generator_is_rotation() {
        // e^{[0 -t; t 0]} = [cos t, -sin t; sin t, cos t]: independent check.
        let t = 2.7;
        let e = expm(&[[0.0, -t], [t, 0.0]]);
        assert!((e[0][0] - libm::cos(t)).abs() < 1e-14);
        assert!((e[1][0] - libm::sin(t)).abs() < 1e-14);
        assert!((e[0][1] + libm::sin(t)).abs() < 1e-14);
    }

    /// The exact discretization must agree with a fine RK4 integration of the
    /// continuous model (an independent integrator).
    #[test]
    fn exact_discretization_matches_rk4() {
        let m = params();
        let c = continuous(&m, 0.991);
        let ts = 25e-6 * m.omega_b_rad_s();
        let d = Discrete::exact(&c, ts);
        let x0 = [0.8, -0.4, 0.7, 0.5];
        let v = [0.6, -0.3];
        let deriv = |x: &[f64; 4]| -> [f64; 4] {
            core::array::from_fn(|r| {
                (0..4).map(|k| c.f[r][k] * x[k]).sum::<f64>() + c.g[r][0] * v[0] + c.g[r][1] * v[1]
            })
        };
        let n = 1000;
        let h = ts / n as f64;
        let mut x = x0;
        for _ in 0..n {
            let k1 = deriv(&x);
            let x2: [f64; 4] = core::array::from_fn(|i| x[i] + 0.5 * h * k1[i]);
            let k2 = deriv(&x2);
            let x3: [f64; 4] = core::array::from_fn(|i| x[i] + 0.5 * h * k2[i]);
            let k3 = deriv(&x3);
            let x4: [f64; 4] = core::array::from_fn(|i| x[i] + h * k3[i]);
            let k4 = deriv(&x4);
            x = core::array::from_fn(|i| {
                x[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
            });
        }
        let y = d.step(&x0, v);
        for i in 0..4 {
            assert!(
                (x[i] - y[i]).abs() < 1e-13,
                "state {i}: {} vs {}",
                x[i],
                y[i]
            );
        }
    }

    /// At steady state (current phasor at omega_s, flux from
    /// [`steady_state_flux`]) the rotor flux equation is satisfied:
    /// `dpsi/dt = j omega_s psi`.
    #[test]
    fn steady_state_flux_satisfies_rotor_equation() {
        let m = params();
        let c = continuous(&m, 0.991);
        let i = [0.6, 0.8];
        let psi = steady_state_flux(&m, i, 1.0, 0.991);
        let x = [i[0], i[1], psi[0], psi[1]];
        let dpsi: [f64; 2] = core::array::from_fn(|r| (0..4).map(|k| c.f[2 + r][k] * x[k]).sum());
        // j omega_s psi = [-psi_b, psi_a]
        assert!((dpsi[0] + psi[1]).abs() < 1e-12);
        assert!((dpsi[1] - psi[0]).abs() < 1e-12);
    }
}
