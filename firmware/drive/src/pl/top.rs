//! Top/ID block: mode, status summary, access errors, watchdog heartbeat.
use regmap::bus::{BusError, RegisterBus};
use regmap::mode;
use regmap::regs::top::{Ctrl, CtrlValue, Err, Heartbeat, HeartbeatValue, Status};

/// Source of the switching state (`CTRL.MODE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// All gates off.
    Off,
    /// PWM comparators, duties from the PS (FOC on the PS).
    Foc,
    /// The MPDTC core's decisions through the control sequence.
    Mpdtc,
}

impl Mode {
    /// The `CTRL.MODE` value.
    pub fn reg(self) -> u32 {
        match self {
            Mode::Off => mode::OFF,
            Mode::Foc => mode::FOC_PWM,
            Mode::Mpdtc => mode::MPDTC,
        }
    }
    /// Console name.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Off => "off",
            Mode::Foc => "foc",
            Mode::Mpdtc => "mpdtc",
        }
    }
    /// Parses a console name (`off`, `foc`, `mpdtc`).
    pub fn from_name(s: &str) -> Option<Self> {
        [Mode::Off, Mode::Foc, Mode::Mpdtc]
            .into_iter()
            .find(|m| m.name() == s)
    }
}

/// `STATUS` decoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TopStatus {
    /// `STATUS.MODE`.
    pub mode: u32,
    /// The gate driver is enabled.
    pub gates_active: bool,
    /// A fault is latched.
    pub fault: bool,
}

/// The Top/ID block.
pub struct Top<B>(pub B);

impl<B: RegisterBus> Top<B> {
    /// Selects the switching-state source.
    pub fn set_mode(&mut self, m: Mode) -> Result<(), BusError> {
        Ctrl::write(&mut self.0, CtrlValue::ZERO.with_mode(m.reg()))
    }
    /// `STATUS`.
    pub fn status(&mut self) -> Result<TopStatus, BusError> {
        let s = Status::read(&mut self.0)?;
        Ok(TopStatus {
            mode: s.mode(),
            gates_active: s.gates_active(),
            fault: s.fault(),
        })
    }
    /// Restarts the PL watchdog (any value; a counter helps debugging).
    pub fn heartbeat(&mut self, beat: u32) -> Result<(), BusError> {
        Heartbeat::write(&mut self.0, HeartbeatValue::ZERO.with_value(beat))
    }
    /// Sticky access-error flags (`ERR`: bit 0 BAD_VALUE, bit 1 BAD_ADDR).
    pub fn errors(&mut self) -> Result<u32, BusError> {
        Ok(Err::read(&mut self.0)?.bits())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;
    use regmap::{self, TOP};

    #[test]
    fn mode_names_and_register_values() {
        for (m, n, v) in [
            (Mode::Off, "off", 0),
            (Mode::Foc, "foc", 1),
            (Mode::Mpdtc, "mpdtc", 2),
        ] {
            assert_eq!(Mode::from_name(n), Some(m));
            assert_eq!(m.name(), n);
            assert_eq!(m.reg(), v);
        }
        assert_eq!(Mode::from_name("FOC"), None);
        assert_eq!(Mode::from_name(""), None);
    }

    #[test]
    fn mode_heartbeat_and_status() {
        let mut pl = FakePl::new();
        Top(&mut pl).set_mode(Mode::Mpdtc).unwrap();
        assert_eq!(pl.get(regmap::CTRL_ADDR), 2);
        Top(&mut pl).heartbeat(7).unwrap();
        assert_eq!(pl.get(regmap::HEARTBEAT_ADDR), 7);
        pl.set(TOP.addr(&regmap::STATUS), 0b1110);
        assert_eq!(
            Top(&mut pl).status().unwrap(),
            TopStatus {
                mode: 2,
                gates_active: true,
                fault: true
            }
        );
    }
}
