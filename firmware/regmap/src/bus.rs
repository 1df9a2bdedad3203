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
    /// Reads the registers at `addrs`, in this order, back to back into
    /// `out` (one word each; `out` at least as long as `addrs`). Every read
    /// is made; the result is the first one's error, if any. A bus that
    /// sends requests (the co-simulation bridge) sends them together and
    /// waits once.
    fn read_many(&mut self, addrs: &[usize], out: &mut [u32]) -> Result<(), BusError> {
        let mut first = Ok(());
        for (a, o) in addrs.iter().zip(out.iter_mut()) {
            match self.read(*a) {
                Ok(v) => *o = v,
                Err(e) => {
                    *o = 0;
                    first = first.and(Err(e));
                }
            }
        }
        first
    }
}

impl<B: RegisterBus + ?Sized> RegisterBus for &mut B {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        (**self).read(addr)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        (**self).write(addr, value)
    }
    fn read_many(&mut self, addrs: &[usize], out: &mut [u32]) -> Result<(), BusError> {
        (**self).read_many(addrs, out)
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

    fn many<B: RegisterBus>(mut bus: B, a: &[usize], out: &mut [u32]) -> Result<(), BusError> {
        bus.read_many(a, out)
    }

    #[test]
    fn read_many_reads_every_address_in_order_and_reports_the_first_error() {
        let mut bus = Four([(0x10, 1), (0x14, 2), (0x18, 3), (0x1C, 4)]);
        let mut out = [9u32; 4];
        // Through `&mut B`'s forwarding, as the drivers call it.
        assert_eq!(many(&mut bus, &[0x1C, 0x10, 0x18], &mut out), Ok(()));
        assert_eq!(out, [4, 1, 3, 9]);
        // An unmapped address in the middle: the reads after it still made.
        assert_eq!(
            bus.read_many(&[0x14, 0x20, 0x18], &mut out),
            Err(BusError::SlaveError)
        );
        assert_eq!(out, [2, 0, 3, 9]);
    }

    /// A bus that answers groups itself (as the co-simulation bridge does).
    struct Grouped(Four, u32);

    impl RegisterBus for Grouped {
        fn read(&mut self, addr: usize) -> Result<u32, BusError> {
            self.0.read(addr)
        }
        fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
            self.0.write(addr, value)
        }
        fn read_many(&mut self, addrs: &[usize], out: &mut [u32]) -> Result<(), BusError> {
            self.1 += 1;
            self.0.read_many(addrs, out)
        }
    }

    #[test]
    fn a_mutable_reference_forwards_groups_to_the_bus() {
        let mut bus = Grouped(Four([(0x10, 5), (0x14, 6), (0x18, 0), (0x1C, 0)]), 0);
        let mut out = [0u32; 2];
        assert_eq!(many(&mut bus, &[0x14, 0x10], &mut out), Ok(()));
        assert_eq!((out, bus.1), ([6, 5], 1));
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
