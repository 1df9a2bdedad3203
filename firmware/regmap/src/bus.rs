//! The one interface between PL drivers and whatever answers their register
//! accesses: volatile MMIO on GP0 on a board, the simulated PL under QEMU,
//! a fake bus in host tests, the Verilated `pl_top` in co-simulation.
//!
//! Addresses are absolute byte addresses of 32-bit registers (for example
//! `regmap::PWM.addr(&regmap::DUTY_A)`); every access is one whole word.

/// Why a register access failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BusError {
    /// The slave answered `SLVERR`: an unmapped offset, or a write to a
    /// read-only register (the PL also sets `ERR.BAD_ADDR`).
    SlaveError,
    /// No PL answers: the bitstream is not loaded or does not match the
    /// register map, so the driver refuses to touch GP0 (on a real Zynq an
    /// access to an unconfigured PL hangs the AXI bus).
    Absent,
}

/// A 32-bit register bus.
///
/// `&mut self` on reads too: a bus may be a simulation whose state advances
/// or a link that has to send a request.
pub trait RegisterBus {
    /// Reads the register at the absolute address `addr`.
    fn read(&mut self, addr: usize) -> Result<u32, BusError>;
    /// Writes `value` to the register at the absolute address `addr`, all
    /// four byte strobes set.
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError>;
}

impl<B: RegisterBus + ?Sized> RegisterBus for &mut B {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        (**self).read(addr)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        (**self).write(addr, value)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bus that remembers the last write to each of 4 addresses.
    struct Four([(usize, u32); 4]);

    impl RegisterBus for Four {
        fn read(&mut self, addr: usize) -> Result<u32, BusError> {
            self.0
                .iter()
                .find(|(a, _)| *a == addr)
                .map(|(_, v)| *v)
                .ok_or(BusError::SlaveError)
        }
        fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
            let slot = self
                .0
                .iter_mut()
                .find(|(a, _)| *a == addr)
                .ok_or(BusError::SlaveError)?;
            slot.1 = value;
            Ok(())
        }
    }

    fn poke<B: RegisterBus>(mut bus: B, addr: usize, v: u32) -> Result<(), BusError> {
        bus.write(addr, v)
    }

    #[test]
    fn a_mutable_reference_is_a_bus() {
        let mut bus = Four([(0x10, 0), (0x14, 0), (0x18, 0), (0x1C, 0)]);
        poke(&mut bus, 0x14, 7).unwrap();
        assert_eq!(bus.read(0x14), Ok(7));
        assert_eq!(poke(&mut bus, 0x20, 1), Err(BusError::SlaveError));
        assert_eq!(bus.read(0x20), Err(BusError::SlaveError));
    }
}
