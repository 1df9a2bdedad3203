//! The drive's application objects: everything in its dictionary that the
//! `canopen` node does not own itself (the node owns the communication
//! objects, the PDO parameters and 0x6040/0x6041/0x605A/0x6060/0x6061/
//! 0x6502).
//!
//! One table, [`OBJECTS`], describes every object (type, access, PDO
//! mapping, limits, name); [`DriveObjects`] reads and writes the values:
//! set-points and actual values in a [`ProcessImage`] that the control
//! loop exchanges at its boundary, configuration through a
//! [`ConfigPort`]. The EDS ([`super::eds`]) is written from the same table.

use crate::config::{self, ConfigError, Kind, N_PARAMS, PARAMS};
use canopen::cia402::{Action, Transition};
use canopen::node::Application;
use canopen::od::{Abort, Access, DataType, Entry, Limits, ObjectDictionary};

/// The vendor object index of every configuration parameter, by name.
/// Assigned once and never moved: a parameter added to the table gets the
/// next free index here (a test fails until it has one), so a robot's
/// configuration tool keeps addressing the same parameter.
pub const CONFIG_OBJECTS: [(&str, u16); N_PARAMS] = [
    ("motor_r_s", 0x2000),
    ("motor_l", 0x2001),
    ("motor_psi_pm", 0x2002),
    ("motor_pole_pairs", 0x2003),
    ("u_dc", 0x2004),
    ("enc_cpr", 0x2005),
    ("enc_zero", 0x2006),
    ("dead_time", 0x2007),
    ("adc_period", 0x2008),
    ("foc_half_period", 0x2009),
    ("foc_pole", 0x200A),
    ("foc_pred_gain", 0x200B),
    ("mpdtc_t_tol", 0x200C),
    ("mpdtc_p", 0x200D),
    ("mpdtc_k", 0x200E),
    ("mpdtc_k_auto", 0x200F),
    ("mpdtc_int_limit", 0x2010),
    ("mpdtc_aw", 0x2011),
    ("obs_kp", 0x2012),
    ("obs_ki", 0x2013),
    ("obs_limit", 0x2014),
    ("mpdtc_align_time", 0x2015),
    ("torque_limit", 0x2016),
    ("current_limit", 0x2017),
    ("watchdog_timeout", 0x2018),
    ("mpdtc_ps_fed", 0x2019),
    ("vel_kp", 0x201A),
    ("vel_ki", 0x201B),
    ("pos_kp", 0x201C),
    ("load_inertia", 0x201D),
    ("traj_vel_limit", 0x201E),
    ("traj_accel_limit", 0x201F),
    ("vel_limit", 0x2020),
    ("pos_min", 0x2021),
    ("pos_max", 0x2022),
    ("imp_kp_max", 0x2023),
    ("imp_kd_max", 0x2024),
    ("calibration_current", 0x2025),
    ("calibration_voltage", 0x2026),
];

/// The torque loop under the CiA 402 modes (vendor object), UNSIGNED8.
pub const TORQUE_LOOP: u16 = 0x2100;
/// The vendor impedance mode's gains and feed-forward (its position and
/// velocity set-points are 0x607A and 0x60FF), a record of REAL32.
pub const IMPEDANCE: u16 = 0x2101;

/// CiA 402 device type: profile 402, "servo drive" (additional
/// information 0x0002, CiA 402-2 §6.2).
pub const DEVICE_TYPE: u32 = 0x0002_0192;
/// 0x1010/0x1011 signatures: "save" and "load", ISO 8859 characters
/// little-endian (CiA 301 v4.2 §7.5.2.13/14).
pub const SIGNATURE_SAVE: u32 = u32::from_le_bytes(*b"save");
/// See [`SIGNATURE_SAVE`].
pub const SIGNATURE_LOAD: u32 = u32::from_le_bytes(*b"load");
/// 0x1008, the manufacturer device name.
pub const DEVICE_NAME: &str = "predictive servo drive";
/// 0x1009, the hardware: the SoC the firmware runs on.
pub const HARDWARE_VERSION: &str = "Zynq-7000";
/// 0x100A, the firmware version.
pub const SOFTWARE_VERSION: &str = env!("CARGO_PKG_VERSION");

/// One sub-index of an object.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sub {
    pub sub: u8,
    pub name: &'static str,
    pub data_type: DataType,
    pub access: Access,
    pub pdo_mappable: bool,
    pub limits: Limits,
}

/// One object: a VAR (one sub-index 0) or a RECORD/ARRAY (sub 0 the count).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Object {
    pub index: u16,
    pub name: &'static str,
    pub subs: &'static [Sub],
}

const fn s(sub: u8, name: &'static str, data_type: DataType, access: Access) -> Sub {
    Sub {
        sub,
        name,
        data_type,
        access,
        pdo_mappable: false,
        limits: Limits::None,
    }
}

const fn pdo(mut x: Sub) -> Sub {
    x.pdo_mappable = true;
    x
}

const fn lim(mut x: Sub, min: i64, max: i64) -> Sub {
    x.limits = Limits::Int { min, max };
    x
}

const fn rlim(mut x: Sub, min: f32, max: f32) -> Sub {
    x.limits = Limits::Real { min, max };
    x
}

const fn var(index: u16, name: &'static str, sub: &'static [Sub]) -> Object {
    Object {
        index,
        name,
        subs: sub,
    }
}

use Access::{Const, Ro, Rw};
use DataType::{
    Integer16, Integer32, Integer8, Real32, Unsigned16, Unsigned32, Unsigned8, VisibleString,
};

/// Length of the identity strings (0x1008..0x100A), bytes.
const NAME_LEN: u8 = 32;

/// Every application object but the vendor configuration objects
/// ([`CONFIG_OBJECTS`], described from the configuration table), in
/// index order.
pub const OBJECTS: &[Object] = &[
    var(
        0x1000,
        "Device type",
        &[s(0, "Device type", Unsigned32, Const)],
    ),
    var(
        0x1008,
        "Manufacturer device name",
        &[s(
            0,
            "Manufacturer device name",
            VisibleString(NAME_LEN),
            Const,
        )],
    ),
    var(
        0x1009,
        "Manufacturer hardware version",
        &[s(
            0,
            "Manufacturer hardware version",
            VisibleString(NAME_LEN),
            Const,
        )],
    ),
    var(
        0x100A,
        "Manufacturer software version",
        &[s(
            0,
            "Manufacturer software version",
            VisibleString(NAME_LEN),
            Const,
        )],
    ),
    var(
        0x1010,
        "Store parameters",
        &[
            s(0, "Highest sub-index supported", Unsigned8, Const),
            s(1, "Save all parameters", Unsigned32, Rw),
        ],
    ),
    var(
        0x1011,
        "Restore default parameters",
        &[
            s(0, "Highest sub-index supported", Unsigned8, Const),
            s(1, "Restore all default parameters", Unsigned32, Rw),
        ],
    ),
    var(
        0x1018,
        "Identity object",
        &[
            s(0, "Highest sub-index supported", Unsigned8, Const),
            s(1, "Vendor-ID", Unsigned32, Const),
            s(2, "Product code", Unsigned32, Const),
            s(3, "Revision number", Unsigned32, Const),
            s(4, "Serial number", Unsigned32, Const),
        ],
    ),
    var(
        0x6007,
        "Abort connection option code",
        &[lim(
            s(0, "Abort connection option code", Integer16, Rw),
            0,
            3,
        )],
    ),
    var(
        0x603F,
        "Error code",
        &[pdo(s(0, "Error code", Unsigned16, Ro))],
    ),
    var(
        0x6064,
        "Position actual value",
        &[pdo(s(0, "Position actual value", Integer32, Ro))],
    ),
    var(
        0x606C,
        "Velocity actual value",
        &[pdo(s(0, "Velocity actual value", Integer32, Ro))],
    ),
    var(
        0x6071,
        "Target torque",
        &[pdo(s(0, "Target torque", Integer16, Rw))],
    ),
    var(
        0x6072,
        "Max torque",
        &[pdo(lim(s(0, "Max torque", Unsigned16, Rw), 0, 1000))],
    ),
    var(
        0x6076,
        "Motor rated torque",
        &[s(0, "Motor rated torque", Unsigned32, Ro)],
    ),
    var(
        0x6077,
        "Torque actual value",
        &[pdo(s(0, "Torque actual value", Integer16, Ro))],
    ),
    var(
        0x607A,
        "Target position",
        &[pdo(s(0, "Target position", Integer32, Rw))],
    ),
    var(
        0x607D,
        "Software position limit",
        &[
            s(0, "Highest sub-index supported", Unsigned8, Const),
            s(1, "Min position limit", Integer32, Rw),
            s(2, "Max position limit", Integer32, Rw),
        ],
    ),
    var(
        0x6081,
        "Profile velocity",
        &[pdo(s(0, "Profile velocity", Unsigned32, Rw))],
    ),
    var(
        0x6083,
        "Profile acceleration",
        &[pdo(s(0, "Profile acceleration", Unsigned32, Rw))],
    ),
    var(
        0x6084,
        "Profile deceleration",
        &[pdo(s(0, "Profile deceleration", Unsigned32, Rw))],
    ),
    var(
        0x608F,
        "Position encoder resolution",
        &[
            s(0, "Highest sub-index supported", Unsigned8, Const),
            s(1, "Encoder increments", Unsigned32, Ro),
            s(2, "Motor revolutions", Unsigned32, Const),
        ],
    ),
    var(
        0x6098,
        "Homing method",
        &[lim(s(0, "Homing method", Integer8, Rw), 37, 37)],
    ),
    var(
        0x60C2,
        "Interpolation time period",
        &[
            s(0, "Highest sub-index supported", Unsigned8, Const),
            s(1, "Interpolation time period value", Unsigned8, Rw),
            lim(s(2, "Interpolation time index", Integer8, Rw), -6, -3),
        ],
    ),
    var(
        0x60F4,
        "Following error actual value",
        &[pdo(s(0, "Following error actual value", Integer32, Ro))],
    ),
    var(
        0x60FF,
        "Target velocity",
        &[pdo(s(0, "Target velocity", Integer32, Rw))],
    ),
    var(
        TORQUE_LOOP,
        "Torque loop (0 FOC, 1 MPDTC)",
        &[pdo(lim(
            s(0, "Torque loop (0 FOC, 1 MPDTC)", Unsigned8, Rw),
            0,
            1,
        ))],
    ),
    var(
        IMPEDANCE,
        "Impedance mode",
        &[
            s(0, "Highest sub-index supported", Unsigned8, Const),
            pdo(rlim(
                s(1, "Stiffness kp (N m/rev)", Real32, Rw),
                0.0,
                f32::MAX,
            )),
            pdo(rlim(
                s(2, "Damping kd (N m s/rev)", Real32, Rw),
                0.0,
                f32::MAX,
            )),
            pdo(rlim(
                s(3, "Torque feed-forward (N m)", Real32, Rw),
                -f32::MAX,
                f32::MAX,
            )),
        ],
    ),
];

/// The description of (index, sub) in [`OBJECTS`].
fn fixed(index: u16, sub: u8) -> Option<Result<Sub, Abort>> {
    let o = OBJECTS.iter().find(|o| o.index == index)?;
    Some(
        o.subs
            .iter()
            .find(|x| x.sub == sub)
            .copied()
            .ok_or(Abort::SubindexDoesNotExist),
    )
}

/// The configuration parameter behind vendor object `index`, with its
/// position in [`PARAMS`].
pub fn config_param(index: u16) -> Option<(usize, &'static config::Param)> {
    let (name, _) = CONFIG_OBJECTS.iter().find(|(_, i)| *i == index)?;
    config::lookup(name)
}

/// The vendor object of the configuration parameter at `ix` in [`PARAMS`].
pub fn config_index(ix: usize) -> Option<u16> {
    let name = PARAMS.get(ix)?.name;
    CONFIG_OBJECTS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, i)| *i)
}

/// The entry of a configuration parameter: UNSIGNED32 for an integer
/// parameter (every one is at least 0), REAL32 otherwise, with the
/// table's range. Not PDO-mappable: a parameter change may need the gates
/// off, which a cyclic write cannot wait for.
pub fn config_sub(p: &config::Param) -> Sub {
    match p.kind {
        Kind::Integer => lim(s(0, p.name, Unsigned32, Rw), p.min as i64, p.max as i64),
        Kind::Real => rlim(s(0, p.name, Real32, Rw), p.min as f32, p.max as f32),
    }
}

/// The drive's configuration as the dictionary reaches it.
pub trait ConfigPort {
    /// The value of the parameter at `ix` in [`PARAMS`], in its unit.
    fn value(&self, ix: usize) -> f64;
    /// Sets it as `config set` does (range, the whole configuration's
    /// check, gates off where the parameter needs it); on an error
    /// nothing changes.
    fn set(&mut self, ix: usize, v: f64) -> Result<(), ConfigRefusal>;
}

/// A configuration held as values on a base servo configuration, with
/// the gates' state the parameters that need them off are checked
/// against: the port of a drive whose configuration lives in RAM (the
/// host's tests, and the firmware's copy before `config save`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConfigValues {
    pub values: config::Config,
    pub base: crate::servo::ServoConfig,
    pub gates_on: bool,
}

impl ConfigValues {
    /// The configuration `base` makes, gates off.
    pub fn new(base: crate::servo::ServoConfig) -> Self {
        Self {
            values: config::Config::from_servo(&base),
            base,
            gates_on: false,
        }
    }
}

impl ConfigPort for ConfigValues {
    fn value(&self, ix: usize) -> f64 {
        self.values.values().get(ix).copied().unwrap_or(f64::NAN)
    }

    fn set(&mut self, ix: usize, v: f64) -> Result<(), ConfigRefusal> {
        let p = PARAMS
            .get(ix)
            .ok_or(ConfigRefusal::Config(ConfigError::UnknownName))?;
        if self.gates_on && p.gates_off {
            return Err(ConfigRefusal::GatesOn);
        }
        self.values
            .set(&self.base, p.name, v)
            .map_err(ConfigRefusal::Config)
    }
}

/// Why the drive refused a configuration write.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ConfigRefusal {
    /// The configuration check's reason.
    Config(ConfigError),
    /// The parameter needs the gates off, and they are on.
    GatesOn,
}

impl ConfigRefusal {
    /// The SDO abort for it, `v` the refused value.
    pub fn abort(self, v: f64) -> Abort {
        match self {
            ConfigRefusal::Config(ConfigError::OutOfRange(p)) if v > p.max => Abort::ValueTooHigh,
            ConfigRefusal::Config(ConfigError::OutOfRange(_)) => Abort::ValueTooLow,
            ConfigRefusal::Config(ConfigError::NotANumber | ConfigError::NotWhole) => {
                Abort::ValueRange
            }
            ConfigRefusal::Config(ConfigError::UnknownName) => Abort::ObjectDoesNotExist,
            ConfigRefusal::Config(ConfigError::Invalid(_)) => Abort::ParameterIncompatible,
            ConfigRefusal::GatesOn => Abort::WrongDeviceState,
        }
    }
}

/// The vendor impedance mode's gains and torque feed-forward.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Impedance {
    pub kp_nm_per_rev: f32,
    pub kd_nm_s_per_rev: f32,
    pub torque_ff_nm: f32,
}

/// The values the control loop and the dictionary exchange: set-points
/// written over SDO or RPDO (taken by the loop at its next boundary) and
/// actual values the loop writes at its boundary (read by SDO or TPDO).
/// Units: see the module's factor group.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProcessImage {
    /// 0x6071, per mille of 0x6076.
    pub target_torque_permille: i16,
    /// 0x6072, per mille of 0x6076.
    pub max_torque_permille: u16,
    /// 0x607A, counts.
    pub target_position_counts: i32,
    /// 0x60FF, counts/s.
    pub target_velocity_counts_s: i32,
    /// 0x6081, counts/s.
    pub profile_velocity_counts_s: u32,
    /// 0x6083, counts/s².
    pub profile_acceleration_counts_s2: u32,
    /// 0x6084, counts/s².
    pub profile_deceleration_counts_s2: u32,
    /// 0x6098: 37, home on the current position, is the one method.
    pub homing_method: i8,
    /// 0x60C2: the set-point period is `value` x 10^`index` s.
    pub interpolation_value: u8,
    /// See [`Self::interpolation_value`].
    pub interpolation_index: i8,
    /// 0x6007: 0 nothing, 1 fault, 2 disable voltage, 3 quick stop, on a
    /// lost heartbeat or RPDO timeout.
    pub abort_connection_option: i16,
    /// 0x2100: 0 FOC, 1 MPDTC.
    pub torque_loop: u8,
    /// 0x2101.
    pub impedance: Impedance,
    /// 0x6064, counts.
    pub position_actual_counts: i32,
    /// 0x606C, counts/s.
    pub velocity_actual_counts_s: i32,
    /// 0x6077, per mille of 0x6076.
    pub torque_actual_permille: i16,
    /// 0x60F4, counts.
    pub following_error_counts: i32,
    /// 0x603F, the CiA 402 error code of the latched fault (0: none).
    pub error_code: u16,
}

impl Default for ProcessImage {
    fn default() -> Self {
        Self {
            target_torque_permille: 0,
            max_torque_permille: 1000,
            target_position_counts: 0,
            target_velocity_counts_s: 0,
            profile_velocity_counts_s: 0,
            profile_acceleration_counts_s2: 0,
            profile_deceleration_counts_s2: 0,
            homing_method: 37,
            // 1 ms, the set-point period a 1 kHz SYNC gives.
            interpolation_value: 1,
            interpolation_index: -3,
            abort_connection_option: 3,
            torque_loop: 1,
            impedance: Impedance::default(),
            position_actual_counts: 0,
            velocity_actual_counts_s: 0,
            torque_actual_permille: 0,
            following_error_counts: 0,
            error_code: 0,
        }
    }
}

/// Requests the dictionary leaves for the drive to carry out outside the
/// SDO transfer (they may need the flash or the gates).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Requests {
    /// 0x1010:1 got "save": `config save`.
    pub save: bool,
    /// 0x1011:1 got "load": `config reset` (in effect after a save and a
    /// reset, as CiA 301 says).
    pub restore: bool,
}

/// Most CiA 402 actions one pass of the network path can leave for the
/// control loop: one controlword makes at most two transitions.
pub const ACTIONS: usize = 8;

/// The drive's application dictionary over a configuration port.
pub struct DriveObjects<C> {
    pub config: C,
    pub image: ProcessImage,
    pub requests: Requests,
    /// CiA 402 actions not yet carried out, oldest first.
    pub actions: heapless::Deque<Action, ACTIONS>,
    /// Actions refused because [`Self::actions`] was full (the drive
    /// treats any as a fault: a transition it did not carry out).
    pub actions_lost: u32,
    /// 0x1018:4.
    pub serial_number: u32,
}

impl<C: ConfigPort> DriveObjects<C> {
    pub fn new(config: C) -> Self {
        Self {
            config,
            image: ProcessImage::default(),
            requests: Requests::default(),
            actions: heapless::Deque::new(),
            actions_lost: 0,
            serial_number: 0,
        }
    }

    fn cpr(&self) -> f64 {
        self.config
            .value(config::lookup("enc_cpr").map_or(0, |(i, _)| i))
    }

    /// A position limit in counts from the configuration's `pos_min` or
    /// `pos_max` (rev), rounded to the nearest count and held in INTEGER32.
    fn limit_counts(&self, name: &str) -> i32 {
        let rev = config::lookup(name).map_or(0.0, |(i, _)| self.config.value(i));
        let c = libm::round(rev * self.cpr());
        c.clamp(f64::from(i32::MIN), f64::from(i32::MAX)) as i32
    }

    fn set_config(&mut self, ix: usize, v: f64) -> Result<(), Abort> {
        self.config.set(ix, v).map_err(|r| r.abort(v))
    }

    fn set_limit_counts(&mut self, name: &str, counts: i32) -> Result<(), Abort> {
        let (ix, _) = config::lookup(name).ok_or(Abort::ObjectDoesNotExist)?;
        let cpr = self.cpr();
        if cpr <= 0.0 {
            return Err(Abort::ParameterIncompatible);
        }
        self.set_config(ix, f64::from(counts) / cpr)
    }
}

/// The shortest decimal that reads back as `x` (f32), as f64: an SDO's
/// REAL32 0.075 is the configuration's 0.075, not 0.07500000298.
fn f32_to_f64_decimal(x: f32) -> f64 {
    use core::fmt::Write;
    let mut s: heapless::String<48> = heapless::String::new();
    if write!(s, "{x}").is_err() {
        return f64::from(x);
    }
    s.parse::<f64>().unwrap_or(f64::from(x))
}

fn put(out: &mut [u8], b: &[u8]) -> Result<usize, Abort> {
    out.get_mut(..b.len())
        .ok_or(Abort::General)?
        .copy_from_slice(b);
    Ok(b.len())
}

/// The little-endian integer in `data` (already checked against the
/// entry's length), sign-extended from `bits`.
fn int(data: &[u8]) -> i64 {
    let mut b = [0u8; 4];
    let k = data.len().min(4);
    b[..k].copy_from_slice(&data[..k]);
    let u = u32::from_le_bytes(b);
    match k {
        1 => i64::from(u as u8 as i8),
        2 => i64::from(u as u16 as i16),
        _ => i64::from(u as i32),
    }
}

fn uint(data: &[u8]) -> u32 {
    let mut b = [0u8; 4];
    let k = data.len().min(4);
    b[..k].copy_from_slice(&data[..k]);
    u32::from_le_bytes(b)
}

fn real(data: &[u8]) -> f32 {
    f32::from_le_bytes([
        data.first().copied().unwrap_or(0),
        data.get(1).copied().unwrap_or(0),
        data.get(2).copied().unwrap_or(0),
        data.get(3).copied().unwrap_or(0),
    ])
}

impl<C: ConfigPort> ObjectDictionary for DriveObjects<C> {
    fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort> {
        let x = match fixed(index, sub) {
            Some(r) => r?,
            None => {
                let (_, p) = config_param(index).ok_or(Abort::ObjectDoesNotExist)?;
                if sub != 0 {
                    return Err(Abort::SubindexDoesNotExist);
                }
                config_sub(p)
            }
        };
        Ok(Entry {
            index,
            sub,
            data_type: x.data_type,
            access: x.access,
            pdo_mappable: x.pdo_mappable,
            limits: x.limits,
        })
    }

    fn read(&mut self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
        let im = &self.image;
        match (index, sub) {
            (0x1000, 0) => put(out, &DEVICE_TYPE.to_le_bytes()),
            (0x1008, 0) => put(out, DEVICE_NAME.as_bytes()),
            (0x1009, 0) => put(out, HARDWARE_VERSION.as_bytes()),
            (0x100A, 0) => put(out, SOFTWARE_VERSION.as_bytes()),
            (0x1010 | 0x1011, 0) => put(out, &[1]),
            // Bit 0: the device saves (restores) on command.
            (0x1010 | 0x1011, 1) => put(out, &1u32.to_le_bytes()),
            (0x1018, 0) => put(out, &[4]),
            // No CiA vendor-ID is assigned to the project: 0.
            (0x1018, 1) => put(out, &0u32.to_le_bytes()),
            (0x1018, 2) => put(out, &0x0402u32.to_le_bytes()),
            (0x1018, 3) => put(out, &revision_number(SOFTWARE_VERSION).to_le_bytes()),
            (0x1018, 4) => put(out, &self.serial_number.to_le_bytes()),
            (0x6007, 0) => put(out, &im.abort_connection_option.to_le_bytes()),
            (0x603F, 0) => put(out, &im.error_code.to_le_bytes()),
            (0x6064, 0) => put(out, &im.position_actual_counts.to_le_bytes()),
            (0x606C, 0) => put(out, &im.velocity_actual_counts_s.to_le_bytes()),
            (0x6071, 0) => put(out, &im.target_torque_permille.to_le_bytes()),
            (0x6072, 0) => put(out, &im.max_torque_permille.to_le_bytes()),
            (0x6076, 0) => {
                let ix = config::lookup("torque_limit").map_or(0, |(i, _)| i);
                let mnm = libm::round(self.config.value(ix) * 1000.0);
                put(
                    out,
                    &(mnm.clamp(0.0, f64::from(u32::MAX)) as u32).to_le_bytes(),
                )
            }
            (0x6077, 0) => put(out, &im.torque_actual_permille.to_le_bytes()),
            (0x607A, 0) => put(out, &im.target_position_counts.to_le_bytes()),
            (0x607D, 0) => put(out, &[2]),
            (0x607D, 1) => put(out, &self.limit_counts("pos_min").to_le_bytes()),
            (0x607D, 2) => put(out, &self.limit_counts("pos_max").to_le_bytes()),
            (0x6081, 0) => put(out, &im.profile_velocity_counts_s.to_le_bytes()),
            (0x6083, 0) => put(out, &im.profile_acceleration_counts_s2.to_le_bytes()),
            (0x6084, 0) => put(out, &im.profile_deceleration_counts_s2.to_le_bytes()),
            (0x608F, 0) => put(out, &[2]),
            (0x608F, 1) => put(out, &(self.cpr() as u32).to_le_bytes()),
            (0x608F, 2) => put(out, &1u32.to_le_bytes()),
            (0x6098, 0) => put(out, &im.homing_method.to_le_bytes()),
            (0x60C2, 0) => put(out, &[2]),
            (0x60C2, 1) => put(out, &[im.interpolation_value]),
            (0x60C2, 2) => put(out, &im.interpolation_index.to_le_bytes()),
            (0x60F4, 0) => put(out, &im.following_error_counts.to_le_bytes()),
            (0x60FF, 0) => put(out, &im.target_velocity_counts_s.to_le_bytes()),
            (TORQUE_LOOP, 0) => put(out, &[im.torque_loop]),
            (IMPEDANCE, 0) => put(out, &[3]),
            (IMPEDANCE, 1) => put(out, &im.impedance.kp_nm_per_rev.to_le_bytes()),
            (IMPEDANCE, 2) => put(out, &im.impedance.kd_nm_s_per_rev.to_le_bytes()),
            (IMPEDANCE, 3) => put(out, &im.impedance.torque_ff_nm.to_le_bytes()),
            _ => {
                let (ix, p) = config_param(index).ok_or(Abort::ObjectDoesNotExist)?;
                if sub != 0 {
                    return Err(Abort::SubindexDoesNotExist);
                }
                let v = self.config.value(ix);
                match p.kind {
                    Kind::Integer => put(out, &(v as u32).to_le_bytes()),
                    Kind::Real => put(out, &(v as f32).to_le_bytes()),
                }
            }
        }
    }

    /// `data` has passed the entry's access, length and limit checks
    /// (`canopen::od::write_checked`).
    fn write(&mut self, index: u16, sub: u8, data: &[u8]) -> Result<(), Abort> {
        let im = &mut self.image;
        match (index, sub) {
            (0x1010, 1) if uint(data) == SIGNATURE_SAVE => self.requests.save = true,
            (0x1011, 1) if uint(data) == SIGNATURE_LOAD => self.requests.restore = true,
            (0x1010 | 0x1011, 1) => return Err(Abort::CannotStore),
            (0x6007, 0) => im.abort_connection_option = int(data) as i16,
            (0x6071, 0) => im.target_torque_permille = int(data) as i16,
            (0x6072, 0) => im.max_torque_permille = uint(data) as u16,
            (0x607A, 0) => im.target_position_counts = int(data) as i32,
            (0x607D, 1) => return self.set_limit_counts("pos_min", int(data) as i32),
            (0x607D, 2) => return self.set_limit_counts("pos_max", int(data) as i32),
            (0x6081, 0) => im.profile_velocity_counts_s = uint(data),
            (0x6083, 0) => im.profile_acceleration_counts_s2 = uint(data),
            (0x6084, 0) => im.profile_deceleration_counts_s2 = uint(data),
            (0x6098, 0) => im.homing_method = int(data) as i8,
            (0x60C2, 1) => im.interpolation_value = uint(data) as u8,
            (0x60C2, 2) => im.interpolation_index = int(data) as i8,
            (0x60FF, 0) => im.target_velocity_counts_s = int(data) as i32,
            (TORQUE_LOOP, 0) => im.torque_loop = uint(data) as u8,
            (IMPEDANCE, 1) => im.impedance.kp_nm_per_rev = real(data),
            (IMPEDANCE, 2) => im.impedance.kd_nm_s_per_rev = real(data),
            (IMPEDANCE, 3) => im.impedance.torque_ff_nm = real(data),
            _ => {
                let (ix, p) = config_param(index).ok_or(Abort::ObjectDoesNotExist)?;
                if sub != 0 {
                    return Err(Abort::SubindexDoesNotExist);
                }
                let v = match p.kind {
                    Kind::Integer => f64::from(uint(data)),
                    Kind::Real => f32_to_f64_decimal(real(data)),
                };
                return self.set_config(ix, v);
            }
        }
        Ok(())
    }
}

impl<C: ConfigPort> Application for DriveObjects<C> {
    fn on_drive_transition(&mut self, t: &Transition) {
        if t.action == Action::None {
            return;
        }
        if self.actions.push_back(t.action).is_err() {
            self.actions_lost = self.actions_lost.saturating_add(1);
        }
    }

    fn on_reset_application(&mut self) {
        let serial = self.serial_number;
        self.image = ProcessImage::default();
        self.requests = Requests::default();
        self.actions.clear();
        self.serial_number = serial;
    }
}

/// 0x1018:3 from a `major.minor.patch` version: the major revision in the
/// high 16 bits, the minor in the low (CiA 301 v4.2 §7.5.2.23; the patch
/// level is not in it); 0 for a version it cannot read.
pub fn revision_number(version: &str) -> u32 {
    let mut parts = version.split('.');
    let mut next = || parts.next().and_then(|p| p.parse::<u16>().ok());
    match (next(), next()) {
        (Some(major), Some(minor)) => (u32::from(major) << 16) | u32::from(minor),
        _ => 0,
    }
}
