//! The simulated drive (plant): induction machine + five-level ANPC
//! inverter, integrated exactly over each sampling interval.
//!
//! For a fixed three-phase switch position the whole drive is an affine LTI
//! system in `z = [i_s_ab, psi_r_ab, v_n, v_ph_abc]` (8 states): the output
//! voltages are affine in `v_n` and `v_ph` ([`anpc::TABLE`]) and the
//! capacitor currents are linear in the stator currents. So the exact step
//! is `[z; 1](k+1) = e^{M T_s} [z; 1](k)` with the 9x9 augmented matrix `M`
//! built below. Unlike the controller's model (eq. 2), the capacitor
//! voltages see the current's variation within the step and the machine
//! sees the capacitor voltages' variation. The last few transition matrices
//! are cached because the position changes only every few steps.
#![allow(clippy::needless_range_loop)]

use super::anpc;
use super::machine::{self, expm, Continuous};
use super::params::{DriveParams, ParamError};

/// Physical state of the drive, pu.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlantState {
    /// `[i_s_alpha, i_s_beta, psi_r_alpha, psi_r_beta]`, pu.
    pub x_m: [f64; 4],
    /// Neutral point potential, pu.
    pub v_n_pu: f64,
    /// Phase capacitor voltages, pu.
    pub v_ph_pu: [f64; 3],
}

const CACHE: usize = 16;
const S3_2: f64 = 0.866_025_403_784_438_6;
/// `K` of eq. (1).
const K: [[f64; 3]; 2] = [
    [2.0 / 3.0, -1.0 / 3.0, -1.0 / 3.0],
    [0.0, 2.0 / 3.0 * S3_2, -2.0 / 3.0 * S3_2],
];
/// `K^-1` of eq. (1).
const KINV: [[f64; 2]; 3] = [[1.0, 0.0], [-0.5, S3_2], [-0.5, -S3_2]];

/// Exact plant with a small cache of transition matrices.
pub struct Plant {
    p: DriveParams,
    cont: Continuous,
    ts_pu: f64,
    cache: [([u8; 3], [[f64; 9]; 9]); CACHE],
    cache_used: usize,
    cache_next: usize,
}

impl Plant {
    /// Builds the plant for the operating point's rotor speed.
    pub fn new(p: &DriveParams) -> Result<Self, ParamError> {
        p.validate()?;
        Ok(Self {
            p: *p,
            cont: machine::continuous(&p.machine, p.operating_point.omega_r_pu),
            ts_pu: p.controller.ts_pu(&p.machine),
            cache: [([0; 3], [[0.0; 9]; 9]); CACHE],
            cache_used: 0,
            cache_next: 0,
        })
    }

    /// The continuous augmented matrix `M(s)` (normalized time).
    pub fn augmented(&self, s: [u8; 3]) -> [[f64; 9]; 9] {
        let inv = &self.p.inverter;
        let mut m = [[0.0; 9]; 9];
        for r in 0..4 {
            m[r][..4].copy_from_slice(&self.cont.f[r]);
        }
        for x in 0..3 {
            let pos = &anpc::TABLE[(s[x] & 7) as usize];
            // Machine: G K v_abc, v_x = rail V_dc/2 + n v_n + ph v_ph,x.
            for r in 0..2 {
                let gk = self.cont.g[r][r] * K[r][x];
                m[r][4] += gk * pos.n_coef as f64;
                m[r][5 + x] += gk * pos.ph_coef as f64;
                m[r][8] += gk * pos.rail as f64 * 0.5 * inv.v_dc_pu;
            }
            // Capacitors: i_x = K^-1 i_ab.
            for c in 0..2 {
                m[4][c] -= pos.np_current as f64 * KINV[x][c] / (2.0 * inv.c_dc_pu);
                m[5 + x][c] += pos.ph_current as f64 * KINV[x][c] / inv.c_ph_pu;
            }
        }
        m
    }

    fn transition(&mut self, s: [u8; 3]) -> [[f64; 9]; 9] {
        if let Some(e) = self.cache[..self.cache_used].iter().find(|e| e.0 == s) {
            return e.1;
        }
        let mut m = self.augmented(s);
        for r in m.iter_mut() {
            for v in r.iter_mut() {
                *v *= self.ts_pu;
            }
        }
        let e = expm(&m);
        self.cache[self.cache_next] = (s, e);
        self.cache_next = (self.cache_next + 1) % CACHE;
        self.cache_used = (self.cache_used + 1).min(CACHE);
        e
    }

    /// Advances `z` by one sampling interval with position `s` (positions
    /// above 7 are masked to 0..=7; callers pass controller output).
    pub fn step(&mut self, z: &PlantState, s: [u8; 3]) -> PlantState {
        let s = [s[0] & 7, s[1] & 7, s[2] & 7];
        let phi = self.transition(s);
        let v = [
            z.x_m[0],
            z.x_m[1],
            z.x_m[2],
            z.x_m[3],
            z.v_n_pu,
            z.v_ph_pu[0],
            z.v_ph_pu[1],
            z.v_ph_pu[2],
            1.0,
        ];
        let mut y = [0.0; 8];
        for r in 0..8 {
            y[r] = (0..9).map(|c| phi[r][c] * v[c]).sum();
        }
        PlantState {
            x_m: [y[0], y[1], y[2], y[3]],
            v_n_pu: y[4],
            v_ph_pu: [y[5], y[6], y[7]],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frames::{clarke, inv_clarke};
    use crate::mpdcc::machine::Discrete;

    /// With huge capacitors the plant's machine part must equal the
    /// machine-only exact discretization fed with the nominal voltages.
    #[test]
    fn stiff_capacitors_reduce_to_machine_discretization() {
        let mut p = DriveParams::default();
        p.inverter.c_dc_pu = 1e12;
        p.inverter.c_ph_pu = 1e12;
        let mut plant = Plant::new(&p).unwrap();
        let z = PlantState {
            x_m: [0.5, -0.7, 0.6, 0.8],
            v_n_pu: 0.0,
            v_ph_pu: [p.inverter.v_ph_ref_pu(); 3],
        };
        let s = [7, 2, 4];
        let y = plant.step(&z, s);
        let ts = p.controller.ts_pu(&p.machine);
        let d = Discrete::exact(
            &machine::continuous(&p.machine, p.operating_point.omega_r_pu),
            ts,
        );
        let v = anpc::output_voltages(s, p.inverter.v_dc_pu, 0.0, z.v_ph_pu);
        let x = d.step(&z.x_m, clarke(v).into());
        for i in 0..4 {
            assert!((x[i] - y.x_m[i]).abs() < 1e-12);
        }
    }

    /// Over one step the plant's capacitor voltages must agree with eq. (2)
    /// applied to the average of the start and end currents (trapezoid), to
    /// second order in `T_s`.
    #[test]
    fn capacitor_change_matches_trapezoid_of_currents() {
        let p = DriveParams::default();
        let mut plant = Plant::new(&p).unwrap();
        let z = PlantState {
            x_m: [0.9, 0.3, 0.6, 0.8],
            v_n_pu: 0.01,
            v_ph_pu: [0.47, 0.49, 0.5],
        };
        let s = [2, 5, 6];
        let y = plant.step(&z, s);
        let ts = p.controller.ts_pu(&p.machine);
        let i0 = inv_clarke(z.x_m[0], z.x_m[1]);
        let i1 = inv_clarke(y.x_m[0], y.x_m[1]);
        let im: [f64; 3] = core::array::from_fn(|x| 0.5 * (i0[x] + i1[x]));
        let mut xi = [z.v_n_pu, z.v_ph_pu[0], z.v_ph_pu[1], z.v_ph_pu[2]];
        anpc::inverter_euler_step(&mut xi, s, im, ts, p.inverter.c_dc_pu, p.inverter.c_ph_pu);
        assert!(
            (xi[0] - y.v_n_pu).abs() < 1e-7,
            "{} {} {}",
            xi[0],
            y.v_n_pu,
            z.v_n_pu
        );
        for x in 0..3 {
            assert!((xi[1 + x] - y.v_ph_pu[x]).abs() < 1e-7, "{x}");
        }
        // And the step really moved them (the test is not vacuous).
        assert!((y.v_ph_pu[0] - z.v_ph_pu[0]).abs() > 1e-4);
    }
}
