//! Fault block: latched faults, over-current limit, watchdog timeout.
use crate::bus::{BusError, RegisterBus};
use crate::regs::fault::{
    FaultStatus, FaultStatusValue, OcLimit, OcLimitValue, WdgTimeout, WdgTimeoutValue,
};

/// Latched fault bits (`FAULT_STATUS`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Faults(pub u32);

impl Faults {
    /// Bit names, by bit position (the register map's field names).
    pub const NAMES: [&'static str; 3] = ["OVERCURRENT", "EXTERNAL", "WATCHDOG"];
    /// The watchdog bit.
    pub const WATCHDOG: u32 = FaultStatusValue::ZERO.with_watchdog(true).bits();
    /// The latched flags, by field, in bit order (as [`Self::NAMES`]).
    fn flags(self) -> [bool; 3] {
        let v = FaultStatusValue::from_bits(self.0);
        [v.overcurrent(), v.external(), v.watchdog()]
    }
    /// No fault latched.
    pub fn none(self) -> bool {
        !self.flags().contains(&true)
    }
    /// Names of the set bits, in bit order.
    pub fn names(self) -> impl Iterator<Item = &'static str> {
        Self::NAMES
            .into_iter()
            .zip(self.flags())
            .filter(|(_, set)| *set)
            .map(|(n, _)| n)
    }
    /// Writes `none` or the names separated by spaces.
    pub fn write_names<W: core::fmt::Write>(self, out: &mut W) -> core::fmt::Result {
        if self.none() {
            return out.write_str("none");
        }
        for (i, n) in self.names().enumerate() {
            if i > 0 {
                out.write_char(' ')?;
            }
            out.write_str(n)?;
        }
        Ok(())
    }
}

/// The fault block.
pub struct Fault<B>(pub B);

impl<B: RegisterBus> Fault<B> {
    /// Latched faults.
    pub fn latched(&mut self) -> Result<Faults, BusError> {
        Ok(Faults(FaultStatus::read(&mut self.0)?.bits()))
    }
    /// Clears every latched fault whose condition is gone (write 1 to clear);
    /// returns what is still latched. The gates stay off until `GATE_EN`
    /// is written 1 again.
    pub fn clear(&mut self) -> Result<Faults, BusError> {
        FaultStatus::write(
            &mut self.0,
            FaultStatusValue::ZERO
                .with_overcurrent(true)
                .with_external(true)
                .with_watchdog(true),
        )?;
        self.latched()
    }
    /// Watchdog timeout, PL clock cycles (the PL clamps to >= 1000).
    pub fn set_watchdog_timeout(&mut self, cycles: u32) -> Result<(), BusError> {
        WdgTimeout::write(&mut self.0, WdgTimeoutValue::ZERO.with_value(cycles))
    }
    /// Over-current trip level, ADC counts of a raw sample's magnitude.
    pub fn set_oc_limit(&mut self, counts: u32) -> Result<(), BusError> {
        OcLimit::write(&mut self.0, OcLimitValue::ZERO.with_value(counts))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;
    use crate::regmap::{self, FAULT};
    use std::string::String;

    #[test]
    fn names_of_latched_faults() {
        let s = |f: Faults| {
            let mut o = String::new();
            f.write_names(&mut o).unwrap();
            o
        };
        assert_eq!(s(Faults(0)), "none");
        assert_eq!(s(Faults(4)), "WATCHDOG");
        assert_eq!(s(Faults(5)), "OVERCURRENT WATCHDOG");
    }

    #[test]
    fn clear_is_write_one_to_clear() {
        let mut pl = FakePl::new();
        pl.set(regmap::FAULT_STATUS_ADDR, Faults::WATCHDOG);
        assert_eq!(Fault(&mut pl).latched().unwrap(), Faults(4));
        assert!(Fault(&mut pl).clear().unwrap().none());
        Fault(&mut pl).set_watchdog_timeout(5).unwrap();
        assert_eq!(pl.get(FAULT.addr(&regmap::WDG_TIMEOUT)), 1000);
    }
}
