//! The simulated motor's own true parameters, as one table: the plant's
//! electrical parameters, its mechanics, its encoder mounting and whether
//! the rotor is held. They are the simulated motor's, not the controllers'
//! (the drive's configuration), so the two can differ on purpose.
//!
//! [`SIM_PARAMS`] lists name, unit, range and description; [`SimMotor::set`]
//! checks a value (finite, whole where integer, in range, then the whole
//! motor as the plant checks it) and changes nothing on an error. The
//! defaults ([`SimMotor::default`]) are the paper's motor held at
//! standstill with the encoder's zero on the d axis.
use super::mechanics::Mechanics;
use super::params::MotorParams;
use super::plant::MechanicalMode;
use crate::validate::ParamError;

/// One row of [`SIM_PARAMS`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimParam {
    /// Name on the console.
    pub name: &'static str,
    /// Unit (`1` for dimensionless).
    pub unit: &'static str,
    /// Smallest value.
    pub min: f64,
    /// Largest value.
    pub max: f64,
    /// Whole numbers only.
    pub integer: bool,
    /// What it is.
    pub description: &'static str,
}

const fn p(
    name: &'static str,
    unit: &'static str,
    min: f64,
    max: f64,
    integer: bool,
    description: &'static str,
) -> SimParam {
    SimParam {
        name,
        unit,
        min,
        max,
        integer,
        description,
    }
}

/// Every parameter of the simulated motor, in `sim list` order.
pub const SIM_PARAMS: [SimParam; 17] = [
    p("r_s", "ohm", 1e-3, 100.0, false, "stator resistance per phase (star equivalent)"),
    p("l", "H", 1e-6, 0.1, false, "stator inductance L_d = L_q"),
    p("psi_pm", "Wb", 1e-4, 1.0, false, "permanent-magnet flux linkage amplitude"),
    p("pole_pairs", "1", 1.0, 64.0, true, "pole pairs"),
    p("j", "kg m^2", 1e-7, 1.0, false, "inertia on the rotor (rotor and load)"),
    p("b", "N m s/rad", 0.0, 10.0, false, "viscous friction"),
    p("coulomb", "N m", 0.0, 10.0, false, "Coulomb friction (sticks at rest)"),
    p("load_torque", "N m", -10.0, 10.0, false, "constant load torque (positive opposes positive speed)"),
    p("spring", "N m/rad", 0.0, 1000.0, false, "joint spring about position 0"),
    p("enc_offset", "counts", 0.0, 65534.0, true, "encoder count with the rotor d axis on phase a (what enc_zero configures; ENC_POS reads it from the first index pulse on)"),
    p("enc_dir", "1", -1.0, 1.0, true, "encoder counting direction, +1 or -1"),
    p("locked", "1", 0.0, 1.0, true, "1: the rotor is held at its angle (a dynamometer at 0 rad/s), 0: it moves"),
    p("enc_dead", "1", 0.0, 1.0, true, "1: the encoder's lines hold their levels whatever the rotor does (a dead encoder), 0: they follow it"),
    p("phase_open", "1", 0.0, 3.0, true, "1, 2, 3: phase a, b or c disconnected (its current is 0), 0: all connected"),
    p("fault_ext", "1", 0.0, 1.0, true, "1: the PL's external fault input asserted, 0: released"),
    p("enc_invert", "1", 0.0, 1.0, true, "1: the encoder's A and B lines both inverted (two counts off), 0: not; a change moves A and B in the same instant, an illegal quadrature step (the PL's ENCODER_LOSS)"),
    p("adc_card", "1", 0.0, 1.0, true, "1: the ADC card is fitted, 0: absent (data-ready held low by the board's pull-down: no ADC result, no control-period boundary in mode off, ADC_STUCK with the gates on)"),
];

/// Why `sim set` refused a value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SimSetError {
    /// No such parameter.
    Unknown,
    /// Not finite, not whole, out of range, or refused by the plant.
    Bad(ParamError),
}

/// The simulated motor's true parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimMotor {
    /// Electrical parameters (and DC link) of the plant.
    pub motor: MotorParams,
    /// Mechanics when not locked.
    pub mech: Mechanics,
    /// Encoder count with the d axis on phase a.
    pub enc_offset: u32,
    /// Encoder direction: +1 counts up with positive rotation.
    pub enc_dir: i32,
    /// The rotor is held.
    pub locked: bool,
    /// The encoder's lines are frozen (a dead encoder).
    pub enc_dead: bool,
    /// Disconnected phase: 0 none, 1..=3 phase a..c.
    pub phase_open: u8,
    /// The external fault input is asserted.
    pub fault_ext: bool,
    /// The encoder's A and B lines are both inverted.
    pub enc_invert: bool,
    /// The ADC card is fitted (its converter answers the convert pulses).
    pub adc_card: bool,
}

impl Default for SimMotor {
    fn default() -> Self {
        let motor = MotorParams::default();
        Self {
            motor,
            mech: Mechanics::rotor(motor.j_kg_m2, motor.friction_nm_s_per_rad),
            enc_offset: 0,
            enc_dir: 1,
            locked: true,
            enc_dead: false,
            phase_open: 0,
            fault_ext: false,
            enc_invert: false,
            adc_card: true,
        }
    }
}

impl SimMotor {
    /// The plant's mechanics: held at 0 rad/s when locked.
    pub fn mechanical_mode(&self) -> MechanicalMode {
        if self.locked {
            MechanicalMode::ConstantSpeed
        } else {
            MechanicalMode::Joint(self.mech)
        }
    }

    /// The value of parameter `i` of [`SIM_PARAMS`] (NaN past the end).
    pub fn get(&self, i: usize) -> f64 {
        match i {
            0 => self.motor.r_s_ohm,
            1 => self.motor.l_d_h,
            2 => self.motor.psi_pm_wb,
            3 => f64::from(self.motor.pole_pairs),
            4 => self.mech.j_kg_m2,
            5 => self.mech.b_nm_s_per_rad,
            6 => self.mech.coulomb_nm,
            7 => self.mech.load_torque_nm,
            8 => self.mech.spring_nm_per_rad,
            9 => f64::from(self.enc_offset),
            10 => f64::from(self.enc_dir),
            11 => f64::from(u8::from(self.locked)),
            12 => f64::from(u8::from(self.enc_dead)),
            13 => f64::from(self.phase_open),
            14 => f64::from(u8::from(self.fault_ext)),
            15 => f64::from(u8::from(self.enc_invert)),
            16 => f64::from(u8::from(self.adc_card)),
            _ => f64::NAN,
        }
    }

    /// Sets `name` to `value`, checked; on an error nothing changes.
    /// `enc_offset` must also stay below `cpr`.
    pub fn set(&mut self, name: &str, value: f64, cpr: u32) -> Result<(), SimSetError> {
        let i = SIM_PARAMS
            .iter()
            .position(|q| q.name == name)
            .ok_or(SimSetError::Unknown)?;
        let q = &SIM_PARAMS[i];
        let bad = |reason| {
            Err(SimSetError::Bad(ParamError {
                field: q.name,
                reason,
            }))
        };
        if !value.is_finite() {
            return bad("must be finite");
        }
        if q.integer && libm::floor(value) != value {
            return bad("must be a whole number");
        }
        if !(q.min..=q.max).contains(&value) {
            return bad("out of range (see `sim list`)");
        }
        let mut next = *self;
        match i {
            0 => next.motor.r_s_ohm = value,
            1 => {
                next.motor.l_d_h = value;
                next.motor.l_q_h = value;
            }
            2 => next.motor.psi_pm_wb = value,
            3 => next.motor.pole_pairs = value as u32,
            4 => next.mech.j_kg_m2 = value,
            5 => next.mech.b_nm_s_per_rad = value,
            6 => next.mech.coulomb_nm = value,
            7 => next.mech.load_torque_nm = value,
            8 => next.mech.spring_nm_per_rad = value,
            9 if value as u32 >= cpr => {
                return bad("must be below the encoder's counts per revolution")
            }
            9 => next.enc_offset = value as u32,
            10 if value == 0.0 => return bad("must be +1 or -1"),
            10 => next.enc_dir = value as i32,
            11 => next.locked = value == 1.0,
            12 => next.enc_dead = value == 1.0,
            13 => next.phase_open = value as u8,
            14 => next.fault_ext = value == 1.0,
            15 => next.enc_invert = value == 1.0,
            _ => next.adc_card = value == 1.0,
        }
        next.motor.validate().map_err(SimSetError::Bad)?;
        next.mech.validate().map_err(SimSetError::Bad)?;
        *self = next;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_todays_motor_held_at_standstill() {
        let m = SimMotor::default();
        assert_eq!(m.motor, MotorParams::default());
        assert_eq!(m.mechanical_mode(), MechanicalMode::ConstantSpeed);
        for (i, q) in SIM_PARAMS.iter().enumerate() {
            let v = m.get(i);
            assert!(v >= q.min && v <= q.max, "{} = {v}", q.name);
        }
        assert_eq!(m.get(0), 0.555);
        assert_eq!(m.get(11), 1.0);
    }

    #[test]
    fn set_checks_and_a_refused_value_changes_nothing() {
        let mut m = SimMotor::default();
        m.set("locked", 0.0, 4096).unwrap();
        m.set("load_torque", 0.2, 4096).unwrap();
        assert_eq!(m.mech.load_torque_nm, 0.2);
        assert!(matches!(m.mechanical_mode(), MechanicalMode::Joint(j) if j.load_torque_nm == 0.2));
        let before = m;
        for (n, v) in [
            ("j", 0.0),
            ("j", f64::NAN),
            ("b", -1.0),
            ("pole_pairs", 2.5),
            ("enc_dir", 0.0),
            ("enc_offset", 4096.0),
            ("locked", 2.0),
            ("load_torque", f64::INFINITY),
        ] {
            assert!(
                matches!(m.set(n, v, 4096), Err(SimSetError::Bad(_))),
                "{n} {v}"
            );
            assert_eq!(m, before);
        }
        assert_eq!(m.set("nope", 1.0, 4096), Err(SimSetError::Unknown));
        m.set("l", 1e-3, 4096).unwrap();
        assert_eq!((m.motor.l_d_h, m.motor.l_q_h), (1e-3, 1e-3));
        m.set("enc_dir", -1.0, 4096).unwrap();
        assert_eq!(m.enc_dir, -1);
    }
}
