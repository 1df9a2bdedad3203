//! A fake PL for driver tests: every register of the map with its reset
//! value and the table's write rules (`Register::apply_write`), plus a log of
//! the writes. Its one behaviour: `ADC_COUNT` advances at every read while
//! `ADC_CTRL.ENABLE` is set (an ADC that keeps converting); otherwise tests
//! poke read-only registers through [`FakePl::set`] to play the hardware.
use regmap::bus::{BusError, RegisterBus};
use regmap::{self, RegError};
use std::vec::Vec;

pub(crate) struct FakePl {
    regs: Vec<(usize, u32)>,
    /// Every accepted or rejected write, in order.
    pub writes: Vec<(usize, u32)>,
}

impl FakePl {
    pub fn new() -> Self {
        let mut regs = Vec::new();
        for b in regmap::BLOCKS {
            for r in b.registers {
                regs.push((b.addr(r), r.reset));
            }
        }
        Self {
            regs,
            writes: Vec::new(),
        }
    }
    /// Sets a register as the hardware would (any access type).
    pub fn set(&mut self, addr: usize, v: u32) {
        self.regs.iter_mut().find(|(a, _)| *a == addr).unwrap().1 = v;
    }
    pub fn get(&self, addr: usize) -> u32 {
        self.regs.iter().find(|(a, _)| *a == addr).unwrap().1
    }
}

impl RegisterBus for FakePl {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        let count = regmap::ADC.addr(&regmap::ADC_COUNT);
        if addr == count && self.get(regmap::ADC.addr(&regmap::ADC_CTRL)) & 1 != 0 {
            self.set(count, self.get(count).wrapping_add(1));
        }
        self.regs
            .iter()
            .find(|(a, _)| *a == addr)
            .map(|(_, v)| *v)
            .ok_or(BusError::SlaveError)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.writes.push((addr, value));
        let (_, reg) = regmap::lookup(addr).ok_or(BusError::SlaveError)?;
        let slot = self.regs.iter_mut().find(|(a, _)| *a == addr).unwrap();
        match reg.apply_write(slot.1, value) {
            Ok(v) => {
                slot.1 = v;
                Ok(())
            }
            Err(RegError::ReadOnly) => Err(BusError::SlaveError),
            Err(RegError::Rejected) => Ok(()),
        }
    }
}
