//! Is our bitstream in the PL? Decided before the first GP0 access.
//!
//! On a real Zynq an AXI GP0 access while the PL is unconfigured never
//! completes and hangs the interconnect, so the order is fixed:
//! 1. the PS's device-configuration block (devcfg, UG585 ch. 6) says the PL
//!    is configured: `INT_STS.PCFG_DONE` (bit 2 of `0xF800_700C`); this read
//!    is on the PS side and always safe;
//! 2. only then `ID` and `VERSION` are read over GP0; `ID` must be
//!    [`regmap::ID_VALUE`] and the major version of `VERSION` the one this
//!    firmware was built against.
//!
//! QEMU 7.2's `xilinx-zynq-a9` models devcfg; with no bitstream (QEMU cannot
//! load one) `INT_STS` reads `0x0000_0000` after reset (measured: `status`
//! prints it), so `PCFG_DONE` is clear and the firmware never touches GP0:
//! it selects the simulated PL instead.
use regmap::bus::RegisterBus;
use regmap::regs::top::{Id, Version, VersionValue};

/// Absolute address of devcfg `INT_STS` (PS side, always readable).
pub const DEVCFG_INT_STS: usize = 0xF800_7000 + 0x0C;
/// `INT_STS.PCFG_DONE`: the PL has been configured.
pub const PCFG_DONE: u32 = 1 << 2;

/// What is in the PL.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Presence {
    /// devcfg says the PL is not configured: GP0 must not be touched.
    Unconfigured,
    /// The PL is configured but `ID` is not ours (another design).
    Foreign {
        /// What `ID` read.
        id: u32,
    },
    /// Our bitstream with a register map of another major version.
    Incompatible {
        /// `VERSION` as read (major << 16 | minor).
        version: u32,
    },
    /// Our bitstream, compatible register map.
    Ours {
        /// `VERSION` as read (major << 16 | minor).
        version: u32,
    },
}

impl Presence {
    /// Whether the drivers may use the PL behind GP0.
    pub fn usable(self) -> bool {
        matches!(self, Presence::Ours { .. })
    }
}

/// Major version of the register map this firmware speaks.
pub const fn major(version: u32) -> u32 {
    VersionValue::from_bits(version).major()
}

/// Decides from devcfg's `INT_STS` (read by the caller from
/// [`DEVCFG_INT_STS`]) and, only when `PCFG_DONE` is set, `ID`/`VERSION`
/// over `bus`. A bus error on `ID` counts as a foreign design.
pub fn detect<B: RegisterBus>(devcfg_int_sts: u32, bus: &mut B) -> Presence {
    if devcfg_int_sts & PCFG_DONE == 0 {
        return Presence::Unconfigured;
    }
    let id = Id::read(bus).map_or(0, |v| v.value());
    if id != regmap::ID_VALUE {
        return Presence::Foreign { id };
    }
    let version = Version::read(bus).map_or(0, |v| v.bits());
    if major(version) != major(regmap::VERSION.reset) {
        Presence::Incompatible { version }
    } else {
        Presence::Ours { version }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;
    use regmap::bus::BusError;

    /// A bus that must never be touched.
    struct Untouchable;
    impl RegisterBus for Untouchable {
        fn read(&mut self, addr: usize) -> Result<u32, BusError> {
            panic!("GP0 read at {addr:#x} with the PL unconfigured")
        }
        fn write(&mut self, addr: usize, _: u32) -> Result<(), BusError> {
            panic!("GP0 write at {addr:#x} with the PL unconfigured")
        }
    }

    #[test]
    fn unconfigured_pl_is_never_touched() {
        // What QEMU reports (0) and every other value without bit 2.
        for sts in [0, !PCFG_DONE] {
            assert_eq!(detect(sts, &mut Untouchable), Presence::Unconfigured);
        }
        assert!(!Presence::Unconfigured.usable());
    }

    #[test]
    fn our_bitstream_is_recognised_by_id_and_major_version() {
        let mut pl = FakePl::new();
        let v = regmap::VERSION.reset;
        assert_eq!(detect(PCFG_DONE, &mut pl), Presence::Ours { version: v });
        assert!(Presence::Ours { version: v }.usable());
        // A newer minor version still speaks our map.
        pl.set(regmap::TOP.addr(&regmap::VERSION), v + 1);
        assert!(detect(PCFG_DONE, &mut pl).usable());
        // Another major version does not.
        pl.set(regmap::TOP.addr(&regmap::VERSION), v + 0x1_0000);
        assert_eq!(
            detect(PCFG_DONE, &mut pl),
            Presence::Incompatible {
                version: v + 0x1_0000
            }
        );
        pl.set(regmap::TOP.addr(&regmap::ID), 0xDEAD_BEEF);
        assert_eq!(
            detect(PCFG_DONE, &mut pl),
            Presence::Foreign { id: 0xDEAD_BEEF }
        );
    }
}
