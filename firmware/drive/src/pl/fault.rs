//! Fault block: latched faults, over-current limit, watchdog timeout.
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::fault::{
    FaultStatus, FaultStatusValue, OcLimit, OcLimitValue, WdgTimeout, WdgTimeoutValue,
};

/// Latched faults of the drive: bits 0..=4 are `FAULT_STATUS` (the PL
/// turns the gates off itself), bits 3.. the faults the PS detects (the
/// drive turns the gates off in the control step that sees them; bits 3
/// and 4 have both: the PL's and the PS's checks latch the same fault).
/// The stable fault code of bit `n` is `n + 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Faults(pub u32);

impl Faults {
    /// Bit names, by bit position (the register map's field names first).
    pub const NAMES: [&'static str; 10] = [
        "OVERCURRENT",
        "EXTERNAL",
        "WATCHDOG",
        "ENCODER_LOSS",
        "ADC_STUCK",
        "CONTROL_OVERRUN",
        "POSITION_LIMIT",
        "OVERSPEED",
        "ENCODER_DEAD",
        "PHASE_OPEN",
    ];
    /// The overcurrent bit.
    pub const OVERCURRENT: u32 = FaultStatusValue::ZERO.with_overcurrent(true).bits();
    /// The external fault input's bit.
    pub const EXTERNAL: u32 = FaultStatusValue::ZERO.with_external(true).bits();
    /// The watchdog bit.
    pub const WATCHDOG: u32 = FaultStatusValue::ZERO.with_watchdog(true).bits();
    /// The bits of `FAULT_STATUS`.
    pub const PL_MASK: u32 = 0b1_1111;
    /// An illegal quadrature step (PL), or the encoder position jumped
    /// further in one control period than the motor can turn (PS): noise,
    /// lost counts, a broken line.
    pub const ENCODER_LOSS: u32 = FaultStatusValue::ZERO.with_encoder_loss(true).bits();
    /// No raw ADC sample for a sample period and a margin (PL), or a
    /// control period without a new ADC result (PS).
    pub const ADC_STUCK: u32 = FaultStatusValue::ZERO.with_adc_stuck(true).bits();
    /// Two or more control periods in a row without a control step.
    pub const CONTROL_OVERRUN: u32 = 1 << 5;
    /// The multi-turn position left the soft limits `pos_min`..`pos_max`.
    pub const POSITION_LIMIT: u32 = 1 << 6;
    /// The velocity estimate exceeded `vel_limit` by the margin.
    pub const OVERSPEED: u32 = 1 << 7;
    /// The encoder stood still for a window while the back-EMF said the
    /// rotor turns (`servo::evidence`).
    pub const ENCODER_DEAD: u32 = 1 << 8;
    /// A phase current stayed at zero for a window while its reference
    /// said it must not (`servo::evidence`).
    pub const PHASE_OPEN: u32 = 1 << 9;
    /// The latched flags, in bit order (as [`Self::NAMES`]).
    fn flags(self) -> [bool; 10] {
        let v = FaultStatusValue::from_bits(self.0 & Self::PL_MASK);
        let b = |m: u32| self.0 & m != 0;
        [
            v.overcurrent(),
            v.external(),
            v.watchdog(),
            b(Self::ENCODER_LOSS),
            b(Self::ADC_STUCK),
            b(Self::CONTROL_OVERRUN),
            b(Self::POSITION_LIMIT),
            b(Self::OVERSPEED),
            b(Self::ENCODER_DEAD),
            b(Self::PHASE_OPEN),
        ]
    }
    /// Stable code of the fault `bit` (0-based): `bit + 1`.
    pub const fn code(bit: usize) -> u32 {
        bit as u32 + 1
    }
    /// The bits set, in bit order.
    pub fn bits(self) -> impl Iterator<Item = usize> {
        self.flags()
            .into_iter()
            .enumerate()
            .filter(|(_, set)| *set)
            .map(|(i, _)| i)
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
        Ok(Faults(
            FaultStatus::read(&mut self.0)?.bits() & Faults::PL_MASK,
        ))
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
                .with_watchdog(true)
                .with_encoder_loss(true)
                .with_adc_stuck(true),
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
    use regmap::{self, FAULT};
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
        assert_eq!(
            s(Faults(Faults::ADC_STUCK | Faults::CONTROL_OVERRUN | 2)),
            "EXTERNAL ADC_STUCK CONTROL_OVERRUN"
        );
        assert_eq!(s(Faults(Faults::ENCODER_LOSS)), "ENCODER_LOSS");
        let codes: std::vec::Vec<u32> = Faults(0b11_1111).bits().map(Faults::code).collect();
        assert_eq!(codes, [1, 2, 3, 4, 5, 6]);
    }

    #[test]
    fn clear_is_write_one_to_clear() {
        let mut pl = FakePl::new();
        pl.set(regmap::FAULT_STATUS_ADDR, Faults::WATCHDOG);
        assert_eq!(Fault(&mut pl).latched().unwrap(), Faults(4));
        assert!(Fault(&mut pl).clear().unwrap().none());
        pl.set(
            regmap::FAULT_STATUS_ADDR,
            Faults::ENCODER_LOSS | Faults::ADC_STUCK,
        );
        assert_eq!(
            Fault(&mut pl).latched().unwrap(),
            Faults(Faults::ENCODER_LOSS | Faults::ADC_STUCK)
        );
        assert!(Fault(&mut pl).clear().unwrap().none());
        Fault(&mut pl).set_watchdog_timeout(5).unwrap();
        assert_eq!(pl.get(FAULT.addr(&regmap::WDG_TIMEOUT)), 1000);
    }
}
