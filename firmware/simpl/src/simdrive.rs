//! [`SimDrive`]: the simulated `pl_top` ([`SimPl`]) coupled to the inverter
//! ([`super::inverter`]), the PMSM plant ([`Plant`], exact ZOH between
//! events) and the measurement chain (ADC counts of the phase currents at
//! each convert pulse, encoder A/B/Z levels from the rotor angle).
//!
//! Time: PL clock cycles (10 ns). The plant is advanced lazily, only when
//! its voltage changes (a gate edge), when the ADC samples it (convert
//! pulse), when the encoder moves by one count, and at the end of each
//! [`SimDrive::advance`]; between those instants its voltage is constant,
//! so the closed form is exact. A register access occupies one PL cycle (see
//! [`super::pl`]).

use super::adc::{adc_word, Converter};

/// Seed of the converter's data-ready draws ([`SimConfig::converter`]).
const CONVERTER_SEED: u64 = 0xADC0_DA7A;
use super::inverter::potentials;
use super::pl::{Events, Pins, SimPl};
use core::f64::consts::PI;
use models::pmsm::frames::leg_voltage_alpha_beta;
use models::pmsm::mechanics::Mechanics;
use models::pmsm::params::{check_finite, check_pos, MotorParams, ParamError};
use models::pmsm::plant::{MechanicalMode, Plant};
use models::pmsm::sim_motor::{SimMotor, SimSetError};
use regmap::bus::{BusError, RegisterBus};

/// Seconds per PL clock cycle.
pub const CYCLE_S: f64 = 1.0 / regmap::PL_CLOCK_HZ as f64;

/// Longest plant segment in cycles (4 us): in [`MechanicalMode::Inertia`]
/// the plant holds the speed constant within a segment.
const MAX_SEGMENT: u64 = 400;
/// Longest segment while a leg conducts through a diode with all gates off
/// (1 us): the diode choice is re-judged after it.
const DIODE_SEGMENT: u64 = 100;

/// The simulated motor, inverter and sensors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimConfig {
    /// Motor (default: the paper's Maxon EC 60 flat at 48 V).
    pub motor: MotorParams,
    /// Mechanics (default: constant speed, a dynamometer holds the rotor).
    pub mechanics: MechanicalMode,
    /// Electrical speed at the start (the constant speed in
    /// [`MechanicalMode::ConstantSpeed`]), rad/s. Default 0.
    pub omega_e_rad_s: f64,
    /// Current per ADC count, A (the board's shunt and amplifier): default
    /// 16 A full scale, 7.8125 mA per count (12-bit signed).
    pub adc_amps_per_count: f64,
    /// Conversion time of the ADC: its result (`drdy`) follows the convert
    /// pulse by this many cycles plus one. Default 50 (0.5 us). Must stay
    /// below ADC_PERIOD - 1 for every result to arrive.
    pub adc_conversion_cycles: u32,
    /// Extra delay of the converter's data-ready, drawn per conversion from
    /// `0..=adc_drdy_jitter_cycles` (an asynchronous converter: its edge has
    /// any phase against the PL clock). Default 0. Together with the
    /// conversion time and the width it must stay below ADC_PERIOD - 1.
    pub adc_drdy_jitter_cycles: u32,
    /// Data-ready high time, drawn per conversion from
    /// `1..=adc_drdy_width_cycles` cycles (0 counts as 1). Default 1.
    pub adc_drdy_width_cycles: u32,
    /// Encoder quadrature counts per mechanical revolution (4 per line);
    /// the index pulse is high during count 0. Default 4096 (ENC_CPR reset).
    pub encoder_cpr: u32,
}

impl Default for SimConfig {
    fn default() -> Self {
        Self {
            motor: MotorParams::default(),
            mechanics: MechanicalMode::ConstantSpeed,
            omega_e_rad_s: 0.0,
            adc_amps_per_count: 16.0 / 2048.0,
            adc_conversion_cycles: 50,
            adc_drdy_jitter_cycles: 0,
            adc_drdy_width_cycles: 1,
            encoder_cpr: 4096,
        }
    }
}

impl SimConfig {
    /// Checks every field (the motor and mechanics as [`Plant::new`] does).
    pub fn validate(&self) -> Result<(), ParamError> {
        Plant::new(&self.motor, 0.0, self.mechanics, self.omega_e_rad_s)?;
        check_pos("adc_amps_per_count", self.adc_amps_per_count)?;
        if self.adc_conversion_cycles > 60_000 {
            return Err(ParamError {
                field: "adc_conversion_cycles",
                reason: "must be at most 60000 (below the longest ADC_PERIOD)",
            });
        }
        if self.adc_drdy_jitter_cycles > 1000 || self.adc_drdy_width_cycles > 1000 {
            return Err(ParamError {
                field: "adc_drdy_jitter_cycles",
                reason: "jitter and width must be at most 1000 cycles each",
            });
        }
        if !(4..=65_535).contains(&self.encoder_cpr) {
            return Err(ParamError {
                field: "encoder_cpr",
                reason: "must be in 4..=65535 (ENC_CPR range)",
            });
        }
        Ok(())
    }

    /// The converter this configuration describes (seeded: the same draws
    /// on every model of `pl_top` given it).
    pub fn converter(&self) -> Converter {
        Converter::jittered(
            self.adc_conversion_cycles,
            self.adc_drdy_jitter_cycles,
            self.adc_drdy_width_cycles,
            CONVERTER_SEED,
        )
    }

    /// ADC counts of a phase current (round to nearest, saturated to the
    /// 12-bit range; NaN reads 0).
    pub fn adc_counts(&self, i_a: f64) -> i32 {
        let c = libm::round(i_a / self.adc_amps_per_count);
        if c.is_nan() {
            0
        } else {
            c.clamp(-2048.0, 2047.0) as i32
        }
    }
}

/// How the three current sensors are wired to the ADC's channels: a
/// wiring fault injected to test the drive's sensor check (default: each
/// channel measures its own phase with the right sign).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AdcWiring {
    /// The phase (0 = a) each channel a, b, c measures.
    pub source: [usize; 3],
    /// Each channel reads its phase's current negated.
    pub inverted: [bool; 3],
}

impl Default for AdcWiring {
    fn default() -> Self {
        Self {
            source: [0, 1, 2],
            inverted: [false; 3],
        }
    }
}

impl AdcWiring {
    /// The channels' currents from the phase currents `i`, A.
    pub fn apply(&self, i: [f64; 3]) -> [f64; 3] {
        core::array::from_fn(|ch| {
            let x = i[self.source[ch].min(2)];
            if self.inverted[ch] {
                -x
            } else {
                x
            }
        })
    }
}

/// What one [`SimDrive::advance`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Advance {
    /// PL cycles simulated (by this call).
    pub cycles: u64,
    /// Control-period boundaries crossed since the last `advance` (also
    /// those crossed during register accesses in between): PWM period starts
    /// in mode FOC-PWM, ADC average strobes otherwise (the MPDTC sequence's
    /// SAMPLE point), each judged by the mode in force in its cycle
    /// ([`Events::control_boundary`]), as `IRQ_STATUS.BOUNDARY` is.
    pub control_periods: u32,
    /// ADC average strobes crossed.
    pub adc_averages: u32,
    /// PWM period starts crossed.
    pub pwm_periods: u32,
}

/// Plant truth for diagnostics (the plant as of the end of the last
/// `advance`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Truth {
    /// Electromagnetic torque, N m.
    pub torque_nm: f64,
    /// d-axis current, A.
    pub i_d_a: f64,
    /// q-axis current, A.
    pub i_q_a: f64,
    /// Phase currents a, b, c, A.
    pub i_abc_a: [f64; 3],
    /// Electrical speed, rad/s.
    pub omega_e_rad_s: f64,
    /// Electrical angle, rad, `[0, 2 pi)`.
    pub theta_e_rad: f64,
    /// Mechanical angle since the start (not wrapped), rad.
    pub theta_m_rad: f64,
    /// Gate transitions per leg (a, b, c) since the start.
    pub transitions: [u64; 3],
}

/// What the simulation has cost so far (for estimating its run time on a
/// slower machine, e.g. the firmware under QEMU).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Work {
    /// PL cycles simulated one by one (events and register accesses).
    pub stepped_cycles: u64,
    /// Quiet spans jumped over in closed form.
    pub skips: u64,
    /// Plant segments (closed-form ZOH evaluations).
    pub plant_segments: u64,
}

/// A model of `pl_top` that [`SimDrive`] couples to the plant: the
/// event-driven [`SimPl`] (default), or the Verilated RTL in co-simulation
/// (`rtl-sim`'s bridge). Time in PL clock cycles; pins apply from the next
/// cycle on.
pub trait PlModel {
    /// PL cycles run since the release of reset.
    fn cycles(&self) -> u64;
    /// Gate outputs now (bit 2 = leg a).
    fn gates(&self) -> crate::gates::GateOutputs;
    /// Pin levels and converter data driven into the PL.
    fn pins_mut(&mut self) -> &mut Pins;
    /// Fits or removes the ADC card ([`crate::adc::Converter::set_fitted`]),
    /// from the next cycle on.
    fn set_adc_fitted(&mut self, fitted: bool);
    /// Runs up to `max` cycles without bus accesses, stopping after the
    /// first cycle whose events hit `stop`: (cycles run, merged events).
    fn run(&mut self, max: u64, stop: &Events) -> (u64, Events);
    /// Bus read (the cycles it takes are seen through [`Self::cycles`]).
    fn read(&mut self, addr: usize) -> (Result<u32, BusError>, Events);
    /// Bus write of a whole word.
    fn write(&mut self, addr: usize, value: u32) -> (Result<(), BusError>, Events);
    /// (cycles stepped one by one, closed-form skips) so far.
    fn work(&self) -> (u64, u64);
}

impl PlModel for SimPl {
    fn cycles(&self) -> u64 {
        SimPl::cycles(self)
    }
    fn gates(&self) -> crate::gates::GateOutputs {
        SimPl::gates(self)
    }
    fn pins_mut(&mut self) -> &mut Pins {
        &mut self.pins
    }
    fn set_adc_fitted(&mut self, fitted: bool) {
        SimPl::set_adc_fitted(self, fitted);
    }
    fn run(&mut self, max: u64, stop: &Events) -> (u64, Events) {
        SimPl::run(self, max, stop)
    }
    fn read(&mut self, addr: usize) -> (Result<u32, BusError>, Events) {
        SimPl::read(self, addr)
    }
    fn write(&mut self, addr: usize, value: u32) -> (Result<(), BusError>, Events) {
        SimPl::write(self, addr, value)
    }
    fn work(&self) -> (u64, u64) {
        (self.stepped, self.skips)
    }
}

/// Simulated `pl_top` + inverter + PMSM + ADC/encoder chain.
#[derive(Debug, Clone)]
pub struct SimDrive<P = SimPl> {
    pl: P,
    plant: Plant,
    cfg: SimConfig,
    /// Cycles since the plant was last advanced.
    lag: u64,
    /// Gate outputs the plant sees since its last advance.
    gates: (u8, u8),
    theta_m_rad: f64,
    /// Encoder count with the d axis on phase a (the rotor at angle 0).
    enc_offset: u32,
    /// Encoder direction, +1 or -1.
    enc_dir: i32,
    /// Mechanics while not locked (`sim set`).
    mech: Mechanics,
    /// Counts of the rotor angle (`floor(theta_m cpr / 2 pi)`), before the
    /// encoder's offset and direction.
    enc_count: i64,
    transitions: [u64; 3],
    carried: Advance,
    segments: u64,
    adc_wiring: AdcWiring,
    /// The encoder's pins are frozen (`sim set enc_dead`).
    enc_dead: bool,
    /// Disconnected phase, 0 none, 1..=3 a..c (`sim set phase_open`).
    phase_open: u8,
    /// The external fault input is asserted.
    fault_ext: bool,
    /// The encoder's A and B lines are inverted (`sim set enc_invert`).
    enc_invert: bool,
    /// The ADC card is fitted (`sim set adc_card`).
    adc_card: bool,
    /// PL cycle from which all six gate outputs have been off (`None`
    /// while one is on).
    gates_off_since: Option<u64>,
}

impl SimDrive {
    /// The drive right after the PL's reset, motor at rest current, angle 0.
    pub fn new(cfg: &SimConfig) -> Result<Self, ParamError> {
        cfg.validate()?;
        Self::with_pl(cfg, SimPl::with_converter(cfg.converter()))
    }
}

impl<P: PlModel> SimDrive<P> {
    /// The drive on another model of `pl_top` (right after its reset; its
    /// converter must be `cfg.converter()`, answering each convert pulse
    /// with the word in its pins).
    pub fn with_pl(cfg: &SimConfig, pl: P) -> Result<Self, ParamError> {
        cfg.validate()?;
        let plant = Plant::new(&cfg.motor, 0.0, cfg.mechanics, cfg.omega_e_rad_s)?;
        let mut s = Self {
            pl,
            plant,
            cfg: *cfg,
            lag: 0,
            gates: (0, 0),
            theta_m_rad: 0.0,
            enc_offset: 0,
            enc_dir: 1,
            mech: match cfg.mechanics {
                MechanicalMode::Joint(m) => m,
                _ => Mechanics::rotor(cfg.motor.j_kg_m2, cfg.motor.friction_nm_s_per_rad),
            },
            enc_count: 0,
            transitions: [0; 3],
            carried: Advance::default(),
            segments: 0,
            adc_wiring: AdcWiring::default(),
            enc_dead: false,
            phase_open: 0,
            fault_ext: false,
            enc_invert: false,
            adc_card: true,
            gates_off_since: Some(0),
        };
        s.update_encoder_pins();
        Ok(s)
    }

    /// The configuration.
    pub fn config(&self) -> &SimConfig {
        &self.cfg
    }

    /// PL cycles simulated since reset.
    pub fn pl_cycles(&self) -> u64 {
        self.pl.cycles()
    }

    /// Simulated time since reset, s.
    pub fn time_s(&self) -> f64 {
        self.pl.cycles() as f64 * CYCLE_S
    }

    /// `sim_time_scale` = guest (wall) time / simulated time, for a guest
    /// that has run `guest_s` seconds while this drive simulated
    /// [`Self::time_s`]; 0 before any simulated time.
    pub fn sim_time_scale(&self, guest_s: f64) -> f64 {
        let t = self.time_s();
        if t > 0.0 && guest_s.is_finite() {
            guest_s / t
        } else {
            0.0
        }
    }

    /// Work done so far.
    pub fn work(&self) -> Work {
        let (stepped_cycles, skips) = self.pl.work();
        Work {
            stepped_cycles,
            skips,
            plant_segments: self.segments,
        }
    }

    /// The PL model.
    pub fn pl(&self) -> &P {
        &self.pl
    }

    /// Gate outputs now (bit 2 = leg a).
    pub fn gates(&self) -> crate::gates::GateOutputs {
        self.pl.gates()
    }

    /// Changes the load torque (Inertia mechanics only), N m.
    pub fn set_load_torque_nm(&mut self, load_nm: f64) -> Result<(), ParamError> {
        check_finite("load_torque_nm", load_nm)?;
        self.plant.set_load_torque_nm(load_nm)
    }

    /// The simulated motor's true parameters (`sim list`).
    pub fn sim_motor(&self) -> SimMotor {
        SimMotor {
            motor: *self.plant.motor(),
            mech: self.mech,
            enc_offset: self.enc_offset,
            enc_dir: self.enc_dir,
            locked: !matches!(self.plant.mechanics(), MechanicalMode::Joint(_)),
            enc_dead: self.enc_dead,
            phase_open: self.phase_open,
            fault_ext: self.fault_ext,
            enc_invert: self.enc_invert,
            adc_card: self.adc_card,
        }
    }

    /// Sets one parameter of the simulated motor (`sim set`), checked as
    /// [`SimMotor::set`]; the rotor keeps its angle, speed and currents
    /// (locking it stops it). On an error nothing changes.
    pub fn sim_set(&mut self, name: &str, value: f64) -> Result<(), SimSetError> {
        let mut m = self.sim_motor();
        m.set(name, value, self.cfg.encoder_cpr)?;
        self.apply_sim_motor(&m).map_err(SimSetError::Bad)
    }

    /// Applies a whole set of the simulated motor's parameters (`sim reset`:
    /// [`SimMotor::default`]). On an error nothing changes.
    pub fn apply_sim_motor(&mut self, m: &SimMotor) -> Result<(), ParamError> {
        self.flush();
        if m.enc_offset >= self.cfg.encoder_cpr || !(m.enc_dir == 1 || m.enc_dir == -1) {
            return Err(ParamError {
                field: "enc_offset",
                reason: "must be below the counts per revolution, direction +1 or -1",
            });
        }
        let mut plant = self.plant.clone();
        plant.set_motor(&m.motor)?;
        plant.set_mechanics(m.mechanical_mode())?;
        if m.locked {
            let st = *plant.state();
            plant.set_state(st.i_alpha_a, st.i_beta_a, st.theta_e_rad, 0.0)?;
        }
        self.plant = plant;
        self.cfg.motor = m.motor;
        self.mech = m.mech;
        self.enc_offset = m.enc_offset;
        self.enc_dir = m.enc_dir;
        self.enc_dead = m.enc_dead;
        self.phase_open = m.phase_open.min(3);
        self.set_external_fault(m.fault_ext);
        self.enc_invert = m.enc_invert;
        self.adc_card = m.adc_card;
        self.pl.set_adc_fitted(m.adc_card);
        self.update_encoder_pins();
        Ok(())
    }

    /// The plant, to set a state in a test.
    #[cfg(test)]
    pub(crate) fn plant_mut_for_tests(&mut self) -> &mut Plant {
        &mut self.plant
    }

    /// Drives the external fault input (active low at the pin): `true`
    /// asserts the fault from the next cycle on.
    pub fn set_external_fault(&mut self, asserted: bool) {
        self.fault_ext = asserted;
        self.pl.pins_mut().fault_ext_n = !asserted;
    }

    /// Plant truth (as of the end of the last [`Self::advance`]).
    pub fn truth(&self) -> Truth {
        let st = self.plant.state();
        let (i_d_a, i_q_a) = self.plant.i_dq_a();
        Truth {
            torque_nm: self.plant.torque_nm(),
            i_d_a,
            i_q_a,
            i_abc_a: self.plant.i_abc_a(),
            omega_e_rad_s: st.omega_e_rad_s,
            theta_e_rad: st.theta_e_rad,
            theta_m_rad: self.theta_m_rad,
            transitions: self.transitions,
        }
    }

    /// Rewires the current sensors to the ADC's channels (a fault for the
    /// sensor check to find), from the next conversion on.
    pub fn set_adc_wiring(&mut self, w: AdcWiring) {
        self.adc_wiring = w;
    }

    /// PL cycle from which all six gate outputs have been off, `None` while
    /// one is on: the instant a fault's gates-off took effect for good
    /// (a dead time alone ends when the next switch turns on).
    pub fn gates_off_since(&self) -> Option<u64> {
        self.gates_off_since
    }

    /// Control-period boundaries that register accesses crossed since the
    /// last advance (reported by the next one).
    pub fn boundaries_crossed(&self) -> u32 {
        self.carried.control_periods
    }

    /// Advances `cycles` PL cycles, event by event.
    pub fn advance(&mut self, cycles: u64) -> Advance {
        self.run(cycles, false)
    }

    /// Advances until just after the next control-period boundary (see
    /// [`Advance::control_periods`]), at most `max_cycles`.
    pub fn advance_to_boundary(&mut self, max_cycles: u64) -> Advance {
        self.run(max_cycles, true)
    }

    fn run(&mut self, max: u64, to_boundary: bool) -> Advance {
        let mut adv = core::mem::take(&mut self.carried);
        let mut left = max;
        while left > 0 {
            let enc = self.cycles_to_next_count();
            let (k, ev) = self.pl.run(left.min(enc), &Events::ALL);
            left -= k;
            adv.cycles += k;
            self.lag += k;
            let boundary = self.on_events(&ev, &mut adv);
            if self.lag >= MAX_SEGMENT || k == enc {
                // Inertia: bounded segments; encoder: the next count is due.
                self.flush();
            }
            if to_boundary && boundary {
                break;
            }
        }
        self.flush();
        adv
    }

    /// Reacts to the events of a stepped cycle; `true` at a control boundary.
    fn on_events(&mut self, ev: &Events, adv: &mut Advance) -> bool {
        if ev.gates {
            self.flush();
            let g = self.pl.gates();
            // A switch turning on is one transition of its leg.
            let on = (g.hi & !self.gates.0) | (g.lo & !self.gates.1);
            for (x, n) in self.transitions.iter_mut().enumerate() {
                *n += u64::from(on >> (2 - x) & 1);
            }
            self.gates = (g.hi, g.lo);
            self.gates_off_since = match (g.hi | g.lo, self.gates_off_since) {
                (0, Some(c)) => Some(c),
                (0, None) => Some(self.pl.cycles()),
                _ => None,
            };
        }
        if ev.adc_convert {
            self.flush();
            let i = self.adc_wiring.apply(self.plant.i_abc_a());
            self.pl.pins_mut().adc_word = adc_word(i.map(|x| self.cfg.adc_counts(x)));
        }
        adv.adc_averages += u32::from(ev.adc_average);
        adv.pwm_periods += u32::from(ev.pwm_period);
        // The PL's own judgement, cycle by cycle: the mode after a bus
        // access is not the mode of every cycle of it.
        adv.control_periods += u32::from(ev.control_boundary);
        ev.control_boundary
    }

    /// Cycles until the encoder moves by one count at the present speed.
    fn cycles_to_next_count(&self) -> u64 {
        let p = self.cfg.motor.pole_pairs as f64;
        let w_m = self.plant.state().omega_e_rad_s / p;
        if w_m == 0.0 || !w_m.is_finite() {
            return u64::MAX;
        }
        let per_count = 2.0 * PI / self.cfg.encoder_cpr as f64;
        let edge = if w_m > 0.0 {
            (self.enc_count + 1) as f64 * per_count
        } else {
            self.enc_count as f64 * per_count
        };
        let dt = (edge - self.theta_m_rad) / w_m;
        let c = libm::ceil(dt / CYCLE_S) as u64;
        c.saturating_sub(self.lag).max(1)
    }

    /// Advances the plant over the lagging cycles with the gate levels it
    /// has seen since its last advance, then moves the encoder pins.
    fn flush(&mut self) {
        let (hi, lo) = self.gates;
        while self.lag > 0 {
            let i = self.plant.i_abc_a();
            let pot = potentials(hi, lo, i);
            let diode = hi == 0 && lo == 0 && pot.is_some();
            let seg = self
                .lag
                .min(if diode { DIODE_SEGMENT } else { MAX_SEGMENT });
            let h = seg as f64 * CYCLE_S;
            match pot {
                Some(p) => {
                    let (ua, ub) = leg_voltage_alpha_beta(p, self.cfg.motor.u_dc_v);
                    self.plant.advance_voltage(ua, ub, h);
                }
                // Open circuit: no current, the rotor moves on its own.
                None => self.plant.advance_open(h),
            }
            if self.phase_open != 0 {
                self.open_phase();
            }
            self.theta_m_rad = self.plant.theta_m_rad();
            self.lag -= seg;
            self.segments += 1;
        }
        self.update_encoder_pins();
    }

    /// A disconnected phase `x` carries no current: its terminal floats to
    /// whatever voltage keeps `i_x = 0`, so the current keeps only its
    /// component across the other two phases. Modelled by removing the
    /// component along phase `x`'s axis after each plant segment (segments
    /// are at most `MAX_SEGMENT` cycles, short against `L / R`).
    fn open_phase(&mut self) {
        let st = *self.plant.state();
        let ang = -2.0 * PI / 3.0 * f64::from(self.phase_open - 1);
        let (ux, uy) = (libm::cos(ang), libm::sin(ang));
        let ix = st.i_alpha_a * ux + st.i_beta_a * uy;
        let _ = self.plant.set_state(
            st.i_alpha_a - ix * ux,
            st.i_beta_a - ix * uy,
            st.theta_e_rad,
            st.omega_e_rad_s,
        );
    }

    fn update_encoder_pins(&mut self) {
        let cpr = self.cfg.encoder_cpr as i64;
        let count = libm::floor(self.theta_m_rad / (2.0 * PI) * cpr as f64) as i64;
        self.enc_count = count;
        if self.enc_dead {
            // The lines hold their last levels.
            return;
        }
        let count = i64::from(self.enc_dir) * count + i64::from(self.enc_offset);
        let (a, b) = [(false, false), (true, false), (true, true), (false, true)]
            [count.rem_euclid(4) as usize];
        let (a, b) = (a ^ self.enc_invert, b ^ self.enc_invert);
        let z = count.rem_euclid(cpr) == 0;
        let pins = self.pl.pins_mut();
        pins.enc_a = a;
        pins.enc_b = b;
        pins.enc_z = z;
    }

    /// Accounts for the `cycles` a bus access took (one for [`SimPl`]).
    fn bus_events(&mut self, ev: &Events, cycles: u64) {
        self.lag += cycles;
        let mut adv = self.carried;
        adv.cycles += cycles;
        self.on_events(ev, &mut adv);
        self.carried = adv;
    }
}

impl<P: PlModel> RegisterBus for SimDrive<P> {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        let c0 = self.pl.cycles();
        let (r, ev) = self.pl.read(addr);
        self.bus_events(&ev, self.pl.cycles() - c0);
        r
    }

    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        let c0 = self.pl.cycles();
        let (r, ev) = self.pl.write(addr, value);
        self.bus_events(&ev, self.pl.cycles() - c0);
        r
    }
}
