// Generated from firmware/regmap/src/lib.rs by `cargo run -p regmap-gen`;
// do not edit (a test fails when this file is stale).
//! Typed access to the PL registers, one module per block.
//!
//! Per register a zero-sized type (`regs::pwm::DeadTime`, the table name in
//! camel case) with its absolute `ADDR`, its table entry `DEF`, and the
//! accesses its type allows: RW `read`/`write`/`modify`, RO `read`, W1C
//! `read`/`write` (no `modify`: writing back what was read would clear every
//! set flag). Its value type (`DeadTimeValue`) has a getter and a `with_*`
//! setter per field (`bool` for one bit, else `u32` masked to the field's
//! width); a register without fields has one field, `value`, and when its
//! format is two's complement also `value_i32`/`with_value_i32` (sign-
//! extended read, write masked to the register's width). What the
//! hardware does with an out-of-range word (mask, clamp, reject) is in each
//! register's doc. Every access is one whole-word `RegisterBus` access:
//!
//! ```
//! # use regmap::bus::{BusError, RegisterBus};
//! # struct Bus(u32);
//! # impl RegisterBus for Bus {
//! #     fn read(&mut self, _: usize) -> Result<u32, BusError> { Ok(self.0) }
//! #     fn write(&mut self, _: usize, v: u32) -> Result<(), BusError> { self.0 = v; Ok(()) }
//! # }
//! use regmap::regs::pwm::{DeadTime, DeadTimeValue, GateCtrl};
//! let mut bus = Bus(0);
//! DeadTime::write(&mut bus, DeadTimeValue::ZERO.with_value(100))?;
//! GateCtrl::modify(&mut bus, |v| v.with_gate_en(true))?;
//! assert!(GateCtrl::read(&mut bus)?.gate_en());
//! # Ok::<(), BusError>(())
//! ```

use crate as regmap;
use crate::bus::{BusError, RegisterBus};
use crate::Register;

/// Block 0 `TOP` at `0x43C00000`: Identification, mode, status, heartbeat.
pub mod top {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C00000;

    /// `TOP.ID` at `0x43C00000` (RO, 32 bits, reset `0x50534452`): Identifies the bitstream.
    ///
    /// Format: ASCII "PSDR". Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Id;

    impl Id {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ID;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<IdValue, BusError> {
            bus.read(Self::ADDR).map(IdValue)
        }
    }

    /// A value of [`Id`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct IdValue(u32);

    impl IdValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x50534452);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (ASCII "PSDR").
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for IdValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.VERSION` at `0x43C00004` (RO, 32 bits, reset `0x10004`): Version of this register map (bumped when the table changes).
    ///
    /// Format: major.minor, 16 bits each. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Version;

    impl Version {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::VERSION;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<VersionValue, BusError> {
            bus.read(Self::ADDR).map(VersionValue)
        }
    }

    /// A value of [`Version`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct VersionValue(u32);

    impl VersionValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x10004);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `MINOR` (bits 15:0, 16 bits): minor version
        pub const fn minor(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `MINOR` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_minor(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `MAJOR` (bits 31:16, 16 bits): major version
        pub const fn major(self) -> u32 {
            (self.0 >> 16) & 0xFFFF
        }

        /// Sets `MAJOR` (bits 31:16, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_major(self, v: u32) -> Self {
            Self((self.0 & !(0xFFFF << 16)) | ((v & 0xFFFF) << 16))
        }
    }

    impl Default for VersionValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.CTRL` at `0x43C00008` (RW, 2 bits, reset `0x0`): Selects the source of the switching state.
    ///
    /// Format: enum. Writes: the hardware rejects a word above 2: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Ctrl;

    impl Ctrl {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CTRL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CtrlValue, BusError> {
            bus.read(Self::ADDR).map(CtrlValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CtrlValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CtrlValue) -> CtrlValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`Ctrl`]; bits above bit 1 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CtrlValue(u32);

    impl CtrlValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `MODE` (bits 1:0, 2 bits): 0 off, 1 FOC-PWM (PWM comparators), 2 MPDTC (mpdtc_core's S[k+1], or PWM.SW_STATE if MPDTC_CTRL.MANUAL); 3 is rejected
        pub const fn mode(self) -> u32 {
            self.0 & 0x3
        }

        /// Sets `MODE` (bits 1:0, 2 bits) to the low 2 bits of `v` (higher bits are dropped).
        pub const fn with_mode(self, v: u32) -> Self {
            Self((self.0 & !0x3) | (v & 0x3))
        }
    }

    impl Default for CtrlValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.STATUS` at `0x43C0000C` (RO, 4 bits, reset `0x0`): Summary of the drive state.
    ///
    /// Format: bits. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Status;

    impl Status {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0000C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<StatusValue, BusError> {
            bus.read(Self::ADDR).map(StatusValue)
        }
    }

    /// A value of [`Status`]; bits above bit 3 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct StatusValue(u32);

    impl StatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `MODE` (bits 1:0, 2 bits): CTRL.MODE
        pub const fn mode(self) -> u32 {
            self.0 & 0x3
        }

        /// Sets `MODE` (bits 1:0, 2 bits) to the low 2 bits of `v` (higher bits are dropped).
        pub const fn with_mode(self, v: u32) -> Self {
            Self((self.0 & !0x3) | (v & 0x3))
        }

        /// `GATES_ACTIVE` (bit 2): the gate driver is enabled (GATE_EN, mode not off, no fault; in mode MPDTC with MPDTC_CTRL.MANUAL = 0 also the control sequence out of IDLE)
        pub const fn gates_active(self) -> bool {
            (self.0 >> 2) & 1 != 0
        }

        /// Sets `GATES_ACTIVE` (bit 2).
        pub const fn with_gates_active(self, v: bool) -> Self {
            Self((self.0 & !(1 << 2)) | ((v as u32) << 2))
        }

        /// `FAULT` (bit 3): a fault is latched (FAULT.FAULT_STATUS != 0)
        pub const fn fault(self) -> bool {
            (self.0 >> 3) & 1 != 0
        }

        /// Sets `FAULT` (bit 3).
        pub const fn with_fault(self, v: bool) -> Self {
            Self((self.0 & !(1 << 3)) | ((v as u32) << 3))
        }
    }

    impl Default for StatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.ERR` at `0x43C00010` (W1C, 2 bits, reset `0x0`): Sticky access-error flags.
    ///
    /// Format: bits, sticky. Writes: write 1 to clear (a bit whose condition is still present stays set).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Err;

    impl Err {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00010;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ERR;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<ErrValue, BusError> {
            bus.read(Self::ADDR).map(ErrValue)
        }

        /// Writes `value`: every 1 bit clears that flag.
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: ErrValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }
    }

    /// A value of [`Err`]; bits above bit 1 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct ErrValue(u32);

    impl ErrValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `BAD_VALUE` (bit 0): a write was rejected (out of range)
        pub const fn bad_value(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `BAD_VALUE` (bit 0).
        pub const fn with_bad_value(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }

        /// `BAD_ADDR` (bit 1): an access hit an unmapped offset or wrote a read-only register (SLVERR)
        pub const fn bad_addr(self) -> bool {
            (self.0 >> 1) & 1 != 0
        }

        /// Sets `BAD_ADDR` (bit 1).
        pub const fn with_bad_addr(self, v: bool) -> Self {
            Self((self.0 & !(1 << 1)) | ((v as u32) << 1))
        }
    }

    impl Default for ErrValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.HEARTBEAT` at `0x43C00014` (RW, 32 bits, reset `0x0`): Every write restarts the watchdog (FAULT.WDG_TIMEOUT); reads back the last value.
    ///
    /// Format: any value. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Heartbeat;

    impl Heartbeat {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00014;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::HEARTBEAT;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<HeartbeatValue, BusError> {
            bus.read(Self::ADDR).map(HeartbeatValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: HeartbeatValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(HeartbeatValue) -> HeartbeatValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`Heartbeat`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct HeartbeatValue(u32);

    impl HeartbeatValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (any value).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for HeartbeatValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.SCRATCH` at `0x43C00018` (RW, 32 bits, reset `0x0`): No effect; for bus tests.
    ///
    /// Format: any value. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Scratch;

    impl Scratch {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00018;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::SCRATCH;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<ScratchValue, BusError> {
            bus.read(Self::ADDR).map(ScratchValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: ScratchValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(ScratchValue) -> ScratchValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`Scratch`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct ScratchValue(u32);

    impl ScratchValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (any value).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for ScratchValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.IRQ_EN` at `0x43C00040` (RW, 2 bits, reset `0x0`): Which IRQ_STATUS flags drive the interrupt line (reset: none).
    ///
    /// Format: bits. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct IrqEn;

    impl IrqEn {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00040;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::IRQ_EN;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<IrqEnValue, BusError> {
            bus.read(Self::ADDR).map(IrqEnValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: IrqEnValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(IrqEnValue) -> IrqEnValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`IrqEn`]; bits above bit 1 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct IrqEnValue(u32);

    impl IrqEnValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `BOUNDARY` (bit 0): IRQ_STATUS.BOUNDARY raises irq_o
        pub const fn boundary(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `BOUNDARY` (bit 0).
        pub const fn with_boundary(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }

        /// `FAULT` (bit 1): IRQ_STATUS.FAULT raises irq_o
        pub const fn fault(self) -> bool {
            (self.0 >> 1) & 1 != 0
        }

        /// Sets `FAULT` (bit 1).
        pub const fn with_fault(self, v: bool) -> Self {
            Self((self.0 & !(1 << 1)) | ((v as u32) << 1))
        }
    }

    impl Default for IrqEnValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.IRQ_STATUS` at `0x43C00044` (W1C, 3 bits, reset `0x0`): Why irq_o is high: irq_o = |(IRQ_STATUS[1:0] & IRQ_EN), registered (one cycle late). The handler writes the flags it serves back to clear them.
    ///
    /// Format: bits, sticky. Writes: write 1 to clear (a bit whose condition is still present stays set).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct IrqStatus;

    impl IrqStatus {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00044;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::IRQ_STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<IrqStatusValue, BusError> {
            bus.read(Self::ADDR).map(IrqStatusValue)
        }

        /// Writes `value`: every 1 bit clears that flag.
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: IrqStatusValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }
    }

    /// A value of [`IrqStatus`]; bits above bit 2 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct IrqStatusValue(u32);

    impl IrqStatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `BOUNDARY` (bit 0): a control-period boundary with its sample ready: the new ADC average (modes off and MPDTC) or the PWM counter bottom (mode FOC-PWM)
        pub const fn boundary(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `BOUNDARY` (bit 0).
        pub const fn with_boundary(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }

        /// `FAULT` (bit 1): a fault was newly latched (FAULT_STATUS left 0)
        pub const fn fault(self) -> bool {
            (self.0 >> 1) & 1 != 0
        }

        /// Sets `FAULT` (bit 1).
        pub const fn with_fault(self, v: bool) -> Self {
            Self((self.0 & !(1 << 1)) | ((v as u32) << 1))
        }

        /// `MISSED` (bit 2): a boundary came while BOUNDARY was still set (a control step missed); no interrupt of its own
        pub const fn missed(self) -> bool {
            (self.0 >> 2) & 1 != 0
        }

        /// Sets `MISSED` (bit 2).
        pub const fn with_missed(self, v: bool) -> Self {
            Self((self.0 & !(1 << 2)) | ((v as u32) << 2))
        }
    }

    impl Default for IrqStatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `TOP.BOUNDARY_AGE` at `0x43C00048` (RO, 16 bits, reset `0x0`): 0 in the cycle after IRQ_STATUS.BOUNDARY is set, then counts: read at the start of the control step, the step's latency after the boundary.
    ///
    /// Format: unsigned, PL clock cycles (10 ns), saturates at 65535. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct BoundaryAge;

    impl BoundaryAge {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C00048;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::BOUNDARY_AGE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<BoundaryAgeValue, BusError> {
            bus.read(Self::ADDR).map(BoundaryAgeValue)
        }
    }

    /// A value of [`BoundaryAge`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct BoundaryAgeValue(u32);

    impl BoundaryAgeValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles (10 ns), saturates at 65535).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for BoundaryAgeValue {
        fn default() -> Self {
            Self::RESET
        }
    }
}

/// Block 1 `MPDTC` at `0x43C01000`: mpdtc_core: inputs and parameter registers (formats: docs/mpdtc-fixed.md), start, status, telemetry.
pub mod mpdtc {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C01000;

    /// `MPDTC.MPDTC_CTRL` at `0x43C01000` (RW, 3 bits, reset `0x3`): Source of the MPDTC switching state, state reset and core-input path (reset: manual, cleared, PS-fed).
    ///
    /// Format: bits. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcCtrl;

    impl MpdtcCtrl {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_CTRL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcCtrlValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcCtrlValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcCtrlValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcCtrlValue) -> MpdtcCtrlValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcCtrl`]; bits above bit 2 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcCtrlValue(u32);

    impl MpdtcCtrlValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x3);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `MANUAL` (bit 0): 1 = in mode MPDTC the gates follow PWM.SW_STATE, 0 = the control sequence (MPDTC_SEQ_STATUS: alignment, then mpdtc_core's S[k+1] at each control-period boundary) drives them
        pub const fn manual(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `MANUAL` (bit 0).
        pub const fn with_manual(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }

        /// `STATE_CLR` (bit 1): 1 = hold the core's state (S[k], S[k-1], observer, integrator) at zero
        pub const fn state_clr(self) -> bool {
            (self.0 >> 1) & 1 != 0
        }

        /// Sets `STATE_CLR` (bit 1).
        pub const fn with_state_clr(self, v: bool) -> Self {
            Self((self.0 & !(1 << 1)) | ((v as u32) << 1))
        }

        /// `AUTO` (bit 2): 1 = autonomous loop: every averaged ADC sample starts the PL front end (mpdtc_frontend: encoder angle, speed, sin/cos, ADC offset/gain, Clarke/Park from the MPDTC_FE_* registers), whose result starts the core in SAMPLE; the PS writes only MPDTC_IN_T_REF and MPDTC_START is ignored. 0 = the PS writes every MPDTC_IN_* and MPDTC_START each period (debug path)
        pub const fn auto(self) -> bool {
            (self.0 >> 2) & 1 != 0
        }

        /// Sets `AUTO` (bit 2).
        pub const fn with_auto(self, v: bool) -> Self {
            Self((self.0 & !(1 << 2)) | ((v as u32) << 2))
        }
    }

    impl Default for MpdtcCtrlValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_START` at `0x43C01004` (RW, 32 bits, reset `0x0`): While the control sequence is IDLE, every write starts one decision on the MPDTC_IN_* and MPDTC_P_* registers (ignored while the core is busy or STATE_CLR is set). In SAMPLE a write is the PS's hand-shake "inputs of this period written": the decision starts once the period's ADC sample is in; writes in INITIAL, MPDTC and PWM are ignored. Reads back the last value.
    ///
    /// Format: any value. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcStart;

    impl MpdtcStart {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_START;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcStartValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcStartValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcStartValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcStartValue) -> MpdtcStartValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcStart`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcStartValue(u32);

    impl MpdtcStartValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (any value).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for MpdtcStartValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_STATUS` at `0x43C01008` (RO, 32 bits, reset `0x0`): Core status; poll DONE_COUNT to see a decision complete.
    ///
    /// Format: bits and a counter. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcStatus;

    impl MpdtcStatus {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcStatusValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcStatusValue)
        }
    }

    /// A value of [`MpdtcStatus`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcStatusValue(u32);

    impl MpdtcStatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `BUSY` (bit 0): a decision is in flight
        pub const fn busy(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `BUSY` (bit 0).
        pub const fn with_busy(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }

        /// `S_NEXT` (bits 3:1, 3 bits): S[k+1] of the last decision (bits SaSbSc)
        pub const fn s_next(self) -> u32 {
            (self.0 >> 1) & 0x7
        }

        /// Sets `S_NEXT` (bits 3:1, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_s_next(self, v: u32) -> Self {
            Self((self.0 & !(0x7 << 1)) | ((v & 0x7) << 1))
        }

        /// `DONE_COUNT` (bits 31:16, 16 bits): decisions completed since reset (wraps)
        pub const fn done_count(self) -> u32 {
            (self.0 >> 16) & 0xFFFF
        }

        /// Sets `DONE_COUNT` (bits 31:16, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_done_count(self, v: u32) -> Self {
            Self((self.0 & !(0xFFFF << 16)) | ((v & 0xFFFF) << 16))
        }
    }

    impl Default for MpdtcStatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_LATENCY` at `0x43C0100C` (RO, 8 bits, reset `0x27`): Input strobe to S[k+1], fixed; also the initiation interval.
    ///
    /// Format: unsigned, PL clock cycles. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcLatency;

    impl MpdtcLatency {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0100C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_LATENCY;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcLatencyValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcLatencyValue)
        }
    }

    /// A value of [`MpdtcLatency`]; bits above bit 7 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcLatencyValue(u32);

    impl MpdtcLatencyValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x27);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 7:0, 8 bits): The whole register (unsigned, PL clock cycles).
        pub const fn value(self) -> u32 {
            self.0 & 0xFF
        }

        /// Sets `VALUE` (bits 7:0, 8 bits) to the low 8 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFF) | (v & 0xFF))
        }
    }

    impl Default for MpdtcLatencyValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_ID` at `0x43C01010` (RW, 25 bits, reset `0x0`): Measured (averaged) i_d.
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInId;

    impl MpdtcInId {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01010;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_ID;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInIdValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcInIdValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInIdValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInIdValue) -> MpdtcInIdValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInId`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInIdValue(u32);

    impl MpdtcInIdValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcInIdValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_IQ` at `0x43C01014` (RW, 25 bits, reset `0x0`): Measured (averaged) i_q.
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInIq;

    impl MpdtcInIq {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01014;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_IQ;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInIqValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcInIqValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInIqValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInIqValue) -> MpdtcInIqValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInIq`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInIqValue(u32);

    impl MpdtcInIqValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcInIqValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_COS0` at `0x43C01018` (RW, 18 bits, reset `0x0`): cos, middle of [k-1, k].
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInCos0;

    impl MpdtcInCos0 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01018;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_COS0;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInCos0Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcInCos0Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInCos0Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInCos0Value) -> MpdtcInCos0Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInCos0`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInCos0Value(u32);

    impl MpdtcInCos0Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInCos0Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_SIN0` at `0x43C0101C` (RW, 18 bits, reset `0x0`): sin, middle of [k-1, k].
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInSin0;

    impl MpdtcInSin0 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0101C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_SIN0;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInSin0Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcInSin0Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInSin0Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInSin0Value) -> MpdtcInSin0Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInSin0`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInSin0Value(u32);

    impl MpdtcInSin0Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInSin0Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_COS1` at `0x43C01020` (RW, 18 bits, reset `0x0`): cos, middle of [k, k+1].
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInCos1;

    impl MpdtcInCos1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01020;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_COS1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInCos1Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcInCos1Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInCos1Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInCos1Value) -> MpdtcInCos1Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInCos1`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInCos1Value(u32);

    impl MpdtcInCos1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInCos1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_SIN1` at `0x43C01024` (RW, 18 bits, reset `0x0`): sin, middle of [k, k+1].
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInSin1;

    impl MpdtcInSin1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01024;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_SIN1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInSin1Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcInSin1Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInSin1Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInSin1Value) -> MpdtcInSin1Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInSin1`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInSin1Value(u32);

    impl MpdtcInSin1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInSin1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_COS2` at `0x43C01028` (RW, 18 bits, reset `0x0`): cos, middle of [k+1, k+2].
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInCos2;

    impl MpdtcInCos2 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01028;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_COS2;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInCos2Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcInCos2Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInCos2Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInCos2Value) -> MpdtcInCos2Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInCos2`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInCos2Value(u32);

    impl MpdtcInCos2Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInCos2Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_SIN2` at `0x43C0102C` (RW, 18 bits, reset `0x0`): sin, middle of [k+1, k+2].
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInSin2;

    impl MpdtcInSin2 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0102C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_SIN2;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInSin2Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcInSin2Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInSin2Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInSin2Value) -> MpdtcInSin2Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInSin2`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInSin2Value(u32);

    impl MpdtcInSin2Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInSin2Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_W_TS` at `0x43C01030` (RW, 18 bits, reset `0x0`): w_e Ts.
    ///
    /// Format: COEF sQ1.16, rad per period. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInWTs;

    impl MpdtcInWTs {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01030;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_W_TS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInWTsValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcInWTsValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInWTsValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInWTsValue) -> MpdtcInWTsValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInWTs`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInWTsValue(u32);

    impl MpdtcInWTsValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, rad per period).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInWTsValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IN_T_REF` at `0x43C01034` (RW, 18 bits, reset `0x0`): Torque reference T*.
    ///
    /// Format: TRQ sQ3.14, two's complement in [17:0], N m. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInTRef;

    impl MpdtcInTRef {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01034;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IN_T_REF;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcInTRefValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcInTRefValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcInTRefValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcInTRefValue) -> MpdtcInTRefValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcInTRef`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcInTRefValue(u32);

    impl MpdtcInTRefValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (TRQ sQ3.14, two's complement in [17:0], N m).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcInTRefValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_A` at `0x43C01040` (RW, 18 bits, reset `0x0`): a = 1 - R Ts / L.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPA;

    impl MpdtcPA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01040;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPAValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPAValue) -> MpdtcPAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPA`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPAValue(u32);

    impl MpdtcPAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_LAMBDA` at `0x43C01044` (RW, 18 bits, reset `0x0`): Measurement age, periods.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPLambda;

    impl MpdtcPLambda {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01044;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_LAMBDA;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPLambdaValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPLambdaValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPLambdaValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPLambdaValue) -> MpdtcPLambdaValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPLambda`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPLambdaValue(u32);

    impl MpdtcPLambdaValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPLambdaValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_U0` at `0x43C01048` (RW, 25 bits, reset `0x0`): U0 = (Ts / L) 2/3 U_dc.
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPU0;

    impl MpdtcPU0 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01048;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_U0;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPU0Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcPU0Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPU0Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPU0Value) -> MpdtcPU0Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPU0`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPU0Value(u32);

    impl MpdtcPU0Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcPU0Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_U0_HALF` at `0x43C0104C` (RW, 25 bits, reset `0x0`): U0 / 2.
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPU0Half;

    impl MpdtcPU0Half {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0104C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_U0_HALF;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPU0HalfValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPU0HalfValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPU0HalfValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPU0HalfValue) -> MpdtcPU0HalfValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPU0Half`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPU0HalfValue(u32);

    impl MpdtcPU0HalfValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcPU0HalfValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_U0_H` at `0x43C01050` (RW, 25 bits, reset `0x0`): U0 sqrt(3) / 2.
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPU0H;

    impl MpdtcPU0H {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01050;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_U0_H;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPU0HValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPU0HValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPU0HValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPU0HValue) -> MpdtcPU0HValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPU0H`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPU0HValue(u32);

    impl MpdtcPU0HValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcPU0HValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_PSI_L` at `0x43C01054` (RW, 25 bits, reset `0x0`): psi / L.
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPPsiL;

    impl MpdtcPPsiL {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01054;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_PSI_L;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPPsiLValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPPsiLValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPPsiLValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPPsiLValue) -> MpdtcPPsiLValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPPsiL`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPPsiLValue(u32);

    impl MpdtcPPsiLValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcPPsiLValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_KINV_T` at `0x43C01058` (RW, 25 bits, reset `0x0`): 1 / k_T.
    ///
    /// Format: KINV sQ8.16, two's complement in [24:0], A/(N m). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKinvT;

    impl MpdtcPKinvT {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01058;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_KINV_T;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPKinvTValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPKinvTValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPKinvTValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPKinvTValue) -> MpdtcPKinvTValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPKinvT`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKinvTValue(u32);

    impl MpdtcPKinvTValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (KINV sQ8.16, two's complement in [24:0], A/(N m)).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcPKinvTValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_TOL` at `0x43C0105C` (RW, 24 bits, reset `0x0`): Band T_tol / k_T.
    ///
    /// Format: CUR, non-negative (24 bits: negative values cannot be written). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPTol;

    impl MpdtcPTol {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0105C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_TOL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPTolValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPTolValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPTolValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPTolValue) -> MpdtcPTolValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPTol`]; bits above bit 23 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPTolValue(u32);

    impl MpdtcPTolValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 23:0, 24 bits): The whole register (CUR, non-negative (24 bits: negative values cannot be written)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFFFF
        }

        /// Sets `VALUE` (bits 23:0, 24 bits) to the low 24 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFFFF) | (v & 0xFFFFFF))
        }
    }

    impl Default for MpdtcPTolValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_K_INT` at `0x43C01060` (RW, 18 bits, reset `0x0`): Integrator gain K Ts.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKInt;

    impl MpdtcPKInt {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01060;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_K_INT;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPKIntValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPKIntValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPKIntValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPKIntValue) -> MpdtcPKIntValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPKInt`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKIntValue(u32);

    impl MpdtcPKIntValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPKIntValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_INT_LIM` at `0x43C01064` (RW, 24 bits, reset `0x0`): Integrator clamp.
    ///
    /// Format: CUR, non-negative (24 bits). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPIntLim;

    impl MpdtcPIntLim {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01064;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_INT_LIM;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPIntLimValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPIntLimValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPIntLimValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPIntLimValue) -> MpdtcPIntLimValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPIntLim`]; bits above bit 23 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPIntLimValue(u32);

    impl MpdtcPIntLimValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 23:0, 24 bits): The whole register (CUR, non-negative (24 bits)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFFFF
        }

        /// Sets `VALUE` (bits 23:0, 24 bits) to the low 24 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFFFF) | (v & 0xFFFFFF))
        }
    }

    impl Default for MpdtcPIntLimValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_INT_COND` at `0x43C01068` (RW, 1 bits, reset `0x0`): 1 = integrate only after a decision with a candidate in the band.
    ///
    /// Format: bit. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPIntCond;

    impl MpdtcPIntCond {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01068;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_INT_COND;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPIntCondValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPIntCondValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPIntCondValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPIntCondValue) -> MpdtcPIntCondValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPIntCond`]; bits above bit 0 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPIntCondValue(u32);

    impl MpdtcPIntCondValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bit 0): The whole register (bit).
        pub const fn value(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `VALUE` (bit 0).
        pub const fn with_value(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }
    }

    impl Default for MpdtcPIntCondValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_KP_O` at `0x43C0106C` (RW, 18 bits, reset `0x0`): Observer b Kp.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKpO;

    impl MpdtcPKpO {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0106C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_KP_O;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPKpOValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPKpOValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPKpOValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPKpOValue) -> MpdtcPKpOValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPKpO`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKpOValue(u32);

    impl MpdtcPKpOValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPKpOValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_KI_O` at `0x43C01070` (RW, 18 bits, reset `0x0`): Observer b Kp Ki Ts.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKiO;

    impl MpdtcPKiO {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01070;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_KI_O;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPKiOValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPKiOValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPKiOValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPKiOValue) -> MpdtcPKiOValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPKiO`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPKiOValue(u32);

    impl MpdtcPKiOValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPKiOValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_ETA_LIM` at `0x43C01074` (RW, 24 bits, reset `0x0`): Observer clamp b eps_max.
    ///
    /// Format: CUR, non-negative (24 bits). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPEtaLim;

    impl MpdtcPEtaLim {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01074;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_ETA_LIM;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPEtaLimValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcPEtaLimValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPEtaLimValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPEtaLimValue) -> MpdtcPEtaLimValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPEtaLim`]; bits above bit 23 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPEtaLimValue(u32);

    impl MpdtcPEtaLimValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 23:0, 24 bits): The whole register (CUR, non-negative (24 bits)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFFFF
        }

        /// Sets `VALUE` (bits 23:0, 24 bits) to the low 24 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFFFF) | (v & 0xFFFFFF))
        }
    }

    impl Default for MpdtcPEtaLimValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_W2_0` at `0x43C01078` (RW, 18 bits, reset `0x0`): Cost weight, 0 transitions.
    ///
    /// Format: WGT sQ3.14, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW20;

    impl MpdtcPW20 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01078;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_W2_0;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPW20Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcPW20Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPW20Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPW20Value) -> MpdtcPW20Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPW20`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW20Value(u32);

    impl MpdtcPW20Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (WGT sQ3.14, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPW20Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_W2_1` at `0x43C0107C` (RW, 18 bits, reset `0x0`): Cost weight, 1 transition.
    ///
    /// Format: WGT sQ3.14, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW21;

    impl MpdtcPW21 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0107C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_W2_1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPW21Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcPW21Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPW21Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPW21Value) -> MpdtcPW21Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPW21`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW21Value(u32);

    impl MpdtcPW21Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (WGT sQ3.14, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPW21Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_W2_2` at `0x43C01080` (RW, 18 bits, reset `0x0`): Cost weight, 2 transitions.
    ///
    /// Format: WGT sQ3.14, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW22;

    impl MpdtcPW22 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01080;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_W2_2;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPW22Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcPW22Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPW22Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPW22Value) -> MpdtcPW22Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPW22`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW22Value(u32);

    impl MpdtcPW22Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (WGT sQ3.14, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPW22Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_P_W2_3` at `0x43C01084` (RW, 18 bits, reset `0x0`): Cost weight, 3 transitions.
    ///
    /// Format: WGT sQ3.14, two's complement in [17:0]. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW23;

    impl MpdtcPW23 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01084;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_P_W2_3;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcPW23Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcPW23Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcPW23Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcPW23Value) -> MpdtcPW23Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcPW23`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcPW23Value(u32);

    impl MpdtcPW23Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (WGT sQ3.14, two's complement in [17:0]).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcPW23Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_IQ_REF` at `0x43C01090` (RO, 25 bits, reset `0x0`): i_q* of the last decision (telemetry).
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcIqRef;

    impl MpdtcIqRef {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C01090;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_IQ_REF;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcIqRefValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcIqRefValue)
        }
    }

    /// A value of [`MpdtcIqRef`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcIqRefValue(u32);

    impl MpdtcIqRefValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcIqRefValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_SEQ_STATUS` at `0x43C010A0` (RO, 32 bits, reset `0x0`): State of the control sequence (mpdtc_seq), active in mode MPDTC with MPDTC_CTRL.MANUAL = 0 and STATE_CLR = 0. Counters keep their values through IDLE.
    ///
    /// Format: enum, bits and counters. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcSeqStatus;

    impl MpdtcSeqStatus {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010A0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_SEQ_STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcSeqStatusValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcSeqStatusValue)
        }
    }

    /// A value of [`MpdtcSeqStatus`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcSeqStatusValue(u32);

    impl MpdtcSeqStatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `STATE` (bits 2:0, 3 bits): 0 IDLE, 1 INITIAL (alignment), 2 SAMPLE, 3 MPDTC, 4 PWM (regmap::seq_state)
        pub const fn state(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `STATE` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_state(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }

        /// `SAMPLED` (bit 3): SAMPLE has this period's averaged ADC sample (waits for MPDTC_START)
        pub const fn sampled(self) -> bool {
            (self.0 >> 3) & 1 != 0
        }

        /// Sets `SAMPLED` (bit 3).
        pub const fn with_sampled(self, v: bool) -> Self {
            Self((self.0 & !(1 << 3)) | ((v as u32) << 3))
        }

        /// `ALIGNED` (bit 4): the alignment of the current run finished (MPDTC_ALIGN_POS valid); 0 from IDLE
        pub const fn aligned(self) -> bool {
            (self.0 >> 4) & 1 != 0
        }

        /// Sets `ALIGNED` (bit 4).
        pub const fn with_aligned(self, v: bool) -> Self {
            Self((self.0 & !(1 << 4)) | ((v as u32) << 4))
        }

        /// `OVERRUNS` (bits 15:8, 8 bits): control-period boundaries that found no S[k+1] ready (in SAMPLE with the sample taken, or in MPDTC): S[k] held one more period (wraps)
        pub const fn overruns(self) -> u32 {
            (self.0 >> 8) & 0xFF
        }

        /// Sets `OVERRUNS` (bits 15:8, 8 bits) to the low 8 bits of `v` (higher bits are dropped).
        pub const fn with_overruns(self, v: u32) -> Self {
            Self((self.0 & !(0xFF << 8)) | ((v & 0xFF) << 8))
        }

        /// `PERIODS` (bits 31:16, 16 bits): control periods completed: S[k+1] applied at a boundary (wraps)
        pub const fn periods(self) -> u32 {
            (self.0 >> 16) & 0xFFFF
        }

        /// Sets `PERIODS` (bits 31:16, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_periods(self, v: u32) -> Self {
            Self((self.0 & !(0xFFFF << 16)) | ((v & 0xFFFF) << 16))
        }
    }

    impl Default for MpdtcSeqStatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_ALIGN_VEC` at `0x43C010A4` (RW, 3 bits, reset `0x4`): Switching state of the rotor alignment (INITIAL): 100 = phase a upper, b and c lower, the voltage vector on the a axis = d axis at angle 0. 000 and 111 are zero vectors (no alignment current).
    ///
    /// Format: bits SaSbSc (index 4 Sa + 2 Sb + Sc). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignVec;

    impl MpdtcAlignVec {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010A4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_ALIGN_VEC;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcAlignVecValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcAlignVecValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcAlignVecValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcAlignVecValue) -> MpdtcAlignVecValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcAlignVec`]; bits above bit 2 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignVecValue(u32);

    impl MpdtcAlignVecValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x4);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 2:0, 3 bits): The whole register (bits SaSbSc (index 4 Sa + 2 Sb + Sc)).
        pub const fn value(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `VALUE` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }
    }

    impl Default for MpdtcAlignVecValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_ALIGN_PERIOD` at `0x43C010A8` (RW, 16 bits, reset `0x1388`): Period P of the alignment chopper (reset 50 us = 20 kHz). Read at every cycle.
    ///
    /// Format: unsigned, PL clock cycles. Writes: the hardware clamps the written word to 2..=65535 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignPeriod;

    impl MpdtcAlignPeriod {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010A8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_ALIGN_PERIOD;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(
            bus: &mut B,
        ) -> Result<MpdtcAlignPeriodValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcAlignPeriodValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcAlignPeriodValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcAlignPeriodValue) -> MpdtcAlignPeriodValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcAlignPeriod`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignPeriodValue(u32);

    impl MpdtcAlignPeriodValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x1388);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdtcAlignPeriodValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_ALIGN_ON` at `0x43C010AC` (RW, 16 bits, reset `0xFA`): Cycles with MPDTC_ALIGN_VEC at the start of each chopper period, the zero vector 000 for the rest; the hardware caps it at floor(P / 2) (duty <= 50 %, never full time). Reset 250 / 5000 = 5 %: about 0.05 x (2/3 x 48 V) / 0.555 ohm = 2.9 A in phase a for the paper's motor (less the dead time).
    ///
    /// Format: unsigned, PL clock cycles per chopper period. Writes: the hardware clamps the written word to 0..=32767 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignOn;

    impl MpdtcAlignOn {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010AC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_ALIGN_ON;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcAlignOnValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcAlignOnValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcAlignOnValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcAlignOnValue) -> MpdtcAlignOnValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcAlignOn`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignOnValue(u32);

    impl MpdtcAlignOnValue {
        /// The value after reset.
        pub const RESET: Self = Self(0xFA);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles per chopper period).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdtcAlignOnValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_ALIGN_TIME` at `0x43C010B0` (RW, 32 bits, reset `0x2FAF080`): Duration of INITIAL (rotor alignment), reset 0.5 s.
    ///
    /// Format: unsigned, PL clock cycles. Writes: the hardware clamps the written word to 1..=4294967295 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignTime;

    impl MpdtcAlignTime {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010B0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_ALIGN_TIME;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcAlignTimeValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcAlignTimeValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcAlignTimeValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcAlignTimeValue) -> MpdtcAlignTimeValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcAlignTime`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignTimeValue(u32);

    impl MpdtcAlignTimeValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x2FAF080);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (unsigned, PL clock cycles).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for MpdtcAlignTimeValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_ALIGN_POS` at `0x43C010B4` (RO, 16 bits, reset `0x0`): ENC_POS latched when INITIAL ends (rotor d axis on phase a): the angle reference; the PS uses theta_e = (ENC_POS - ALIGN_POS) pp 2 pi / ENC_CPR. The encoder counter itself is not changed.
    ///
    /// Format: unsigned, counts (as ENC_POS). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignPos;

    impl MpdtcAlignPos {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010B4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_ALIGN_POS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcAlignPosValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcAlignPosValue)
        }
    }

    /// A value of [`MpdtcAlignPos`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcAlignPosValue(u32);

    impl MpdtcAlignPosValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, counts (as ENC_POS)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdtcAlignPosValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_ANG_SCALE` at `0x43C010B8` (RW, 32 bits, reset `0x700000`): round(pole_pairs 2^32 / ENC_CPR) mod 2^32: pole pairs and counts per revolution for the autonomous loop (the PL has no divider); theta_e = (ENC_POS - MPDTC_ALIGN_POS mod ENC_CPR) x this, mod one turn. Reset: 7 pole pairs, 4096 counts.
    ///
    /// Format: unsigned 32-bit, 2^-32 electrical turn per encoder count (range 0..2^32-1). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAngScale;

    impl MpdtcFeAngScale {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010B8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_ANG_SCALE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(
            bus: &mut B,
        ) -> Result<MpdtcFeAngScaleValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeAngScaleValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeAngScaleValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeAngScaleValue) -> MpdtcFeAngScaleValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeAngScale`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAngScaleValue(u32);

    impl MpdtcFeAngScaleValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x700000);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (unsigned 32-bit, 2^-32 electrical turn per encoder count (range 0..2^32-1)).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for MpdtcFeAngScaleValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_SPD_SCALE` at `0x43C010BC` (RW, 32 bits, reset `0x1C06E1A`): round(pole_pairs Ts 2^40 / (ENC_CPR T_window)): the angle step per control period from ENC_SPEED (w_e Ts). Reset: 7 pole pairs, Ts = 1564 cycles, 4096 counts, ENC_WINDOW 100,000 cycles.
    ///
    /// Format: unsigned 32-bit, 2^-40 electrical turn per control period per (count per ENC_WINDOW) (range 0..2^32-1). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeSpdScale;

    impl MpdtcFeSpdScale {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010BC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_SPD_SCALE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(
            bus: &mut B,
        ) -> Result<MpdtcFeSpdScaleValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeSpdScaleValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeSpdScaleValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeSpdScaleValue) -> MpdtcFeSpdScaleValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeSpdScale`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeSpdScaleValue(u32);

    impl MpdtcFeSpdScaleValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x1C06E1A);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (unsigned 32-bit, 2^-40 electrical turn per control period per (count per ENC_WINDOW) (range 0..2^32-1)).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for MpdtcFeSpdScaleValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_AGE0` at `0x43C010C0` (RW, 18 bits, reset `0x3E000`): Instant of cos0/sin0 relative to the sample, periods: lambda - 1/2 (lambda = age of the averaged measurement). Reset -0.125.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0], control periods (range -2..2). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAge0;

    impl MpdtcFeAge0 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010C0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_AGE0;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeAge0Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeAge0Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeAge0Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeAge0Value) -> MpdtcFeAge0Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeAge0`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAge0Value(u32);

    impl MpdtcFeAge0Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x3E000);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0], control periods (range -2..2)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcFeAge0Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_AGE1` at `0x43C010C4` (RW, 18 bits, reset `0xE000`): Instant of cos1/sin1: lambda + 1/2 periods. Reset 0.875.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0], control periods (range -2..2). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAge1;

    impl MpdtcFeAge1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010C4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_AGE1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeAge1Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeAge1Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeAge1Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeAge1Value) -> MpdtcFeAge1Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeAge1`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAge1Value(u32);

    impl MpdtcFeAge1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0xE000);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0], control periods (range -2..2)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcFeAge1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_AGE2` at `0x43C010C8` (RW, 18 bits, reset `0x1E000`): Instant of cos2/sin2: lambda + 3/2 periods. Reset 1.875.
    ///
    /// Format: COEF sQ1.16, two's complement in [17:0], control periods (range -2..2). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAge2;

    impl MpdtcFeAge2 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010C8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_AGE2;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeAge2Value, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeAge2Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeAge2Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeAge2Value) -> MpdtcFeAge2Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeAge2`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeAge2Value(u32);

    impl MpdtcFeAge2Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x1E000);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (COEF sQ1.16, two's complement in [17:0], control periods (range -2..2)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcFeAge2Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_OFF_A` at `0x43C010CC` (RW, 16 bits, reset `0x0`): Subtracted from ADC_IA before the gain.
    ///
    /// Format: signed 16-bit two's complement, ADC counts (range -32768..32767). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeOffA;

    impl MpdtcFeOffA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010CC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_OFF_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeOffAValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeOffAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeOffAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeOffAValue) -> MpdtcFeOffAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeOffA`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeOffAValue(u32);

    impl MpdtcFeOffAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, ADC counts (range -32768..32767)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdtcFeOffAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_OFF_B` at `0x43C010D0` (RW, 16 bits, reset `0x0`): Subtracted from ADC_IB before the gain.
    ///
    /// Format: signed 16-bit two's complement, ADC counts (range -32768..32767). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeOffB;

    impl MpdtcFeOffB {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010D0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_OFF_B;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeOffBValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeOffBValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeOffBValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeOffBValue) -> MpdtcFeOffBValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeOffB`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeOffBValue(u32);

    impl MpdtcFeOffBValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, ADC counts (range -32768..32767)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdtcFeOffBValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_OFF_C` at `0x43C010D4` (RW, 16 bits, reset `0x0`): Subtracted from ADC_IC before the gain.
    ///
    /// Format: signed 16-bit two's complement, ADC counts (range -32768..32767). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeOffC;

    impl MpdtcFeOffC {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010D4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_OFF_C;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeOffCValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeOffCValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeOffCValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeOffCValue) -> MpdtcFeOffCValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeOffC`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeOffCValue(u32);

    impl MpdtcFeOffCValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, ADC counts (range -32768..32767)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdtcFeOffCValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_GAIN_A` at `0x43C010D8` (RW, 18 bits, reset `0x0`): i_a = sat25(round((ADC_IA - OFF_A) GAIN_A / 2^4)), CUR. Reset 0 (no current until the PS sets the board's gain).
    ///
    /// Format: signed 18-bit two's complement in [17:0], 2^-20 A per ADC count (range +-0.125 A per count). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeGainA;

    impl MpdtcFeGainA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010D8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_GAIN_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeGainAValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeGainAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeGainAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeGainAValue) -> MpdtcFeGainAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeGainA`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeGainAValue(u32);

    impl MpdtcFeGainAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (signed 18-bit two's complement in [17:0], 2^-20 A per ADC count (range +-0.125 A per count)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcFeGainAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_GAIN_B` at `0x43C010DC` (RW, 18 bits, reset `0x0`): As MPDTC_FE_GAIN_A, phase b.
    ///
    /// Format: signed 18-bit two's complement in [17:0], 2^-20 A per ADC count (range +-0.125 A per count). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeGainB;

    impl MpdtcFeGainB {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010DC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_GAIN_B;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeGainBValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeGainBValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeGainBValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeGainBValue) -> MpdtcFeGainBValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeGainB`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeGainBValue(u32);

    impl MpdtcFeGainBValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (signed 18-bit two's complement in [17:0], 2^-20 A per ADC count (range +-0.125 A per count)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcFeGainBValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_GAIN_C` at `0x43C010E0` (RW, 18 bits, reset `0x0`): As MPDTC_FE_GAIN_A, phase c.
    ///
    /// Format: signed 18-bit two's complement in [17:0], 2^-20 A per ADC count (range +-0.125 A per count). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeGainC;

    impl MpdtcFeGainC {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010E0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_GAIN_C;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeGainCValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeGainCValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdtcFeGainCValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdtcFeGainCValue) -> MpdtcFeGainCValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdtcFeGainC`]; bits above bit 17 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeGainCValue(u32);

    impl MpdtcFeGainCValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 17:0, 18 bits): The whole register (signed 18-bit two's complement in [17:0], 2^-20 A per ADC count (range +-0.125 A per count)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FFFF
        }

        /// Sets `VALUE` (bits 17:0, 18 bits) to the low 18 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FFFF) | (v & 0x3FFFF))
        }

        /// `VALUE` as a two's-complement number: bit 17 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 14) as i32) >> 14
        }

        /// Sets `VALUE` to `v` in two's complement, its low 18 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x3FFFF) | (v as u32 & 0x3FFFF))
        }
    }

    impl Default for MpdtcFeGainCValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_ID` at `0x43C010E4` (RO, 25 bits, reset `0x0`): i_d of the front end's last result (MPDTC_CTRL.AUTO = 1; Park at the sample's angle), MPDTC_FE_LATENCY_CYCLES = 9 cycles after the averaged sample.
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeId;

    impl MpdtcFeId {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010E4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_ID;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeIdValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeIdValue)
        }
    }

    /// A value of [`MpdtcFeId`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeIdValue(u32);

    impl MpdtcFeIdValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcFeIdValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDTC.MPDTC_FE_IQ` at `0x43C010E8` (RO, 25 bits, reset `0x0`): i_q of the front end's last result (as MPDTC_FE_ID).
    ///
    /// Format: CUR sQ8.16, two's complement in [24:0], A. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeIq;

    impl MpdtcFeIq {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C010E8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDTC_FE_IQ;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdtcFeIqValue, BusError> {
            bus.read(Self::ADDR).map(MpdtcFeIqValue)
        }
    }

    /// A value of [`MpdtcFeIq`]; bits above bit 24 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdtcFeIqValue(u32);

    impl MpdtcFeIqValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 24:0, 25 bits): The whole register (CUR sQ8.16, two's complement in [24:0], A).
        pub const fn value(self) -> u32 {
            self.0 & 0x1FFFFFF
        }

        /// Sets `VALUE` (bits 24:0, 25 bits) to the low 25 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v & 0x1FFFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 24 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 7) as i32) >> 7
        }

        /// Sets `VALUE` to `v` in two's complement, its low 25 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0x1FFFFFF) | (v as u32 & 0x1FFFFFF))
        }
    }

    impl Default for MpdtcFeIqValue {
        fn default() -> Self {
            Self::RESET
        }
    }
}

/// Block 2 `MPDCC` at `0x43C02000`: mpdcc_core (paper 001): s(k-1), state, constants and bounds (formats: docs/mpdcc-fpga.md), start, status, the decision and its cost in cycles.
pub mod mpdcc {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C02000;

    /// `MPDCC.MPDCC_START` at `0x43C02000` (RW, 1 bits, reset `0x0`): A write while MPDCC_STATUS.BUSY = 0 snapshots the input and constant registers and starts one decision (ignored while busy). Reads back the last value.
    ///
    /// Format: any value. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccStart;

    impl MpdccStart {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_START;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccStartValue, BusError> {
            bus.read(Self::ADDR).map(MpdccStartValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccStartValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccStartValue) -> MpdccStartValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccStart`]; bits above bit 0 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccStartValue(u32);

    impl MpdccStartValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bit 0): The whole register (any value).
        pub const fn value(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `VALUE` (bit 0).
        pub const fn with_value(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }
    }

    impl Default for MpdccStartValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_STATUS` at `0x43C02004` (RO, 32 bits, reset `0x0`): State of the core; poll until BUSY = 0 and DONE = 1.
    ///
    /// Format: bits and a counter. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccStatus;

    impl MpdccStatus {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccStatusValue, BusError> {
            bus.read(Self::ADDR).map(MpdccStatusValue)
        }
    }

    /// A value of [`MpdccStatus`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccStatusValue(u32);

    impl MpdccStatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `BUSY` (bit 0): a decision runs (from the cycle after the START write)
        pub const fn busy(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `BUSY` (bit 0).
        pub const fn with_busy(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }

        /// `DONE` (bit 1): the result registers hold the decision of the last START (0 from the START write until BUSY falls, and after reset)
        pub const fn done(self) -> bool {
            (self.0 >> 1) & 1 != 0
        }

        /// Sets `DONE` (bit 1).
        pub const fn with_done(self, v: bool) -> Self {
            Self((self.0 & !(1 << 1)) | ((v as u32) << 1))
        }

        /// `COUNT` (bits 31:16, 16 bits): decisions completed since reset (wraps)
        pub const fn count(self) -> u32 {
            (self.0 >> 16) & 0xFFFF
        }

        /// Sets `COUNT` (bits 31:16, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_count(self, v: u32) -> Self {
            Self((self.0 & !(0xFFFF << 16)) | ((v & 0xFFFF) << 16))
        }
    }

    impl Default for MpdccStatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_N_USE` at `0x43C02008` (RW, 3 bits, reset `0x1`): Explorers the next decision uses (n_use); the core takes at most MPDCC_CONFIG.EXPLORERS of them. Only the cycle count depends on it.
    ///
    /// Format: unsigned, explorer units. Writes: the hardware clamps the written word to 1..=6 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccNUse;

    impl MpdccNUse {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_N_USE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccNUseValue, BusError> {
            bus.read(Self::ADDR).map(MpdccNUseValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccNUseValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccNUseValue) -> MpdccNUseValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccNUse`]; bits above bit 2 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccNUseValue(u32);

    impl MpdccNUseValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x1);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 2:0, 3 bits): The whole register (unsigned, explorer units).
        pub const fn value(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `VALUE` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }
    }

    impl Default for MpdccNUseValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_CONFIG` at `0x43C0200C` (RO, 16 bits, reset `0x4731`): The constants the core is built with (reset: the default build); Coeffs must agree (lambda, m_bits, nodes).
    ///
    /// Format: four unsigned fields. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccConfig;

    impl MpdccConfig {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0200C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_CONFIG;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccConfigValue, BusError> {
            bus.read(Self::ADDR).map(MpdccConfigValue)
        }
    }

    /// A value of [`MpdccConfig`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccConfigValue(u32);

    impl MpdccConfigValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x4731);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `EXPLORERS` (bits 3:0, 4 bits): explorer units instantiated (N)
        pub const fn explorers(self) -> u32 {
            self.0 & 0xF
        }

        /// Sets `EXPLORERS` (bits 3:0, 4 bits) to the low 4 bits of `v` (higher bits are dropped).
        pub const fn with_explorers(self, v: u32) -> Self {
            Self((self.0 & !0xF) | (v & 0xF))
        }

        /// `LAMBDA` (bits 7:4, 4 bits): lambda = log2 L, extrapolation steps
        pub const fn lambda(self) -> u32 {
            (self.0 >> 4) & 0xF
        }

        /// Sets `LAMBDA` (bits 7:4, 4 bits) to the low 4 bits of `v` (higher bits are dropped).
        pub const fn with_lambda(self, v: u32) -> Self {
            Self((self.0 & !(0xF << 4)) | ((v & 0xF) << 4))
        }

        /// `M_BITS` (bits 11:8, 4 bits): M = log2 N_bar, search bits
        pub const fn m_bits(self) -> u32 {
            (self.0 >> 8) & 0xF
        }

        /// Sets `M_BITS` (bits 11:8, 4 bits) to the low 4 bits of `v` (higher bits are dropped).
        pub const fn with_m_bits(self, v: u32) -> Self {
            Self((self.0 & !(0xF << 8)) | ((v & 0xF) << 8))
        }

        /// `NODES` (bits 15:12, 4 bits): interpolation nodes
        pub const fn nodes(self) -> u32 {
            (self.0 >> 12) & 0xF
        }

        /// Sets `NODES` (bits 15:12, 4 bits) to the low 4 bits of `v` (higher bits are dropped).
        pub const fn with_nodes(self, v: u32) -> Self {
            Self((self.0 & !(0xF << 12)) | ((v & 0xF) << 12))
        }
    }

    impl Default for MpdccConfigValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_S_PREV` at `0x43C02010` (RW, 9 bits, reset `0x0`): Switch positions applied in the previous period, s(k-1).
    ///
    /// Format: three unsigned 3-bit switch positions 0..7. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccSPrev;

    impl MpdccSPrev {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02010;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_S_PREV;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccSPrevValue, BusError> {
            bus.read(Self::ADDR).map(MpdccSPrevValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccSPrevValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccSPrevValue) -> MpdccSPrevValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccSPrev`]; bits above bit 8 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccSPrevValue(u32);

    impl MpdccSPrevValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `A` (bits 2:0, 3 bits): phase a position
        pub const fn a(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `A` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_a(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }

        /// `B` (bits 5:3, 3 bits): phase b position
        pub const fn b(self) -> u32 {
            (self.0 >> 3) & 0x7
        }

        /// Sets `B` (bits 5:3, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_b(self, v: u32) -> Self {
            Self((self.0 & !(0x7 << 3)) | ((v & 0x7) << 3))
        }

        /// `C` (bits 8:6, 3 bits): phase c position
        pub const fn c(self) -> u32 {
            (self.0 >> 6) & 0x7
        }

        /// Sets `C` (bits 8:6, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_c(self, v: u32) -> Self {
            Self((self.0 & !(0x7 << 6)) | ((v & 0x7) << 6))
        }
    }

    impl Default for MpdccSPrevValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_I_A` at `0x43C02014` (RW, 16 bits, reset `0x0`): Stator current i_s,alpha.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIA;

    impl MpdccIA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02014;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_I_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccIAValue, BusError> {
            bus.read(Self::ADDR).map(MpdccIAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccIAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccIAValue) -> MpdccIAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccIA`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIAValue(u32);

    impl MpdccIAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccIAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_I_B` at `0x43C02018` (RW, 16 bits, reset `0x0`): Stator current i_s,beta.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIB;

    impl MpdccIB {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02018;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_I_B;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccIBValue, BusError> {
            bus.read(Self::ADDR).map(MpdccIBValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccIBValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccIBValue) -> MpdccIBValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccIB`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIBValue(u32);

    impl MpdccIBValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccIBValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_PSI_A` at `0x43C0201C` (RW, 16 bits, reset `0x0`): Rotor flux psi_r,alpha, pu.
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccPsiA;

    impl MpdccPsiA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0201C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_PSI_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccPsiAValue, BusError> {
            bus.read(Self::ADDR).map(MpdccPsiAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccPsiAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccPsiAValue) -> MpdccPsiAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccPsiA`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccPsiAValue(u32);

    impl MpdccPsiAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccPsiAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_PSI_B` at `0x43C02020` (RW, 16 bits, reset `0x0`): Rotor flux psi_r,beta, pu.
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccPsiB;

    impl MpdccPsiB {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02020;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_PSI_B;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccPsiBValue, BusError> {
            bus.read(Self::ADDR).map(MpdccPsiBValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccPsiBValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccPsiBValue) -> MpdccPsiBValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccPsiB`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccPsiBValue(u32);

    impl MpdccPsiBValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccPsiBValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_V_N` at `0x43C02024` (RW, 16 bits, reset `0x0`): Neutral-point voltage v_n.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVN;

    impl MpdccVN {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02024;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_V_N;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccVNValue, BusError> {
            bus.read(Self::ADDR).map(MpdccVNValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccVNValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccVNValue) -> MpdccVNValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccVN`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVNValue(u32);

    impl MpdccVNValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccVNValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_V_PH_A` at `0x43C02028` (RW, 16 bits, reset `0x0`): Phase capacitor voltage, a.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhA;

    impl MpdccVPhA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02028;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_V_PH_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccVPhAValue, BusError> {
            bus.read(Self::ADDR).map(MpdccVPhAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccVPhAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccVPhAValue) -> MpdccVPhAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccVPhA`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhAValue(u32);

    impl MpdccVPhAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccVPhAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_V_PH_B` at `0x43C0202C` (RW, 16 bits, reset `0x0`): Phase capacitor voltage, b.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhB;

    impl MpdccVPhB {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0202C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_V_PH_B;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccVPhBValue, BusError> {
            bus.read(Self::ADDR).map(MpdccVPhBValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccVPhBValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccVPhBValue) -> MpdccVPhBValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccVPhB`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhBValue(u32);

    impl MpdccVPhBValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccVPhBValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_V_PH_C` at `0x43C02030` (RW, 16 bits, reset `0x0`): Phase capacitor voltage, c.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhC;

    impl MpdccVPhC {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02030;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_V_PH_C;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccVPhCValue, BusError> {
            bus.read(Self::ADDR).map(MpdccVPhCValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccVPhCValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccVPhCValue) -> MpdccVPhCValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccVPhC`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhCValue(u32);

    impl MpdccVPhCValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccVPhCValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_IREF_A` at `0x43C02034` (RW, 16 bits, reset `0x0`): Current reference i_s*,alpha(k).
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIrefA;

    impl MpdccIrefA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02034;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_IREF_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccIrefAValue, BusError> {
            bus.read(Self::ADDR).map(MpdccIrefAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccIrefAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccIrefAValue) -> MpdccIrefAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccIrefA`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIrefAValue(u32);

    impl MpdccIrefAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccIrefAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_IREF_B` at `0x43C02038` (RW, 16 bits, reset `0x0`): Current reference i_s*,beta(k).
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIrefB;

    impl MpdccIrefB {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02038;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_IREF_B;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccIrefBValue, BusError> {
            bus.read(Self::ADDR).map(MpdccIrefBValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccIrefBValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccIrefBValue) -> MpdccIrefBValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccIrefB`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccIrefBValue(u32);

    impl MpdccIrefBValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccIrefBValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_OMEGA_R` at `0x43C0203C` (RW, 16 bits, reset `0x0`): Rotor speed omega_r.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccOmegaR;

    impl MpdccOmegaR {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0203C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_OMEGA_R;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccOmegaRValue, BusError> {
            bus.read(Self::ADDR).map(MpdccOmegaRValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccOmegaRValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccOmegaRValue) -> MpdccOmegaRValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccOmegaR`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccOmegaRValue(u32);

    impl MpdccOmegaRValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccOmegaRValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_OMEGA_S` at `0x43C02040` (RW, 16 bits, reset `0x0`): Stator (reference) frequency omega_s.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccOmegaS;

    impl MpdccOmegaS {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02040;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_OMEGA_S;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccOmegaSValue, BusError> {
            bus.read(Self::ADDR).map(MpdccOmegaSValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccOmegaSValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccOmegaSValue) -> MpdccOmegaSValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccOmegaS`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccOmegaSValue(u32);

    impl MpdccOmegaSValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccOmegaSValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_TAU` at `0x43C02080` (RW, 16 bits, reset `0x0`): L T / tau_s.
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCTau;

    impl MpdccCTau {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02080;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_TAU;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCTauValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCTauValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCTauValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCTauValue) -> MpdccCTauValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCTau`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCTauValue(u32);

    impl MpdccCTauValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCTauValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_R` at `0x43C02084` (RW, 16 bits, reset `0x0`): L T X_m / (D tau_r).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCR;

    impl MpdccCR {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02084;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_R;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCRValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCRValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCRValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCRValue) -> MpdccCRValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCR`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCRValue(u32);

    impl MpdccCRValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCRValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_W` at `0x43C02088` (RW, 16 bits, reset `0x0`): L T X_m / D (times omega_r).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCW;

    impl MpdccCW {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02088;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_W;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCWValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCWValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCWValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCWValue) -> MpdccCWValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCW`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCWValue(u32);

    impl MpdccCWValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCWValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_P` at `0x43C0208C` (RW, 16 bits, reset `0x0`): p (L T)^2 (times omega_r^2).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCP;

    impl MpdccCP {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0208C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_P;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCPValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCPValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCPValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCPValue) -> MpdccCPValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCP`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCPValue(u32);

    impl MpdccCPValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCPValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_S` at `0x43C02090` (RW, 16 bits, reset `0x0`): L T (times omega_s).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCS;

    impl MpdccCS {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02090;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_S;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCSValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCSValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCSValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCSValue) -> MpdccCSValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCS`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCSValue(u32);

    impl MpdccCSValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCSValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_3` at `0x43C02094` (RW, 16 bits, reset `0x0`): (L T)^2 / 6 (third-order rotation).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccC3;

    impl MpdccC3 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02094;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_3;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccC3Value, BusError> {
            bus.read(Self::ADDR).map(MpdccC3Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccC3Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccC3Value) -> MpdccC3Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccC3`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccC3Value(u32);

    impl MpdccC3Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccC3Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_D` at `0x43C02098` (RW, 16 bits, reset `0x0`): Stator damping L T / (2 tau_s).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCD;

    impl MpdccCD {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02098;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_D;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCDValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCDValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCDValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCDValue) -> MpdccCDValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCD`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCDValue(u32);

    impl MpdccCDValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCDValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_N` at `0x43C0209C` (RW, 16 bits, reset `0x0`): L T / (2 C_dc) (times i_x).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCN;

    impl MpdccCN {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0209C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_N;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCNValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCNValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCNValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCNValue) -> MpdccCNValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCN`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCNValue(u32);

    impl MpdccCNValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCNValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_PH` at `0x43C020A0` (RW, 16 bits, reset `0x0`): L T / C_ph (times i_x).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCPh;

    impl MpdccCPh {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020A0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_PH;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCPhValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCPhValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCPhValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCPhValue) -> MpdccCPhValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCPh`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCPhValue(u32);

    impl MpdccCPhValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCPhValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_S3H` at `0x43C020A4` (RW, 16 bits, reset `0x0`): sqrt(3) / 2.
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccS3h;

    impl MpdccS3h {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020A4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_S3H;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccS3hValue, BusError> {
            bus.read(Self::ADDR).map(MpdccS3hValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccS3hValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccS3hValue) -> MpdccS3hValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccS3h`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccS3hValue(u32);

    impl MpdccS3hValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccS3hValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_V_PH_REF` at `0x43C020A8` (RW, 16 bits, reset `0x0`): Phase capacitor reference V_dc / 4.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhRef;

    impl MpdccVPhRef {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020A8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_V_PH_REF;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccVPhRefValue, BusError> {
            bus.read(Self::ADDR).map(MpdccVPhRefValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccVPhRefValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccVPhRefValue) -> MpdccVPhRefValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccVPhRef`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVPhRefValue(u32);

    impl MpdccVPhRefValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccVPhRefValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_TAU1` at `0x43C020AC` (RW, 16 bits, reset `0x0`): One step: T / tau_s.
    ///
    /// Format: signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCTau1;

    impl MpdccCTau1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020AC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_TAU1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCTau1Value, BusError> {
            bus.read(Self::ADDR).map(MpdccCTau1Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCTau1Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCTau1Value) -> MpdccCTau1Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCTau1`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCTau1Value(u32);

    impl MpdccCTau1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCTau1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_R1` at `0x43C020B0` (RW, 16 bits, reset `0x0`): One step: T X_m / (D tau_r).
    ///
    /// Format: signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCR1;

    impl MpdccCR1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020B0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_R1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCR1Value, BusError> {
            bus.read(Self::ADDR).map(MpdccCR1Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCR1Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCR1Value) -> MpdccCR1Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCR1`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCR1Value(u32);

    impl MpdccCR1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCR1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_W1` at `0x43C020B4` (RW, 16 bits, reset `0x0`): One step: T X_m / D.
    ///
    /// Format: signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCW1;

    impl MpdccCW1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020B4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_W1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCW1Value, BusError> {
            bus.read(Self::ADDR).map(MpdccCW1Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCW1Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCW1Value) -> MpdccCW1Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCW1`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCW1Value(u32);

    impl MpdccCW1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCW1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_C_S1` at `0x43C020B8` (RW, 16 bits, reset `0x0`): One step: T.
    ///
    /// Format: signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCS1;

    impl MpdccCS1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020B8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_C_S1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCS1Value, BusError> {
            bus.read(Self::ADDR).map(MpdccCS1Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccCS1Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccCS1Value) -> MpdccCS1Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccCS1`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCS1Value(u32);

    impl MpdccCS1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccCS1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_VDC_HALF` at `0x43C020BC` (RW, 16 bits, reset `0x0`): V_dc / 2.
    ///
    /// Format: Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVdcHalf;

    impl MpdccVdcHalf {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020BC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_VDC_HALF;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccVdcHalfValue, BusError> {
            bus.read(Self::ADDR).map(MpdccVdcHalfValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccVdcHalfValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccVdcHalfValue) -> MpdccVdcHalfValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccVdcHalf`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccVdcHalfValue(u32);

    impl MpdccVdcHalfValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13 signed 16-bit two's complement, pu (range +-4, LSB 1.22e-4)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccVdcHalfValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_G3` at `0x43C020C0` (RW, 16 bits, reset `0x0`): L T X_r / (3 D).
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccG3;

    impl MpdccG3 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020C0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_G3;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccG3Value, BusError> {
            bus.read(Self::ADDR).map(MpdccG3Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccG3Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccG3Value) -> MpdccG3Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccG3`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccG3Value(u32);

    impl MpdccG3Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccG3Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_GD` at `0x43C020C4` (RW, 16 bits, reset `0x0`): g3 c_d.
    ///
    /// Format: Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccGd;

    impl MpdccGd {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020C4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_GD;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccGdValue, BusError> {
            bus.read(Self::ADDR).map(MpdccGdValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccGdValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccGdValue) -> MpdccGdValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccGd`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccGdValue(u32);

    impl MpdccGdValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q1.14 signed 16-bit two's complement (range +-2, LSB 6.10e-5)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccGdValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_G3_1` at `0x43C020C8` (RW, 16 bits, reset `0x0`): One step: T X_r / (3 D).
    ///
    /// Format: signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccG31;

    impl MpdccG31 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020C8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_G3_1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccG31Value, BusError> {
            bus.read(Self::ADDR).map(MpdccG31Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccG31Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccG31Value) -> MpdccG31Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccG31`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccG31Value(u32);

    impl MpdccG31Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, 17 fractional bits (range +-0.25, LSB 7.6e-6)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for MpdccG31Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_BND_IA` at `0x43C020CC` (RW, 16 bits, reset `0x0`): Bound delta_i, phase a current.
    ///
    /// Format: Q2.13, 0..32767 (0..4 pu). Writes: the hardware rejects a word above 32767: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndIa;

    impl MpdccBndIa {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020CC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_BND_IA;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccBndIaValue, BusError> {
            bus.read(Self::ADDR).map(MpdccBndIaValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccBndIaValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccBndIaValue) -> MpdccBndIaValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccBndIa`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndIaValue(u32);

    impl MpdccBndIaValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13, 0..32767 (0..4 pu)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccBndIaValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_BND_IB` at `0x43C020D0` (RW, 16 bits, reset `0x0`): Bound delta_i, phase b current.
    ///
    /// Format: Q2.13, 0..32767 (0..4 pu). Writes: the hardware rejects a word above 32767: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndIb;

    impl MpdccBndIb {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020D0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_BND_IB;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccBndIbValue, BusError> {
            bus.read(Self::ADDR).map(MpdccBndIbValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccBndIbValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccBndIbValue) -> MpdccBndIbValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccBndIb`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndIbValue(u32);

    impl MpdccBndIbValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13, 0..32767 (0..4 pu)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccBndIbValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_BND_IC` at `0x43C020D4` (RW, 16 bits, reset `0x0`): Bound delta_i, phase c current.
    ///
    /// Format: Q2.13, 0..32767 (0..4 pu). Writes: the hardware rejects a word above 32767: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndIc;

    impl MpdccBndIc {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020D4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_BND_IC;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccBndIcValue, BusError> {
            bus.read(Self::ADDR).map(MpdccBndIcValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccBndIcValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccBndIcValue) -> MpdccBndIcValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccBndIc`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndIcValue(u32);

    impl MpdccBndIcValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13, 0..32767 (0..4 pu)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccBndIcValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_BND_VN` at `0x43C020D8` (RW, 16 bits, reset `0x0`): Bound on |v_n|.
    ///
    /// Format: Q2.13, 0..32767 (0..4 pu). Writes: the hardware rejects a word above 32767: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVn;

    impl MpdccBndVn {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020D8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_BND_VN;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccBndVnValue, BusError> {
            bus.read(Self::ADDR).map(MpdccBndVnValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccBndVnValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccBndVnValue) -> MpdccBndVnValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccBndVn`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVnValue(u32);

    impl MpdccBndVnValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13, 0..32767 (0..4 pu)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccBndVnValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_BND_VPA` at `0x43C020DC` (RW, 16 bits, reset `0x0`): Bound on |v_ph,a - V_dc/4|.
    ///
    /// Format: Q2.13, 0..32767 (0..4 pu). Writes: the hardware rejects a word above 32767: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVpa;

    impl MpdccBndVpa {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020DC;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_BND_VPA;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccBndVpaValue, BusError> {
            bus.read(Self::ADDR).map(MpdccBndVpaValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccBndVpaValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccBndVpaValue) -> MpdccBndVpaValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccBndVpa`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVpaValue(u32);

    impl MpdccBndVpaValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13, 0..32767 (0..4 pu)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccBndVpaValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_BND_VPB` at `0x43C020E0` (RW, 16 bits, reset `0x0`): Bound on |v_ph,b - V_dc/4|.
    ///
    /// Format: Q2.13, 0..32767 (0..4 pu). Writes: the hardware rejects a word above 32767: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVpb;

    impl MpdccBndVpb {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020E0;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_BND_VPB;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccBndVpbValue, BusError> {
            bus.read(Self::ADDR).map(MpdccBndVpbValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccBndVpbValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccBndVpbValue) -> MpdccBndVpbValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccBndVpb`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVpbValue(u32);

    impl MpdccBndVpbValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13, 0..32767 (0..4 pu)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccBndVpbValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_BND_VPC` at `0x43C020E4` (RW, 16 bits, reset `0x0`): Bound on |v_ph,c - V_dc/4|.
    ///
    /// Format: Q2.13, 0..32767 (0..4 pu). Writes: the hardware rejects a word above 32767: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVpc;

    impl MpdccBndVpc {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020E4;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_BND_VPC;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccBndVpcValue, BusError> {
            bus.read(Self::ADDR).map(MpdccBndVpcValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccBndVpcValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccBndVpcValue) -> MpdccBndVpcValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccBndVpc`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccBndVpcValue(u32);

    impl MpdccBndVpcValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (Q2.13, 0..32767 (0..4 pu)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccBndVpcValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_LAMBDA_N` at `0x43C020E8` (RW, 16 bits, reset `0x0`): Weight lambda_n of the terminal v_n^2 term of J.
    ///
    /// Format: UQ8.8 unsigned 16-bit (0..256, LSB 3.9e-3). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccLambdaN;

    impl MpdccLambdaN {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C020E8;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_LAMBDA_N;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccLambdaNValue, BusError> {
            bus.read(Self::ADDR).map(MpdccLambdaNValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: MpdccLambdaNValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(MpdccLambdaNValue) -> MpdccLambdaNValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`MpdccLambdaN`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccLambdaNValue(u32);

    impl MpdccLambdaNValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (UQ8.8 unsigned 16-bit (0..256, LSB 3.9e-3)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccLambdaNValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_DECISION` at `0x43C02100` (RO, 24 bits, reset `0x0`): The last decision.
    ///
    /// Format: three 3-bit positions, an enum, an unsigned step count. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccDecision;

    impl MpdccDecision {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02100;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_DECISION;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccDecisionValue, BusError> {
            bus.read(Self::ADDR).map(MpdccDecisionValue)
        }
    }

    /// A value of [`MpdccDecision`]; bits above bit 23 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccDecisionValue(u32);

    impl MpdccDecisionValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `S_A` (bits 2:0, 3 bits): phase a position s(k)
        pub const fn s_a(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `S_A` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_s_a(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }

        /// `S_B` (bits 5:3, 3 bits): phase b position
        pub const fn s_b(self) -> u32 {
            (self.0 >> 3) & 0x7
        }

        /// Sets `S_B` (bits 5:3, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_s_b(self, v: u32) -> Self {
            Self((self.0 & !(0x7 << 3)) | ((v & 0x7) << 3))
        }

        /// `S_C` (bits 8:6, 3 bits): phase c position
        pub const fn s_c(self) -> u32 {
            (self.0 >> 6) & 0x7
        }

        /// Sets `S_C` (bits 8:6, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_s_c(self, v: u32) -> Self {
            Self((self.0 & !(0x7 << 6)) | ((v & 0x7) << 6))
        }

        /// `KIND` (bits 13:12, 2 bits): 0 kept, 1 optimal, 2 deadlock (regmap::mpdcc_kind)
        pub const fn kind(self) -> u32 {
            (self.0 >> 12) & 0x3
        }

        /// Sets `KIND` (bits 13:12, 2 bits) to the low 2 bits of `v` (higher bits are dropped).
        pub const fn with_kind(self, v: u32) -> Self {
            Self((self.0 & !(0x3 << 12)) | ((v & 0x3) << 12))
        }

        /// `L_STAR` (bits 23:16, 8 bits): L*, steps, of an optimal decision (else 0)
        pub const fn l_star(self) -> u32 {
            (self.0 >> 16) & 0xFF
        }

        /// Sets `L_STAR` (bits 23:16, 8 bits) to the low 8 bits of `v` (higher bits are dropped).
        pub const fn with_l_star(self, v: u32) -> Self {
            Self((self.0 & !(0xFF << 16)) | ((v & 0xFF) << 16))
        }
    }

    impl Default for MpdccDecisionValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_COST` at `0x43C02104` (RO, 32 bits, reset `0x0`): J of the chosen candidate (kept: 0).
    ///
    /// Format: UQ15.17 unsigned, transitions per step (0xFFFFFFFF = +inf). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCost;

    impl MpdccCost {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02104;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_COST;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCostValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCostValue)
        }
    }

    /// A value of [`MpdccCost`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCostValue(u32);

    impl MpdccCostValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (UQ15.17 unsigned, transitions per step (0xFFFFFFFF = +inf)).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for MpdccCostValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_J_DL` at `0x43C02108` (RO, 32 bits, reset `0x0`): J_dl (eq. 15) of the chosen candidate (kept: 0).
    ///
    /// Format: signed 32-bit two's complement, Q2.13 pu. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccJDl;

    impl MpdccJDl {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02108;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_J_DL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccJDlValue, BusError> {
            bus.read(Self::ADDR).map(MpdccJDlValue)
        }
    }

    /// A value of [`MpdccJDl`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccJDlValue(u32);

    impl MpdccJDlValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (signed 32-bit two's complement, Q2.13 pu).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for MpdccJDlValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_CYCLES` at `0x43C0210C` (RO, 24 bits, reset `0x0`): Cost in time of the last decision.
    ///
    /// Format: unsigned PL clock cycles and an unsigned count. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCycles;

    impl MpdccCycles {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0210C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_CYCLES;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccCyclesValue, BusError> {
            bus.read(Self::ADDR).map(MpdccCyclesValue)
        }
    }

    /// A value of [`MpdccCycles`]; bits above bit 23 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccCyclesValue(u32);

    impl MpdccCyclesValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `CYCLES` (bits 15:0, 16 bits): clock edges from the core's start strobe to its done strobe
        pub const fn cycles(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `CYCLES` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_cycles(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `CANDIDATES` (bits 23:16, 8 bits): candidates evaluated (kept: 0; the search runs anyway)
        pub const fn candidates(self) -> u32 {
            (self.0 >> 16) & 0xFF
        }

        /// Sets `CANDIDATES` (bits 23:16, 8 bits) to the low 8 bits of `v` (higher bits are dropped).
        pub const fn with_candidates(self, v: u32) -> Self {
            Self((self.0 & !(0xFF << 16)) | ((v & 0xFF) << 16))
        }
    }

    impl Default for MpdccCyclesValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `MPDCC.MPDCC_DEADLOCKS` at `0x43C02110` (RO, 16 bits, reset `0x0`): Deadlock decisions (KIND = 2) since reset.
    ///
    /// Format: unsigned, wraps. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccDeadlocks;

    impl MpdccDeadlocks {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C02110;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::MPDCC_DEADLOCKS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<MpdccDeadlocksValue, BusError> {
            bus.read(Self::ADDR).map(MpdccDeadlocksValue)
        }
    }

    /// A value of [`MpdccDeadlocks`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct MpdccDeadlocksValue(u32);

    impl MpdccDeadlocksValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, wraps).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for MpdccDeadlocksValue {
        fn default() -> Self {
            Self::RESET
        }
    }
}

/// Block 3 `PWM` at `0x43C03000`: Gate enable, dead time, centre-aligned PWM, switching state.
pub mod pwm {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C03000;

    /// `PWM.GATE_CTRL` at `0x43C03000` (RW, 1 bits, reset `0x0`): Gate enable.
    ///
    /// Format: bit. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct GateCtrl;

    impl GateCtrl {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C03000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::GATE_CTRL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<GateCtrlValue, BusError> {
            bus.read(Self::ADDR).map(GateCtrlValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: GateCtrlValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(GateCtrlValue) -> GateCtrlValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`GateCtrl`]; bits above bit 0 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct GateCtrlValue(u32);

    impl GateCtrlValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `GATE_EN` (bit 0): 1 = gates follow the selected controller, 0 = all gates off (safe state); held at 0 by the hardware while a fault is latched
        pub const fn gate_en(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `GATE_EN` (bit 0).
        pub const fn with_gate_en(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }
    }

    impl Default for GateCtrlValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.DEAD_TIME` at `0x43C03004` (RW, 10 bits, reset `0x32`): Cycles with both gates of a leg off before either turns on (reset 500 ns).
    ///
    /// Format: unsigned, PL clock cycles (10 ns); 0 acts as 1. Writes: the hardware clamps the written word to 0..=1023 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DeadTime;

    impl DeadTime {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C03004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::DEAD_TIME;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<DeadTimeValue, BusError> {
            bus.read(Self::ADDR).map(DeadTimeValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: DeadTimeValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(DeadTimeValue) -> DeadTimeValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`DeadTime`]; bits above bit 9 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DeadTimeValue(u32);

    impl DeadTimeValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x32);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 9:0, 10 bits): The whole register (unsigned, PL clock cycles (10 ns); 0 acts as 1).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FF
        }

        /// Sets `VALUE` (bits 9:0, 10 bits) to the low 10 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FF) | (v & 0x3FF))
        }
    }

    impl Default for DeadTimeValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.PWM_PERIOD` at `0x43C03008` (RW, 16 bits, reset `0x9C4`): Up-down counter top: f_pwm = 100 MHz / (2 PWM_PERIOD) (reset 20 kHz). Takes effect at the next counter bottom.
    ///
    /// Format: unsigned, PL clock cycles. Writes: the hardware clamps the written word to 2..=65535 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct PwmPeriod;

    impl PwmPeriod {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C03008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::PWM_PERIOD;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<PwmPeriodValue, BusError> {
            bus.read(Self::ADDR).map(PwmPeriodValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: PwmPeriodValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(PwmPeriodValue) -> PwmPeriodValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`PwmPeriod`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct PwmPeriodValue(u32);

    impl PwmPeriodValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x9C4);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for PwmPeriodValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.DUTY_A` at `0x43C0300C` (RW, 16 bits, reset `0x4E2`): Upper switch on while the counter < DUTY (centre aligned): duty = DUTY / PWM_PERIOD; >= PWM_PERIOD is 100 %. Loaded at the counter bottom.
    ///
    /// Format: unsigned, PL clock cycles (compare value). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DutyA;

    impl DutyA {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0300C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::DUTY_A;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<DutyAValue, BusError> {
            bus.read(Self::ADDR).map(DutyAValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: DutyAValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(DutyAValue) -> DutyAValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`DutyA`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DutyAValue(u32);

    impl DutyAValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x4E2);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles (compare value)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for DutyAValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.DUTY_B` at `0x43C03010` (RW, 16 bits, reset `0x4E2`): Upper switch on while the counter < DUTY (centre aligned): duty = DUTY / PWM_PERIOD; >= PWM_PERIOD is 100 %. Loaded at the counter bottom.
    ///
    /// Format: unsigned, PL clock cycles (compare value). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DutyB;

    impl DutyB {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C03010;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::DUTY_B;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<DutyBValue, BusError> {
            bus.read(Self::ADDR).map(DutyBValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: DutyBValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(DutyBValue) -> DutyBValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`DutyB`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DutyBValue(u32);

    impl DutyBValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x4E2);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles (compare value)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for DutyBValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.DUTY_C` at `0x43C03014` (RW, 16 bits, reset `0x4E2`): Upper switch on while the counter < DUTY (centre aligned): duty = DUTY / PWM_PERIOD; >= PWM_PERIOD is 100 %. Loaded at the counter bottom.
    ///
    /// Format: unsigned, PL clock cycles (compare value). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DutyC;

    impl DutyC {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C03014;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::DUTY_C;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<DutyCValue, BusError> {
            bus.read(Self::ADDR).map(DutyCValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: DutyCValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(DutyCValue) -> DutyCValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`DutyC`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct DutyCValue(u32);

    impl DutyCValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x4E2);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles (compare value)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for DutyCValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.SW_STATE` at `0x43C03018` (RW, 3 bits, reset `0x0`): Switching state applied in mode MPDTC when MPDTC_CTRL.MANUAL = 1.
    ///
    /// Format: bits SaSbSc (index 4 Sa + 2 Sb + Sc). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct SwState;

    impl SwState {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C03018;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::SW_STATE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<SwStateValue, BusError> {
            bus.read(Self::ADDR).map(SwStateValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: SwStateValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(SwStateValue) -> SwStateValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`SwState`]; bits above bit 2 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct SwStateValue(u32);

    impl SwStateValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 2:0, 3 bits): The whole register (bits SaSbSc (index 4 Sa + 2 Sb + Sc)).
        pub const fn value(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `VALUE` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }
    }

    impl Default for SwStateValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.GATE_STATUS` at `0x43C0301C` (RO, 9 bits, reset `0x0`): Gate driver outputs as driven now.
    ///
    /// Format: bits, leg a = highest bit of each field. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct GateStatus;

    impl GateStatus {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0301C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::GATE_STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<GateStatusValue, BusError> {
            bus.read(Self::ADDR).map(GateStatusValue)
        }
    }

    /// A value of [`GateStatus`]; bits above bit 8 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct GateStatusValue(u32);

    impl GateStatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `HI` (bits 2:0, 3 bits): upper gates (a, b, c = bits 2, 1, 0)
        pub const fn hi(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `HI` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_hi(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }

        /// `LO` (bits 5:3, 3 bits): lower gates
        pub const fn lo(self) -> u32 {
            (self.0 >> 3) & 0x7
        }

        /// Sets `LO` (bits 5:3, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_lo(self, v: u32) -> Self {
            Self((self.0 & !(0x7 << 3)) | ((v & 0x7) << 3))
        }

        /// `STATE` (bits 8:6, 3 bits): switching state requested by the selected source
        pub const fn state(self) -> u32 {
            (self.0 >> 6) & 0x7
        }

        /// Sets `STATE` (bits 8:6, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_state(self, v: u32) -> Self {
            Self((self.0 & !(0x7 << 6)) | ((v & 0x7) << 6))
        }
    }

    impl Default for GateStatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `PWM.PWM_COUNT` at `0x43C03020` (RO, 17 bits, reset `0x0`): Centre-aligned PWM counter.
    ///
    /// Format: unsigned, PL clock cycles. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct PwmCount;

    impl PwmCount {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C03020;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::PWM_COUNT;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<PwmCountValue, BusError> {
            bus.read(Self::ADDR).map(PwmCountValue)
        }
    }

    /// A value of [`PwmCount`]; bits above bit 16 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct PwmCountValue(u32);

    impl PwmCountValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `COUNT` (bits 15:0, 16 bits): up-down counter
        pub const fn count(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `COUNT` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_count(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `DOWN` (bit 16): 1 while counting down
        pub const fn down(self) -> bool {
            (self.0 >> 16) & 1 != 0
        }

        /// Sets `DOWN` (bit 16).
        pub const fn with_down(self, v: bool) -> Self {
            Self((self.0 & !(1 << 16)) | ((v as u32) << 16))
        }
    }

    impl Default for PwmCountValue {
        fn default() -> Self {
            Self::RESET
        }
    }
}

/// Block 4 `ADC` at `0x43C04000`: ADC front end: 3 phase currents, sampled every ADC_PERIOD, averaged by 2^ADC_AVG_LOG2.
pub mod adc {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C04000;

    /// `ADC.ADC_CTRL` at `0x43C04000` (RW, 1 bits, reset `0x1`): ADC front-end control.
    ///
    /// Format: bit. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcCtrl;

    impl AdcCtrl {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C04000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ADC_CTRL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<AdcCtrlValue, BusError> {
            bus.read(Self::ADDR).map(AdcCtrlValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: AdcCtrlValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(AdcCtrlValue) -> AdcCtrlValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`AdcCtrl`]; bits above bit 0 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcCtrlValue(u32);

    impl AdcCtrlValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x1);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `ENABLE` (bit 0): 1 = convert every ADC_PERIOD (on from reset, so the over-current trip works)
        pub const fn enable(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `ENABLE` (bit 0).
        pub const fn with_enable(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }
    }

    impl Default for AdcCtrlValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ADC.ADC_PERIOD` at `0x43C04004` (RW, 16 bits, reset `0x187`): Cycles between conversion starts: 391 = 255.75 kHz (nearest to the paper's 256 kHz); 2^ADC_AVG_LOG2 samples are averaged (reset 4), so results come at 1/2^ADC_AVG_LOG2 of it.
    ///
    /// Format: unsigned, PL clock cycles. Writes: the hardware clamps the written word to 16..=65535 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcPeriod;

    impl AdcPeriod {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C04004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ADC_PERIOD;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<AdcPeriodValue, BusError> {
            bus.read(Self::ADDR).map(AdcPeriodValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: AdcPeriodValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(AdcPeriodValue) -> AdcPeriodValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`AdcPeriod`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcPeriodValue(u32);

    impl AdcPeriodValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x187);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, PL clock cycles).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for AdcPeriodValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ADC.ADC_IA` at `0x43C04008` (RO, 16 bits, reset `0x0`): Latest average of 2^ADC_AVG_LOG2 samples of this phase current.
    ///
    /// Format: signed 12-bit ADC counts sign-extended to 16 bits (Q11.0 of full scale); floor(sum / 2^ADC_AVG_LOG2). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcIa;

    impl AdcIa {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C04008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ADC_IA;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<AdcIaValue, BusError> {
            bus.read(Self::ADDR).map(AdcIaValue)
        }
    }

    /// A value of [`AdcIa`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcIaValue(u32);

    impl AdcIaValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 12-bit ADC counts sign-extended to 16 bits (Q11.0 of full scale); floor(sum / 2^ADC_AVG_LOG2)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for AdcIaValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ADC.ADC_IB` at `0x43C0400C` (RO, 16 bits, reset `0x0`): Latest average of 2^ADC_AVG_LOG2 samples of this phase current.
    ///
    /// Format: signed 12-bit ADC counts sign-extended to 16 bits (Q11.0 of full scale); floor(sum / 2^ADC_AVG_LOG2). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcIb;

    impl AdcIb {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0400C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ADC_IB;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<AdcIbValue, BusError> {
            bus.read(Self::ADDR).map(AdcIbValue)
        }
    }

    /// A value of [`AdcIb`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcIbValue(u32);

    impl AdcIbValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 12-bit ADC counts sign-extended to 16 bits (Q11.0 of full scale); floor(sum / 2^ADC_AVG_LOG2)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for AdcIbValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ADC.ADC_IC` at `0x43C04010` (RO, 16 bits, reset `0x0`): Latest average of 2^ADC_AVG_LOG2 samples of this phase current.
    ///
    /// Format: signed 12-bit ADC counts sign-extended to 16 bits (Q11.0 of full scale); floor(sum / 2^ADC_AVG_LOG2). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcIc;

    impl AdcIc {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C04010;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ADC_IC;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<AdcIcValue, BusError> {
            bus.read(Self::ADDR).map(AdcIcValue)
        }
    }

    /// A value of [`AdcIc`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcIcValue(u32);

    impl AdcIcValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 12-bit ADC counts sign-extended to 16 bits (Q11.0 of full scale); floor(sum / 2^ADC_AVG_LOG2)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for AdcIcValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ADC.ADC_COUNT` at `0x43C04014` (RO, 32 bits, reset `0x0`): Averaged results produced since reset.
    ///
    /// Format: unsigned, wraps. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcCount;

    impl AdcCount {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C04014;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ADC_COUNT;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<AdcCountValue, BusError> {
            bus.read(Self::ADDR).map(AdcCountValue)
        }
    }

    /// A value of [`AdcCount`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcCountValue(u32);

    impl AdcCountValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (unsigned, wraps).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for AdcCountValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ADC.ADC_AVG_LOG2` at `0x43C04018` (RW, 2 bits, reset `0x2`): Samples per averaged result (ADC_IA..IC, ADC_COUNT, the averaged-sample strobe = the MPDTC control-period boundary): control period = ADC_PERIOD x 2^ADC_AVG_LOG2 cycles. Reset 2 (4 samples, 1564 cycles = 63.94 kHz with ADC_PERIOD 391); 1 us = ADC_PERIOD 100 with 0, or 25 with 2.
    ///
    /// Format: unsigned, log2 of the samples averaged: 0 = 1, 1 = 2, 2 = 4 (3 is rejected). Writes: the hardware rejects a word above 2: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcAvgLog2;

    impl AdcAvgLog2 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C04018;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ADC_AVG_LOG2;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<AdcAvgLog2Value, BusError> {
            bus.read(Self::ADDR).map(AdcAvgLog2Value)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: AdcAvgLog2Value,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(AdcAvgLog2Value) -> AdcAvgLog2Value,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`AdcAvgLog2`]; bits above bit 1 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct AdcAvgLog2Value(u32);

    impl AdcAvgLog2Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x2);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 1:0, 2 bits): The whole register (unsigned, log2 of the samples averaged: 0 = 1, 1 = 2, 2 = 4 (3 is rejected)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3
        }

        /// Sets `VALUE` (bits 1:0, 2 bits) to the low 2 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3) | (v & 0x3))
        }
    }

    impl Default for AdcAvgLog2Value {
        fn default() -> Self {
            Self::RESET
        }
    }
}

/// Block 5 `ENC` at `0x43C05000`: Incremental encoder (A/B quadrature + index).
pub mod enc {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C05000;

    /// `ENC.ENC_CPR` at `0x43C05000` (RW, 16 bits, reset `0x1000`): Position wraps at ENC_CPR.
    ///
    /// Format: unsigned, quadrature counts (4 per line) per mechanical revolution. Writes: the hardware clamps the written word to 4..=65535 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncCpr;

    impl EncCpr {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C05000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ENC_CPR;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<EncCprValue, BusError> {
            bus.read(Self::ADDR).map(EncCprValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: EncCprValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(EncCprValue) -> EncCprValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`EncCpr`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncCprValue(u32);

    impl EncCprValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x1000);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, quadrature counts (4 per line) per mechanical revolution).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for EncCprValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ENC.ENC_POS` at `0x43C05004` (RO, 16 bits, reset `0x0`): Mechanical position; the index pulse sets it to 0.
    ///
    /// Format: unsigned, counts in 0..ENC_CPR-1. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncPos;

    impl EncPos {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C05004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ENC_POS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<EncPosValue, BusError> {
            bus.read(Self::ADDR).map(EncPosValue)
        }
    }

    /// A value of [`EncPos`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncPosValue(u32);

    impl EncPosValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, counts in 0..ENC_CPR-1).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for EncPosValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ENC.ENC_SPEED` at `0x43C05008` (RO, 16 bits, reset `0x0`): Counts moved during the last complete window (positive = A leads B).
    ///
    /// Format: signed 16-bit, counts per ENC_WINDOW (saturated). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncSpeed;

    impl EncSpeed {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C05008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ENC_SPEED;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<EncSpeedValue, BusError> {
            bus.read(Self::ADDR).map(EncSpeedValue)
        }
    }

    /// A value of [`EncSpeed`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncSpeedValue(u32);

    impl EncSpeedValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit, counts per ENC_WINDOW (saturated)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for EncSpeedValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ENC.ENC_WINDOW` at `0x43C0500C` (RW, 24 bits, reset `0x186A0`): Speed measurement window (reset 1 ms).
    ///
    /// Format: unsigned, PL clock cycles. Writes: the hardware clamps the written word to 100..=16777215 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncWindow;

    impl EncWindow {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0500C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ENC_WINDOW;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<EncWindowValue, BusError> {
            bus.read(Self::ADDR).map(EncWindowValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: EncWindowValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(EncWindowValue) -> EncWindowValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`EncWindow`]; bits above bit 23 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncWindowValue(u32);

    impl EncWindowValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x186A0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 23:0, 24 bits): The whole register (unsigned, PL clock cycles).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFFFF
        }

        /// Sets `VALUE` (bits 23:0, 24 bits) to the low 24 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFFFF) | (v & 0xFFFFFF))
        }
    }

    impl Default for EncWindowValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ENC.ENC_INDEX` at `0x43C05010` (RO, 16 bits, reset `0x0`): Index pulses seen since reset.
    ///
    /// Format: unsigned, wraps. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncIndex;

    impl EncIndex {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C05010;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ENC_INDEX;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<EncIndexValue, BusError> {
            bus.read(Self::ADDR).map(EncIndexValue)
        }
    }

    /// A value of [`EncIndex`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncIndexValue(u32);

    impl EncIndexValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, wraps).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for EncIndexValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `ENC.ENC_POS_SAMPLE` at `0x43C05014` (RO, 16 bits, reset `0x0`): ENC_POS latched in the cycle of the control-period boundary (the strobe of IRQ_STATUS.BOUNDARY: the new ADC average, or the PWM counter bottom in mode FOC-PWM), so the control step reads the position of the instant its sample belongs to, however late after the boundary it reads.
    ///
    /// Format: unsigned, counts in 0..ENC_CPR-1. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncPosSample;

    impl EncPosSample {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C05014;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::ENC_POS_SAMPLE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<EncPosSampleValue, BusError> {
            bus.read(Self::ADDR).map(EncPosSampleValue)
        }
    }

    /// A value of [`EncPosSample`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct EncPosSampleValue(u32);

    impl EncPosSampleValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, counts in 0..ENC_CPR-1).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for EncPosSampleValue {
        fn default() -> Self {
            Self::RESET
        }
    }
}

/// Block 6 `FAULT` at `0x43C06000`: Over-current, external, watchdog, encoder-loss and ADC-stuck faults, latched.
pub mod fault {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C06000;

    /// `FAULT.FAULT_STATUS` at `0x43C06000` (W1C, 5 bits, reset `0x0`): Any set bit forces all gates off (at the clock edge after the condition) and holds GATE_EN at 0; a bit clears on a written 1 unless its condition is present in that cycle. Then GATE_EN must be written 1 again.
    ///
    /// Format: bits, latched. Writes: write 1 to clear (a bit whose condition is still present stays set).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct FaultStatus;

    impl FaultStatus {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C06000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::FAULT_STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<FaultStatusValue, BusError> {
            bus.read(Self::ADDR).map(FaultStatusValue)
        }

        /// Writes `value`: every 1 bit clears that flag.
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: FaultStatusValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }
    }

    /// A value of [`FaultStatus`]; bits above bit 4 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct FaultStatusValue(u32);

    impl FaultStatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `OVERCURRENT` (bit 0): |ADC sample| > OC_LIMIT on a phase
        pub const fn overcurrent(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `OVERCURRENT` (bit 0).
        pub const fn with_overcurrent(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }

        /// `EXTERNAL` (bit 1): external fault input asserted
        pub const fn external(self) -> bool {
            (self.0 >> 1) & 1 != 0
        }

        /// Sets `EXTERNAL` (bit 1).
        pub const fn with_external(self, v: bool) -> Self {
            Self((self.0 & !(1 << 1)) | ((v as u32) << 1))
        }

        /// `WATCHDOG` (bit 2): no HEARTBEAT write for WDG_TIMEOUT cycles
        pub const fn watchdog(self) -> bool {
            (self.0 >> 2) & 1 != 0
        }

        /// Sets `WATCHDOG` (bit 2).
        pub const fn with_watchdog(self, v: bool) -> Self {
            Self((self.0 & !(1 << 2)) | ((v as u32) << 2))
        }

        /// `ENCODER_LOSS` (bit 3): an illegal quadrature step (A and B changed in one clock) while GATE_EN = 1
        pub const fn encoder_loss(self) -> bool {
            (self.0 >> 3) & 1 != 0
        }

        /// Sets `ENCODER_LOSS` (bit 3).
        pub const fn with_encoder_loss(self, v: bool) -> Self {
            Self((self.0 & !(1 << 3)) | ((v as u32) << 3))
        }

        /// `ADC_STUCK` (bit 4): no raw ADC sample for ADC_PERIOD + 16 cycles while GATE_EN = 1 (the timer restarts at every sample and every change of ADC_CTRL.ENABLE)
        pub const fn adc_stuck(self) -> bool {
            (self.0 >> 4) & 1 != 0
        }

        /// Sets `ADC_STUCK` (bit 4).
        pub const fn with_adc_stuck(self, v: bool) -> Self {
            Self((self.0 & !(1 << 4)) | ((v as u32) << 4))
        }
    }

    impl Default for FaultStatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `FAULT.FAULT_RAW` at `0x43C06004` (RO, 5 bits, reset `0x0`): The fault conditions now, unlatched.
    ///
    /// Format: bits, as FAULT_STATUS. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct FaultRaw;

    impl FaultRaw {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C06004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::FAULT_RAW;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<FaultRawValue, BusError> {
            bus.read(Self::ADDR).map(FaultRawValue)
        }
    }

    /// A value of [`FaultRaw`]; bits above bit 4 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct FaultRawValue(u32);

    impl FaultRawValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 4:0, 5 bits): The whole register (bits, as FAULT_STATUS).
        pub const fn value(self) -> u32 {
            self.0 & 0x1F
        }

        /// Sets `VALUE` (bits 4:0, 5 bits) to the low 5 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x1F) | (v & 0x1F))
        }
    }

    impl Default for FaultRawValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `FAULT.OC_LIMIT` at `0x43C06008` (RW, 11 bits, reset `0x708`): Trip when a raw sample's magnitude exceeds it (-2048 always trips).
    ///
    /// Format: unsigned ADC counts (as ADC_IA). Writes: the hardware clamps the written word to 0..=2047 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct OcLimit;

    impl OcLimit {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C06008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::OC_LIMIT;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<OcLimitValue, BusError> {
            bus.read(Self::ADDR).map(OcLimitValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: OcLimitValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(OcLimitValue) -> OcLimitValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`OcLimit`]; bits above bit 10 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct OcLimitValue(u32);

    impl OcLimitValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x708);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 10:0, 11 bits): The whole register (unsigned ADC counts (as ADC_IA)).
        pub const fn value(self) -> u32 {
            self.0 & 0x7FF
        }

        /// Sets `VALUE` (bits 10:0, 11 bits) to the low 11 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x7FF) | (v & 0x7FF))
        }
    }

    impl Default for OcLimitValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `FAULT.WDG_TIMEOUT` at `0x43C0600C` (RW, 32 bits, reset `0x989680`): Cycles without a HEARTBEAT write before the watchdog trips (reset 100 ms).
    ///
    /// Format: unsigned, PL clock cycles. Writes: the hardware clamps the written word to 1000..=4294967295 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct WdgTimeout;

    impl WdgTimeout {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0600C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::WDG_TIMEOUT;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<WdgTimeoutValue, BusError> {
            bus.read(Self::ADDR).map(WdgTimeoutValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: WdgTimeoutValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(WdgTimeoutValue) -> WdgTimeoutValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`WdgTimeout`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct WdgTimeoutValue(u32);

    impl WdgTimeoutValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x989680);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (unsigned, PL clock cycles).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for WdgTimeoutValue {
        fn default() -> Self {
            Self::RESET
        }
    }
}

/// Block 7 `CAPTURE` at `0x43C07000`: Triggered capture buffer (capture_buf): a ring of CAPTURE_DEPTH samples of nine channels at the control rate, with pre-trigger.
pub mod capture {
    use super::*;

    /// Absolute address of the block.
    pub const BASE: usize = 0x43C07000;

    /// `CAPTURE.CAP_SOURCE` at `0x43C07000` (RW, 2 bits, reset `0x0`): Trigger of the armed capture, tested at each sample; a CAP_TRIG write triggers whatever the source.
    ///
    /// Format: enum: 0 manual, 1 reference step, 2 threshold, 3 fault. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapSource;

    impl CapSource {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07000;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_SOURCE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapSourceValue, BusError> {
            bus.read(Self::ADDR).map(CapSourceValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapSourceValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapSourceValue) -> CapSourceValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapSource`]; bits above bit 1 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapSourceValue(u32);

    impl CapSourceValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 1:0, 2 bits): The whole register (enum: 0 manual, 1 reference step, 2 threshold, 3 fault).
        pub const fn value(self) -> u32 {
            self.0 & 0x3
        }

        /// Sets `VALUE` (bits 1:0, 2 bits) to the low 2 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3) | (v & 0x3))
        }
    }

    impl Default for CapSourceValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_PRE` at `0x43C07004` (RW, 10 bits, reset `0x80`): Samples kept before the trigger sample (latched by CAP_ARM); the record holds CAPTURE_DEPTH - CAP_PRE samples from the trigger on. A trigger before CAP_PRE samples were taken keeps fewer (CAP_STATUS.TRIG_INDEX).
    ///
    /// Format: unsigned, samples. Writes: the hardware clamps the written word to 0..=1023 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapPre;

    impl CapPre {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07004;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_PRE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapPreValue, BusError> {
            bus.read(Self::ADDR).map(CapPreValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapPreValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapPreValue) -> CapPreValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapPre`]; bits above bit 9 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapPreValue(u32);

    impl CapPreValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x80);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 9:0, 10 bits): The whole register (unsigned, samples).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FF
        }

        /// Sets `VALUE` (bits 9:0, 10 bits) to the low 10 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FF) | (v & 0x3FF))
        }
    }

    impl Default for CapPreValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DECIM` at `0x43C07008` (RW, 8 bits, reset `0x0`): A sample every CAP_DECIM + 1 averaged ADC results (adc_avg_valid): 0 = the MPDTC control rate, 3 = the FOC control rate (one PWM period).
    ///
    /// Format: unsigned, averaged ADC results per sample - 1. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapDecim;

    impl CapDecim {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07008;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DECIM;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapDecimValue, BusError> {
            bus.read(Self::ADDR).map(CapDecimValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapDecimValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapDecimValue) -> CapDecimValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapDecim`]; bits above bit 7 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapDecimValue(u32);

    impl CapDecimValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 7:0, 8 bits): The whole register (unsigned, averaged ADC results per sample - 1).
        pub const fn value(self) -> u32 {
            self.0 & 0xFF
        }

        /// Sets `VALUE` (bits 7:0, 8 bits) to the low 8 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFF) | (v & 0xFF))
        }
    }

    impl Default for CapDecimValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_STEP` at `0x43C0700C` (RW, 16 bits, reset `0x1F4`): Source 1 triggers on a sample whose CAP_IN_TREF differs from the previous sample's by at least this much (reset 0.05 N m).
    ///
    /// Format: unsigned, 0.1 mN m. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapStep;

    impl CapStep {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0700C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_STEP;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapStepValue, BusError> {
            bus.read(Self::ADDR).map(CapStepValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapStepValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapStepValue) -> CapStepValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapStep`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapStepValue(u32);

    impl CapStepValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x1F4);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, 0.1 mN m).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for CapStepValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_THR_CH` at `0x43C07010` (RW, 3 bits, reset `0x2`): Channel source 2 compares with CAP_THR_LEVEL.
    ///
    /// Format: enum: 0 i_d, 1 i_q, 2 torque, 3 torque reference, 4 selectable. Writes: the hardware rejects a word above 4: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapThrCh;

    impl CapThrCh {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07010;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_THR_CH;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapThrChValue, BusError> {
            bus.read(Self::ADDR).map(CapThrChValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapThrChValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapThrChValue) -> CapThrChValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapThrCh`]; bits above bit 2 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapThrChValue(u32);

    impl CapThrChValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x2);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 2:0, 3 bits): The whole register (enum: 0 i_d, 1 i_q, 2 torque, 3 torque reference, 4 selectable).
        pub const fn value(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `VALUE` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }
    }

    impl Default for CapThrChValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_THR_LEVEL` at `0x43C07014` (RW, 16 bits, reset `0x0`): Source 2 triggers when the channel crosses this level between two samples (rising: previous < level <= present; falling: previous > level >= present).
    ///
    /// Format: signed 16-bit two's complement, the channel's unit. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapThrLevel;

    impl CapThrLevel {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07014;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_THR_LEVEL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapThrLevelValue, BusError> {
            bus.read(Self::ADDR).map(CapThrLevelValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapThrLevelValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapThrLevelValue) -> CapThrLevelValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapThrLevel`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapThrLevelValue(u32);

    impl CapThrLevelValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, the channel's unit).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for CapThrLevelValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_THR_EDGE` at `0x43C07018` (RW, 1 bits, reset `0x0`): Direction of the threshold crossing.
    ///
    /// Format: 0 rising, 1 falling. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapThrEdge;

    impl CapThrEdge {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07018;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_THR_EDGE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapThrEdgeValue, BusError> {
            bus.read(Self::ADDR).map(CapThrEdgeValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapThrEdgeValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapThrEdgeValue) -> CapThrEdgeValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapThrEdge`]; bits above bit 0 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapThrEdgeValue(u32);

    impl CapThrEdgeValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bit 0): The whole register (0 rising, 1 falling).
        pub const fn value(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `VALUE` (bit 0).
        pub const fn with_value(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }
    }

    impl Default for CapThrEdgeValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_SEL` at `0x43C0701C` (RW, 3 bits, reset `0x0`): What the selectable channel records: the low 16 bits of that register.
    ///
    /// Format: enum: 0 ADC_IA, 1 ADC_IB, 2 ADC_IC, 3 ENC_POS, 4 ENC_SPEED. Writes: the hardware rejects a word above 4: the register keeps its value and `ERR.BAD_VALUE` is set.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapSel;

    impl CapSel {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0701C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_SEL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapSelValue, BusError> {
            bus.read(Self::ADDR).map(CapSelValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapSelValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapSelValue) -> CapSelValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapSel`]; bits above bit 2 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapSelValue(u32);

    impl CapSelValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 2:0, 3 bits): The whole register (enum: 0 ADC_IA, 1 ADC_IB, 2 ADC_IC, 3 ENC_POS, 4 ENC_SPEED).
        pub const fn value(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `VALUE` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }
    }

    impl Default for CapSelValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_ARM` at `0x43C07020` (RW, 1 bits, reset `0x0`): Every write starts a new record: the ring empties, CAP_PRE is latched, state ARMED.
    ///
    /// Format: any value. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapArm;

    impl CapArm {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07020;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_ARM;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapArmValue, BusError> {
            bus.read(Self::ADDR).map(CapArmValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapArmValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapArmValue) -> CapArmValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapArm`]; bits above bit 0 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapArmValue(u32);

    impl CapArmValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bit 0): The whole register (any value).
        pub const fn value(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `VALUE` (bit 0).
        pub const fn with_value(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }
    }

    impl Default for CapArmValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_TRIG` at `0x43C07024` (RW, 1 bits, reset `0x0`): A write while ARMED triggers at the next sample (any source); ignored otherwise.
    ///
    /// Format: any value. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapTrig;

    impl CapTrig {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07024;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_TRIG;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapTrigValue, BusError> {
            bus.read(Self::ADDR).map(CapTrigValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapTrigValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapTrigValue) -> CapTrigValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapTrig`]; bits above bit 0 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapTrigValue(u32);

    impl CapTrigValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bit 0): The whole register (any value).
        pub const fn value(self) -> bool {
            self.0 & 1 != 0
        }

        /// Sets `VALUE` (bit 0).
        pub const fn with_value(self, v: bool) -> Self {
            Self((self.0 & !1) | v as u32)
        }
    }

    impl Default for CapTrigValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_STATUS` at `0x43C07028` (RO, 32 bits, reset `0x0`): Capture progress; the record is index 0 (oldest) to COUNT - 1.
    ///
    /// Format: state and counters. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapStatus;

    impl CapStatus {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07028;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_STATUS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapStatusValue, BusError> {
            bus.read(Self::ADDR).map(CapStatusValue)
        }
    }

    /// A value of [`CapStatus`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapStatusValue(u32);

    impl CapStatusValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `STATE` (bits 1:0, 2 bits): 0 idle, 1 armed, 2 triggered, 3 done (regmap::cap_state)
        pub const fn state(self) -> u32 {
            self.0 & 0x3
        }

        /// Sets `STATE` (bits 1:0, 2 bits) to the low 2 bits of `v` (higher bits are dropped).
        pub const fn with_state(self, v: u32) -> Self {
            Self((self.0 & !0x3) | (v & 0x3))
        }

        /// `TRIG_INDEX` (bits 14:4, 11 bits): record index of the trigger sample (valid in DONE)
        pub const fn trig_index(self) -> u32 {
            (self.0 >> 4) & 0x7FF
        }

        /// Sets `TRIG_INDEX` (bits 14:4, 11 bits) to the low 11 bits of `v` (higher bits are dropped).
        pub const fn with_trig_index(self, v: u32) -> Self {
            Self((self.0 & !(0x7FF << 4)) | ((v & 0x7FF) << 4))
        }

        /// `COUNT` (bits 26:16, 11 bits): samples in the record (at most CAPTURE_DEPTH)
        pub const fn count(self) -> u32 {
            (self.0 >> 16) & 0x7FF
        }

        /// Sets `COUNT` (bits 26:16, 11 bits) to the low 11 bits of `v` (higher bits are dropped).
        pub const fn with_count(self, v: u32) -> Self {
            Self((self.0 & !(0x7FF << 16)) | ((v & 0x7FF) << 16))
        }
    }

    impl Default for CapStatusValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_IN_ID` at `0x43C07030` (RW, 16 bits, reset `0x0`): Channel 0, measured d current, written by the PS every control period.
    ///
    /// Format: signed 16-bit two's complement, mA (range +-32.767 A). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInId;

    impl CapInId {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07030;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_IN_ID;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapInIdValue, BusError> {
            bus.read(Self::ADDR).map(CapInIdValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapInIdValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapInIdValue) -> CapInIdValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapInId`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInIdValue(u32);

    impl CapInIdValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, mA (range +-32.767 A)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for CapInIdValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_IN_IQ` at `0x43C07034` (RW, 16 bits, reset `0x0`): Channel 1, measured q current, written by the PS every control period.
    ///
    /// Format: signed 16-bit two's complement, mA (range +-32.767 A). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInIq;

    impl CapInIq {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07034;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_IN_IQ;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapInIqValue, BusError> {
            bus.read(Self::ADDR).map(CapInIqValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapInIqValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapInIqValue) -> CapInIqValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapInIq`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInIqValue(u32);

    impl CapInIqValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, mA (range +-32.767 A)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for CapInIqValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_IN_TORQUE` at `0x43C07038` (RW, 16 bits, reset `0x0`): Channel 2, torque from the measured currents, written by the PS every control period.
    ///
    /// Format: signed 16-bit two's complement, 0.1 mN m (range +-3.2767 N m). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInTorque;

    impl CapInTorque {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07038;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_IN_TORQUE;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapInTorqueValue, BusError> {
            bus.read(Self::ADDR).map(CapInTorqueValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapInTorqueValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapInTorqueValue) -> CapInTorqueValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapInTorque`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInTorqueValue(u32);

    impl CapInTorqueValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, 0.1 mN m (range +-3.2767 N m)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for CapInTorqueValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_IN_TREF` at `0x43C0703C` (RW, 16 bits, reset `0x0`): Channel 3, torque reference, written by the PS every control period.
    ///
    /// Format: signed 16-bit two's complement, 0.1 mN m (range +-3.2767 N m). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInTref;

    impl CapInTref {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0703C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_IN_TREF;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapInTrefValue, BusError> {
            bus.read(Self::ADDR).map(CapInTrefValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapInTrefValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapInTrefValue) -> CapInTrefValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapInTref`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInTrefValue(u32);

    impl CapInTrefValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed 16-bit two's complement, 0.1 mN m (range +-3.2767 N m)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for CapInTrefValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_RD_INDEX` at `0x43C07040` (RW, 10 bits, reset `0x0`): Sample CAP_DATA0..5 show, one cycle after the write.
    ///
    /// Format: unsigned, record index (0 = oldest). Writes: the hardware clamps the written word to 0..=1023 (so a value wider than the field is clamped, not wrapped).
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapRdIndex;

    impl CapRdIndex {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07040;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_RD_INDEX;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapRdIndexValue, BusError> {
            bus.read(Self::ADDR).map(CapRdIndexValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapRdIndexValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapRdIndexValue) -> CapRdIndexValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapRdIndex`]; bits above bit 9 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapRdIndexValue(u32);

    impl CapRdIndexValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 9:0, 10 bits): The whole register (unsigned, record index (0 = oldest)).
        pub const fn value(self) -> u32 {
            self.0 & 0x3FF
        }

        /// Sets `VALUE` (bits 9:0, 10 bits) to the low 10 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0x3FF) | (v & 0x3FF))
        }
    }

    impl Default for CapRdIndexValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DATA0` at `0x43C07044` (RO, 32 bits, reset `0x0`): Channels 0 and 1 of sample CAP_RD_INDEX.
    ///
    /// Format: two 16-bit fields, formats of CAP_IN_ID/IQ. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData0;

    impl CapData0 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07044;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DATA0;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapData0Value, BusError> {
            bus.read(Self::ADDR).map(CapData0Value)
        }
    }

    /// A value of [`CapData0`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData0Value(u32);

    impl CapData0Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `I_D` (bits 15:0, 16 bits): i_d, mA, two's complement
        pub const fn i_d(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `I_D` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_i_d(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `I_Q` (bits 31:16, 16 bits): i_q, mA, two's complement
        pub const fn i_q(self) -> u32 {
            (self.0 >> 16) & 0xFFFF
        }

        /// Sets `I_Q` (bits 31:16, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_i_q(self, v: u32) -> Self {
            Self((self.0 & !(0xFFFF << 16)) | ((v & 0xFFFF) << 16))
        }
    }

    impl Default for CapData0Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DATA1` at `0x43C07048` (RO, 32 bits, reset `0x0`): Channels 2 and 3 of sample CAP_RD_INDEX.
    ///
    /// Format: two 16-bit fields, formats of CAP_IN_TORQUE/TREF. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData1;

    impl CapData1 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07048;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DATA1;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapData1Value, BusError> {
            bus.read(Self::ADDR).map(CapData1Value)
        }
    }

    /// A value of [`CapData1`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData1Value(u32);

    impl CapData1Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `TORQUE` (bits 15:0, 16 bits): torque, 0.1 mN m, two's complement
        pub const fn torque(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `TORQUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_torque(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `TREF` (bits 31:16, 16 bits): torque reference, 0.1 mN m, two's complement
        pub const fn tref(self) -> u32 {
            (self.0 >> 16) & 0xFFFF
        }

        /// Sets `TREF` (bits 31:16, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_tref(self, v: u32) -> Self {
            Self((self.0 & !(0xFFFF << 16)) | ((v & 0xFFFF) << 16))
        }
    }

    impl Default for CapData1Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DATA2` at `0x43C0704C` (RO, 32 bits, reset `0x0`): Channels 5 (switching state) and 4 (selectable) of sample CAP_RD_INDEX.
    ///
    /// Format: bits and a 16-bit field. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData2;

    impl CapData2 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0704C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DATA2;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapData2Value, BusError> {
            bus.read(Self::ADDR).map(CapData2Value)
        }
    }

    /// A value of [`CapData2`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData2Value(u32);

    impl CapData2Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `SW` (bits 2:0, 3 bits): switching state applied to the gate driver (GATE_STATUS.STATE)
        pub const fn sw(self) -> u32 {
            self.0 & 0x7
        }

        /// Sets `SW` (bits 2:0, 3 bits) to the low 3 bits of `v` (higher bits are dropped).
        pub const fn with_sw(self, v: u32) -> Self {
            Self((self.0 & !0x7) | (v & 0x7))
        }

        /// `SEL` (bits 31:16, 16 bits): the selectable channel (CAP_SEL)
        pub const fn sel(self) -> u32 {
            (self.0 >> 16) & 0xFFFF
        }

        /// Sets `SEL` (bits 31:16, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_sel(self, v: u32) -> Self {
            Self((self.0 & !(0xFFFF << 16)) | ((v & 0xFFFF) << 16))
        }
    }

    impl Default for CapData2Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DEPTH` at `0x43C07050` (RO, 16 bits, reset `0x400`): Size of the ring.
    ///
    /// Format: unsigned, samples. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapDepth;

    impl CapDepth {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07050;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DEPTH;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapDepthValue, BusError> {
            bus.read(Self::ADDR).map(CapDepthValue)
        }
    }

    /// A value of [`CapDepth`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapDepthValue(u32);

    impl CapDepthValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x400);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (unsigned, samples).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }
    }

    impl Default for CapDepthValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_IN_POS` at `0x43C07054` (RW, 32 bits, reset `0x0`): Channel 6, multi-turn position, written by the PS every control period: the encoder steps since the last `pos zero`, each taken the shortest way round and summed in 64 bits (models::motion::PositionEstimator), of which this is the low 32 bits (a reader unwraps it by sample differences below 2^31 counts).
    ///
    /// Format: signed 32-bit two's complement, encoder counts (range +-2^31 counts: +-524288 rev at 4096 counts/rev), wraps. Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInPos;

    impl CapInPos {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07054;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_IN_POS;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapInPosValue, BusError> {
            bus.read(Self::ADDR).map(CapInPosValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapInPosValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapInPosValue) -> CapInPosValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapInPos`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInPosValue(u32);

    impl CapInPosValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (signed 32-bit two's complement, encoder counts (range +-2^31 counts: +-524288 rev at 4096 counts/rev), wraps).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for CapInPosValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_IN_VEL` at `0x43C07058` (RW, 32 bits, reset `0x0`): Channel 7, velocity, written by the PS every control period: the estimate `status` shows (the tracking observer on the count, models::motion::PositionEstimator), rounded to nearest, saturated.
    ///
    /// Format: signed Q16.16 rev/s (32-bit two's complement, LSB 2^-16 rev/s, range -32768..+32767.99998 rev/s). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInVel;

    impl CapInVel {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07058;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_IN_VEL;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapInVelValue, BusError> {
            bus.read(Self::ADDR).map(CapInVelValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapInVelValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapInVelValue) -> CapInVelValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapInVel`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInVelValue(u32);

    impl CapInVelValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (signed Q16.16 rev/s (32-bit two's complement, LSB 2^-16 rev/s, range -32768..+32767.99998 rev/s)).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for CapInVelValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_IN_FERR` at `0x43C0705C` (RW, 16 bits, reset `0x0`): Channel 8, position reference minus position (0 in the torque loop), written by the PS every control period, rounded to nearest, saturated.
    ///
    /// Format: signed Q12.4 counts (16-bit two's complement, LSB 1/16 count, range -2048..+2047.9375 counts). Writes: every value of the implemented bits is valid; bits above the width are dropped.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInFerr;

    impl CapInFerr {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C0705C;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_IN_FERR;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapInFerrValue, BusError> {
            bus.read(Self::ADDR).map(CapInFerrValue)
        }

        /// Writes `value` (one store).
        pub fn write<B: RegisterBus + ?Sized>(
            bus: &mut B,
            value: CapInFerrValue,
        ) -> Result<(), BusError> {
            bus.write(Self::ADDR, value.0)
        }

        /// Reads, applies `f`, writes the result back (not atomic).
        pub fn modify<B: RegisterBus + ?Sized>(
            bus: &mut B,
            f: impl FnOnce(CapInFerrValue) -> CapInFerrValue,
        ) -> Result<(), BusError> {
            let v = Self::read(bus)?;
            Self::write(bus, f(v))
        }
    }

    /// A value of [`CapInFerr`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapInFerrValue(u32);

    impl CapInFerrValue {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed Q12.4 counts (16-bit two's complement, LSB 1/16 count, range -2048..+2047.9375 counts)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for CapInFerrValue {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DATA3` at `0x43C07060` (RO, 32 bits, reset `0x0`): Channel 6 (position) of sample CAP_RD_INDEX.
    ///
    /// Format: signed 32-bit two's complement, encoder counts (range +-2^31 counts: +-524288 rev at 4096 counts/rev), wraps. Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData3;

    impl CapData3 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07060;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DATA3;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapData3Value, BusError> {
            bus.read(Self::ADDR).map(CapData3Value)
        }
    }

    /// A value of [`CapData3`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData3Value(u32);

    impl CapData3Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (signed 32-bit two's complement, encoder counts (range +-2^31 counts: +-524288 rev at 4096 counts/rev), wraps).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for CapData3Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DATA4` at `0x43C07064` (RO, 32 bits, reset `0x0`): Channel 7 (velocity) of sample CAP_RD_INDEX.
    ///
    /// Format: signed Q16.16 rev/s (32-bit two's complement, LSB 2^-16 rev/s, range -32768..+32767.99998 rev/s). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData4;

    impl CapData4 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07064;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DATA4;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapData4Value, BusError> {
            bus.read(Self::ADDR).map(CapData4Value)
        }
    }

    /// A value of [`CapData4`]; bits above bit 31 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData4Value(u32);

    impl CapData4Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 31:0, 32 bits): The whole register (signed Q16.16 rev/s (32-bit two's complement, LSB 2^-16 rev/s, range -32768..+32767.99998 rev/s)).
        pub const fn value(self) -> u32 {
            self.0
        }

        /// Sets `VALUE` (bits 31:0, 32 bits).
        pub const fn with_value(self, v: u32) -> Self {
            Self(v)
        }
    }

    impl Default for CapData4Value {
        fn default() -> Self {
            Self::RESET
        }
    }

    /// `CAPTURE.CAP_DATA5` at `0x43C07068` (RO, 16 bits, reset `0x0`): Channel 8 (following error) of sample CAP_RD_INDEX.
    ///
    /// Format: signed Q12.4 counts (16-bit two's complement, LSB 1/16 count, range -2048..+2047.9375 counts). Writes: read-only: a write answers SLVERR and sets `ERR.BAD_ADDR`.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData5;

    impl CapData5 {
        /// Absolute byte address.
        pub const ADDR: usize = 0x43C07068;
        /// The table entry.
        pub const DEF: &'static Register = &regmap::CAP_DATA5;

        /// Reads the register.
        pub fn read<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<CapData5Value, BusError> {
            bus.read(Self::ADDR).map(CapData5Value)
        }
    }

    /// A value of [`CapData5`]; bits above bit 15 are 0 when read.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct CapData5Value(u32);

    impl CapData5Value {
        /// The value after reset.
        pub const RESET: Self = Self(0x0);
        /// All zeros.
        pub const ZERO: Self = Self(0);

        /// From the raw 32-bit word.
        pub const fn from_bits(bits: u32) -> Self {
            Self(bits)
        }

        /// The raw 32-bit word.
        pub const fn bits(self) -> u32 {
            self.0
        }

        /// `VALUE` (bits 15:0, 16 bits): The whole register (signed Q12.4 counts (16-bit two's complement, LSB 1/16 count, range -2048..+2047.9375 counts)).
        pub const fn value(self) -> u32 {
            self.0 & 0xFFFF
        }

        /// Sets `VALUE` (bits 15:0, 16 bits) to the low 16 bits of `v` (higher bits are dropped).
        pub const fn with_value(self, v: u32) -> Self {
            Self((self.0 & !0xFFFF) | (v & 0xFFFF))
        }

        /// `VALUE` as a two's-complement number: bit 15 sign-extended.
        pub const fn value_i32(self) -> i32 {
            ((self.0 << 16) as i32) >> 16
        }

        /// Sets `VALUE` to `v` in two's complement, its low 16 bits (higher bits are dropped).
        pub const fn with_value_i32(self, v: i32) -> Self {
            Self((self.0 & !0xFFFF) | (v as u32 & 0xFFFF))
        }
    }

    impl Default for CapData5Value {
        fn default() -> Self {
            Self::RESET
        }
    }
}
