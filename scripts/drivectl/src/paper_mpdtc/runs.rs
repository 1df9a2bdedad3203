//! Closed-loop runs on the PMSM plant and runner (`models::pmsm::closed_loop`),
//! reduced to 15.625 us windows.

use anyhow::{anyhow, Result};
use models::pmsm::closed_loop::{self, Controller, RunSummary};
use models::pmsm::params::{MotorParams, SamplingParams};
use models::pmsm::plant::{MechanicalMode, Plant};

/// ADC samples per averaging window (paper: 4 at 256 kHz = one MPDTC period).
pub const WINDOW_SAMPLES: usize = 4;

/// Result of a run.
pub struct Trace {
    /// Averaged windows.
    pub windows: Vec<Window>,
    /// Totals (transitions).
    pub summary: RunSummary,
}

/// One averaged window.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Window {
    /// End time of the window, s.
    pub t_s: f64,
    /// Mean d current, A.
    pub i_d_a: f64,
    /// Mean q current, A.
    pub i_q_a: f64,
    /// Mean torque, N m.
    pub torque_nm: f64,
    /// Reference at the window end, N m.
    pub torque_ref_nm: f64,
}

/// How the rotor is held during an experiment.
#[derive(Clone, Copy)]
pub enum Mech {
    /// Free rotor with its inertia, no load, from rest.
    Free,
}

/// Runs `ctrl` for `duration_s` against the plant `motor` (ideal inverter
/// unless `drive.dead_time_s > 0`), reference `r(t)`.
pub fn run<C: Controller + ?Sized>(
    ctrl: &mut C,
    motor: &MotorParams,
    drive: &SamplingParams,
    mech: Mech,
    duration_s: f64,
    r: impl FnMut(f64) -> f64,
) -> Result<Trace> {
    let (mode, w0) = match mech {
        Mech::Free => (
            MechanicalMode::Inertia {
                load_torque_nm: 0.0,
            },
            0.0,
        ),
    };
    let mut plant = Plant::new(motor, drive.dead_time_s, mode, w0).map_err(|e| anyhow!("{e}"))?;
    let n = (duration_s / ctrl.period_s()).round() as u64;
    let mut windows = Vec::with_capacity((duration_s * 64e3) as usize + 8);
    let mut acc = Window::default();
    let mut k = 0usize;
    let summary = closed_loop::run(&mut plant, ctrl, drive, n, r, |p| {
        acc.i_d_a += p.i_d_a;
        acc.i_q_a += p.i_q_a;
        acc.torque_nm += p.torque_nm;
        k += 1;
        if k == WINDOW_SAMPLES {
            let s = 1.0 / WINDOW_SAMPLES as f64;
            windows.push(Window {
                t_s: p.t_s,
                i_d_a: acc.i_d_a * s,
                i_q_a: acc.i_q_a * s,
                torque_nm: acc.torque_nm * s,
                torque_ref_nm: p.torque_ref_nm,
            });
            acc = Window::default();
            k = 0;
        }
    })
    .map_err(|e| anyhow!("{e}"))?;
    Ok(Trace { windows, summary })
}
