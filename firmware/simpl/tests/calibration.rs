//! `calibrate` on the simulated PL and motor: the drive's calibration
//! (`drive::servo::calibrate` running `models::calibration`) against
//! simulated motors whose true parameters are drawn at random, with the
//! simulated inverter's dead time and the ADC's quantization and delay.
use drive::pl::top::Mode;
use drive::servo::sensors::PlTime;
use drive::servo::{Servo, ServoConfig};
use models::calibration::{Outcome, Phases, Results};
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
    let rep = s.calibrate(&mut bus, &setup, &mut |_| true).unwrap();
    assert_eq!(rep.stopped, None);
    assert!(!s.gates_on(&mut bus).unwrap());
    (rep.results, rep.cycles)
}

fn el_deg(m: &SimMotor, est_counts: f64) -> f64 {
    let p = f64::from(m.motor.pole_pairs);
    let d = (est_counts - f64::from(m.enc_offset)) * p * 360.0 / 4096.0;
    d - 360.0 * (d / 360.0).round()
}

#[test]
fn one_draw_debug() {
    let mut r = Rng(1);
    let m = draw(&mut r);
    let (res, cycles) = calibrate(&m);
    std::println!("truth {m:?}");
    std::println!("res {res:#?} cycles {cycles}");
    if let Outcome::Done(e) | Outcome::Poor(e, _) = res.encoder {
        std::println!("offset error {} el deg", el_deg(&m, e.zero_exact));
    }
}
