//! Agreement of the drive under QEMU (firmware on the simulated PL) with
//! the host simulation of the same motor and controllers
//! (`drive::pmsm::sim`, the paper-000 experiments' plant): the -3 dB
//! torque bandwidth of a 0.3 N m sine reference, from the firmware's
//! `sweep` and from the host run, within 10 %.
use drive::pmsm::foc::{Foc, FocParams};
use drive::pmsm::mpdtc_ctrl::MpdtcRef;
use drive::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use drive::pmsm::params::{DriveParams, MotorParams};
use drive::pmsm::plant::{MechanicalMode, Plant};
use drive::pmsm::sim::{self, Controller};
use drive::servo::{bandwidth_hz, tone_response, SweepPoint};
use drivectl::link::Final;
use std::f64::consts::PI;
use std::time::Duration;
use system_tests::{boot, cmd};

const AMP_NM: f64 = 0.3;

/// Host run of `ctrl` with a sine reference at `f_hz`: gain and phase of
/// the control period's mean torque against the reference, after 1 ms (at
/// least one period) of transient, over 4 ms.
fn host_point<C: Controller>(mut ctrl: C, f_hz: f64) -> SweepPoint {
    let motor = MotorParams::default();
    let drive = DriveParams::default();
    let mode = MechanicalMode::Inertia {
        load_torque_nm: 0.0,
    };
    let mut plant = Plant::new(&motor, drive.dead_time_s, mode, 0.0).unwrap();
    let ts = ctrl.period_s();
    let skip = ((1e-3f64).max(1.0 / f_hz) / ts).ceil() as usize;
    let n = skip + (4e-3 / ts).ceil() as usize;
    let (mut refs, mut outs) = (Vec::new(), Vec::new());
    let (mut acc, mut k) = (0.0, 0);
    sim::run(
        &mut plant,
        &mut ctrl,
        &drive,
        n as u64,
        |t| AMP_NM * (2.0 * PI * f_hz * t).sin(),
        |p| {
            acc += p.torque_nm;
            k += 1;
            if p.end_of_period {
                refs.push(p.torque_ref_nm);
                outs.push(acc / k as f64);
                (acc, k) = (0.0, 0);
            }
        },
    )
    .unwrap();
    tone_response(&refs[skip..], &outs[skip..], f_hz, ts).unwrap()
}

fn host_bandwidth<C: Controller>(make: impl Fn() -> C, freqs: &[f64]) -> f64 {
    let pts: Vec<SweepPoint> = freqs.iter().map(|&f| host_point(make(), f)).collect();
    println!("host: {pts:?}");
    bandwidth_hz(&pts).expect("host -3 dB point in the grid")
}

fn qemu_bandwidth(mode: &str, sweep: &str) -> f64 {
    let mut s = boot();
    assert!(cmd(&mut s, &format!("mode {mode}")).is_ok());
    assert!(cmd(&mut s, "enable").is_ok());
    let r = s.command(sweep, Duration::from_secs(300)).unwrap();
    assert_eq!(r.fin, Final::Ok, "{r:?}");
    println!("qemu {mode}: {:?}", r.lines);
    let b = r.lines.last().and_then(|l| l.strip_prefix("bandwidth: "));
    b.and_then(|x| x.split_whitespace().next()?.parse().ok())
        .unwrap_or_else(|| panic!("no bandwidth in {r:?}"))
}

fn geom(f0: f64, f1: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|k| f0 * (f1 / f0).powf(k as f64 / (n - 1) as f64))
        .collect()
}

#[test]
fn mpdtc_bandwidth_agrees_with_the_host_simulation() {
    let cfg = MpdtcConfig::new(MotorParams::default(), MpdtcParams::default()).unwrap();
    let host = host_bandwidth(|| MpdtcRef::new(cfg), &geom(2000.0, 8000.0, 7));
    let qemu = qemu_bandwidth("mpdtc", "sweep 2000 8000 0.3 7");
    println!("MPDTC -3 dB: QEMU {qemu:.0} Hz, host {host:.0} Hz");
    assert!(
        (qemu / host - 1.0).abs() <= 0.10,
        "QEMU {qemu} Hz, host {host} Hz"
    );
}

#[test]
fn foc_bandwidth_agrees_with_the_host_simulation() {
    let make = || Foc::new(&MotorParams::default(), &FocParams::default()).unwrap();
    let host = host_bandwidth(make, &geom(1500.0, 3990.0, 6));
    let qemu = qemu_bandwidth("foc", "sweep 1500 3990 0.3 6");
    println!("FOC -3 dB: QEMU {qemu:.0} Hz, host {host:.0} Hz");
    assert!(
        (qemu / host - 1.0).abs() <= 0.10,
        "QEMU {qemu} Hz, host {host} Hz"
    );
}
