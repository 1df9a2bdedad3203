//! `debug bench`: guest instructions of the control code.
//!
//! Counted on the A9 global timer: under QEMU with `-icount shift=0` every
//! guest instruction advances virtual time by exactly 1 ns and QEMU's A9
//! timers tick every 10 ns of virtual time, so one count = 10 guest
//! instructions. Each figure is the mean over [`RUNS`] calls (IRQs masked),
//! less the cost of an empty call, so the resolution is 10 / RUNS
//! instructions. (QEMU 7.2's Cortex-A9 has no PMU cycle counter: PMCCNTR
//! reads 0.) Without `-icount` the numbers are host-speed noise;
//! `scripts/bench` runs it with `-icount shift=0`.
use crate::ps::timer;
use drive::console::Bench;
use drive::hil::{self, Paced};
use drive::pl::mpdcc::Mpdcc;
use drive::pl::top::Mode;
use drive::servo::{Servo, ServoConfig};
use models::mpdcc::machine::expm;
use models::mpdcc::plant::Plant;
use models::pmsm::closed_loop::{Controller, Measurement};
use models::pmsm::foc::{Foc, FocParams};
use models::pmsm::params::MotorParams;
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::adc::{AdcCount, AdcIa, AdcIaValue, AdcIb, AdcIbValue, AdcIc, AdcIcValue};
use regmap::regs::enc::{EncCpr, EncCprValue, EncPos, EncPosValue, EncWindow, EncWindowValue};
use regmap::regs::mpdcc::{MpdccDecision, MpdccDecisionValue, MpdccStatus, MpdccStatusValue};
use regmap::regs::mpdtc::{MpdtcSeqStatus, MpdtcSeqStatusValue};
use regmap::regs::pwm::{GateCtrl, GateCtrlValue};
use regmap::seq_state;

/// Calls per figure.
const RUNS: u32 = 64;
/// Guest instructions per global-timer count under `-icount shift=0`.
const INSNS_PER_COUNT: u64 = 10;

fn total(f: &mut impl FnMut()) -> u64 {
    let t0 = timer::global_count();
    for _ in 0..RUNS {
        f();
    }
    timer::global_count() - t0
}

/// Mean instructions of `f` over [`RUNS`] calls, IRQs masked.
fn count(mut f: impl FnMut()) -> u32 {
    crate::irq::free(|| {
        let empty = total(&mut || core::hint::black_box(()));
        let full = total(&mut f);
        (full.saturating_sub(empty) * INSNS_PER_COUNT / u64::from(RUNS)) as u32
    })
}

/// A PL that answers every read like a running drive (gates on, the MPDTC
/// sequence in SAMPLE, aligned, a new ADC result every read of
/// `ADC_COUNT`; the MPDCC core done, keeping the start position (4, 4, 4))
/// and drops writes: the control code's own cost, without the simulated
/// PL's.
struct Quiet {
    adc_count: u32,
}

impl RegisterBus for Quiet {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        Ok(match addr {
            GateCtrl::ADDR => GateCtrlValue::ZERO.with_gate_en(true).bits(),
            MpdtcSeqStatus::ADDR => MpdtcSeqStatusValue::ZERO
                .with_state(seq_state::SAMPLE)
                .with_sampled(true)
                .with_aligned(true)
                .bits(),
            AdcIa::ADDR => AdcIaValue::ZERO.with_value_i32(200).bits(),
            AdcIb::ADDR => AdcIbValue::ZERO.with_value_i32(-100).bits(),
            AdcIc::ADDR => AdcIcValue::ZERO.with_value_i32(-100).bits(),
            EncCpr::ADDR => EncCprValue::ZERO.with_value(4096).bits(),
            EncPos::ADDR => EncPosValue::ZERO.with_value(1234).bits(),
            EncWindow::ADDR => EncWindowValue::ZERO.with_value(100_000).bits(),
            MpdccStatus::ADDR => MpdccStatusValue::ZERO.with_done(true).bits(),
            MpdccDecision::ADDR => MpdccDecisionValue::ZERO
                .with_s_a(4)
                .with_s_b(4)
                .with_s_c(4)
                .bits(),
            AdcCount::ADDR => {
                self.adc_count = self.adc_count.wrapping_add(1);
                self.adc_count
            }
            _ => 0,
        })
    }
    fn write(&mut self, _: usize, _: u32) -> Result<(), BusError> {
        Ok(())
    }
}

/// Runs the measurements; `None` if the control step latched a fault on
/// the quiet PL (its figure would not be the whole step's).
pub fn run() -> Option<Bench> {
    let motor = MotorParams::default();
    let mut foc = Foc::new(&motor, &FocParams::default()).expect("paper FOC parameters");
    let mut k = 0u32;
    let foc_step = count(|| {
        k += 1;
        let m = Measurement {
            i_abc_a: [2.0, -1.0, -1.0],
            theta_e_rad: 0.001 * k as f64,
            omega_e_rad_s: 100.0,
        };
        core::hint::black_box(foc.step(core::hint::black_box(&m), 0.4));
    });
    let mut servo = Servo::new(&ServoConfig::default()).expect("default servo configuration");
    let mut bus = Quiet { adc_count: 0 };
    let _ = servo.set_mode(&mut bus, Mode::Mpdtc);
    let _ = servo.enable(&mut bus);
    let _ = servo.set_torque_ref(0.4);
    let mpdtc_period = count(|| {
        let _ = servo.control_step(&mut bus);
    });
    // A fault would have stopped the controller part way: no figure then.
    if !servo.faults(&mut bus).map(|f| f.none()).unwrap_or(false) {
        return None;
    }
    // `mode mpdcc`: one boundary of the HIL loop (decision read, plant
    // step with its transition matrix cached, quantization, inputs and
    // START), and the 9 x 9 matrix exponential of a cache miss.
    let (p, _) = hil::default_core().ok()?;
    let mut h = Paced::new(&p).ok()?;
    let mut page = Mpdcc(Quiet { adc_count: 0 });
    h.tick(&mut page).ok()?;
    h.tick(&mut page).ok()?;
    let mpdcc_boundary = count(|| {
        let _ = h.tick(&mut page);
    });
    if h.status().stopped.is_some() {
        return None;
    }
    let a = Plant::new(&p).ok()?.augmented([4; 3]);
    let ts = p.controller.ts_pu(&p.machine);
    let a = a.map(|r| r.map(|v| v * ts));
    let mpdcc_expm = count(|| {
        core::hint::black_box(expm(core::hint::black_box(&a)));
    });
    let log_frame = count(crate::log::bench_frame);
    Some(Bench {
        log_frame,
        foc_step,
        mpdtc_period,
        mpdcc_boundary,
        mpdcc_expm,
        runs: RUNS,
    })
}
