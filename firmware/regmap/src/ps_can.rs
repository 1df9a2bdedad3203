//! The Zynq-7000 PS CAN controller's registers (Zynq-7000 SoC TRM, UG585,
//! chapter 18 "CAN Controller" and appendix B, module `can`): offsets from
//! the controller's base, bit positions and masks.
//!
//! This is not part of the PL map ([`crate::BLOCKS`]): the controller is a
//! hard PS peripheral, so nothing is generated from these constants; the
//! driver (`drive::can`) and its model (`simpl::ps_can`) share them.
//!
//! Every register is 32 bits wide. `TXFIFO_*` and `TXHPB_*` are write-only,
//! `RXFIFO_*` read-only; a message is four words (identifier, DLC, data word
//! 1, data word 2) and the write of data word 2 queues it, so every message
//! writes all four words.

/// Base address of CAN0 (UG585 appendix B, `can0`).
pub const CAN0_BASE: usize = 0xE000_8000;
/// Base address of CAN1.
pub const CAN1_BASE: usize = 0xE000_9000;

/// Messages the TX FIFO holds (UG585 ch. 18.1: 64-message deep FIFOs).
pub const TX_FIFO_DEPTH: usize = 64;
/// Messages the RX FIFO holds.
pub const RX_FIFO_DEPTH: usize = 64;
/// Acceptance filters (pairs of mask and identifier registers).
pub const FILTER_COUNT: usize = 4;

// ------------------------------------------------------------- offsets
/// Software reset register.
pub const SRR: usize = 0x00;
/// Mode select register (writable only in configuration mode).
pub const MSR: usize = 0x04;
/// Baud rate prescaler register (writable only in configuration mode).
pub const BRPR: usize = 0x08;
/// Bit timing register (writable only in configuration mode).
pub const BTR: usize = 0x0C;
/// Error counter register (read-only).
pub const ECR: usize = 0x10;
/// Error status register (write 1 to clear).
pub const ESR: usize = 0x14;
/// Status register (read-only).
pub const SR: usize = 0x18;
/// Interrupt status register (read-only; cleared through [`ICR`]).
pub const ISR: usize = 0x1C;
/// Interrupt enable register.
pub const IER: usize = 0x20;
/// Interrupt clear register (write-only).
pub const ICR: usize = 0x24;
/// Timestamp control register.
pub const TCR: usize = 0x28;
/// Watermark interrupt register.
pub const WIR: usize = 0x2C;
/// TX FIFO: identifier.
pub const TXFIFO_ID: usize = 0x30;
/// TX FIFO: data length code.
pub const TXFIFO_DLC: usize = 0x34;
/// TX FIFO: data bytes 0..=3.
pub const TXFIFO_DATA1: usize = 0x38;
/// TX FIFO: data bytes 4..=7 (its write queues the message).
pub const TXFIFO_DATA2: usize = 0x3C;
/// TX high-priority buffer: identifier.
pub const TXHPB_ID: usize = 0x40;
/// TX high-priority buffer: data length code.
pub const TXHPB_DLC: usize = 0x44;
/// TX high-priority buffer: data bytes 0..=3.
pub const TXHPB_DATA1: usize = 0x48;
/// TX high-priority buffer: data bytes 4..=7 (its write queues the message).
pub const TXHPB_DATA2: usize = 0x4C;
/// RX FIFO: identifier of the oldest message.
pub const RXFIFO_ID: usize = 0x50;
/// RX FIFO: data length code and timestamp of the oldest message.
pub const RXFIFO_DLC: usize = 0x54;
/// RX FIFO: data bytes 0..=3 of the oldest message.
pub const RXFIFO_DATA1: usize = 0x58;
/// RX FIFO: data bytes 4..=7 of the oldest message (its read removes the
/// message from the FIFO).
pub const RXFIFO_DATA2: usize = 0x5C;
/// Acceptance filter register: which filters are in use.
pub const AFR: usize = 0x60;

/// Offset of acceptance filter mask register `n` (0-based: AFMR1 is `n = 0`).
/// `None` for `n >= FILTER_COUNT`.
pub const fn afmr(n: usize) -> Option<usize> {
    if n < FILTER_COUNT {
        Some(0x64 + 8 * n)
    } else {
        None
    }
}

/// Offset of acceptance filter identifier register `n` (0-based: AFIR1 is
/// `n = 0`). `None` for `n >= FILTER_COUNT`.
pub const fn afir(n: usize) -> Option<usize> {
    if n < FILTER_COUNT {
        Some(0x68 + 8 * n)
    } else {
        None
    }
}

/// The last register's offset (AFIR4).
pub const LAST_OFFSET: usize = 0x80;

// --------------------------------------------------------------- fields
/// `SRR`: software reset (self-clearing; every register to its reset value).
pub const SRR_SRST: u32 = 1 << 0;
/// `SRR`: CAN enable (0: configuration mode).
pub const SRR_CEN: u32 = 1 << 1;

/// `MSR`: sleep mode request.
pub const MSR_SLEEP: u32 = 1 << 0;
/// `MSR`: loopback mode request.
pub const MSR_LBACK: u32 = 1 << 1;
/// `MSR`: snoop mode request (receive only, no acknowledge, no error frames).
pub const MSR_SNOOP: u32 = 1 << 2;

/// `BRPR.BRP`: the prescaler is `BRP + 1` reference-clock cycles per time
/// quantum.
pub const BRPR_BRP_MASK: u32 = 0xFF;

/// `BTR.TS1` (bits 3:0): propagation plus phase segment 1, `TS1 + 1` quanta.
pub const BTR_TS1_SHIFT: u32 = 0;
/// `BTR.TS1` mask (unshifted).
pub const BTR_TS1_MASK: u32 = 0xF;
/// `BTR.TS2` (bits 6:4): phase segment 2, `TS2 + 1` quanta.
pub const BTR_TS2_SHIFT: u32 = 4;
/// `BTR.TS2` mask (unshifted).
pub const BTR_TS2_MASK: u32 = 0x7;
/// `BTR.SJW` (bits 8:7): synchronisation jump width, `SJW + 1` quanta.
pub const BTR_SJW_SHIFT: u32 = 7;
/// `BTR.SJW` mask (unshifted).
pub const BTR_SJW_MASK: u32 = 0x3;

/// `ECR.TEC` (bits 7:0): transmit error counter.
pub const ECR_TEC_SHIFT: u32 = 0;
/// `ECR.REC` (bits 15:8): receive error counter.
pub const ECR_REC_SHIFT: u32 = 8;
/// Mask of either counter (unshifted).
pub const ECR_COUNT_MASK: u32 = 0xFF;

/// `ESR`: CRC error.
pub const ESR_CRCER: u32 = 1 << 0;
/// `ESR`: form error.
pub const ESR_FMER: u32 = 1 << 1;
/// `ESR`: stuff error.
pub const ESR_STER: u32 = 1 << 2;
/// `ESR`: bit error.
pub const ESR_BERR: u32 = 1 << 3;
/// `ESR`: acknowledge error.
pub const ESR_ACKER: u32 = 1 << 4;

/// `SR`: configuration mode.
pub const SR_CONFIG: u32 = 1 << 0;
/// `SR`: loopback mode.
pub const SR_LBACK: u32 = 1 << 1;
/// `SR`: sleep mode.
pub const SR_SLEEP: u32 = 1 << 2;
/// `SR`: normal mode.
pub const SR_NORMAL: u32 = 1 << 3;
/// `SR`: bus idle.
pub const SR_BIDLE: u32 = 1 << 4;
/// `SR`: bus busy.
pub const SR_BBSY: u32 = 1 << 5;
/// `SR`: error warning (a counter at 96 or more).
pub const SR_ERRWRN: u32 = 1 << 6;
/// `SR.ESTAT` (bits 8:7): error state, values [`ESTAT_CONFIG`] ...
pub const SR_ESTAT_SHIFT: u32 = 7;
/// `SR.ESTAT` mask (unshifted).
pub const SR_ESTAT_MASK: u32 = 0x3;
/// `SR`: the high-priority TX buffer is full.
pub const SR_TXBFLL: u32 = 1 << 9;
/// `SR`: the TX FIFO is full.
pub const SR_TXFLL: u32 = 1 << 10;
/// `SR`: acceptance filter busy (mask and identifier registers not writable).
pub const SR_ACFBSY: u32 = 1 << 11;
/// `SR`: snoop mode.
pub const SR_SNOOP: u32 = 1 << 12;

/// `SR.ESTAT`: configuration mode.
pub const ESTAT_CONFIG: u32 = 0b00;
/// `SR.ESTAT`: error active.
pub const ESTAT_ACTIVE: u32 = 0b01;
/// `SR.ESTAT`: bus off.
pub const ESTAT_BUS_OFF: u32 = 0b10;
/// `SR.ESTAT`: error passive.
pub const ESTAT_PASSIVE: u32 = 0b11;

/// `ISR`/`IER`/`ICR`: arbitration lost.
pub const IXR_ARBLST: u32 = 1 << 0;
/// Transmission succeeded.
pub const IXR_TXOK: u32 = 1 << 1;
/// TX FIFO full.
pub const IXR_TXFLL: u32 = 1 << 2;
/// TX high-priority buffer full.
pub const IXR_TXBFLL: u32 = 1 << 3;
/// A message was received.
pub const IXR_RXOK: u32 = 1 << 4;
/// RX FIFO read while empty.
pub const IXR_RXUFLW: u32 = 1 << 5;
/// RX FIFO overflow: a received message was dropped.
pub const IXR_RXOFLW: u32 = 1 << 6;
/// RX FIFO not empty.
pub const IXR_RXNEMP: u32 = 1 << 7;
/// An error was recorded in `ESR`.
pub const IXR_ERROR: u32 = 1 << 8;
/// The controller entered bus off.
pub const IXR_BSOFF: u32 = 1 << 9;
/// The controller entered sleep mode.
pub const IXR_SLP: u32 = 1 << 10;
/// The controller woke up from sleep mode.
pub const IXR_WKUP: u32 = 1 << 11;
/// RX FIFO at or above its watermark.
pub const IXR_RXFWMFLL: u32 = 1 << 12;
/// TX FIFO at or below its watermark.
pub const IXR_TXFWMEMP: u32 = 1 << 13;
/// TX FIFO empty.
pub const IXR_TXFEMP: u32 = 1 << 14;
/// Every implemented interrupt bit.
pub const IXR_ALL: u32 = (1 << 15) - 1;

/// Identifier register (`*_ID`, `AFMR`, `AFIR`): standard identifier
/// `IDH`, bits 31:21.
pub const ID_IDH_SHIFT: u32 = 21;
/// `IDH` mask (unshifted): 11 bits.
pub const ID_IDH_MASK: u32 = 0x7FF;
/// Substitute remote transmission request; for a standard frame, the RTR
/// bit (1: remote frame).
pub const ID_SRRRTR: u32 = 1 << 20;
/// Identifier extension (1: extended 29-bit identifier).
pub const ID_IDE: u32 = 1 << 19;
/// Extended identifier `IDL`, bits 18:1.
pub const ID_IDL_SHIFT: u32 = 1;
/// `IDL` mask (unshifted): 18 bits.
pub const ID_IDL_MASK: u32 = 0x3_FFFF;
/// RTR bit of an extended frame.
pub const ID_RTR: u32 = 1 << 0;

/// `*_DLC.DLC` (bits 31:28): data length code.
pub const DLC_SHIFT: u32 = 28;
/// `DLC` mask (unshifted).
pub const DLC_MASK: u32 = 0xF;
/// `RXFIFO_DLC.RXT` (bits 15:0): receive timestamp.
pub const DLC_RXT_MASK: u32 = 0xFFFF;

/// `AFR.UAFn`: filter `n` (0-based) in use. `None` for `n >= FILTER_COUNT`.
pub const fn afr_uaf(n: usize) -> Option<u32> {
    if n < FILTER_COUNT {
        Some(1 << n)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Offsets and fields typed from the TRM's appendix B tables, not from
    /// the constants above.
    #[test]
    fn offsets_and_fields_match_the_trm() {
        assert_eq!(CAN0_BASE + SR, 0xE000_8018);
        assert_eq!(CAN1_BASE + ISR, 0xE000_901C);
        assert_eq!(CAN0_BASE + TXFIFO_ID, 0xE000_8030);
        assert_eq!(RXFIFO_DATA2, 0x5C);
        assert_eq!(afmr(0), Some(0x64));
        assert_eq!(afir(0), Some(0x68));
        assert_eq!(afmr(3), Some(0x7C));
        assert_eq!(afir(3), Some(LAST_OFFSET));
        assert_eq!((afmr(4), afir(4), afr_uaf(4)), (None, None, None));
        assert_eq!(afr_uaf(3), Some(0b1000));
        // SR: ESTAT 8:7, TXBFLL 9, TXFLL 10, ACFBSY 11, SNOOP 12.
        assert_eq!(SR_ESTAT_MASK << SR_ESTAT_SHIFT, 0x180);
        assert_eq!((SR_TXBFLL, SR_TXFLL, SR_ACFBSY), (0x200, 0x400, 0x800));
        // BTR: TS1 3:0, TS2 6:4, SJW 8:7.
        assert_eq!(BTR_TS2_MASK << BTR_TS2_SHIFT, 0x70);
        assert_eq!(BTR_SJW_MASK << BTR_SJW_SHIFT, 0x180);
        // ISR: RXOFLW 6, RXNEMP 7, ERROR 8, BSOFF 9.
        assert_eq!((IXR_RXOFLW, IXR_RXNEMP), (0x40, 0x80));
        assert_eq!((IXR_ERROR, IXR_BSOFF), (0x100, 0x200));
        assert_eq!(IXR_ALL, 0x7FFF);
        // ID: IDH 31:21, SRR 20, IDE 19, IDL 18:1, RTR 0.
        assert_eq!(ID_IDH_MASK << ID_IDH_SHIFT, 0xFFE0_0000);
        assert_eq!((ID_SRRRTR, ID_IDE), (0x0010_0000, 0x0008_0000));
        assert_eq!(ID_IDL_MASK << ID_IDL_SHIFT, 0x0007_FFFE);
        assert_eq!(DLC_MASK << DLC_SHIFT, 0xF000_0000);
    }
}
