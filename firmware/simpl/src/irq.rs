//! `ctrl_irq`: the control interrupt to the PS (`irq_o`, `IRQ_F2P[0]`),
//! cycle for cycle as `pl-bitstream-src/rtl/ctrl_irq.v`: sticky flags
//! `IRQ_STATUS` (bit 0 boundary, bit 1 newly latched fault, bit 2 a
//! boundary on an unacknowledged one), the line `|(flags[1:0] & IRQ_EN)`
//! one cycle late, and `BOUNDARY_AGE` (cycles since the last boundary,
//! saturating at 16 bits).

/// The block's registers.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CtrlIrq {
    /// `IRQ_STATUS`.
    pub status: u8,
    fault_q: bool,
    /// The line.
    pub irq: bool,
    /// `BOUNDARY_AGE`.
    pub age: u16,
}

impl CtrlIrq {
    /// One clock edge: `boundary` strobe, `fault` (a fault latched), `en`
    /// (`IRQ_EN`), `clr` (the ones written to `IRQ_STATUS` this cycle).
    pub fn step(&mut self, boundary: bool, fault: bool, en: u32, clr: u8) {
        let kept = self.status & !clr;
        let set = u8::from(boundary)
            | (u8::from(fault && !self.fault_q) << 1)
            | (u8::from(boundary && kept & 1 != 0) << 2);
        let d = kept | set;
        self.status = d;
        self.fault_q = fault;
        self.irq = u32::from(d & 3) & en != 0;
        self.age = if boundary {
            0
        } else {
            self.age.saturating_add(1)
        };
    }

    /// Cycles from now in which only the age changes, with `fault` and
    /// `en` constant and no boundary: none while the line or the fault
    /// edge detector has yet to follow its input.
    pub fn quiet(&self, fault: bool, en: u32) -> u64 {
        if self.fault_q != fault || self.irq != (u32::from(self.status & 3) & en != 0) {
            0
        } else {
            crate::NEVER
        }
    }

    /// `k` quiet cycles.
    pub fn skip(&mut self, k: u64) {
        self.age = (u64::from(self.age) + k).min(u64::from(u16::MAX)) as u16;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_line_and_age_as_the_rtl() {
        let mut b = CtrlIrq::default();
        b.step(false, false, 0b01, 0);
        assert_eq!((b.status, b.irq, b.age), (0, false, 1));
        // Boundary: flag, line one edge later (same edge as the flag).
        b.step(true, false, 0b01, 0);
        assert_eq!((b.status, b.irq, b.age), (1, true, 0));
        // Second boundary before the acknowledge: missed.
        b.step(true, false, 0b01, 0);
        assert_eq!(b.status, 0b101);
        // Acknowledge of both with a boundary in the same cycle: the
        // boundary wins, no new miss (the old one was cleared).
        b.step(true, false, 0b01, 0b101);
        assert_eq!((b.status, b.irq), (0b001, true));
        b.step(false, false, 0b01, 0b001);
        assert_eq!((b.status, b.irq, b.age), (0, false, 1));
        // A fault edge sets FAULT; raises the line only when enabled.
        b.step(false, true, 0b01, 0);
        assert_eq!((b.status, b.irq), (0b010, false));
        b.step(false, true, 0b11, 0);
        assert_eq!((b.status, b.irq), (0b010, true));
        b.skip(1_000_000);
        assert_eq!(b.age, u16::MAX);
    }
}
