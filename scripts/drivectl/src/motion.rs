//! Host simulation of the outer loops: the product's `Servo` (the same
//! loops, estimator and torque loops the firmware runs) on the simulated PL
//! and motor (`simpl::SimDrive`, the same plant code the firmware's
//! simulated PL runs), one control step per control-period boundary as the
//! firmware's control interrupt does. The QEMU system tests compare the
//! firmware's `move` with [`run_move`].
use drive::pl::top::Mode;
use drive::servo::motion::{MotionStatus, MoveResult};
use drive::servo::{Servo, ServoConfig};
use simpl::{SimConfig, SimDrive};

/// One sample of a run, every control period.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time since the command, s.
    pub t_s: f64,
    /// The outer loops' view.
    pub motion: MotionStatus,
    /// Torque reference, N m.
    pub torque_ref_nm: f64,
    /// Measured torque, N m.
    pub torque_nm: f64,
}

/// The servo on the simulated PL with the simulated motor's parameters
/// `sim` (`name`, value as `sim set` takes them), in `mode`, gates on,
/// after `settle_s` of running at 0 N m (the MPDTC aligns the rotor first).
pub fn setup(mode: Mode, sim: &[(&str, f64)], settle_s: f64) -> anyhow::Result<(Servo, SimDrive)> {
    let mut d = SimDrive::new(&SimConfig::default()).map_err(|e| anyhow::anyhow!("{e}"))?;
    for (n, v) in sim {
        d.sim_set(n, *v)
            .map_err(|e| anyhow::anyhow!("sim set {n} {v}: {e:?}"))?;
    }
    let cfg = ServoConfig::for_plant(
        SimConfig::default().motor,
        SimConfig::default().adc_amps_per_count,
    );
    let mut s = Servo::new(&cfg).map_err(|e| anyhow::anyhow!("{e}"))?;
    s.init(&mut d).map_err(|e| anyhow::anyhow!("{e:?}"))?;
    s.set_mode(&mut d, mode)
        .map_err(|e| anyhow::anyhow!("{e:?}"))?;
    s.enable(&mut d).map_err(|e| anyhow::anyhow!("{e:?}"))?;
    let n = (settle_s * s.control_rate_hz()) as usize;
    run(&mut s, &mut d, n, |_| false)?;
    Ok((s, d))
}

/// Runs up to `max` control periods until `done`; the samples.
pub fn run(
    s: &mut Servo,
    d: &mut SimDrive,
    max: usize,
    mut done: impl FnMut(&Servo) -> bool,
) -> anyhow::Result<Vec<Sample>> {
    let mut out = Vec::new();
    let dt = s.control_period_s();
    for k in 0..max {
        let a = d.advance_to_boundary(20_000);
        anyhow::ensure!(a.control_periods >= 1, "no control boundary in 200 us");
        s.control_step(d).map_err(|e| anyhow::anyhow!("{e:?}"))?;
        out.push(Sample {
            t_s: (k + 1) as f64 * dt,
            motion: s.motion_status(),
            torque_ref_nm: s.torque_ref_nm(),
            torque_nm: s.measured().torque_nm,
        });
        if done(s) {
            break;
        }
    }
    Ok(out)
}

/// `move <distance> [<window>]` after [`setup`]: its figures and samples.
pub fn run_move(
    mode: Mode,
    sim: &[(&str, f64)],
    distance_rev: f64,
    window_s: f64,
) -> anyhow::Result<(MoveResult, Vec<Sample>)> {
    let (mut s, mut d) = setup(mode, sim, 3e-3)?;
    s.begin_move(&mut d, distance_rev, window_s)
        .map_err(|e| anyhow::anyhow!("{e:?}"))?;
    let samples = run(&mut s, &mut d, 200_000, |s| !s.move_pending())?;
    let r = s.move_result().ok_or_else(|| {
        anyhow::anyhow!("the move did not complete (faults: {:?})", s.faults(&mut d))
    })?;
    Ok((r, samples))
}

#[cfg(test)]
mod tests {
    use super::*;

    const FREE: &[(&str, f64)] = &[("locked", 0.0)];

    fn check_move(mode: Mode) {
        let (r, _) = run_move(mode, FREE, 1.0, 0.02).unwrap();
        println!("{mode:?} move 1 rev on the host: {r:?}");
        assert!((r.move_time_s - 0.09).abs() < 1e-9);
        assert!(r.final_error_counts.abs() <= 1.0, "{r:?}");
        assert!(r.settling_s.is_some_and(|t| t <= 5e-3), "{r:?}");
        assert!(r.overshoot_counts <= 2.0, "{r:?}");
    }

    #[test]
    fn move_one_revolution_mpdtc() {
        check_move(Mode::Mpdtc);
    }

    #[test]
    fn move_one_revolution_foc() {
        check_move(Mode::Foc);
    }
}
