//! Is our bitstream in the PL? Decided before the first GP0 access.
//!
//! On a real Zynq an AXI GP0 access while the PL is unconfigured, while the
//! PS-PL level shifters are off or while the PL's AXI slave is held in
//! reset never completes and hangs the interconnect, so the order is fixed:
//! 1. the GP0 guard ([`Guard`]), three PS-side reads that are always safe:
//!    the device-configuration block (devcfg, UG585 ch. 6) says the PL is
//!    configured (`INT_STS.PCFG_DONE`, bit 2 of `0xF800_700C`), the SLCR's
//!    `LVL_SHFTR_EN` (`0xF800_0900`) is `0xF` (all PS-PL level shifters
//!    on), and `FPGA_RST_CTRL` (`0xF800_0240`) does not hold
//!    `FCLK_RESET0_N`, the reset of the design's AXI interconnect and
//!    `pl_top` (bit 0, `FPGA0_OUT_RST`);
//! 2. the EMIO signature ([`gp0_access`]): our `board_top` drives the
//!    constant [`SIGNATURE`] (the register map's `ID` value, `"PSDR"`) into
//!    the PS7's 32 EMIO GPIO inputs, which the PS reads in the GPIO
//!    controller's bank-2 input register `DATA_RO_2` (`0xE000_A068`,
//!    EMIO GPIO 54..85) without any AXI access to the PL. A configured PL
//!    whose signature is not ours is a foreign design and GP0 is not
//!    touched at all, not even for the boot's `GATE_CTRL` write: a foreign
//!    design neither sees a write nor gets the chance to answer one with a
//!    bus error. The word means something only once the guard passed (the
//!    PL configured, the PL-to-PS level shifters on), so it is read after
//!    the guard and the guard's verdict comes first;
//! 3. only then `ID` and `VERSION` are read over GP0; `ID` must be
//!    [`regmap::ID_VALUE`] and the major version of `VERSION` the one this
//!    firmware was built against. The signature makes `ID` a second line:
//!    a design that copies the signature but not the register map is still
//!    caught here (and a bus error here is survived, `pl.rs`).
//!
//! QEMU 7.2's `xilinx-zynq-a9` models devcfg; with no bitstream (QEMU cannot
//! load one) `INT_STS` reads `0x0000_0000` after reset (measured: `status`
//! prints it), so `PCFG_DONE` is clear and the firmware never touches GP0,
//! nor the GPIO controller (QEMU 7.2 does not model it): the signature is
//! not exercised under QEMU.
//!
//! An unconfigured PL alone does not mean QEMU: a board booted without our
//! bitstream reads the same. The simulated PL (or the co-simulated RTL) is
//! chosen only where [`platform`] says the firmware runs in an emulator:
//! SLCR `PSS_IDCODE` (`0xF800_0530`, a PS register, always readable) holds
//! the JTAG IDCODE of the die on every Zynq-7000 (UG585, register
//! `PSS_IDCODE`: bit 0 reads 1 and bits 11:1 are Xilinx's JEDEC
//! manufacturer code `0x049`), so a Zynq reads `0x093` in its low 12 bits.
//! QEMU 7.2 does not model the register: it reads `0x0000_0000` (measured,
//! the banner prints it). A board cannot fail the check; an emulator that
//! one day models the IDCODE passes for a board and gets `pl: absent`,
//! never a simulated motor on real gates.
use regmap::bus::RegisterBus;
use regmap::regs::top::{Id, Version, VersionValue};

/// Absolute address of devcfg `INT_STS` (PS side, always readable).
pub const DEVCFG_INT_STS: usize = 0xF800_7000 + 0x0C;
/// `INT_STS.PCFG_DONE`: the PL has been configured.
pub const PCFG_DONE: u32 = 1 << 2;
/// Absolute address of SLCR `LVL_SHFTR_EN`.
pub const SLCR_LVL_SHFTR_EN: usize = 0xF800_0900;
/// `LVL_SHFTR_EN` with every PS-PL level shifter enabled.
pub const LVL_SHFTR_ALL: u32 = 0xF;
/// Absolute address of SLCR `FPGA_RST_CTRL`.
pub const SLCR_FPGA_RST_CTRL: usize = 0xF800_0240;
/// `FPGA_RST_CTRL.FPGA0_OUT_RST`: `FCLK_RESET0_N` held (the PL's AXI slave
/// in reset).
pub const FPGA0_OUT_RST: u32 = 1 << 0;

/// Absolute address of the GPIO controller's `DATA_RO_2` (UG585 appendix B,
/// `gpio`): the input value of bank 2, EMIO GPIO 54..85, bit 0 = GPIO 54.
/// A PS register, but only readable with the controller's AMBA clock on
/// ([`SLCR_APER_CLK_CTRL`]).
pub const GPIO_DATA_RO_2: usize = 0xE000_A000 + 0x68;
/// Absolute address of SLCR `APER_CLK_CTRL` (AMBA peripheral clock gates).
pub const SLCR_APER_CLK_CTRL: usize = 0xF800_0000 + 0x12C;
/// `APER_CLK_CTRL.GPIO_CPU_1XCLKACT`: the GPIO controller's AMBA clock.
/// A read of a clock-gated peripheral can hang the bus, so it is set before
/// `DATA_RO_2` is read.
pub const GPIO_CPU_1XCLKACT: u32 = 1 << 22;
/// What our `board_top` drives into the PS7's EMIO GPIO inputs: the
/// register map's `ID` value (`"PSDR"`), one source of truth for the RTL
/// (`RM_ID_RESET` in `regmap.vh`) and the firmware.
pub const SIGNATURE: u32 = regmap::ID_VALUE;

/// The three PS-side words the GP0 guard reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Guard {
    /// devcfg `INT_STS`.
    pub int_sts: u32,
    /// SLCR `LVL_SHFTR_EN`.
    pub lvl_shftr_en: u32,
    /// SLCR `FPGA_RST_CTRL`.
    pub fpga_rst_ctrl: u32,
}

/// The first check of the GP0 guard that failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GuardFailure {
    /// `INT_STS.PCFG_DONE` clear: the PL is not configured.
    Unconfigured,
    /// `LVL_SHFTR_EN` is not `0xF` (its value).
    LevelShifters(u32),
    /// `FPGA_RST_CTRL` holds `FCLK_RESET0_N` (its value).
    PlReset(u32),
}

impl Guard {
    /// Whether GP0 may be touched; the first failed check otherwise.
    pub fn check(&self) -> Result<(), GuardFailure> {
        if self.int_sts & PCFG_DONE == 0 {
            Err(GuardFailure::Unconfigured)
        } else if self.lvl_shftr_en & LVL_SHFTR_ALL != LVL_SHFTR_ALL {
            Err(GuardFailure::LevelShifters(self.lvl_shftr_en))
        } else if self.fpga_rst_ctrl & FPGA0_OUT_RST != 0 {
            Err(GuardFailure::PlReset(self.fpga_rst_ctrl))
        } else {
            Ok(())
        }
    }
}

/// What `status` prints after `gp0_guard: `.
impl core::fmt::Display for Guard {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self.check() {
            Ok(()) => f.write_str("pass")?,
            Err(GuardFailure::Unconfigured) => {
                f.write_str("fail: devcfg INT_STS.PCFG_DONE clear (PL not configured)")?
            }
            Err(GuardFailure::LevelShifters(v)) => write!(
                f,
                "fail: SLCR LVL_SHFTR_EN 0x{v:x} (needs 0xf: PS-PL level shifters off)"
            )?,
            Err(GuardFailure::PlReset(v)) => write!(
                f,
                "fail: SLCR FPGA_RST_CTRL 0x{v:08x} (FCLK_RESET0_N held: PL in reset)"
            )?,
        }
        write!(
            f,
            " (INT_STS 0x{:08x}, LVL_SHFTR_EN 0x{:x}, FPGA_RST_CTRL 0x{:08x})",
            self.int_sts, self.lvl_shftr_en, self.fpga_rst_ctrl
        )
    }
}

/// Absolute address of SLCR `PSS_IDCODE` (PS side, always readable).
pub const SLCR_PSS_IDCODE: usize = 0xF800_0000 + 0x530;
/// Low 12 bits of every Zynq-7000's `PSS_IDCODE`: Xilinx's JEDEC
/// manufacturer code `0x049` in bits 11:1 and the constant 1 in bit 0.
pub const IDCODE_XILINX: u32 = (0x049 << 1) | 1;

/// What the firmware runs on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Platform {
    /// Zynq silicon: only a bitstream may be driven.
    Zynq,
    /// An emulator (QEMU): the simulated PL may stand in for the PL.
    Emulator,
}

/// The platform from SLCR `PSS_IDCODE` as read (see the module docs).
pub fn platform(pss_idcode: u32) -> Platform {
    if pss_idcode & 0xFFF == IDCODE_XILINX {
        Platform::Zynq
    } else {
        Platform::Emulator
    }
}

/// What answers the drivers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Selection {
    /// Our bitstream behind GP0; `VERSION` as read.
    Bitstream {
        /// `VERSION` (major << 16 | minor).
        version: u32,
    },
    /// No bitstream in an emulator: a simulated PL (the Rust model, or the
    /// co-simulated RTL when the emulator's command line asks for it).
    Simulated,
    /// Nothing the firmware may drive: no bitstream on a board, or a PL
    /// that is not ours. The drive commands answer `ERR pl-absent`.
    Absent(Presence),
}

/// The backend for what [`detect`] found on `platform`.
pub fn select(presence: Presence, platform: Platform) -> Selection {
    match (presence, platform) {
        (Presence::Ours { version }, _) => Selection::Bitstream { version },
        (Presence::Unconfigured, Platform::Emulator) => Selection::Simulated,
        (p, _) => Selection::Absent(p),
    }
}

/// What is in the PL.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Presence {
    /// devcfg says the PL is not configured: GP0 must not be touched.
    Unconfigured,
    /// The PL is configured but the level shifters are off or it is held
    /// in reset: GP0 must not be touched.
    Blocked(GuardFailure),
    /// The PL is configured and reachable but its EMIO signature
    /// (`DATA_RO_2`) is not ours: another design, GP0 must not be touched.
    Unsigned {
        /// What `DATA_RO_2` read.
        signature: u32,
    },
    /// The signature is ours but `ID` is not (or GP0 answered with a bus
    /// error): not our register map.
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

/// Whether GP0 may be touched at all, from the guard's words and the EMIO
/// signature word (`DATA_RO_2`), both read by the caller from PS registers:
/// `Ok` only when the guard passes and the signature is ours; otherwise
/// what is in the PL, and GP0 stays untouched (reads and writes alike).
/// The guard decides first: its failure is reported whatever `signature`
/// holds, so a caller that did not read the signature (it must not before
/// the guard passes: see `pl.rs`) may pass anything.
pub fn gp0_access(guard: &Guard, signature: u32) -> Result<(), Presence> {
    match guard.check() {
        Err(GuardFailure::Unconfigured) => Err(Presence::Unconfigured),
        Err(f) => Err(Presence::Blocked(f)),
        Ok(()) if signature != SIGNATURE => Err(Presence::Unsigned { signature }),
        Ok(()) => Ok(()),
    }
}

/// What is in the PL: [`gp0_access`] first, and only when it allows GP0,
/// `ID`/`VERSION` over `bus` ([`detect`]). What the firmware calls.
pub fn detect_signed<B: RegisterBus>(guard: &Guard, signature: u32, bus: &mut B) -> Presence {
    match gp0_access(guard, signature) {
        Ok(()) => detect(guard, bus),
        Err(p) => p,
    }
}

/// The GP0 step of [`detect_signed`]: decides from the guard's words (read
/// by the caller) and, only when the guard passes, `ID`/`VERSION` over
/// `bus`. A bus error on `ID` counts as a foreign design. It does not look
/// at the EMIO signature: call it only after [`gp0_access`] allowed GP0.
pub fn detect<B: RegisterBus>(guard: &Guard, bus: &mut B) -> Presence {
    match guard.check() {
        Ok(()) => {}
        Err(GuardFailure::Unconfigured) => return Presence::Unconfigured,
        Err(f) => return Presence::Blocked(f),
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

    /// A bus that must never be touched (the PL unconfigured, unreachable
    /// or not signed as ours).
    struct Untouchable;
    impl RegisterBus for Untouchable {
        fn read(&mut self, addr: usize) -> Result<u32, BusError> {
            panic!("GP0 read at {addr:#x} where GP0 must not be touched")
        }
        fn write(&mut self, addr: usize, _: u32) -> Result<(), BusError> {
            panic!("GP0 write at {addr:#x} where GP0 must not be touched")
        }
    }

    /// Configured, level shifters on, out of reset.
    const READY: Guard = Guard {
        int_sts: PCFG_DONE,
        lvl_shftr_en: 0xF,
        fpga_rst_ctrl: 0,
    };

    #[test]
    fn unconfigured_pl_is_never_touched() {
        // What QEMU reports (0) and every other value without bit 2.
        for sts in [0, !PCFG_DONE] {
            let g = Guard {
                int_sts: sts,
                ..READY
            };
            assert_eq!(detect(&g, &mut Untouchable), Presence::Unconfigured);
        }
        assert!(!Presence::Unconfigured.usable());
    }

    /// `PSS_IDCODE` of an XC7Z020 (UG585: revision 3, family 0x1B,
    /// subfamily 0x9, device 0x07, manufacturer 0x049, bit 0 set).
    const IDCODE_7Z020: u32 = 0x3372_7093;
    /// What QEMU 7.2's `xilinx-zynq-a9` reads there (measured).
    const IDCODE_QEMU: u32 = 0;

    #[test]
    fn idcode_tells_silicon_from_the_emulator() {
        assert_eq!(platform(IDCODE_7Z020), Platform::Zynq);
        // Any revision and device of the family: the low 12 bits decide.
        for dev in [0x02u32, 0x07, 0x0C, 0x11] {
            let id = (0x1B << 21) | (0x9 << 17) | (dev << 12) | (0x049 << 1) | 1;
            assert_eq!(platform(id), Platform::Zynq, "{id:#x}");
        }
        assert_eq!(platform(IDCODE_QEMU), Platform::Emulator);
        assert_eq!(platform(0xFFFF_FFFF), Platform::Emulator);
    }

    #[test]
    fn a_board_without_bitstream_never_gets_a_simulated_pl() {
        // Every case: (devcfg INT_STS, PSS_IDCODE, ID) -> selection, with
        // GP0 read only when devcfg says the PL is configured.
        let v = regmap::VERSION.reset;
        let pick = |sts: u32, idcode: u32, id: u32| {
            let mut pl = FakePl::new();
            pl.set(regmap::TOP.addr(&regmap::ID), id);
            let p = if sts & PCFG_DONE == 0 {
                detect(
                    &Guard {
                        int_sts: sts,
                        ..READY
                    },
                    &mut Untouchable,
                )
            } else {
                detect(
                    &Guard {
                        int_sts: sts,
                        ..READY
                    },
                    &mut pl,
                )
            };
            select(p, platform(idcode))
        };
        let ours = regmap::ID_VALUE;
        // Board, no bitstream: absent, never simulated.
        assert_eq!(
            pick(0, IDCODE_7Z020, ours),
            Selection::Absent(Presence::Unconfigured)
        );
        // Board, foreign bitstream: absent.
        assert_eq!(
            pick(PCFG_DONE, IDCODE_7Z020, 0x1234_5678),
            Selection::Absent(Presence::Foreign { id: 0x1234_5678 })
        );
        // Board, our bitstream: driven.
        assert_eq!(
            pick(PCFG_DONE, IDCODE_7Z020, ours),
            Selection::Bitstream { version: v }
        );
        // QEMU, nothing configured: the simulated PL.
        assert_eq!(pick(0, IDCODE_QEMU, ours), Selection::Simulated);
        // An emulator with a configured foreign PL is not ours either.
        assert_eq!(
            pick(PCFG_DONE, IDCODE_QEMU, 0),
            Selection::Absent(Presence::Foreign { id: 0 })
        );
    }

    #[test]
    fn level_shifters_off_or_pl_in_reset_block_gp0() {
        // The SLCR reset values: level shifters off, every FCLK reset held.
        for lvl in [0x0, 0x3, 0xA, 0x7] {
            let g = Guard {
                lvl_shftr_en: lvl,
                ..READY
            };
            assert_eq!(
                detect(&g, &mut Untouchable),
                Presence::Blocked(GuardFailure::LevelShifters(lvl))
            );
        }
        let g = Guard {
            fpga_rst_ctrl: 0x01F3_3F0F,
            ..READY
        };
        assert_eq!(
            detect(&g, &mut Untouchable),
            Presence::Blocked(GuardFailure::PlReset(0x01F3_3F0F))
        );
        // Resets of the other FCLK domains do not reach GP0's slave.
        let g = Guard {
            fpga_rst_ctrl: 0b1110,
            ..READY
        };
        assert!(detect(&g, &mut FakePl::new()).usable());
        // The status line names the first failed check.
        let s = std::format!(
            "{}",
            Guard {
                lvl_shftr_en: 0,
                ..READY
            }
        );
        assert!(s.starts_with("fail: SLCR LVL_SHFTR_EN 0x0 "), "{s}");
        let s = std::format!("{READY}");
        assert!(s.starts_with("pass (INT_STS 0x00000004"), "{s}");
        let s = std::format!("{}", Guard::default());
        assert!(s.starts_with("fail: devcfg INT_STS.PCFG_DONE clear"), "{s}");
    }

    #[test]
    fn our_bitstream_is_recognised_by_id_and_major_version() {
        let mut pl = FakePl::new();
        let v = regmap::VERSION.reset;
        assert_eq!(detect(&READY, &mut pl), Presence::Ours { version: v });
        assert!(Presence::Ours { version: v }.usable());
        // A newer minor version still speaks our map.
        pl.set(regmap::TOP.addr(&regmap::VERSION), v + 1);
        assert!(detect(&READY, &mut pl).usable());
        // Another major version does not.
        pl.set(regmap::TOP.addr(&regmap::VERSION), v + 0x1_0000);
        assert_eq!(
            detect(&READY, &mut pl),
            Presence::Incompatible {
                version: v + 0x1_0000
            }
        );
        pl.set(regmap::TOP.addr(&regmap::ID), 0xDEAD_BEEF);
        assert_eq!(
            detect(&READY, &mut pl),
            Presence::Foreign { id: 0xDEAD_BEEF }
        );
    }

    #[test]
    fn our_emio_signature_allows_gp0() {
        // The register map's ID, "PSDR": what board_top drives (RM_ID_RESET).
        assert_eq!(SIGNATURE, 0x5053_4452);
        assert_eq!(gp0_access(&READY, SIGNATURE), Ok(()));
        let v = regmap::VERSION.reset;
        let p = detect_signed(&READY, SIGNATURE, &mut FakePl::new());
        assert_eq!(p, Presence::Ours { version: v });
        assert_eq!(
            select(p, platform(IDCODE_7Z020)),
            Selection::Bitstream { version: v }
        );
        // ID stays the second line: signed as ours but another register map.
        let mut pl = FakePl::new();
        pl.set(regmap::TOP.addr(&regmap::ID), 0xDEAD_BEEF);
        assert_eq!(
            detect_signed(&READY, SIGNATURE, &mut pl),
            Presence::Foreign { id: 0xDEAD_BEEF }
        );
        pl.set(regmap::TOP.addr(&regmap::ID), regmap::ID_VALUE);
        pl.set(regmap::TOP.addr(&regmap::VERSION), v + 0x1_0000);
        assert_eq!(
            detect_signed(&READY, SIGNATURE, &mut pl),
            Presence::Incompatible {
                version: v + 0x1_0000
            }
        );
    }

    #[test]
    fn a_foreign_emio_signature_keeps_gp0_untouched() {
        // Another design's EMIO word, ours with bytes swapped or one bit
        // off, all ones: GP0 is neither read nor written (Untouchable).
        for sig in [
            0x1234_5678,
            SIGNATURE.swap_bytes(),
            SIGNATURE ^ 1,
            SIGNATURE ^ 0x8000_0000,
            0xFFFF_FFFF,
        ] {
            let p = detect_signed(&READY, sig, &mut Untouchable);
            assert_eq!(p, Presence::Unsigned { signature: sig });
            assert_eq!(gp0_access(&READY, sig), Err(p));
            assert!(!p.usable());
            // Never driven, never simulated, on a board or in an emulator.
            assert_eq!(select(p, platform(IDCODE_7Z020)), Selection::Absent(p));
            assert_eq!(select(p, platform(IDCODE_QEMU)), Selection::Absent(p));
        }
    }

    #[test]
    fn an_all_zero_emio_signature_is_not_ours() {
        // What a design reads that leaves the PS7's EMIO inputs undriven
        // (Vivado ties them low): a foreign design, GP0 untouched.
        let p = detect_signed(&READY, 0, &mut Untouchable);
        assert_eq!(p, Presence::Unsigned { signature: 0 });
        assert_eq!(
            select(p, platform(IDCODE_7Z020)),
            Selection::Absent(Presence::Unsigned { signature: 0 })
        );
    }

    #[test]
    fn the_guard_decides_before_the_signature() {
        // The signature is read only once the guard passed; before that the
        // caller passes 0 (QEMU: no GPIO read at all), and even our word
        // cannot open GP0 while the guard fails.
        let unconfigured = Guard {
            int_sts: 0,
            ..READY
        };
        let shifters_off = Guard {
            lvl_shftr_en: 0x3,
            ..READY
        };
        let in_reset = Guard {
            fpga_rst_ctrl: FPGA0_OUT_RST,
            ..READY
        };
        for sig in [0, SIGNATURE, 0x1234_5678] {
            assert_eq!(
                detect_signed(&unconfigured, sig, &mut Untouchable),
                Presence::Unconfigured
            );
            assert_eq!(
                detect_signed(&shifters_off, sig, &mut Untouchable),
                Presence::Blocked(GuardFailure::LevelShifters(0x3))
            );
            assert_eq!(
                detect_signed(&in_reset, sig, &mut Untouchable),
                Presence::Blocked(GuardFailure::PlReset(FPGA0_OUT_RST))
            );
        }
        // QEMU (PL unconfigured, signature not read): the simulated PL, as
        // before the signature existed.
        assert_eq!(
            select(
                detect_signed(&unconfigured, 0, &mut Untouchable),
                platform(IDCODE_QEMU)
            ),
            Selection::Simulated
        );
    }
}
