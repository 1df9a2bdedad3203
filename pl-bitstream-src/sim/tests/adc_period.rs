//! A shortened ADC period with the gates turned on right after it, on the
//! Verilated `pl_top` and on the simulated PL (`simpl`), cycle by cycle:
//! `Adc::set_period` restarts the conversions (ENABLE 0, the period, 1), so
//! the PL's ADC result timer (`ADC_PERIOD` + `ADC_STUCK_MARGIN_CYCLES`)
//! never sees the old period's countdown, and no `ADC_STUCK` trips. The
//! negative control writes the period register alone: the sample timer
//! runs out the old countdown, longer than the new period's result timer,
//! and `ADC_STUCK` trips on both PLs.
use drive::pl::adc::Adc;
use drive::pl::fault::{Fault, Faults};
use drive::pl::pwm::Pwm;
use drive::pl::top::{Mode, Top};
use regmap::bus::RegisterBus;
use regmap::regs::adc::{AdcPeriod, AdcPeriodValue};
use rtl_sim::pl_top::PlTopSim;
use simpl::adc::Converter;
use simpl::{SimConfig, SimDrive};

/// The long period first (15 us between conversions), then the paper's.
const LONG: u32 = 1500;
const SHORT: u32 = 391;
/// PL cycles after a conversion at which the period changes: most of the
/// long countdown still to run.
const AFTER_CONVERSION: u64 = 100;
/// PL cycles watched with the gates on: several short periods.
const WATCH: u64 = 8000;

/// A PL whose time the test lets pass.
trait Clocked: RegisterBus {
    fn run(&mut self, cycles: u64);
}

impl Clocked for PlTopSim {
    fn run(&mut self, cycles: u64) {
        self.idle(cycles as u32);
    }
}

impl Clocked for SimDrive {
    fn run(&mut self, cycles: u64) {
        let _ = self.advance(cycles);
    }
}

/// Mode FOC at 50 % duty, the long period; then, `AFTER_CONVERSION`
/// cycles after a new result, the short period (`restart`: through
/// `Adc::set_period`; else the register alone) and the gates on at once.
/// Returns the latched faults after `WATCH` cycles and the results counted
/// meanwhile.
fn shorten_then_enable<B: Clocked>(pl: &mut B, restart: bool) -> (Faults, u32) {
    Top(&mut *pl).set_mode(Mode::Foc).unwrap();
    Pwm(&mut *pl).set_duties([0.5; 3], 3128).unwrap();
    Adc(&mut *pl).set_period(LONG).unwrap();
    pl.run(4 * u64::from(LONG));
    let n = Adc(&mut *pl).count().unwrap();
    while Adc(&mut *pl).count().unwrap() == n {
        pl.run(1);
    }
    pl.run(AFTER_CONVERSION);
    if restart {
        Adc(&mut *pl).set_period(SHORT).unwrap();
    } else {
        AdcPeriod::write(&mut *pl, AdcPeriodValue::ZERO.with_value(SHORT)).unwrap();
    }
    Pwm(&mut *pl).set_gates(true).unwrap();
    let n0 = Adc(&mut *pl).count().unwrap();
    pl.run(WATCH);
    let f = Fault(&mut *pl).latched().unwrap();
    (f, Adc(&mut *pl).count().unwrap() - n0)
}

fn rtl() -> PlTopSim {
    let mut sim = PlTopSim::new();
    sim.adc = Some(Converter::new(10));
    sim
}

fn simulated() -> SimDrive {
    SimDrive::new(&SimConfig::default()).unwrap()
}

/// Averaged results (4 samples each) in `WATCH` cycles at the short
/// period, less one for the restart's phase.
const RESULTS_MIN: u32 = (WATCH / (4 * SHORT as u64)) as u32 - 1;

#[test]
fn a_shortened_period_then_the_gates_on_trips_nothing_on_both_pls() {
    let (f, n) = shorten_then_enable(&mut rtl(), true);
    assert!(f.none(), "RTL: {f:?}");
    assert!(n >= RESULTS_MIN, "RTL: {n} results");
    let (f, n) = shorten_then_enable(&mut simulated(), true);
    assert!(f.none(), "simulated PL: {f:?}");
    assert!(n >= RESULTS_MIN, "simulated PL: {n} results");
}

#[test]
fn the_period_written_alone_trips_adc_stuck_on_both_pls() {
    let (f, _) = shorten_then_enable(&mut rtl(), false);
    assert_eq!(f.0 & Faults::PL_MASK, Faults::ADC_STUCK, "RTL: {f:?}");
    let (f, _) = shorten_then_enable(&mut simulated(), false);
    assert_eq!(
        f.0 & Faults::PL_MASK,
        Faults::ADC_STUCK,
        "simulated PL: {f:?}"
    );
}
