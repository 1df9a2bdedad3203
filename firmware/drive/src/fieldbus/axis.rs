//! CiA 402 on the servo: the drive functions behind the node's state
//! machine. [`Axis::carry_out`] does what the transitions ask (gates on
//! and off, quick stop, fault reaction, fault reset);
//! [`Axis::exchange`], at each control boundary, hands the set-points of
//! the mode in 0x6061 to the servo's loops and takes its actual values
//! into the process image.
//!
//! The modes, on the torque loop 0x2100 chose (FOC or MPDTC):
//! - CST (10): 0x6071 (limited by 0x6072) is the torque reference.
//! - CSV (9): 0x60FF is the velocity loop's reference.
//! - CSP (8): 0x607A is the position loop's target; each new set-point
//!   starts the servo's trajectory to it (within `traj_vel_limit` and
//!   `traj_accel_limit`), so a stream of set-points one SYNC apart is
//!   followed with the trajectory's lag.
//! - HM (6), method 37: on entering the mode the present position becomes
//!   0 (taken under the velocity loop at 0 rev/s) and the position loop
//!   holds it; "homing attained" (statusword bit 12) and "target reached"
//!   (bit 10) then show.
//! - Vendor impedance (-1): 0x607A and 0x60FF are the law's position and
//!   velocity, 0x2101 its stiffness, damping and torque feed-forward.
//!
//! Set-points the servo refuses while the MPDTC aligns the rotor wait for
//! the alignment's end; any other refusal sets the statusword's "internal
//! limit active" (bit 11) and leaves the loop as it was.

use super::objects::{ConfigPort, DriveObjects};
use crate::pl::fault::Faults;
use crate::pl::top::Mode;
use crate::servo::sensors::PlTime;
use crate::servo::{Servo, ServoError};
use canopen::cia402::{mode, Action, State};
use canopen::node::Node;
use canopen::Frames;
use models::motion::law::Impedance;
use regmap::bus::{BusError, RegisterBus};

/// Statusword bit 12 in homing mode: homing attained.
pub const HOMING_ATTAINED: u16 = 1 << 12;
/// A quick stop (option codes 1..=8) ends once the speed is below this,
/// rev/s.
pub const QUICK_STOP_DONE_REV_S: f64 = 0.05;
/// ... or after this long, s: the gates then go off whatever the speed.
pub const QUICK_STOP_MAX_S: f64 = 0.5;

/// The CiA 402 error code (CiA 402-2 Table 2, the CiA 301 groups where it
/// has none) of the most significant latched fault.
pub fn error_code(f: Faults) -> u16 {
    let has = |bit: u32| f.0 & bit != 0;
    if has(Faults::OVERCURRENT) {
        0x2310 // continuous over-current
    } else if has(Faults::PHASE_OPEN) {
        0x3130 // phase failure
    } else if has(Faults::ENCODER_LOSS) || has(Faults::ENCODER_DEAD) {
        0x7305 // incremental sensor 1 fault
    } else if has(Faults::ADC_STUCK) {
        0x5210 // measurement circuit
    } else if has(Faults::OVERSPEED) {
        0x8400 // velocity speed controller
    } else if has(Faults::POSITION_LIMIT) {
        0x8612 // positioning controller: reference limit
    } else if has(Faults::WATCHDOG) || has(Faults::CONTROL_OVERRUN) {
        0x6010 // software reset (watchdog)
    } else if has(Faults::EXTERNAL) {
        0x9000 // external error
    } else {
        0x1000 // generic error
    }
}

/// Error register (0x1001) bits for a fault: generic (bit 0), and current
/// (bit 1) for an over-current.
fn register_bits(f: Faults) -> u8 {
    let current = f.0 & Faults::OVERCURRENT != 0;
    0x01 | if current { 0x02 } else { 0 }
}

/// A quick stop under way.
#[derive(Debug, Clone, Copy, PartialEq)]
struct QuickStop {
    option_code: i16,
    left_s: f64,
}

/// The mode last set up on the servo and the set-point it got.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Applied {
    None,
    Torque(i16),
    Velocity(i32),
    Position(i32),
    Homed,
    Impedance,
}

/// The CiA 402 axis's own state between calls.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    quick_stop: Option<QuickStop>,
    applied: Applied,
    /// Faults reported to the node, so each latch raises one EMCY.
    reported: u32,
    /// Servo refusals of a set-point since power-on.
    pub refusals: u32,
}

impl Default for Axis {
    fn default() -> Self {
        Self::new()
    }
}

impl Axis {
    pub const fn new() -> Self {
        Self {
            quick_stop: None,
            applied: Applied::None,
            reported: 0,
            refusals: 0,
        }
    }

    /// Carries out the actions the node's transitions left in `obj`,
    /// oldest first; returns the frames to send (EMCY of a failed enable).
    pub fn carry_out<B: PlTime, C: ConfigPort>(
        &mut self,
        servo: &mut Servo,
        bus: &mut B,
        obj: &mut DriveObjects<C>,
        node: &mut Node,
    ) -> Result<Frames, BusError> {
        let mut out = Frames::new();
        while let Some(a) = obj.actions.pop_front() {
            match a {
                Action::None | Action::PowerOn => {}
                Action::EnableOperation => {
                    self.applied = Applied::None;
                    self.quick_stop = None;
                    let m = if obj.image.torque_loop == 0 {
                        Mode::Foc
                    } else {
                        Mode::Mpdtc
                    };
                    let r = servo
                        .set_mode(bus, m)
                        .and_then(|()| servo.enable_checked(bus));
                    if let Err(e) = r {
                        servo.disable(bus).map_err(bus_error)?;
                        let f = match e {
                            ServoError::FaultLatched(f) => f,
                            _ => Faults(0),
                        };
                        raise_fault(f, obj, node, &mut out);
                    }
                }
                Action::DisableOperation | Action::PowerOff | Action::DisableAndPowerOff => {
                    self.quick_stop = None;
                    self.applied = Applied::None;
                    servo.disable(bus).map_err(bus_error)?;
                }
                Action::QuickStop { option_code } => {
                    self.applied = Applied::None;
                    if option_code == 0 || !servo.controlling() {
                        servo.disable(bus).map_err(bus_error)?;
                        node.quick_stop_complete(obj);
                    } else {
                        self.quick_stop = Some(QuickStop {
                            option_code,
                            left_s: QUICK_STOP_MAX_S,
                        });
                        if servo.set_velocity(bus, 0.0).is_err() {
                            self.refusals = self.refusals.saturating_add(1);
                        }
                    }
                }
                Action::FaultReaction => {
                    self.quick_stop = None;
                    self.applied = Applied::None;
                    servo.disable(bus).map_err(bus_error)?;
                    node.fault_reaction_complete(obj);
                }
                Action::ResetFault => {
                    let left = servo.clear_faults(bus).map_err(|e| match e {
                        ServoError::Bus(b) => b,
                        _ => BusError::SlaveError,
                    })?;
                    self.reported = left.0;
                    if left.none() {
                        obj.image.error_code = 0;
                        out.append(&node.clear_errors());
                    } else {
                        raise_fault(left, obj, node, &mut out);
                    }
                }
            }
        }
        Ok(out)
    }

    /// At a control boundary (after the servo's step): a new fault goes to
    /// the node (EMCY, transition 13), the quick stop advances, the mode's
    /// set-points go to the servo, and the actual values come back.
    /// `dt_s` is the time since the last call. Returns the frames to send.
    pub fn exchange<B: RegisterBus, C: ConfigPort>(
        &mut self,
        servo: &mut Servo,
        bus: &mut B,
        obj: &mut DriveObjects<C>,
        node: &mut Node,
        dt_s: f64,
    ) -> Result<Frames, BusError> {
        let mut out = Frames::new();
        let f = servo.faults_recorded();
        let state = node.drive().state();
        if !f.none()
            && f.0 != self.reported
            && !matches!(state, State::Fault | State::FaultReactionActive)
        {
            self.reported = f.0;
            raise_fault(f, obj, node, &mut out);
        }
        if let Some(q) = self.quick_stop.as_mut() {
            q.left_s -= dt_s;
            let v = libm::fabs(servo.motion_status().velocity_rev_s);
            if v < QUICK_STOP_DONE_REV_S || q.left_s <= 0.0 || !servo.controlling() {
                let stay = (5..=8).contains(&q.option_code) && servo.controlling();
                if !stay {
                    servo.disable(bus).map_err(bus_error)?;
                    node.quick_stop_complete(obj);
                }
                self.quick_stop = None;
            }
        } else if node.drive().state() == State::OperationEnabled {
            self.apply(servo, bus, obj, node)?;
        }
        // Last: the values a master reads next are the ones after this
        // boundary's set-points (a new zero shows with its statusword).
        self.actuals(servo, obj);
        Ok(out)
    }

    fn actuals<C: ConfigPort>(&self, servo: &Servo, obj: &mut DriveObjects<C>) {
        let st = servo.motion_status();
        let cpr = f64::from(servo.config().enc_cpr);
        let rated = servo.config().torque_limit_nm;
        let im = &mut obj.image;
        im.position_actual_counts = st.counts as i32;
        im.velocity_actual_counts_s = sat_i32(st.velocity_rev_s * cpr);
        im.following_error_counts = sat_i32(st.following_error_counts);
        im.torque_actual_permille = if rated > 0.0 {
            sat_i32(servo.measured().torque_nm / rated * 1000.0).clamp(-32768, 32767) as i16
        } else {
            0
        };
    }

    fn apply<B: RegisterBus, C: ConfigPort>(
        &mut self,
        servo: &mut Servo,
        bus: &mut B,
        obj: &mut DriveObjects<C>,
        node: &mut Node,
    ) -> Result<(), BusError> {
        if servo.aligning_left_s().is_some() {
            return Ok(());
        }
        let im = obj.image;
        let cpr = f64::from(servo.config().enc_cpr);
        let m = node.drive().mode_display();
        let want = match m {
            mode::CYCLIC_SYNC_TORQUE => {
                let lim = i32::from(im.max_torque_permille);
                Applied::Torque(i32::from(im.target_torque_permille).clamp(-lim, lim) as i16)
            }
            mode::CYCLIC_SYNC_VELOCITY => Applied::Velocity(im.target_velocity_counts_s),
            mode::CYCLIC_SYNC_POSITION => Applied::Position(im.target_position_counts),
            mode::HOMING => Applied::Homed,
            mode::VENDOR => Applied::Impedance,
            _ => Applied::None,
        };
        if want == self.applied && want != Applied::Impedance {
            return Ok(());
        }
        let rated = servo.config().torque_limit_nm;
        let r = match want {
            Applied::None => Ok(()),
            Applied::Torque(p) => servo.set_torque_ref(f64::from(p) / 1000.0 * rated),
            Applied::Velocity(v) => servo.set_velocity(bus, f64::from(v) / cpr),
            Applied::Position(p) => servo.set_position(bus, f64::from(p) / cpr),
            // The velocity loop at 0 first: a loop that holds a position
            // refuses a new zero (the held target would jump); then the
            // position loop holds the new 0.
            Applied::Homed => servo
                .set_velocity(bus, 0.0)
                .and_then(|()| servo.zero_position())
                .and_then(|()| servo.set_position(bus, 0.0)),
            Applied::Impedance => servo.set_impedance(
                bus,
                &Impedance {
                    p: f64::from(im.target_position_counts) / cpr,
                    v: f64::from(im.target_velocity_counts_s) / cpr,
                    kp: f64::from(im.impedance.kp_nm_per_rev),
                    kd: f64::from(im.impedance.kd_nm_s_per_rev),
                    t_ff: f64::from(im.impedance.torque_ff_nm),
                },
            ),
        };
        let d = node.drive_inputs();
        match r {
            Ok(()) => {
                self.applied = want;
                d.set_internal_limit(false);
                if want == Applied::Homed {
                    d.set_application_bits(HOMING_ATTAINED);
                    d.set_target_reached(true);
                } else {
                    d.set_application_bits(0);
                }
            }
            Err(ServoError::Bus(e)) => return Err(e),
            Err(_) => {
                self.refusals = self.refusals.saturating_add(1);
                d.set_internal_limit(true);
            }
        }
        Ok(())
    }
}

/// A drive fault `f` to the node (CiA 402 transition 13, EMCY with its
/// code, the fault bits in the manufacturer bytes) and to 0x603F; its
/// frames go to `out`.
fn raise_fault<C: ConfigPort>(
    f: Faults,
    obj: &mut DriveObjects<C>,
    node: &mut Node,
    out: &mut Frames,
) {
    let code = error_code(f);
    obj.image.error_code = code;
    out.append(&node.drive_fault(obj, code, register_bits(f), mfr_bytes(f)));
}

/// The drive's fault bits, little-endian, in the EMCY's manufacturer bytes.
fn mfr_bytes(f: Faults) -> [u8; 5] {
    let b = f.0.to_le_bytes();
    [b[0], b[1], b[2], b[3], 0]
}

fn bus_error(e: ServoError) -> BusError {
    match e {
        ServoError::Bus(b) => b,
        _ => BusError::SlaveError,
    }
}

fn sat_i32(x: f64) -> i32 {
    if x.is_nan() {
        0
    } else {
        libm::round(x).clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32
    }
}
