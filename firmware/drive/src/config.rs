//! The drive's parameters: one table ([`PARAMS`]) with name, unit, range,
//! default, description and whether a change needs the gates off; the
//! values ([`Config`]) and how they map onto [`ServoConfig`], the one
//! structure the drive (and through it the PL registers) is built from.
//!
//! Every value is an `f64` in the unit the table names; integer parameters
//! hold whole numbers. A [`Config`] is only ever changed through
//! [`Config::set`], which checks the single value (finite, whole where it
//! must be, within `[min, max]`) and then the whole configuration (the
//! drive's own validation, e.g. the observer's stability): on any error it
//! is left as it was.
//!
//! The values not in the table (the current-sensing gain of the board or of
//! the simulated PL, the smallest `step`) stay what the base
//! [`ServoConfig`] has.
use crate::servo::{Servo, ServoConfig};
use core::fmt::{self, Write};
use models::pmsm::params::PSI_PM_FROM_KE_WB;
use models::validate::ParamError;

/// Kind of a parameter's value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Any finite number in range.
    Real,
    /// A whole number in range.
    Integer,
}

/// One row of the parameter table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Param {
    /// Name on the console and in files (`snake_case`).
    pub name: &'static str,
    /// Unit of the value (`1` for dimensionless).
    pub unit: &'static str,
    /// Smallest accepted value, in `unit`.
    pub min: f64,
    /// Largest accepted value, in `unit`.
    pub max: f64,
    /// Value after `config reset`, in `unit`.
    pub default: f64,
    /// Real or integer.
    pub kind: Kind,
    /// Changing it needs the gates off (it changes the PL's timing, the
    /// controllers' models or the fault thresholds).
    pub gates_off: bool,
    /// One line: what it is.
    pub description: &'static str,
}

const fn real(
    name: &'static str,
    unit: &'static str,
    min: f64,
    max: f64,
    default: f64,
    description: &'static str,
) -> Param {
    Param {
        name,
        unit,
        min,
        max,
        default,
        kind: Kind::Real,
        gates_off: true,
        description,
    }
}

const fn int(
    name: &'static str,
    unit: &'static str,
    min: u32,
    max: u32,
    default: u32,
    description: &'static str,
) -> Param {
    Param {
        name,
        unit,
        min: min as f64,
        max: max as f64,
        default: default as f64,
        kind: Kind::Integer,
        gates_off: true,
        description,
    }
}

/// Index of each parameter in [`PARAMS`] and in [`Config`]'s values.
mod ix {
    pub const MOTOR_R_S: usize = 0;
    pub const MOTOR_L: usize = 1;
    pub const MOTOR_PSI_PM: usize = 2;
    pub const MOTOR_POLE_PAIRS: usize = 3;
    pub const U_DC: usize = 4;
    pub const ENC_CPR: usize = 5;
    pub const ENC_ZERO: usize = 6;
    pub const DEAD_TIME: usize = 7;
    pub const ADC_PERIOD: usize = 8;
    pub const FOC_HALF_PERIOD: usize = 9;
    pub const FOC_POLE: usize = 10;
    pub const FOC_PRED_GAIN: usize = 11;
    pub const MPDTC_T_TOL: usize = 12;
    pub const MPDTC_P: usize = 13;
    pub const MPDTC_K: usize = 14;
    pub const MPDTC_K_AUTO: usize = 15;
    pub const MPDTC_INT_LIMIT: usize = 16;
    pub const MPDTC_AW: usize = 17;
    pub const OBS_KP: usize = 18;
    pub const OBS_KI: usize = 19;
    pub const OBS_LIMIT: usize = 20;
    pub const MPDTC_ALIGN_TIME: usize = 21;
    pub const TORQUE_LIMIT: usize = 22;
    pub const CURRENT_LIMIT: usize = 23;
    pub const WATCHDOG_TIMEOUT: usize = 24;
    pub const MPDTC_PS_FED: usize = 25;
    pub const VEL_KP: usize = 26;
    pub const VEL_KI: usize = 27;
    pub const POS_KP: usize = 28;
    pub const LOAD_INERTIA: usize = 29;
    pub const TRAJ_VEL_LIMIT: usize = 30;
    pub const TRAJ_ACCEL_LIMIT: usize = 31;
    pub const VEL_LIMIT: usize = 32;
    pub const POS_MIN: usize = 33;
    pub const POS_MAX: usize = 34;
    pub const IMP_KP_MAX: usize = 35;
    pub const IMP_KD_MAX: usize = 36;
    pub const CAL_CURRENT: usize = 37;
    pub const CAL_VOLTAGE: usize = 38;
    pub const N: usize = 39;
}

/// Number of parameters.
pub const N_PARAMS: usize = ix::N;

/// Every parameter of the drive. The defaults are [`ServoConfig::default`]'s
/// (a test checks it); register ranges come from the register table.
pub const PARAMS: [Param; N_PARAMS] = [
    real(
        "motor_r_s",
        "ohm",
        1e-3,
        100.0,
        0.555,
        "stator resistance per phase (star equivalent) of the controllers' motor model",
    ),
    real(
        "motor_l",
        "H",
        1e-6,
        0.1,
        0.64e-3,
        "stator inductance L_d = L_q (surface PMSM) of the controllers' motor model",
    ),
    real(
        "motor_psi_pm",
        "Wb",
        1e-4,
        1.0,
        PSI_PM_FROM_KE_WB,
        "permanent-magnet flux linkage amplitude of the motor model",
    ),
    int(
        "motor_pole_pairs",
        "1",
        1,
        64,
        7,
        "pole pairs of the motor (electrical angle = pole pairs x mechanical)",
    ),
    real(
        "u_dc",
        "V",
        1.0,
        100.0,
        48.0,
        "DC-link voltage the controllers assume",
    ),
    int(
        "enc_cpr",
        "counts",
        4,
        65535,
        4096,
        "encoder quadrature counts per mechanical revolution (ENC_CPR)",
    ),
    int(
        "enc_zero",
        "counts",
        0,
        65534,
        0,
        "encoder position of the rotor d axis on phase a (FOC; below enc_cpr)",
    ),
    int(
        "dead_time",
        "cycles",
        0,
        regmap::DEAD_TIME_MAX,
        50,
        "inverter dead time (DEAD_TIME), PL clock cycles of 10 ns",
    ),
    int(
        "adc_period",
        "cycles",
        100,
        65535,
        391,
        "ADC sample period (ADC_PERIOD), PL cycles; MPDTC control period = 4 of them",
    ),
    int(
        "foc_half_period",
        "cycles",
        500,
        65535,
        3128,
        "FOC PWM half period (PWM_PERIOD), PL cycles; FOC control period = 2 of them",
    ),
    real(
        "foc_pole",
        "1",
        0.0,
        0.95,
        0.1,
        "FOC current-loop closed-loop pole z_c (0 = deadbeat; bandwidth -ln(z_c) f_s / 2 pi)",
    ),
    real(
        "foc_pred_gain",
        "1",
        0.0,
        1.0,
        0.1,
        "FOC gain of the learned one-step prediction error (0 disables)",
    ),
    real(
        "mpdtc_t_tol",
        "Nm",
        0.0,
        0.5,
        0.08,
        "MPDTC torque tolerance band T_tol",
    ),
    real(
        "mpdtc_p",
        "1",
        0.0,
        0.5,
        0.1,
        "MPDTC switching weight exponent p of the cost",
    ),
    real(
        "mpdtc_k",
        "1/s",
        0.0,
        60_000.0,
        2000.0,
        "MPDTC torque integrator gain K when mpdtc_k_auto is 0 (K times the control period below 1)",
    ),
    int(
        "mpdtc_k_auto",
        "1",
        0,
        1,
        0,
        "1 = MPDTC integrator gain K derived from the motor model and the control period \
         (K = 0.0119 N m / (Ts h), h = one period's full-vector torque step k_T Ts/L 2/3 U_dc), \
         0 = mpdtc_k",
    ),
    real(
        "mpdtc_int_limit",
        "Nm",
        0.0,
        1.0,
        0.2,
        "MPDTC clamp of the torque integrator output",
    ),
    int(
        "mpdtc_aw",
        "1",
        0,
        1,
        0,
        "MPDTC torque integrator anti-windup: 1 = integrate only after a decision that reached \
         the tolerance band (conditional integration), 0 = every period (the paper's Eq. 13)",
    ),
    real(
        "obs_kp",
        "V/A",
        0.0,
        1000.0,
        20.0,
        "MPDTC disturbance observer proportional gain (stability checked)",
    ),
    real(
        "obs_ki",
        "1/s",
        0.0,
        1e6,
        4000.0,
        "MPDTC disturbance observer integral gain (stability checked)",
    ),
    real(
        "obs_limit",
        "V",
        0.1,
        100.0,
        24.0,
        "MPDTC clamp of the observer output and its integral",
    ),
    int(
        "mpdtc_align_time",
        "cycles",
        1000,
        100_000_000,
        20_000_000,
        "MPDTC rotor alignment before the first decision, longest (MPDTC_ALIGN_TIME: +60 deg vector for at most half, then the d axis; each step ends once the encoder is still for 20 ms), PL cycles",
    ),
    Param {
        gates_off: false,
        ..real(
            "torque_limit",
            "Nm",
            0.01,
            5.0,
            1.0,
            "largest accepted torque reference magnitude",
        )
    },
    real(
        "current_limit",
        "A",
        0.1,
        15.9,
        14.0,
        "over-current trip on any phase sample (OC_LIMIT in ADC counts)",
    ),
    int(
        "watchdog_timeout",
        "cycles",
        1000,
        100_000_000,
        200_000,
        "PL watchdog: PL cycles without a heartbeat before the gates go off (WDG_TIMEOUT)",
    ),
    int(
        "mpdtc_ps_fed",
        "1",
        0,
        1,
        0,
        "MPDTC input path: 0 = autonomous (the PL's front end computes the core's inputs, \
         the PS writes only the torque reference), 1 = PS-fed debug path (Park and angles \
         on the PS, MPDTC_IN_* and MPDTC_START every period)",
    ),
    real(
        "vel_kp",
        "Nm s/rev",
        0.0,
        10.0,
        0.5,
        "velocity loop proportional gain (vel, pos, move)",
    ),
    real(
        "vel_ki",
        "Nm/rev",
        0.0,
        10_000.0,
        60.0,
        "velocity loop integral gain (anti-windup: conditional integration)",
    ),
    real(
        "pos_kp",
        "1/s",
        0.0,
        2000.0,
        40.0,
        "position loop gain: velocity command per position error, (rev/s)/rev",
    ),
    real(
        "load_inertia",
        "kg m^2",
        1e-7,
        1.0,
        8.1e-5,
        "total inertia on the rotor for the acceleration feedforward",
    ),
    real(
        "traj_vel_limit",
        "rev/s",
        0.01,
        100.0,
        20.0,
        "trajectory velocity limit (pos, move)",
    ),
    real(
        "traj_accel_limit",
        "rev/s^2",
        1.0,
        100_000.0,
        100.0,
        "trajectory acceleration limit (pos, move) and vel's acceleration limit",
    ),
    real(
        "vel_limit",
        "rev/s",
        0.1,
        100.0,
        50.0,
        "largest velocity command; OVERSPEED latches 10 % above it",
    ),
    real(
        "pos_min",
        "rev",
        -1e6,
        1e6,
        -1000.0,
        "soft limit: POSITION_LIMIT latches below it (gates on)",
    ),
    real(
        "pos_max",
        "rev",
        -1e6,
        1e6,
        1000.0,
        "soft limit: POSITION_LIMIT latches above it (gates on)",
    ),
    real(
        "imp_kp_max",
        "Nm/rev",
        0.0,
        1000.0,
        20.0,
        "largest imp stiffness kp",
    ),
    real(
        "imp_kd_max",
        "Nm s/rev",
        0.0,
        100.0,
        1.0,
        "largest imp damping kd",
    ),
    real(
        "calibration_current",
        "A",
        0.1,
        50.0,
        8.0,
        "largest current magnitude `calibrate` drives (`calibrate` needs it below current_limit)",
    ),
    real(
        "calibration_voltage",
        "V",
        0.1,
        100.0,
        16.0,
        "largest voltage vector magnitude `calibrate` applies (`calibrate` needs it at most u_dc / 2)",
    ),
];

/// The row of `name`, with its index.
pub fn lookup(name: &str) -> Option<(usize, &'static Param)> {
    PARAMS.iter().enumerate().find(|(_, p)| p.name == name)
}

/// Why a value or a configuration was refused (nothing changed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ConfigError {
    /// No parameter of that name.
    UnknownName,
    /// Not a number, or NaN or infinite.
    NotANumber,
    /// An integer parameter got a fractional value.
    NotWhole,
    /// Outside `[min, max]`.
    OutOfRange(&'static Param),
    /// In range on its own, but the drive refuses the configuration.
    Invalid(ParamError),
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ConfigError::UnknownName => f.write_str("no such parameter (see `config list`)"),
            ConfigError::NotANumber => f.write_str("expected a finite number"),
            ConfigError::NotWhole => f.write_str("expected a whole number"),
            ConfigError::OutOfRange(p) => {
                write!(f, "out of range [{}..{}] {}", p.min, p.max, p.unit)
            }
            ConfigError::Invalid(e) => write!(f, "{e}"),
        }
    }
}

/// Values of every parameter, in [`PARAMS`] order and units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Config {
    values: [f64; N_PARAMS],
}

impl Default for Config {
    /// The table's defaults.
    fn default() -> Self {
        let mut values = [0.0; N_PARAMS];
        for (v, p) in values.iter_mut().zip(PARAMS.iter()) {
            *v = p.default;
        }
        Self { values }
    }
}

/// Checks one value against its row: finite, whole if integer, in range.
pub fn check_value(p: &'static Param, v: f64) -> Result<f64, ConfigError> {
    if !v.is_finite() {
        return Err(ConfigError::NotANumber);
    }
    if p.kind == Kind::Integer && libm::trunc(v) != v {
        return Err(ConfigError::NotWhole);
    }
    if !(p.min..=p.max).contains(&v) {
        return Err(ConfigError::OutOfRange(p));
    }
    Ok(v)
}

/// Parses a console value: a decimal number (no unit suffix).
pub fn parse_value(s: &str) -> Result<f64, ConfigError> {
    s.parse::<f64>().map_err(|_| ConfigError::NotANumber)
}

impl Config {
    /// The values, in [`PARAMS`] order.
    pub fn values(&self) -> &[f64; N_PARAMS] {
        &self.values
    }

    /// The value of `name`.
    pub fn get(&self, name: &str) -> Option<f64> {
        lookup(name).map(|(i, _)| self.values[i])
    }

    /// Sets `name` to `v` on a configuration built on `base` (see
    /// [`Config::check`]); on an error nothing changes.
    pub fn set(&mut self, base: &ServoConfig, name: &str, v: f64) -> Result<(), ConfigError> {
        let (i, p) = lookup(name).ok_or(ConfigError::UnknownName)?;
        let mut next = *self;
        next.values[i] = check_value(p, v)?;
        next.check(base)?;
        *self = next;
        Ok(())
    }

    /// Every value in range, and the drive accepts the configuration it
    /// makes on `base`.
    pub fn check(&self, base: &ServoConfig) -> Result<(), ConfigError> {
        for (p, &v) in PARAMS.iter().zip(self.values.iter()) {
            check_value(p, v)?;
        }
        if self.values[ix::ENC_ZERO] >= self.values[ix::ENC_CPR] {
            return Err(ConfigError::Invalid(ParamError {
                field: "enc_zero",
                reason: "must be below enc_cpr",
            }));
        }
        let sc = self.apply(base);
        // The FOC needs a new averaged result (4 ADC periods) every PWM
        // period, and the ADC_STUCK check counts on it.
        if 4 * sc.adc_period_cycles > 2 * sc.foc_half_period_cycles {
            return Err(ConfigError::Invalid(ParamError {
                field: "adc_period",
                reason: "4 ADC periods must fit in the FOC period (2 foc_half_period)",
            }));
        }
        if sc.oc_limit_counts().is_none() {
            return Err(ConfigError::Invalid(ParamError {
                field: "current_limit",
                reason: "beyond the ADC's full scale",
            }));
        }
        Servo::new(&sc).map_err(ConfigError::Invalid)?;
        Ok(())
    }

    /// The values of `sc` (the inverse of [`Config::apply`]).
    pub fn from_servo(sc: &ServoConfig) -> Self {
        let mut v = [0.0; N_PARAMS];
        v[ix::MOTOR_R_S] = sc.motor.r_s_ohm;
        v[ix::MOTOR_L] = sc.motor.l_d_h;
        v[ix::MOTOR_PSI_PM] = sc.motor.psi_pm_wb;
        v[ix::MOTOR_POLE_PAIRS] = f64::from(sc.motor.pole_pairs);
        v[ix::U_DC] = sc.motor.u_dc_v;
        v[ix::ENC_CPR] = f64::from(sc.enc_cpr);
        v[ix::ENC_ZERO] = f64::from(sc.enc_zero);
        v[ix::DEAD_TIME] = f64::from(sc.dead_time_cycles);
        v[ix::ADC_PERIOD] = f64::from(sc.adc_period_cycles);
        v[ix::FOC_HALF_PERIOD] = f64::from(sc.foc_half_period_cycles);
        v[ix::FOC_POLE] = sc.foc.closed_loop_pole;
        v[ix::FOC_PRED_GAIN] = sc.foc.prediction_error_gain;
        v[ix::MPDTC_T_TOL] = sc.mpdtc.t_tol_nm;
        v[ix::MPDTC_P] = sc.mpdtc.p_weight;
        v[ix::MPDTC_K] = sc.mpdtc.k_int_per_s;
        v[ix::MPDTC_K_AUTO] = f64::from(u8::from(sc.mpdtc_k_auto));
        v[ix::MPDTC_INT_LIMIT] = sc.mpdtc.int_limit_nm;
        v[ix::MPDTC_AW] = f64::from(u8::from(sc.mpdtc.int_conditional));
        v[ix::OBS_KP] = sc.mpdtc.obs_kp_v_per_a;
        v[ix::OBS_KI] = sc.mpdtc.obs_ki_per_s;
        v[ix::OBS_LIMIT] = sc.mpdtc.obs_limit_v;
        v[ix::MPDTC_ALIGN_TIME] = f64::from(sc.align_cycles);
        v[ix::TORQUE_LIMIT] = sc.torque_limit_nm;
        v[ix::CURRENT_LIMIT] = sc.current_limit_a;
        v[ix::WATCHDOG_TIMEOUT] = f64::from(sc.watchdog_cycles);
        v[ix::MPDTC_PS_FED] = f64::from(u8::from(sc.mpdtc_ps_fed));
        let m = &sc.motion;
        v[ix::VEL_KP] = m.vel_kp;
        v[ix::VEL_KI] = m.vel_ki;
        v[ix::POS_KP] = m.pos_kp;
        v[ix::LOAD_INERTIA] = m.load_inertia_kg_m2;
        v[ix::TRAJ_VEL_LIMIT] = m.traj_vel_limit;
        v[ix::TRAJ_ACCEL_LIMIT] = m.traj_accel_limit;
        v[ix::VEL_LIMIT] = m.vel_limit;
        v[ix::POS_MIN] = m.pos_min;
        v[ix::POS_MAX] = m.pos_max;
        v[ix::IMP_KP_MAX] = m.imp_kp_max;
        v[ix::IMP_KD_MAX] = m.imp_kd_max;
        v[ix::CAL_CURRENT] = sc.calibration_current_a;
        v[ix::CAL_VOLTAGE] = sc.calibration_voltage_v;
        Self { values: v }
    }

    /// `base` with the table's values in it. Integer values are whole and
    /// in `u32` range once [`Config::check`] passed.
    pub fn apply(&self, base: &ServoConfig) -> ServoConfig {
        let v = &self.values;
        let u = |i: usize| v[i] as u32;
        let mut sc = *base;
        sc.motor.r_s_ohm = v[ix::MOTOR_R_S];
        sc.motor.l_d_h = v[ix::MOTOR_L];
        sc.motor.l_q_h = v[ix::MOTOR_L];
        sc.motor.psi_pm_wb = v[ix::MOTOR_PSI_PM];
        sc.motor.pole_pairs = u(ix::MOTOR_POLE_PAIRS);
        sc.motor.u_dc_v = v[ix::U_DC];
        sc.enc_cpr = u(ix::ENC_CPR);
        sc.enc_zero = u(ix::ENC_ZERO);
        sc.dead_time_cycles = u(ix::DEAD_TIME);
        sc.adc_period_cycles = u(ix::ADC_PERIOD);
        sc.foc_half_period_cycles = u(ix::FOC_HALF_PERIOD);
        sc.foc.closed_loop_pole = v[ix::FOC_POLE];
        sc.foc.prediction_error_gain = v[ix::FOC_PRED_GAIN];
        sc.mpdtc.t_tol_nm = v[ix::MPDTC_T_TOL];
        sc.mpdtc.p_weight = v[ix::MPDTC_P];
        sc.mpdtc.k_int_per_s = v[ix::MPDTC_K];
        sc.mpdtc_k_auto = u(ix::MPDTC_K_AUTO) != 0;
        sc.mpdtc.int_limit_nm = v[ix::MPDTC_INT_LIMIT];
        sc.mpdtc.int_conditional = u(ix::MPDTC_AW) != 0;
        sc.mpdtc.obs_kp_v_per_a = v[ix::OBS_KP];
        sc.mpdtc.obs_ki_per_s = v[ix::OBS_KI];
        sc.mpdtc.obs_limit_v = v[ix::OBS_LIMIT];
        sc.align_cycles = u(ix::MPDTC_ALIGN_TIME);
        sc.torque_limit_nm = v[ix::TORQUE_LIMIT];
        sc.current_limit_a = v[ix::CURRENT_LIMIT];
        sc.watchdog_cycles = u(ix::WATCHDOG_TIMEOUT);
        sc.mpdtc_ps_fed = u(ix::MPDTC_PS_FED) != 0;
        let m = &mut sc.motion;
        m.vel_kp = v[ix::VEL_KP];
        m.vel_ki = v[ix::VEL_KI];
        m.pos_kp = v[ix::POS_KP];
        m.load_inertia_kg_m2 = v[ix::LOAD_INERTIA];
        m.traj_vel_limit = v[ix::TRAJ_VEL_LIMIT];
        m.traj_accel_limit = v[ix::TRAJ_ACCEL_LIMIT];
        m.vel_limit = v[ix::VEL_LIMIT];
        m.pos_min = v[ix::POS_MIN];
        m.pos_max = v[ix::POS_MAX];
        m.imp_kp_max = v[ix::IMP_KP_MAX];
        m.imp_kd_max = v[ix::IMP_KD_MAX];
        sc.calibration_current_a = v[ix::CAL_CURRENT];
        sc.calibration_voltage_v = v[ix::CAL_VOLTAGE];
        sc
    }

    /// Whether `other` differs from `self` in a parameter that needs the
    /// gates off.
    pub fn needs_gates_off(&self, other: &Config) -> bool {
        PARAMS
            .iter()
            .zip(self.values.iter().zip(other.values.iter()))
            .any(|(p, (a, b))| p.gates_off && a != b)
    }
}

/// `<name> = <value> <unit>`.
pub fn write_value<W: Write>(out: &mut W, p: &Param, v: f64) -> fmt::Result {
    write!(out, "{} = {} {}", p.name, v, p.unit)
}

/// The `config list` line of `p` (without the line end):
/// `<name> = <value> <unit>  [<min>..<max>]  <description>`.
pub fn write_list_line<W: Write>(out: &mut W, p: &Param, v: f64) -> fmt::Result {
    write_value(out, p, v)?;
    write!(out, "  [{}..{}]  {}", p.min, p.max, p.description)
}

/// The whole table as one JSON array (no line end): per parameter `name`,
/// `unit`, `min`, `max`, `default`, `description`, `integer`, `gates_off`.
/// The strings hold no `"` or `\` (a test checks), so they need no escapes.
pub fn write_schema<W: Write>(out: &mut W) -> fmt::Result {
    out.write_char('[')?;
    for (i, p) in PARAMS.iter().enumerate() {
        if i > 0 {
            out.write_char(',')?;
        }
        write!(
            out,
            "{{\"name\":\"{}\",\"unit\":\"{}\",\"min\":{},\"max\":{},\"default\":{},\
             \"description\":\"{}\",\"integer\":{},\"gates_off\":{}}}",
            p.name,
            p.unit,
            p.min,
            p.max,
            p.default,
            p.description,
            p.kind == Kind::Integer,
            p.gates_off
        )?;
    }
    out.write_char(']')
}

pub mod spi_nor;
pub mod store;

#[cfg(test)]
mod tests;
