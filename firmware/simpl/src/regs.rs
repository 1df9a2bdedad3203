//! `pl_regs`: the stored registers of the map and the write rules, taken
//! from the [`regmap`] table (`Register::apply_write`: mask, clamp, reject,
//! W1C) rather than restated; read-only registers are views of the blocks
//! (assembled in `pl.rs`).

use regmap::{self, Access, Block, RegError, Register};

/// Stored registers: the map's software-writable ones (RW and W1C), one
/// slot each, in the order of [`regmap::WRITABLE_ADDRS`].
pub const STORED: usize = regmap::WRITABLE_COUNT;

/// Storage slot of a writable register at absolute address `addr`
/// (`None`: unmapped or read-only).
pub const fn slot(addr: usize) -> Option<usize> {
    let mut i = 0;
    while i < STORED {
        if regmap::WRITABLE_ADDRS[i] == addr {
            return Some(i);
        }
        i += 1;
    }
    None
}

/// Slot of a register that must be stored (compile-time check).
pub const fn slot_of(block: &Block, reg: &Register) -> usize {
    match slot(block.addr(reg)) {
        Some(s) => s,
        None => panic!("not a stored register"),
    }
}

/// What a bus write did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WriteResult {
    /// Stored (possibly clamped or masked); `slot` changed to `value`.
    Stored {
        /// Storage slot.
        slot: usize,
        /// New value.
        value: u32,
    },
    /// W1C register: its value after clearing the written ones.
    Cleared {
        /// Storage slot.
        slot: usize,
        /// Value after the clear (before this cycle's new set bits).
        value: u32,
    },
    /// Rejected value: nothing stored, `ERR.BAD_VALUE`.
    Rejected,
    /// Unmapped or read-only: `SLVERR`, `ERR.BAD_ADDR`.
    SlaveError,
}

/// The stored registers, in map order, at their reset values.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Regs {
    /// Values by slot.
    pub v: [u32; STORED],
}

impl Default for Regs {
    fn default() -> Self {
        let mut v = [0; STORED];
        for (x, &addr) in v.iter_mut().zip(regmap::WRITABLE_ADDRS.iter()) {
            // every address is a register of the map (regmap's tests)
            if let Some((_, reg)) = regmap::lookup(addr) {
                *x = reg.reset;
            }
        }
        Self { v }
    }
}

impl Regs {
    /// Value of a stored register.
    pub fn get(&self, slot: usize) -> u32 {
        self.v[slot]
    }

    /// Decodes a write of `value` (all byte strobes) to `addr` by the
    /// table's rules, without changing anything. `w1c_now` gives the
    /// present value of a W1C register kept outside (FAULT_STATUS).
    pub fn decode_write(
        &self,
        addr: usize,
        value: u32,
        w1c_now: impl Fn(usize) -> u32,
    ) -> WriteResult {
        let Some((_, reg)) = regmap::lookup(addr) else {
            return WriteResult::SlaveError;
        };
        let Some(slot) = slot(addr) else {
            return WriteResult::SlaveError;
        };
        match reg.access {
            Access::Ro => WriteResult::SlaveError,
            Access::W1c => {
                let old = w1c_now(slot);
                match reg.apply_write(old, value) {
                    Ok(v) => WriteResult::Cleared { slot, value: v },
                    Err(_) => WriteResult::SlaveError,
                }
            }
            Access::Rw => match reg.apply_write(self.v[slot], value) {
                Ok(v) => WriteResult::Stored { slot, value: v },
                Err(RegError::Rejected) => WriteResult::Rejected,
                Err(RegError::ReadOnly) => WriteResult::SlaveError,
            },
        }
    }
}
