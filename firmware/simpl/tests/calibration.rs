//! `calibrate` on the simulated PL and motor: the drive's calibration
//! (`drive::servo::calibrate` running `models::calibration`) against
//! simulated motors whose true parameters are drawn at random, with the
//! simulated inverter's dead time and the ADC's quantization and delay.
use drive::pl::top::Mode;
use drive::servo::sensors::PlTime;
use drive::servo::{Servo, ServoConfig};
use models::calibration::{Phases, Results};
use models::pmsm::sim_motor::SimMotor;
use models::testrng::Rng;
use regmap::bus::{BusError, RegisterBus};
use simpl::{SimConfig, SimDrive};

/// The simulated PL with its time under the drive's control.
struct Bus(SimDrive);

impl RegisterBus for Bus {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        self.0.read(addr)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.0.write(addr, value)
    }
}

impl PlTime for Bus {
    fn wait_cycles(&mut self, cycles: u64) {
        let _ = self.0.advance(cycles);
    }
}

/// Nominal friction of the draws (the simulated motor's default has none).
const B_NOMINAL: f64 = 2e-4;
const COULOMB_NOMINAL: f64 = 5e-3;

/// A motor within +-40 % of the defaults, encoder anywhere, either way.
fn draw(r: &mut Rng) -> SimMotor {
    let mut m = SimMotor::default();
    let mut f = |x: f64| x * r.uniform(0.6, 1.4);
    m.motor.r_s_ohm = f(m.motor.r_s_ohm);
    let l = f(m.motor.l_d_h);
    m.motor.l_d_h = l;
    m.motor.l_q_h = l;
    m.motor.psi_pm_wb = f(m.motor.psi_pm_wb);
    m.motor.pole_pairs = libm::round(f(7.0)) as u32;
    m.mech.j_kg_m2 = f(m.motor.j_kg_m2);
    m.mech.b_nm_s_per_rad = f(B_NOMINAL);
    m.mech.coulomb_nm = f(COULOMB_NOMINAL);
    m.enc_offset = r.range(0, 4095) as u32;
    m.enc_dir = if r.range(0, 1) == 0 { 1 } else { -1 };
    m.locked = false;
    m
}

fn calibrate(m: &SimMotor) -> (Results, u64) {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    sim.apply_sim_motor(m).unwrap();
    let cfg = ServoConfig::for_plant(
        models::pmsm::params::MotorParams::default(),
        sim.config().adc_amps_per_count,
    );
    let mut bus = Bus(sim);
    let mut s = Servo::new(&cfg).unwrap();
    s.init(&mut bus).unwrap();
    s.set_mode(&mut bus, Mode::Foc).unwrap();
    let setup = s.calibration_setup(8.0, 16.0, Phases::ALL);
    let rep = s
        .calibrate(&mut bus, &setup, &mut |_| {}, &mut || false)
        .unwrap();
    assert_eq!(rep.stopped, None);
    assert!(!s.gates_on(&mut bus).unwrap());
    (rep.results, rep.cycles)
}

fn el_deg(m: &SimMotor, est_counts: f64) -> f64 {
    let p = f64::from(m.motor.pole_pairs);
    let d = (est_counts - f64::from(m.enc_offset)) * p * 360.0 / 4096.0;
    d - 360.0 * (d / 360.0).round()
}

/// Relative error.
fn rel(est: f64, truth: f64) -> f64 {
    (est - truth) / truth
}

/// Ten seeded draws: every estimate within the bounds of the accuracy
/// table (docs/calibration.md), direction and pole pairs exact. Prints
/// the table's rows.
#[test]
fn calibrate_all_on_ten_random_motors() {
    let mut r = Rng(23);
    let mut worst = [0.0f64; 6];
    std::println!("draw | R % | L % | psi % | offset el deg | J % | b % | dir | p");
    for d in 0..10 {
        let m = draw(&mut r);
        let (res, _) = calibrate(&m);
        let e = *res
            .encoder
            .good()
            .unwrap_or_else(|| panic!("draw {d}: {:?} {m:?}", res.encoder));
        assert_eq!(
            (e.dir, e.pole_pairs),
            (m.enc_dir, m.motor.pole_pairs),
            "draw {d}"
        );
        let off = el_deg(&m, f64::from(e.zero_counts));
        let r_ = rel(res.resistance.good().unwrap().value, m.motor.r_s_ohm);
        let l_ = rel(res.inductance.good().unwrap().value, m.motor.l_d_h);
        let psi = rel(res.flux.good().unwrap().value, m.motor.psi_pm_wb);
        let mech = res.mechanics.good().unwrap();
        let j = rel(mech.j.value, m.mech.j_kg_m2);
        let b = rel(mech.b.value, m.mech.b_nm_s_per_rad);
        std::println!(
            "{d} | {:+.2} | {:+.2} | {:+.2} | {:+.2} | {:+.1} | {:+.1} | {} | {}",
            100.0 * r_,
            100.0 * l_,
            100.0 * psi,
            off,
            100.0 * j,
            100.0 * b,
            e.dir,
            e.pole_pairs
        );
        for (w, x) in worst.iter_mut().zip([r_, l_, psi, off / 100.0, j, b]) {
            *w = w.max(x.abs());
        }
    }
    std::println!(
        "worst | {:.2} % | {:.2} % | {:.2} % | {:.2} deg | {:.1} % | {:.1} %",
        100.0 * worst[0],
        100.0 * worst[1],
        100.0 * worst[2],
        100.0 * worst[3],
        100.0 * worst[4],
        100.0 * worst[5]
    );
    assert!(worst[0] < 0.03 && worst[1] < 0.03, "{worst:?}");
    assert!(worst[2] < 0.02, "{worst:?}");
    assert!(worst[3] < 0.01, "{worst:?}");
    assert!(worst[4] < 0.10 && worst[5] < 0.25, "{worst:?}");
}

/// One drawn motor (seed 1: 7 pole pairs, encoder offset 1397 counts):
/// every estimate within the accuracy bounds.
#[test]
fn calibrate_all_on_one_random_motor() {
    let mut r = Rng(1);
    let m = draw(&mut r);
    let (res, _) = calibrate(&m);
    std::println!("{res:?}");
    let e = *res.encoder.good().expect("encoder");
    assert_eq!((e.dir, e.pole_pairs), (m.enc_dir, m.motor.pole_pairs));
    assert!(el_deg(&m, f64::from(e.zero_counts)).abs() < 1.0, "{e:?}");
    assert!(rel(res.resistance.good().unwrap().value, m.motor.r_s_ohm).abs() < 0.03);
    assert!(rel(res.inductance.good().unwrap().value, m.motor.l_d_h).abs() < 0.03);
    assert!(rel(res.flux.good().unwrap().value, m.motor.psi_pm_wb).abs() < 0.02);
    let mech = res.mechanics.good().unwrap();
    assert!(rel(mech.j.value, m.mech.j_kg_m2).abs() < 0.10, "{mech:?}");
    assert!(
        rel(mech.b.value, m.mech.b_nm_s_per_rad).abs() < 0.25,
        "{mech:?}"
    );
}
