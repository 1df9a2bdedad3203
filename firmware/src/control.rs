//! The drive in the firmware: the `Servo` shared between the control
//! interrupt and the console, the PL it talks to, and the interrupts that
//! pace it.
//!
//! Interrupts (one core, handlers do not nest):
//! - the *control interrupt* is the PL's: `irq_o` of `pl_top` on
//!   `IRQ_F2P[0]`, GIC SPI 61, raised at each control-period boundary once
//!   the step's sample is ready (`drive::pl::irq`). It runs
//!   `Servo::control_step`: it reads `BOUNDARY_AGE` (the start latency),
//!   acknowledges `IRQ_STATUS`, then heartbeat, measurement, FOC or MPDTC
//!   inputs. With a bitstream the line is the board's; no PS timer paces
//!   the loop. Under QEMU the PL model's line (the simulated PL's `irq_o`,
//!   or a boundary the co-simulation reported) sets SPI 61 pending through
//!   the distributor (`GICD_ISPENDR`): the same handler and acknowledge.
//!   A boundary that finds the previous one still pending is an overrun.
//!   `debug stall` makes it return early (no step, no heartbeat), so the
//!   PL's watchdog trips while the simulated PL keeps running. The stall
//!   is measured in PL time (the simulated PL's under QEMU: the drive's
//!   own clock, independent of how fast the host runs the guest); while it
//!   lasts the console waits, so the PL tick may use the whole CPU.
//! - the *PL tick* (global-timer comparator, IRQ 27; QEMU only) is the
//!   simulated PL's time: it advances the PL model by up to a control
//!   period and pends SPI 61 when the model's line is up. It is
//!   rescheduled so that the PL model and the control step take at most
//!   about half of the CPU (the rest is the console's): under QEMU the
//!   simulated PL may run slower than real time, `status` reports the
//!   ratio as `sim_time_scale`. With the co-simulated RTL (`cosim`) the PL
//!   runs in guest time on the host: the tick syncs it to now and is set
//!   just after the next control-period boundary the host reported.
use crate::ps::qspi::Qspi;
use crate::ps::{gic, timer};
use crate::{cosim, pl};
use core::cell::RefCell;
use drive::config::spi_nor::SpiNor;
use drive::config::{store, Config};
use drive::console::drive::LATCH_WAIT_PERIODS;
use drive::console::{Bench, DriveError, DriveOps, DriveStatus, Injection, PlKind, StoreStatus};
use drive::fieldbus::{ConfigValues, Link, LinkStatus};
use drive::hil::{self, HilError, HilReport, Paced, PacedStatus};
use drive::pl::capture::{CapSample, CapState, CapStatus, Trigger};
use drive::pl::fault::Faults;
use drive::pl::irq::{self as ctrl_irq, Latency};
use drive::pl::mpdcc::{Mpdcc, MpdccError};
use drive::pl::presence::{self, Selection};
use drive::pl::top::Mode;
use drive::servo::faults::FaultRecord;
use drive::servo::motion::MoveResult;
use drive::servo::sensors::{PlTime, SensorReport};
use drive::servo::{
    record_response, Servo, ServoConfig, ServoError, StepRecorder, StepResult, SweepPoint,
};
use models::motion::law::Impedance;
use models::mpdcc::mpdcc_fixed::Inputs;
use models::pmsm::sim_motor::{SimMotor, SimSetError};
use regmap::bus::{BusError, RegisterBus};
use simpl::{SimConfig, SimDrive};

/// The control interrupt: the PL's `IRQ_F2P[0]`.
pub const IRQ_CONTROL: u32 = gic::IRQ_F2P0;

/// What answers the drivers' register accesses.
// The state lives in one static (no heap): the size difference is the point.
#[allow(clippy::large_enum_variant)]
pub(crate) enum Backend {
    /// Our bitstream behind GP0.
    Gp0(pl::Gp0),
    /// No bitstream: the simulated PL and motor (`simpl`).
    Sim(SimDrive),
    /// No bitstream, QEMU with the bridge: the Verilated `pl_top` and the
    /// motor in the host process `pl-cosim`.
    Cosim(cosim::Cosim),
}

impl RegisterBus for Backend {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        match self {
            Backend::Gp0(b) => b.read(addr),
            Backend::Sim(b) => b.read(addr),
            Backend::Cosim(b) => b.read(addr),
        }
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        match self {
            Backend::Gp0(b) => b.write(addr, value),
            Backend::Sim(b) => b.write(addr, value),
            Backend::Cosim(b) => b.write(addr, value),
        }
    }
    fn read_many(&mut self, addrs: &[usize], out: &mut [u32]) -> Result<(), BusError> {
        match self {
            Backend::Gp0(b) => b.read_many(addrs, out),
            Backend::Sim(b) => b.read_many(addrs, out),
            Backend::Cosim(b) => b.read_many(addrs, out),
        }
    }
}

impl PlTime for Backend {
    fn wait_cycles(&mut self, cycles: u64) {
        match self {
            // The boundaries crossed are no control step's: dropped.
            Backend::Sim(sim) => {
                let _ = sim.advance(cycles);
            }
            // The PL runs on its own (in co-simulation up to the guest time
            // of the next access): the PS waits.
            Backend::Gp0(_) | Backend::Cosim(_) => {
                let until = timer::global_count() + guest_counts(cycles);
                while timer::global_count() < until {}
            }
        }
    }
}

struct State {
    servo: Servo,
    bus: Backend,
    pl: PlKind,
    /// The control interrupt was raised and has not run yet.
    control_pending: bool,
    /// PL time until which the control step is skipped (`debug stall`),
    /// PL clock cycles (simulated PL) or uptime us (bitstream).
    stall_until: u64,
    /// Global-timer count at the start of the current PL tick.
    tick_start: u64,
    /// Uptime when the simulated PL started, us.
    sim_start_us: u64,
    /// Co-simulation: global-timer count of the next PL tick, just after
    /// the next control-period boundary.
    next_tick: u64,
    /// The configuration store.
    store: StoreStatus,
    /// Control-period boundaries the next PL tick crosses without a
    /// control step (`debug fault overrun`, simulated PL).
    skip_boundaries: u32,
    /// PL cycle of the last injected fault's cause (`debug fault-time`).
    inject_cycle: u64,
    /// PL time at the start of the last control step.
    last_step_cycle: u64,
    /// PL time of the last heartbeat without a control step (`keep_alive`).
    last_beat: u64,
    /// Co-simulation: the next control step's boundary is the cause of a
    /// `debug fault overrun` (the second period without a step ends).
    overrun_cause_due: bool,
    /// A `debug fault` to make happen right after the next control step.
    pending_injection: Option<Injection>,
    /// Its outcome, for the console.
    injection_result: Option<Result<(), ServoError>>,
    /// The last `mpdcc run`.
    mpdcc_last: Option<HilReport>,
    /// Control interrupts taken.
    control_irq: u64,
    /// The control step's start latency after the boundary.
    latency: Latency,
    /// Co-simulation: boundaries that the last control step's read of
    /// `IRQ_STATUS` found crossed since the last sync (a step that started
    /// after the next boundary serves it as well, as the acknowledge
    /// clears its flag): the next sync's count less these is what is new.
    absorbed: u32,
    /// Co-simulation: the boundary reported by the last sync is one of the
    /// present timing, so the next one is a period after it. A console
    /// section that wrote registers may have moved the boundaries (a mode
    /// change turns the PWM period start into the boundary, a new ADC
    /// period or restart moves the averages): until a later sync reports
    /// a boundary, the ticks poll (`COSIM_POLL_DIV`;
    /// `drive::pl::irq::phase_known_after`).
    phase_known: bool,
    /// The drive's CANopen device (docs/canopen.md): its frames come and
    /// go through `crate::fieldbus`; the control interrupt hands it the
    /// servo after each step.
    canopen: Link<ConfigValues>,
    /// Frames the device produced in the control interrupt (an EMCY, a
    /// transition's answer), for the network path to send.
    can_out: heapless::Deque<canopen::CanFrame, CAN_OUT>,
    /// Frames dropped because [`State::can_out`] was full.
    can_out_lost: u32,
    /// `Servo::time_s` at the device's last boundary, s.
    canopen_time_s: f64,
}

/// Frames the control interrupt can leave for the network path between
/// two of its polls.
const CAN_OUT: usize = 16;

/// The drive state, touched only with IRQs masked (one core).
struct Shared(RefCell<Option<State>>);
// SAFETY: single core; every access is inside `crate::irq::free`.
unsafe impl Sync for Shared {}
static STATE: Shared = Shared(RefCell::new(None));

fn with<T>(f: impl FnOnce(&mut State) -> T) -> Option<T> {
    crate::irq::free(|| STATE.0.try_borrow_mut().ok()?.as_mut().map(f))
}

/// `with` for the console. In co-simulation its register accesses run the
/// PL to the guest time: they may cross a control-period boundary (served
/// at once, as the bitstream's interrupt is taken when the access ends) or
/// change the period (the next tick was planned with the old one), so the
/// PL is synced and the next tick planned again.
fn console<T>(f: impl FnOnce(&mut State) -> T) -> Option<T> {
    let r = crate::irq::free(|| {
        let mut st = STATE.0.try_borrow_mut().ok()?;
        let s = st.as_mut()?;
        let before = match &s.bus {
            Backend::Cosim(c) => Some((c.last.pl_cycles, c.writes)),
            _ => None,
        };
        let r = f(s);
        let mut raise = false;
        // The simulated PL: a boundary that this section's register
        // accesses crossed is served at its end, as a board takes the
        // control interrupt as soon as the accesses end. Left to the next
        // PL tick, a second section (an `mpdcc run` decision of up to 927
        // cycles each) could cross the next boundary first: a missed step.
        if let Backend::Sim(sim) = &mut s.bus {
            if sim.boundaries_crossed() > 0 {
                let n = sim.advance(0).control_periods;
                let line = sim.pl().irq_line();
                raise = s.serve(n, "console-sim") && line;
            }
        }
        if let (Some((before, writes)), Backend::Cosim(c)) = (before, &s.bus) {
            if c.last.pl_cycles != before {
                let wrote = c.writes != writes;
                let n = s.cosim_sync(timer::global_count(), wrote);
                raise = s.serve(n, "console-cosim");
                if !raise {
                    timer::set_compare(s.next_tick);
                }
            }
        }
        if raise {
            // Pending before the interrupts are back on: a PL tick taken
            // in between would advance past the next boundary first.
            gic::set_pending(IRQ_CONTROL);
        }
        Some(r)
    })?;
    Some(r)
}

/// From the panic and exception handlers (IRQs masked): every gate off on
/// whatever backend answers the drivers (`pl::gates_safe` has already
/// written GP0), and `GATE_EN` read back; `None` when there is no drive or
/// the handler interrupted a holder of the drive state.
pub fn gates_off_read_back() -> Option<bool> {
    let mut st = STATE.0.try_borrow_mut().ok()?;
    let s = st.as_mut()?;
    let mut pwm = drive::pl::pwm::Pwm(&mut s.bus);
    pwm.set_gates(false).ok()?;
    pwm.gates_enabled().ok()
}

/// What the PL check found, for the banner: `pl: ...` and the PS's words.
pub struct Boot {
    /// `PlKind` chosen.
    pub pl: PlKind,
    /// devcfg `INT_STS` as read.
    pub devcfg_int_sts: u32,
    /// SLCR `PSS_IDCODE` as read.
    pub pss_idcode: u32,
}

/// Presence check, then the drive on what was found. Call once, IRQs off.
/// A simulated PL only where `PSS_IDCODE` says QEMU
/// (`drive::pl::presence`): a board without our bitstream gets none.
pub fn init() -> Boot {
    let sts = pl::devcfg_int_sts();
    let idcode = pl::pss_idcode();
    let selection = presence::select(pl::detect(), presence::platform(idcode));
    let mut cfg = ServoConfig::default();
    let bus = match selection {
        Selection::Bitstream { .. } => Some(Backend::Gp0(pl::Gp0)),
        // The semihosting probe runs only here: an emulator answers it.
        Selection::Simulated => match cosim::Cosim::open() {
            // QEMU runs the bridge: the Verilated PL with the same
            // simulated motor.
            Some(c) => {
                let sim = SimConfig::default();
                cfg = ServoConfig::for_plant(sim.motor, sim.adc_amps_per_count);
                Some(Backend::Cosim(c))
            }
            // The simulated PL (the paper's motor, held at standstill),
            // read through the same drivers.
            None => {
                let sim = SimDrive::new(&SimConfig::default()).expect("paper motor parameters");
                cfg = ServoConfig::for_plant(sim.config().motor, sim.config().adc_amps_per_count);
                Some(Backend::Sim(sim))
            }
        },
        Selection::Absent(_) => None,
    };
    let pl_kind = PlKind::of(selection, matches!(bus, Some(Backend::Cosim(_))));
    // The saved configuration, if the flash holds a valid one.
    let mut store = StoreStatus {
        slots: [store::SlotState::Empty; 2],
        loaded: None,
    };
    match store::load(&mut SpiNor(Qspi::init()), &cfg) {
        Ok(l) => {
            store.slots = l.slots;
            if let Some((c, slot)) = l.config {
                cfg = c.apply(&cfg);
                store.loaded = Some(slot);
            }
            defmt::info!(
                "config flash: loaded slot {=?}",
                store.loaded.map(|s| s as u8)
            );
        }
        Err(_) => defmt::warn!("config flash: not readable, defaults"),
    }
    if let Some(mut bus) = bus {
        let mut servo = Servo::new(&cfg).expect("servo configuration");
        let mut link = Link::new(drive::fieldbus::NODE_ID, ConfigValues::new(cfg))
            .expect("CANopen node-ID in 1..=127");
        let mut can_out = heapless::Deque::new();
        for f in link.boot().iter() {
            let _ = can_out.push_back(*f);
        }
        if servo.init(&mut bus).is_ok() && ctrl_irq::enable(&mut bus).is_ok() {
            crate::irq::free(|| {
                *STATE.0.borrow_mut() = Some(State {
                    servo,
                    bus,
                    pl: pl_kind,
                    control_pending: false,
                    stall_until: 0,
                    tick_start: 0,
                    sim_start_us: timer::uptime_us(),
                    next_tick: 0,
                    skip_boundaries: 0,
                    inject_cycle: 0,
                    last_step_cycle: 0,
                    last_beat: 0,
                    overrun_cause_due: false,
                    pending_injection: None,
                    injection_result: None,
                    mpdcc_last: None,
                    control_irq: 0,
                    latency: Latency::default(),
                    absorbed: 0,
                    phase_known: false,
                    store,
                    canopen: link,
                    can_out,
                    can_out_lost: 0,
                    canopen_time_s: 0.0,
                });
            });
            // Above the PL tick (IRQ 27, which at equal priority would win
            // by its lower ID): a pending control step runs before the
            // tick advances the simulated PL to the next boundary, which
            // would count the pending one as missed.
            gic::enable_at(IRQ_CONTROL, gic::PRIORITY_HIGH);
            if !matches!(pl_kind, PlKind::Bitstream(_)) {
                // The PL model's time under QEMU.
                gic::enable(gic::IRQ_GLOBAL_TIMER);
                let first = with(|s| s.first_tick(timer::global_count()))
                    .unwrap_or(timer::global_count() + 1000);
                timer::set_compare(first);
            }
        }
    }
    Boot {
        pl: pl_kind,
        devcfg_int_sts: sts,
        pss_idcode: idcode,
    }
}

/// PL clock cycles of one control period of the active mode.
fn period_cycles(servo: &Servo) -> u64 {
    servo.control_period_cycles()
}

/// Global-timer counts of `cycles` PL clock cycles at real-time speed.
fn guest_counts(cycles: u64) -> u64 {
    cycles * u64::from(timer::PERIPHCLK_HZ / 1_000_000) / 100
}

/// The firmware's periodic tick (the private timer, 1 kHz): with our
/// bitstream, the watchdog's heartbeat while the gates are off and no
/// control-period boundary comes (`State::keep_alive`). Under QEMU the PL
/// tick does it (the private timer runs at 0.3x there, too slow for the
/// 2 ms watchdog).
pub fn on_tick() {
    let _ = with(|s| {
        if matches!(s.bus, Backend::Gp0(_)) {
            s.keep_alive();
        }
    });
}

/// The PL tick (global-timer comparator interrupt).
pub fn on_pl_tick() {
    timer::ack_compare();
    let now = timer::global_count();
    let raise = with(|s| {
        s.tick_start = now;
        if s.control_pending && gic::is_pending(IRQ_CONTROL) {
            // The control step runs first (it has the higher priority and
            // plans the next tick): advancing the PL now would count its
            // boundary as missed.
            return false;
        }
        let boundaries = match &mut s.bus {
            // Up to the next control-period boundary (at most two periods).
            Backend::Sim(sim) => {
                let period = period_cycles(&s.servo);
                // A boundary that the console's register accesses crossed is
                // served now (on a board the control interrupt is taken as
                // soon as the access ends), not one period later. A stuck
                // ADC is the PL's own fault (its result timer), as on a
                // board.
                let mut n = if sim.boundaries_crossed() > 0 {
                    sim.advance(0).control_periods
                } else {
                    sim.advance_to_boundary(2 * period).control_periods
                };
                // `debug fault overrun`: more boundaries before the step.
                let skip = core::mem::take(&mut s.skip_boundaries);
                for _ in 0..skip {
                    n += sim.advance_to_boundary(2 * period).control_periods;
                }
                if skip > 0 {
                    // The second period without a step ends here.
                    s.inject_cycle = sim.pl_cycles();
                }
                if n == 0 {
                    // The PL's own faults (its ADC result timer) first.
                    let _ = s.servo.note_pl_faults(sim);
                    // No result from the ADC that paces the period.
                    let _ = s.servo.note_no_boundary(sim, 2);
                    s.keep_alive();
                }
                n
            }
            // The bitstream's PL paces the step itself (no tick runs).
            Backend::Gp0(_) => 0,
            // The PL runs to now; the next tick comes just after the next
            // boundary (one global-timer count per PL cycle under QEMU).
            Backend::Cosim(_) => {
                let n = s.cosim_sync(now, false);
                if n == 0 {
                    // No step to see the PL's faults (a stuck ADC stops
                    // the MPDTC's boundaries).
                    let _ = s.servo.note_pl_faults(&mut s.bus);
                    s.keep_alive();
                }
                n
            }
        };
        // The simulated PL's line, as the board's would be sampled.
        let line = match &s.bus {
            Backend::Sim(sim) => sim.pl().irq_line(),
            _ => true,
        };
        s.serve(boundaries, "tick") && line
    })
    .unwrap_or(false);
    if raise {
        gic::set_pending(IRQ_CONTROL);
    } else {
        // The simulated PL: a tick that took longer than the spacing (no
        // ADC result, so no boundary: two periods of the plant simulated
        // with the gates off, in short diode segments, on a slow host in
        // real-time QEMU) would set a compare already past and run again
        // at once, and the console would never run; so the next tick comes
        // at least half a spacing after this one's end. (Co-simulation
        // keeps its planned tick: it follows the PL's boundaries.)
        let floor = timer::global_count() + guest_counts(1564) / 2;
        let next = with(|s| match s.bus {
            Backend::Cosim(_) => s.next_tick,
            _ => (now + guest_counts(1564)).max(floor),
        })
        .unwrap_or((now + guest_counts(1564)).max(floor));
        timer::set_compare(next);
    }
}

/// Global-timer counts between a control-period boundary and the PL tick
/// that serves it in co-simulation (the boundary is reported one cycle
/// after the strobe; a little margin keeps the tick after it).
const COSIM_TICK_LAG: u64 = 4;

/// Co-simulation: while the boundaries' phase is not known (after a
/// console section's register writes), or a boundary is due but not yet
/// seen (`drive::pl::irq::next_cosim_tick`), a PL tick every `1 / COSIM_POLL_DIV`
/// of the period looks for the first boundary: the first step after a
/// mode change starts at most that late (MPDTC 195, FOC 782 PL cycles)
/// plus the handler's entry, instead of up to a period, as when the next
/// tick was planned from a boundary of the old timing.
const COSIM_POLL_DIV: u64 = 8;

/// The control interrupt.
pub fn on_control() {
    with(|s| {
        s.control_pending = false;
        s.control_irq += 1;
        // Latency first: the age counts on while the step runs.
        let boundary = match ctrl_irq::take(&mut s.bus) {
            Ok(t) if t.status.boundary() => {
                if let Backend::Cosim(c) = &s.bus {
                    // Boundaries past the one the step was raised for:
                    // this step serves them too (one acknowledge), they
                    // are steps lost, and the next sync must not raise
                    // the interrupt for them again.
                    s.absorbed = c.last.boundaries;
                    if s.absorbed > 0 {
                        defmt::warn!(
                            "overrun: the step found {=u32} more boundaries, {=u32} PL cycles after its own",
                            s.absorbed,
                            t.age
                        );
                    }
                    s.servo.note_overruns(u64::from(s.absorbed));
                }
                s.latency.add(t.age);
                s.servo.note_step_age(t.age);
                if t.status.missed() {
                    if let Backend::Gp0(_) = s.bus {
                        // The PL saw a boundary the step did not.
                        s.servo.note_overruns(1);
                    }
                }
                true
            }
            // A fault flag alone: no step.
            Ok(_) => false,
            Err(_) => true,
        };
        let stalled = s.stalled();
        // Co-simulation `debug fault overrun`: steps left out.
        let skip = boundary && matches!(s.bus, Backend::Cosim(_)) && s.skip_boundaries > 0;
        if let (true, Backend::Cosim(c)) = (boundary && s.overrun_cause_due, &mut s.bus) {
            // The acknowledge may have been a posted write.
            if let Ok(l) = c.last_exact() {
                s.inject_cycle = l.pl_cycles - u64::from(l.since_boundary);
            }
            s.overrun_cause_due = false;
        }
        if stalled {
            s.servo.note_skipped();
        } else if skip {
            s.skip_boundaries -= 1;
            s.servo.note_overruns(1);
            s.overrun_cause_due = s.skip_boundaries == 0;
        } else if boundary {
            s.last_step_cycle = s.pl_now();
            // A bus error leaves the gates to the PL's own fault logic.
            let start = timer::global_count();
            let _ = s.servo.control_step(&mut s.bus);
            // After a step of the running controller (not during the
            // MPDTC's alignment, when the checks over a window wait).
            if s.servo.controlling() {
                if let Some(f) = s.pending_injection.take() {
                    s.injection_result = Some(inject_now(s, f));
                }
            }
            crate::telemetry::on_step(&s.servo, timer::global_count() - start);
            // The CANopen device at the boundary: set-points in, actual
            // values and faults out (after the step and its telemetry, so
            // the step's own count is unchanged).
            let now_s = s.servo.time_s();
            let dt = now_s - core::mem::replace(&mut s.canopen_time_s, now_s);
            if let Ok(out) = s.canopen.boundary(&mut s.servo, &mut s.bus, dt) {
                for f in out.iter() {
                    if s.can_out.push_back(*f).is_err() {
                        s.can_out_lost = s.can_out_lost.wrapping_add(1);
                    }
                }
            }
        }
        let end = timer::global_count();
        if let Backend::Gp0(_) = s.bus {
            // The PL paces the next step.
            return;
        }
        if let Backend::Cosim(_) = s.bus {
            // The PL runs in guest time: the next boundary, or at once
            // when the step ran past it (counted as an overrun there).
            timer::set_compare(s.next_tick.max(end + COSIM_TICK_LAG));
            return;
        }
        let busy = end.saturating_sub(s.tick_start);
        let nominal = guest_counts(period_cycles(&s.servo));
        // At most about half of the CPU for the PL and the control step,
        // all of it during a stall (the console waits for its end).
        let share = if stalled { busy } else { 2 * busy };
        timer::set_compare(s.tick_start + nominal.max(share));
    });
}

impl State {
    /// Global-timer count of the first PL tick. Co-simulation: the PL ran
    /// through the set-up with the interrupts masked, so the boundaries it
    /// crossed are no control steps owed: their flags are cleared, the
    /// bridge's count restarts, and the first tick comes just after the
    /// next boundary, which the first step serves with the loop's own
    /// latency (ticking at a fixed offset from the set-up instead served
    /// a boundary of the set-up up to a period late, or the next one
    /// twice).
    fn first_tick(&mut self, now: u64) -> u64 {
        if !matches!(self.bus, Backend::Cosim(_)) {
            return now + 1000;
        }
        let _ = ctrl_irq::clear(&mut self.bus);
        self.cosim_sync(timer::global_count(), false);
        self.next_tick
    }

    /// The sensor check held the control loop off for milliseconds of PL
    /// time with the gates off: the boundaries it crossed are no overruns.
    fn after_sensor_check(&mut self) {
        if let Backend::Cosim(c) = &mut self.bus {
            let _ = c.sync();
        }
        self.control_pending = false;
    }

    /// Co-simulation: runs the PL to `now` (a global-timer count), plans
    /// the next tick just after the next boundary with the period now set,
    /// and returns the boundaries crossed since the previous sync; `wrote`:
    /// the sync ends a console section that wrote registers.
    fn cosim_sync(&mut self, now: u64, wrote: bool) -> u32 {
        let period = period_cycles(&self.servo);
        let Backend::Cosim(c) = &mut self.bus else {
            return 0;
        };
        let (mut n, since) = match c.sync() {
            Ok(r) => (r.boundaries, u64::from(r.since_boundary)),
            Err(_) => (0, u64::MAX),
        };
        // Those the last control step has served already.
        n = n.saturating_sub(core::mem::take(&mut self.absorbed));
        // A boundary reported after the last register writes fixes the
        // phase; one reported with them may be of the old timing.
        self.phase_known = ctrl_irq::phase_known_after(self.phase_known, wrote, n);
        self.next_tick = ctrl_irq::next_cosim_tick(
            ctrl_irq::SyncPoint {
                now,
                since,
                phase_known: self.phase_known,
            },
            period,
            COSIM_TICK_LAG,
            COSIM_POLL_DIV,
        );
        n
    }
    /// Marks a control step due for `boundaries` crossed; false if none.
    fn serve(&mut self, boundaries: u32, src: &'static str) -> bool {
        if boundaries == 0 {
            return false;
        }
        // Boundaries the control step did not see: the previous one still
        // pending, or more than one crossed at once.
        let missed = u64::from(self.control_pending) + u64::from(boundaries - 1);
        if missed > 0 {
            // Where a step was lost, for the log: who found the boundaries
            // (the PL tick or a console section's sync), how many, and
            // whether a step was still pending.
            defmt::warn!(
                "overrun: {=str} found {=u32} boundaries, a step pending: {=bool}",
                src,
                boundaries,
                self.control_pending
            );
        }
        self.servo.note_overruns(missed);
        self.control_pending = true;
        true
    }
    /// `status`'s figures, with the faults and gates read as one report.
    fn status(&self, mpdcc: Option<PacedStatus>, faults: Faults, gates_on: bool) -> DriveStatus {
        DriveStatus {
            mpdcc,
            mode: self.servo.mode(),
            mpdtc_autonomous: !self.servo.config().mpdtc_ps_fed,
            gates_on,
            faults,
            measured: self.servo.measured(),
            torque_ref_nm: self.servo.torque_ref_nm(),
            control_rate_hz: self.servo.control_rate_hz(),
            periods: self.servo.periods(),
            overruns: self.servo.overruns(),
            control_irq: self.control_irq,
            control_latency: self.latency,
            pl: self.pl,
            sim_time_scale: match &self.bus {
                Backend::Sim(sim) => {
                    let guest_s = (timer::uptime_us() - self.sim_start_us) as f64 * 1e-6;
                    Some(sim.sim_time_scale(guest_s))
                }
                Backend::Gp0(_) | Backend::Cosim(_) => None,
            },
            store: Some(self.store),
            motion: self.servo.motion_status(),
            aligning_left_s: self.servo.aligning_left_s(),
        }
    }

    /// PL time now: cycles of the simulated PL, or uptime in us.
    fn pl_now(&self) -> u64 {
        match &self.bus {
            Backend::Sim(sim) => sim.pl_cycles(),
            Backend::Cosim(c) => c.last.pl_cycles,
            Backend::Gp0(_) => timer::uptime_us(),
        }
    }
    /// PL time after `ms` milliseconds from now.
    fn pl_after_ms(&self, ms: u32) -> u64 {
        let per_ms = match &self.bus {
            Backend::Sim(_) | Backend::Cosim(_) => u64::from(regmap::PL_CLOCK_HZ / 1000),
            Backend::Gp0(_) => 1000,
        };
        self.pl_now() + u64::from(ms) * per_ms
    }
    /// PL time after `n` control periods from now.
    fn pl_after_periods(&self, n: u32) -> u64 {
        let cycles = period_cycles(&self.servo) * u64::from(n);
        match &self.bus {
            Backend::Sim(_) | Backend::Cosim(_) => self.pl_now() + cycles,
            // `pl_now` counts microseconds there.
            Backend::Gp0(_) => {
                self.pl_now() + cycles.div_ceil(u64::from(regmap::PL_CLOCK_HZ / 1_000_000))
            }
        }
    }
    /// Inside a `debug stall`.
    fn stalled(&self) -> bool {
        self.pl_now() < self.stall_until
    }
    /// The watchdog while the gates are off and no control step feeds it
    /// (`Servo::keep_alive`): a heartbeat once a quarter of its timeout
    /// has passed in PL time since the last step or heartbeat (so the PL
    /// tick's polls and a running loop add no register access). Not
    /// during `debug stall`, which stands for a hung control loop.
    fn keep_alive(&mut self) {
        let wdg = u64::from(self.servo.config().watchdog_cycles) / 4;
        let quarter = match &self.bus {
            Backend::Sim(_) | Backend::Cosim(_) => wdg,
            Backend::Gp0(_) => wdg * 1_000_000 / u64::from(regmap::PL_CLOCK_HZ),
        };
        let now = self.pl_now();
        let last = self.last_beat.max(self.last_step_cycle);
        if self.stalled() || now.saturating_sub(last) < quarter {
            return;
        }
        if let Ok(true) = self.servo.keep_alive(&mut self.bus) {
            self.last_beat = self.pl_now();
        }
    }
}

/// The console's handle on the drive. `mode mpdcc`'s HIL loop lives here,
/// in the main loop: its plant step can take several control periods (a
/// transition matrix not in the plant's cache is a 9 x 9 matrix
/// exponential), which the control interrupt must not wait for.
pub struct FwDrive {
    hil: Option<Paced>,
    /// `Servo::periods` when the loop was last served.
    hil_seen: u64,
    /// The telemetry stream.
    tel: crate::telemetry::Ops,
    /// Whether Ctrl-C arrived on the console: polled by the long commands
    /// that run with IRQs masked. The console's owner (`app`, which holds
    /// the UART and its receive ring) provides it, so that this module
    /// needs nothing from the one that calls it.
    interrupted: fn() -> bool,
}

impl FwDrive {
    /// No HIL loop; `interrupted` polls the console for Ctrl-C.
    pub const fn new(interrupted: fn() -> bool) -> Self {
        Self {
            hil: None,
            hil_seen: 0,
            tel: crate::telemetry::Ops,
            interrupted,
        }
    }

    /// Serves `mode mpdcc` from the main loop: one boundary of the loop
    /// when control periods passed since the last one (several passed: the
    /// plant waited, the loop still takes one decision). A stopped loop
    /// stays stopped; `status` says why.
    pub fn background(&mut self) {
        let Some(h) = &mut self.hil else { return };
        if h.status().stopped.is_some() {
            return;
        }
        let Some(now) = console(|s| s.servo.periods()) else {
            return;
        };
        if now == self.hil_seen {
            return;
        }
        self.hil_seen = now;
        // One critical section per register access: the plant step in
        // between runs with the control interrupt enabled.
        let _ = h.tick(&mut Mpdcc(Locked));
    }
}

/// The register bus, one critical section per access.
struct Locked;

impl RegisterBus for Locked {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        console(|s| s.bus.read(addr)).unwrap_or(Err(BusError::Absent))
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        console(|s| s.bus.write(addr, value)).unwrap_or(Err(BusError::Absent))
    }
}

fn run<T>(f: impl FnOnce(&mut State) -> Result<T, ServoError>) -> Result<T, DriveError> {
    match console(f) {
        Some(r) => Ok(r?),
        None => Err(DriveError::Absent),
    }
}

/// `debug flash-pace`: extra time around each flash erase and program, ms.
static FLASH_PACE_MS: core::sync::atomic::AtomicU32 = core::sync::atomic::AtomicU32::new(0);

/// Makes fault `f` happen now and notes its cause's PL cycle.
fn inject_now(s: &mut State, f: Injection) -> Result<(), ServoError> {
    let unsupported = || ServoError::Bus(BusError::SlaveError);
    // `sim set` on the simulated motor of either PL; the cause is the PL's
    // present cycle (the change acts from the next one).
    let sim_set = |s: &mut State, name: &str, v: f64| -> Result<(), ServoError> {
        let ok = match &mut s.bus {
            Backend::Sim(sim) => sim.sim_set(name, v).is_ok(),
            Backend::Cosim(c) => matches!(c.sim_set(name, v), Ok(Ok(()))),
            Backend::Gp0(_) => false,
        };
        s.inject_cycle = s.pl_now();
        if ok {
            Ok(())
        } else {
            Err(unsupported())
        }
    };
    match f {
        Injection::AdcStuck => {
            drive::pl::adc::Adc(&mut s.bus).set_enabled(false)?;
            s.inject_cycle = s.pl_now();
            Ok(())
        }
        Injection::Overcurrent => {
            drive::pl::fault::Fault(&mut s.bus).set_oc_limit(0)?;
            s.inject_cycle = s.pl_now();
            Ok(())
        }
        Injection::External => match &mut s.bus {
            Backend::Sim(sim) => {
                // 10 us at the pin; a boundary crossed here is the next
                // tick's.
                sim.set_external_fault(true);
                s.inject_cycle = sim.pl_cycles();
                let _ = sim.advance(1000);
                sim.set_external_fault(false);
                Ok(())
            }
            Backend::Cosim(_) => {
                sim_set(s, "fault_ext", 1.0)?;
                let until = timer::global_count() + guest_counts(1000);
                while timer::global_count() < until {}
                // Runs the PL over the 10 us.
                drive::pl::fault::Fault(&mut s.bus).latched()?;
                let cause = s.inject_cycle;
                sim_set(s, "fault_ext", 0.0)?;
                s.inject_cycle = cause;
                Ok(())
            }
            Backend::Gp0(_) => Err(unsupported()),
        },
        Injection::AdcSwap | Injection::AdcInvert => match &mut s.bus {
            Backend::Sim(sim) => {
                let mut w = simpl::AdcWiring::default();
                if f == Injection::AdcSwap {
                    w.source = [1, 0, 2];
                } else {
                    w.inverted[0] = true;
                }
                sim.set_adc_wiring(w);
                Ok(())
            }
            Backend::Gp0(_) | Backend::Cosim(_) => Err(unsupported()),
        },
        Injection::Overrun => match &s.bus {
            Backend::Sim(_) | Backend::Cosim(_) => {
                s.skip_boundaries = 2;
                Ok(())
            }
            Backend::Gp0(_) => Err(unsupported()),
        },
        Injection::PositionLimit | Injection::Overspeed => {
            s.servo.tighten_limit(f == Injection::Overspeed)?;
            s.inject_cycle = s.pl_now();
            Ok(())
        }
        Injection::EncoderDead => sim_set(s, "enc_dead", 1.0),
        Injection::EncoderLoss => sim_set(s, "enc_invert", 1.0),
        Injection::PhaseOpen => sim_set(s, "phase_open", 2.0),
        // Paced by the console (`FwDrive::inject`).
        Injection::Watchdog => Err(unsupported()),
    }
}

/// Sleeps until an interrupt.
/// After a `debug fault` of a PS check (decided at the step after the
/// cause): the answer waits until the control loop has recorded the fault,
/// at most 2 ms of PL time. The wait reads the drive's state only (no
/// register access, a few instructions with the interrupts masked), so
/// the steps that decide run on time; a console that polled `status`
/// instead held a deciding step off by its register reads (in
/// co-simulation a few hundred PL cycles), enough to take the gates-off
/// time past its one-period bound.
fn wait_recorded(f: Injection) {
    let bit = match f {
        Injection::EncoderDead => Faults::ENCODER_DEAD,
        Injection::PhaseOpen => Faults::PHASE_OPEN,
        Injection::PositionLimit => Faults::POSITION_LIMIT,
        Injection::Overspeed => Faults::OVERSPEED,
        _ => return,
    };
    let Some(until) = with(|s| s.pl_after_ms(2)) else {
        return;
    };
    while with(|s| s.servo.faults_recorded().0 & bit == 0 && s.pl_now() < until).unwrap_or(false) {
        wait();
    }
}

/// Waits until fault `bit` is latched and the control loop has recorded
/// it, at most [`LATCH_WAIT_PERIODS`] control periods of PL time: the
/// faults the loop saw latched, or `NotLatched`. The answer of
/// `debug fault` then matches what `fault` says right after it. The
/// loop's own view is polled, not the register: a register read syncs the
/// co-simulated PL, and syncs back to back while a step is pending count
/// as missed steps (`CONTROL_OVERRUN`).
fn wait_latched(bit: u32) -> Result<Faults, DriveError> {
    let until = with(|s| s.pl_after_periods(LATCH_WAIT_PERIODS)).ok_or(DriveError::Absent)?;
    loop {
        let (faults, now) =
            with(|s| (s.servo.faults_recorded(), s.pl_now())).ok_or(DriveError::Absent)?;
        if faults.0 & bit != 0 {
            return Ok(faults);
        }
        if now >= until {
            return Err(DriveError::NotLatched(bit));
        }
        wait();
    }
}

fn wait() {
    // SAFETY: WFI has no memory effects.
    unsafe { core::arch::asm!("wfi", options(nomem, nostack)) };
}

impl DriveOps for FwDrive {
    fn mode(&mut self) -> Mode {
        console(|s| s.servo.mode()).unwrap_or(Mode::Off)
    }
    fn set_mode(&mut self, m: Mode) -> Result<(), DriveError> {
        self.hil = None;
        run(|s| s.servo.set_mode(&mut s.bus, m))
    }
    fn set_mpdcc_mode(&mut self) -> Result<(), DriveError> {
        self.hil = None;
        run(|s| s.servo.set_mode(&mut s.bus, Mode::Off))?;
        let (p, f) = hil::default_core().map_err(|_| DriveError::Unsupported)?;
        console(|s| Mpdcc(&mut s.bus).load_coeffs(f.coeffs()))
            .ok_or(DriveError::Absent)?
            .map_err(page_error)?;
        self.hil = Some(Paced::new(&p).map_err(|_| DriveError::Unsupported)?);
        self.hil_seen = console(|s| s.servo.periods()).unwrap_or(0);
        Ok(())
    }
    fn mpdcc_live(&mut self) -> Option<PacedStatus> {
        self.hil.as_ref().map(Paced::status)
    }
    fn enable(&mut self) -> Result<(), DriveError> {
        run(|s| {
            let checked = s.servo.sensor_check_due();
            let r = s.servo.enable_checked(&mut s.bus);
            if checked {
                s.after_sensor_check();
            }
            r
        })
    }
    fn calibrate(
        &mut self,
        phases: models::calibration::Phases,
        on_phase: &mut dyn FnMut(Option<models::calibration::Phase>),
    ) -> Result<drive::servo::calibrate::CalReport, DriveError> {
        let mut interrupted = self.interrupted;
        run(|s| {
            let c = *s.servo.config();
            let setup =
                s.servo
                    .calibration_setup(c.calibration_current_a, c.calibration_voltage_v, phases);
            let r = s
                .servo
                .calibrate(&mut s.bus, &setup, on_phase, &mut interrupted);
            s.after_sensor_check();
            r
        })
    }
    fn sensor_check(&mut self) -> Result<SensorReport, DriveError> {
        run(|s| {
            let r = s.servo.check_sensors(&mut s.bus);
            s.after_sensor_check();
            r
        })
    }
    fn disable(&mut self) -> Result<(), DriveError> {
        run(|s| s.servo.disable(&mut s.bus))
    }
    fn torque_ref(&mut self) -> f64 {
        console(|s| s.servo.torque_ref_nm()).unwrap_or(0.0)
    }
    fn set_torque_ref(&mut self, nm: f64) -> Result<(), DriveError> {
        run(|s| s.servo.set_torque_ref(nm))
    }
    fn step(&mut self, nm: f64, window_s: f64) -> Result<StepResult, DriveError> {
        run(|s| s.servo.begin_step(&mut s.bus, nm, window_s))?;
        let mut copy = StepRecorder::new();
        // Generous: alignment plus the window, at any sim_time_scale seen.
        let deadline = timer::uptime_us() + 60_000_000;
        loop {
            // The metrics of the full recording take longer than a control
            // period: they are computed from a copy with the loop running.
            let (done, pending, period_s) = console(|s| {
                let done = s.servo.step_recording().map(|r| copy.copy_from(r));
                (
                    done.is_some(),
                    s.servo.step_pending(),
                    s.servo.control_period_s(),
                )
            })
            .ok_or(DriveError::Absent)?;
            if let Some(r) = copy.result(period_s).filter(|_| done) {
                return Ok(r);
            }
            if !pending {
                // The gates went off (fault) while recording.
                return Err(DriveError::Servo(ServoError::GatesOff));
            }
            if timer::uptime_us() > deadline {
                return Err(DriveError::Timeout);
            }
            wait();
        }
    }
    fn faults(&mut self) -> Result<Faults, DriveError> {
        run(|s| Ok(s.servo.faults(&mut s.bus)?))
    }
    fn clear_faults(&mut self) -> Result<Faults, DriveError> {
        run(|s| s.servo.clear_faults(&mut s.bus))
    }
    fn stall(&mut self, ms: u32) -> Result<(), DriveError> {
        run(|s| {
            s.stall_until = s.pl_after_ms(ms);
            Ok(())
        })?;
        while console(|s| s.stalled()).unwrap_or(false) {
            wait();
        }
        Ok(())
    }
    fn status(&mut self) -> DriveStatus {
        let mpdcc = self.mpdcc_live();
        console(|s| {
            let (faults, gates_on) = s.servo.faults_then_gates(&mut s.bus).unwrap_or_default();
            s.status(mpdcc, faults, gates_on)
        })
        .unwrap_or(DriveStatus::absent(mpdcc))
    }
    fn bench(&mut self) -> Result<Bench, DriveError> {
        crate::bench::run().ok_or(DriveError::Unsupported)
    }
    fn canopen(&mut self) -> Option<LinkStatus> {
        console(|s| s.canopen.status())
    }
    fn fault_record(&mut self, k: usize) -> Result<(Option<FaultRecord>, u32), DriveError> {
        run(|s| {
            let h = s.servo.fault_history();
            Ok((h.records().nth(k).copied(), h.total))
        })
    }
    fn inject(&mut self, f: Injection) -> Result<Option<Faults>, DriveError> {
        let r = match f {
            Injection::Watchdog => {
                run(|s| {
                    // The last heartbeat is the last step's (written at its
                    // start): the timeout runs out that long after it.
                    let wdg = u64::from(s.servo.config().watchdog_cycles);
                    s.inject_cycle = s.last_step_cycle + wdg;
                    s.stall_until = s.pl_after_ms(3);
                    Ok(())
                })?;
                while console(|s| s.stalled()).unwrap_or(false) {
                    wait();
                }
                Ok(None)
            }
            Injection::Overrun | Injection::AdcSwap | Injection::AdcInvert => {
                run(|s| inject_now(s, f)).map(|()| None)
            }
            _ => {
                // At a fixed point of the control period: right after the
                // next control step of the running controller (after the
                // MPDTC's alignment; the PL's cycle count from the
                // boundary is the step's own, the same every time on the
                // simulated PL); at once with the gates off (no step).
                let gates = run(|s| Ok(s.servo.gates_on(&mut s.bus)?))?;
                if !gates {
                    run(|s| inject_now(s, f)).map(|()| None)
                } else {
                    run(|s| {
                        s.pending_injection = Some(f);
                        s.injection_result = None;
                        Ok(())
                    })?;
                    // The MPDTC's alignment first (0.2 s of PL time; the simulated
                    // PL may run 150 times slower than real time).
                    let deadline = timer::uptime_us() + 60_000_000;
                    let r = loop {
                        if let Some(r) = console(|s| s.injection_result.take()).flatten() {
                            break r.map_err(DriveError::Servo);
                        }
                        if timer::uptime_us() > deadline {
                            let _ = console(|s| s.pending_injection = None);
                            break Err(DriveError::Timeout);
                        }
                        wait();
                    };
                    if r.is_ok() {
                        wait_recorded(f);
                    }
                    // A fault the PL latches within a period: the reply
                    // waits for it, so that `fault` right after shows it.
                    match (r, f.prompt_fault()) {
                        (Ok(()), Some(bit)) => wait_latched(bit).map(Some),
                        (r, _) => r.map(|()| None),
                    }
                }
            }
        };
        r.map_err(|e| match e {
            DriveError::Servo(ServoError::Bus(BusError::SlaveError)) => DriveError::Unsupported,
            e => e,
        })
    }
    fn fault_time(&mut self) -> Result<(u64, Option<u64>), DriveError> {
        console(|s| {
            let off = match &mut s.bus {
                Backend::Sim(sim) => sim.gates_off_since(),
                Backend::Cosim(c) => c
                    .gates_off_since()
                    .map_err(|e| DriveError::Servo(ServoError::Bus(e)))?,
                Backend::Gp0(_) => return Err(DriveError::Unsupported),
            };
            Ok((s.inject_cycle, off))
        })
        .unwrap_or(Err(DriveError::Absent))
    }
    fn config(&mut self) -> Result<ServoConfig, DriveError> {
        run(|s| Ok(*s.servo.config()))
    }
    fn flash_pace(&mut self, ms: u32) -> Result<(), DriveError> {
        FLASH_PACE_MS.store(ms, core::sync::atomic::Ordering::Relaxed);
        Ok(())
    }
    fn save_config(&mut self) -> Result<usize, DriveError> {
        save_config()
    }
    fn reconfigure(&mut self, cfg: &ServoConfig) -> Result<(), DriveError> {
        reconfigure(cfg)
    }
    fn capture_arm(&mut self, t: Trigger, pre: u32, every: u32) -> Result<(), DriveError> {
        run(|s| s.servo.capture_arm(&mut s.bus, t, pre, every))
    }
    fn capture_trigger(&mut self) -> Result<(), DriveError> {
        run(|s| s.servo.capture_trigger(&mut s.bus))
    }
    fn capture_status(&mut self) -> Result<CapStatus, DriveError> {
        run(|s| s.servo.capture_status(&mut s.bus))
    }
    fn capture_sample(&mut self, i: u32) -> Result<CapSample, DriveError> {
        run(|s| s.servo.capture_sample(&mut s.bus, i))
    }
    fn capture_period_s(&mut self) -> f64 {
        console(|s| s.servo.capture_period_s()).unwrap_or(0.0)
    }
    fn sweep_point(&mut self, f_hz: f64, amp_nm: f64) -> Result<SweepPoint, DriveError> {
        run(|s| s.servo.sine_start(&mut s.bus, f_hz, amp_nm))?;
        // Right after `enable` in MPDTC the settling starts at the end of
        // the rotor alignment (0.2 s): no torque follows the sine before.
        let deadline = timer::uptime_us() + 60_000_000;
        let aligning =
            || console(|s| s.servo.gates_on(&mut s.bus).unwrap_or(false) && !s.servo.controlling());
        while aligning().unwrap_or(false) {
            if timer::uptime_us() > deadline {
                return Err(DriveError::Timeout);
            }
            wait();
        }
        let settle_ms = (Servo::sine_settle_s(f_hz) * 1e3) as u32 + 1;
        let until = console(|s| s.pl_after_ms(settle_ms)).ok_or(DriveError::Absent)?;
        let deadline = timer::uptime_us() + 60_000_000;
        let alive = || console(|s| s.servo.sine_running()).unwrap_or(false);
        while console(|s| s.pl_now() < until).unwrap_or(false) {
            if !alive() {
                return Err(DriveError::Servo(ServoError::GatesOff));
            }
            wait();
        }
        run(|s| {
            s.servo.capture_arm(&mut s.bus, Trigger::Manual, 0, 1)?;
            s.servo.capture_trigger(&mut s.bus)
        })?;
        let count = loop {
            let st = run(|s| s.servo.capture_status(&mut s.bus))?;
            if st.state == CapState::Done {
                break st.count;
            }
            if !alive() {
                return Err(DriveError::Servo(ServoError::GatesOff));
            }
            if timer::uptime_us() > deadline {
                return Err(DriveError::Timeout);
            }
            wait();
        };
        // One sample per critical section: the PL keeps running while the
        // record is read, and the control interrupt must not wait for all
        // of it (that would be a control overrun).
        let ts = console(|s| s.servo.capture_period_s()).ok_or(DriveError::Absent)?;
        let p = record_response(count, f_hz, ts, |i| {
            run(|s| s.servo.capture_sample(&mut s.bus, i))
        })?;
        p.ok_or(DriveError::Servo(ServoError::BadFrequency(f_hz)))
    }
    fn sweep_end(&mut self) {
        console(|s| s.servo.sine_stop());
    }
    fn mpdcc_run(&mut self, periods: u32) -> Result<HilReport, DriveError> {
        if !(1..=hil::MAX_PERIODS).contains(&periods) {
            return Err(DriveError::Unsupported);
        }
        // The run's bus accesses take PL time the control step does not get
        // (overruns, the PS's fault checks): never while the gates are on.
        run(|s| match s.servo.gates_on(&mut s.bus) {
            Ok(false) => Ok(()),
            Ok(true) => Err(ServoError::GatesOn),
            Err(b) => Err(ServoError::Bus(b)),
        })?;
        let (p, f) = hil::default_core().map_err(|_| DriveError::Unsupported)?;
        console(|s| Mpdcc(&mut s.bus).load_coeffs(f.coeffs()))
            .ok_or(DriveError::Absent)?
            .map_err(page_error)?;
        // One decision per critical section: the control interrupt and the
        // PL tick run in between; the plant runs here, outside.
        let mut decide = |x: &Inputs| {
            console(|s| Mpdcc(&mut s.bus).decide(x, MPDCC_POLLS))
                .unwrap_or(Err(MpdccError::Bus(BusError::Absent)))
        };
        let r = hil::run(&p, periods, &mut decide).map_err(|e| match e {
            HilError::Page(e) => page_error(e),
            _ => DriveError::Unsupported,
        })?;
        console(|s| s.mpdcc_last = Some(r));
        Ok(r)
    }
    fn mpdcc_report(&mut self) -> Option<HilReport> {
        console(|s| s.mpdcc_last).flatten()
    }
    fn telemetry(&mut self) -> Option<&mut dyn drive::console::TelOps> {
        Some(&mut self.tel)
    }
    fn mmu(&mut self) -> Result<drive::console::MmuReport, DriveError> {
        Ok(crate::ps::mmu::report())
    }
    fn provoke_abort(&mut self) -> Result<(), DriveError> {
        crate::ps::mmu::read_unmapped();
        Ok(())
    }
    fn sensor_check_due(&mut self) -> Option<bool> {
        console(|s| s.servo.sensor_check_due())
    }
    fn gp0_guard(&mut self) -> Option<drive::pl::presence::Guard> {
        Some(pl::guard())
    }
    fn sim_motor(&mut self) -> Result<SimMotor, DriveError> {
        console(|s| match &s.bus {
            Backend::Sim(sim) => Ok(sim.sim_motor()),
            Backend::Cosim(c) => Ok(c.motor),
            Backend::Gp0(_) => Err(DriveError::Unsupported),
        })
        .unwrap_or(Err(DriveError::Absent))
    }
    fn sim_set(&mut self, name: &str, v: f64) -> Result<Result<(), SimSetError>, DriveError> {
        console(|s| match &mut s.bus {
            Backend::Sim(sim) => Ok(sim.sim_set(name, v)),
            Backend::Cosim(c) => c
                .sim_set(name, v)
                .map_err(|e| DriveError::Servo(ServoError::Bus(e))),
            Backend::Gp0(_) => Err(DriveError::Unsupported),
        })
        .unwrap_or(Err(DriveError::Absent))
    }
    fn sim_reset(&mut self) -> Result<(), DriveError> {
        console(|s| match &mut s.bus {
            Backend::Sim(sim) => sim
                .apply_sim_motor(&SimMotor::default())
                .map_err(|_| DriveError::Unsupported),
            Backend::Cosim(c) => c
                .sim_reset()
                .map_err(|e| DriveError::Servo(ServoError::Bus(e))),
            Backend::Gp0(_) => Err(DriveError::Unsupported),
        })
        .unwrap_or(Err(DriveError::Absent))
    }
    fn set_velocity(&mut self, v: f64) -> Result<(), DriveError> {
        run(|s| s.servo.set_velocity(&mut s.bus, v))
    }
    fn set_position(&mut self, p: f64) -> Result<(), DriveError> {
        run(|s| s.servo.set_position(&mut s.bus, p))
    }
    fn zero_position(&mut self) -> Result<(), DriveError> {
        run(|s| s.servo.zero_position())
    }
    fn set_impedance(&mut self, c: &Impedance) -> Result<(), DriveError> {
        run(|s| s.servo.set_impedance(&mut s.bus, c))
    }
    fn run_move(&mut self, distance_rev: f64, window_s: f64) -> Result<MoveResult, DriveError> {
        run(|s| s.servo.begin_move(&mut s.bus, distance_rev, window_s))?;
        // Generous: the trajectory and the window at any sim_time_scale seen.
        let deadline = timer::uptime_us() + 600_000_000;
        loop {
            let (result, pending) = console(|s| (s.servo.move_result(), s.servo.move_pending()))
                .ok_or(DriveError::Absent)?;
            if let Some(r) = result {
                return Ok(r);
            }
            if !pending {
                // The gates went off (fault) or another command took over.
                return Err(DriveError::Servo(ServoError::GatesOff));
            }
            if timer::uptime_us() > deadline {
                return Err(DriveError::Timeout);
            }
            wait();
        }
    }
}

/// Status polls per MPDCC decision: one PL cycle each on the simulated PL,
/// more on the others; a decision takes at most 929 cycles in pl_top's build.
const MPDCC_POLLS: u32 = 2000;

/// The console's error for a failed MPDCC page access.
fn page_error(e: MpdccError) -> DriveError {
    match e {
        MpdccError::Bus(BusError::Absent) => DriveError::Absent,
        MpdccError::Bus(b) => DriveError::Servo(ServoError::Bus(b)),
        MpdccError::Timeout => DriveError::Timeout,
        MpdccError::Format(_) | MpdccError::Config(_) => DriveError::Unsupported,
    }
}

/// `config save`: the running configuration to the flash; the slot.
pub(crate) fn save_config() -> Result<usize, DriveError> {
    let sc = run(|s| Ok(*s.servo.config()))?;
    // The flash is the console's alone: no need to hold off the
    // control loop while it is written.
    let pace_us = u64::from(FLASH_PACE_MS.load(core::sync::atomic::Ordering::Relaxed)) * 1000;
    let mut paced = store::PacedFlash {
        flash: SpiNor(Qspi),
        pause: || {
            let end = timer::uptime_us() + pace_us;
            while timer::uptime_us() < end {
                core::hint::spin_loop();
            }
        },
    };
    let slot =
        store::save(&mut paced, &Config::from_servo(&sc), &sc).map_err(|_| DriveError::Flash)?;
    let mut flash = paced.flash;
    let l = store::load(&mut flash, &sc).map_err(|_| DriveError::Flash)?;
    console(|s| {
        s.store.slots = l.slots;
        s.store.loaded = Some(slot);
    });
    Ok(slot)
}

/// Installs the configuration `cfg` (gates off where it needs them).
pub(crate) fn reconfigure(cfg: &ServoConfig) -> Result<(), DriveError> {
    // The controllers are built with the control interrupt enabled (in
    // co-simulation, one instruction per ns, that arithmetic alone
    // spans several control periods); only their installation holds
    // it off, with the ADC period's restart (`Servo::adopt`: a step
    // between the two would wait for the new period's boundary on the
    // old one). The other PL registers follow one access per critical
    // section, as the MPDCC loop's: the gates are off and stay off
    // meanwhile.
    let next = Servo::rebuild(cfg).map_err(|e| DriveError::from(ServoError::BadConfig(e)))?;
    if let Some(pl) = run(|s| s.servo.adopt(&mut s.bus, next))? {
        pl.write_rest(&mut Locked)
            .map_err(|e| DriveError::from(ServoError::Bus(e)))?;
    }
    Ok(())
}

/// Runs `f` on the CANopen device, the servo and the PL with the drive's
/// state locked (as a console command does); `None` without a drive.
pub(crate) fn with_canopen<T>(
    f: impl FnOnce(&mut Link<ConfigValues>, &mut Servo, &mut Backend) -> T,
) -> Option<T> {
    console(|s| {
        let due = s.servo.sensor_check_due();
        let r = f(&mut s.canopen, &mut s.servo, &mut s.bus);
        if due && !s.servo.sensor_check_due() {
            s.after_sensor_check();
        }
        r
    })
}

/// Moves the frames the control interrupt left for the network path into
/// `out` (oldest first, as many as fit); returns how many were dropped
/// since boot.
pub(crate) fn take_can_out(out: &mut canopen::Frames) -> u32 {
    with(|s| {
        while out.len() < canopen::frame::MAX_FRAMES {
            match s.can_out.pop_front() {
                Some(f) => out.push(f),
                None => break,
            }
        }
        s.can_out_lost
    })
    .unwrap_or(0)
}
