//! The Zynq-7000's Gigabit Ethernet MAC (Cadence GEM, UG585 ch. 16,
//! register reference in appendix B "gem"): register offsets and field
//! encodings, and the bookkeeping of its receive and transmit descriptor
//! rings. The firmware's driver (`firmware/src/ps/gem.rs`) only moves
//! these words to and from the hardware.
//!
//! Descriptors are two 32-bit words (UG585 16.3.5 / 16.3.6). Receive:
//! word 0 = buffer address (bits 31:2), wrap (bit 1), ownership (bit 0: 1
//! once the controller filled the buffer, software gives it back with 0);
//! word 1 = status, the frame length in bits 12:0 with start (bit 14) and
//! end (bit 15) of frame. Transmit: word 0 = buffer address; word 1 =
//! used (bit 31: 1 = software's, the controller sets it after sending),
//! wrap (bit 30), last buffer of the frame (bit 15), length (bits 13:0).
//! The controller walks each ring from its queue base, returns to the
//! base after the descriptor with the wrap bit, and stops at a receive
//! descriptor it does not own or a transmit descriptor marked used.

/// GEM0's register block (UG585 table 4-1); its interrupt is SPI 54.
pub const GEM0_BASE: usize = 0xE000_B000;

/// Register offsets, bytes.
pub mod reg {
    /// Network control.
    pub const NWCTRL: usize = 0x000;
    /// Network configuration.
    pub const NWCFG: usize = 0x004;
    /// DMA configuration.
    pub const DMACFG: usize = 0x010;
    /// Transmit status (write one to clear).
    pub const TXSTATUS: usize = 0x014;
    /// Receive queue base address.
    pub const RXQBASE: usize = 0x018;
    /// Transmit queue base address.
    pub const TXQBASE: usize = 0x01C;
    /// Receive status (write one to clear).
    pub const RXSTATUS: usize = 0x020;
    /// Interrupt status (write one to clear).
    pub const ISR: usize = 0x024;
    /// Interrupt disable.
    pub const IDR: usize = 0x02C;
    /// Specific address 1, bottom (first four bytes of the MAC address).
    pub const SPADDR1_BOT: usize = 0x088;
    /// Specific address 1, top (last two bytes; writing it enables the
    /// filter entry).
    pub const SPADDR1_TOP: usize = 0x08C;
}

/// NWCTRL: receive enable.
pub const NWCTRL_RX_EN: u32 = 1 << 2;
/// NWCTRL: transmit enable.
pub const NWCTRL_TX_EN: u32 = 1 << 3;
/// NWCTRL: management port (MDIO) enable.
pub const NWCTRL_MDIO_EN: u32 = 1 << 4;
/// NWCTRL: clear the statistics registers.
pub const NWCTRL_CLEAR_STATS: u32 = 1 << 5;
/// NWCTRL: start transmission (self-clearing).
pub const NWCTRL_TX_START: u32 = 1 << 9;

/// NWCFG: 100 Mb/s (else 10 Mb/s; ignored at 1 Gb/s).
pub const NWCFG_SPEED_100: u32 = 1 << 0;
/// NWCFG: full duplex.
pub const NWCFG_FULL_DUPLEX: u32 = 1 << 1;
/// NWCFG: remove the 4-byte FCS before writing the frame to memory.
pub const NWCFG_FCS_REMOVE: u32 = 1 << 17;
/// NWCFG: MDC clock divisor field (bits 20:18); 0b011 = pclk / 48.
pub const NWCFG_MDC_DIV_48: u32 = 0b011 << 18;

/// DMACFG: AHB fixed burst length field (bits 4:0); 0b00100 = INCR4.
pub const DMACFG_BURST_INCR4: u32 = 0b00100;
/// DMACFG: receive packet buffer memory size field (bits 9:8); 0b11 =
/// the full 8 KiB.
pub const DMACFG_RX_PBUF_8K: u32 = 0b11 << 8;
/// DMACFG: transmit packet buffer memory size (bit 10): the full 4 KiB.
pub const DMACFG_TX_PBUF_4K: u32 = 1 << 10;
/// DMACFG: receive buffer size field position (bits 23:16, in 64-byte
/// units).
const DMACFG_RX_BUF_SHIFT: u32 = 16;
/// Unit of DMACFG's receive buffer size, bytes.
pub const RX_BUF_UNIT: usize = 64;

/// Receive descriptor word 0: ownership (1 = filled by the controller).
pub const RX_W0_OWNED_BY_SW: u32 = 1 << 0;
/// Receive descriptor word 0: last descriptor of the ring.
pub const RX_W0_WRAP: u32 = 1 << 1;
/// Receive descriptor word 1: frame length mask (bits 12:0), bytes.
pub const RX_W1_LEN_MASK: u32 = 0x1FFF;
/// Receive descriptor word 1: start of frame.
pub const RX_W1_SOF: u32 = 1 << 14;
/// Receive descriptor word 1: end of frame.
pub const RX_W1_EOF: u32 = 1 << 15;

/// Transmit descriptor word 1: used (1 = software's).
pub const TX_W1_USED: u32 = 1 << 31;
/// Transmit descriptor word 1: last descriptor of the ring.
pub const TX_W1_WRAP: u32 = 1 << 30;
/// Transmit descriptor word 1: last buffer of the frame.
pub const TX_W1_LAST: u32 = 1 << 15;
/// Transmit descriptor word 1: length mask (bits 13:0), bytes.
pub const TX_W1_LEN_MASK: u32 = 0x3FFF;

/// Longest Ethernet frame without FCS and VLAN tag, bytes (the MAC's
/// default limit of 1518 with FCS, NWCFG bit 8 clear).
pub const MAX_FRAME: usize = 1514;
/// Size of each frame buffer, bytes: one whole frame, a multiple of
/// [`RX_BUF_UNIT`] (so one frame never spans two receive descriptors) and
/// of the A9's 32-byte cache line.
pub const BUF_BYTES: usize = 1536;

/// NWCFG for a full-duplex 100 Mb/s link, FCS removed, broadcast and
/// the specific address accepted (BCAST_REJ, bit 5, clear); MDC from the
/// 111 MHz CPU_1X clock / 48 = 2.3 MHz (at most 2.5 MHz); the data bus
/// width field (bits 22:21) at its reset value 0b00, the 32-bit AHB of the
/// Zynq-7000's GEM.
pub const NWCFG_VALUE: u32 =
    NWCFG_SPEED_100 | NWCFG_FULL_DUPLEX | NWCFG_FCS_REMOVE | NWCFG_MDC_DIV_48;

/// DMACFG for receive buffers of `buf_bytes` bytes; `None` unless a
/// non-zero multiple of 64 bytes up to 255 * 64.
pub fn dmacfg(buf_bytes: usize) -> Option<u32> {
    if buf_bytes == 0 || buf_bytes % RX_BUF_UNIT != 0 || buf_bytes / RX_BUF_UNIT > 0xFF {
        return None;
    }
    let units = (buf_bytes / RX_BUF_UNIT) as u32;
    Some(
        (units << DMACFG_RX_BUF_SHIFT) | DMACFG_TX_PBUF_4K | DMACFG_RX_PBUF_8K | DMACFG_BURST_INCR4,
    )
}

/// SPADDR1 bottom and top for `mac` (first byte in the lowest bits).
pub fn mac_registers(mac: [u8; 6]) -> (u32, u32) {
    (
        u32::from_le_bytes([mac[0], mac[1], mac[2], mac[3]]),
        u32::from(u16::from_le_bytes([mac[4], mac[5]])),
    )
}

/// Access to a ring of two-word descriptors. The firmware implements it
/// with volatile accesses to the DMA memory, the tests with an array.
pub trait Descriptors {
    /// Number of descriptors.
    fn count(&self) -> usize;
    /// Word `word` (0 or 1) of descriptor `i`.
    fn load(&self, i: usize, word: usize) -> u32;
    /// Stores word `word` (0 or 1) of descriptor `i`.
    fn store(&mut self, i: usize, word: usize, value: u32);
}

/// A filled receive descriptor.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Received {
    /// A whole frame of `len` bytes in descriptor `index`'s buffer.
    Frame { index: usize, len: usize },
    /// A buffer that does not hold a whole frame (no start or end mark,
    /// or a length above the buffer): to be given back unread.
    Bad { index: usize },
}

/// The receive ring's software position.
#[derive(Clone, Copy, Debug, Default)]
pub struct RxRing {
    next: usize,
}

impl RxRing {
    /// Gives every descriptor to the controller, buffer `i` at
    /// `buf_addr(i)` (4-byte aligned), wrap on the last; the controller
    /// starts at descriptor 0.
    pub fn init<D: Descriptors>(d: &mut D, buf_addr: impl Fn(usize) -> u32) -> Self {
        let n = d.count();
        for i in 0..n {
            d.store(i, 1, 0);
            d.store(i, 0, rx_word0(buf_addr(i), i + 1 == n));
        }
        Self { next: 0 }
    }

    /// Index of the next descriptor software reads.
    pub fn next(&self) -> usize {
        self.next
    }

    /// The descriptor at the software position, if the controller filled
    /// it.
    pub fn peek<D: Descriptors>(&self, d: &D) -> Option<Received> {
        let index = self.next;
        if d.load(index, 0) & RX_W0_OWNED_BY_SW == 0 {
            return None;
        }
        let w1 = d.load(index, 1);
        let len = (w1 & RX_W1_LEN_MASK) as usize;
        let whole = w1 & (RX_W1_SOF | RX_W1_EOF) == RX_W1_SOF | RX_W1_EOF;
        Some(if whole && len > 0 && len <= BUF_BYTES {
            Received::Frame { index, len }
        } else {
            Received::Bad { index }
        })
    }

    /// Gives the descriptor at the software position back to the
    /// controller (its buffer address and wrap bit kept) and moves on.
    pub fn release<D: Descriptors>(&mut self, d: &mut D) {
        let i = self.next;
        let w0 = d.load(i, 0) & !RX_W0_OWNED_BY_SW;
        d.store(i, 1, 0);
        d.store(i, 0, w0);
        self.next = (i + 1) % d.count();
    }
}

/// Receive descriptor word 0 for a buffer at `addr`, owned by the
/// controller.
pub fn rx_word0(addr: u32, wrap: bool) -> u32 {
    (addr & !0b11) | if wrap { RX_W0_WRAP } else { 0 }
}

/// Why a frame was not queued for transmission.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TxError {
    /// The next descriptor is still the controller's.
    Busy,
    /// Empty or longer than [`MAX_FRAME`].
    Length,
}

/// The transmit ring's software position.
#[derive(Clone, Copy, Debug, Default)]
pub struct TxRing {
    next: usize,
}

impl TxRing {
    /// Marks every descriptor used (software's), buffer `i` at
    /// `buf_addr(i)`, wrap on the last: the controller sends nothing.
    pub fn init<D: Descriptors>(d: &mut D, buf_addr: impl Fn(usize) -> u32) -> Self {
        let n = d.count();
        for i in 0..n {
            d.store(i, 0, buf_addr(i));
            d.store(i, 1, tx_word1(0, i + 1 == n, false));
        }
        Self { next: 0 }
    }

    /// The descriptor whose buffer the next frame goes into, if the
    /// controller is done with it.
    pub fn free<D: Descriptors>(&self, d: &D) -> Option<usize> {
        (d.load(self.next, 1) & TX_W1_USED != 0).then_some(self.next)
    }

    /// Hands the descriptor at the software position, its buffer holding
    /// `len` bytes, to the controller and moves on; the caller then sets
    /// NWCTRL's start bit.
    pub fn submit<D: Descriptors>(&mut self, d: &mut D, len: usize) -> Result<usize, TxError> {
        if len == 0 || len > MAX_FRAME {
            return Err(TxError::Length);
        }
        let i = self.free(d).ok_or(TxError::Busy)?;
        let n = d.count();
        d.store(i, 1, tx_word1(len as u32, i + 1 == n, true));
        self.next = (i + 1) % n;
        Ok(i)
    }
}

/// Transmit descriptor word 1: a one-buffer frame of `len` bytes handed
/// to the controller (`ready`), or kept by software.
pub fn tx_word1(len: u32, wrap: bool, ready: bool) -> u32 {
    (len & TX_W1_LEN_MASK)
        | TX_W1_LAST
        | if wrap { TX_W1_WRAP } else { 0 }
        | if ready { 0 } else { TX_W1_USED }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ring in plain memory; `hw_*` play the controller's part.
    struct Ring<const N: usize>([[u32; 2]; N]);

    impl<const N: usize> Descriptors for Ring<N> {
        fn count(&self) -> usize {
            N
        }
        fn load(&self, i: usize, word: usize) -> u32 {
            self.0[i][word]
        }
        fn store(&mut self, i: usize, word: usize, value: u32) {
            self.0[i][word] = value;
        }
    }

    impl<const N: usize> Ring<N> {
        /// The controller writes a frame into descriptor `i`.
        fn hw_receive(&mut self, i: usize, w1: u32) {
            self.0[i][0] |= 1;
            self.0[i][1] = w1;
        }
        /// The controller sent descriptor `i`'s frame.
        fn hw_sent(&mut self, i: usize) {
            self.0[i][1] |= 1 << 31;
        }
    }

    const BUF0: u32 = 0x0200_1000;
    fn addr(i: usize) -> u32 {
        BUF0 + i as u32 * 1536
    }

    #[test]
    fn register_fields_by_hand() {
        // NWCFG: bits 0, 1, 17, MDC 0b011 at 18, bus width 0b00 at 21.
        assert_eq!(NWCFG_VALUE, 0x000E_0003);
        // 1536 bytes = 24 units = 0x18 at bit 16; TX pbuf bit 10; RX pbuf
        // 0b11 at 8; burst 4.
        assert_eq!(dmacfg(1536), Some(0x0018_0704));
        assert_eq!(dmacfg(64), Some(0x0001_0704));
        assert_eq!(dmacfg(255 * 64), Some(0x00FF_0704));
        assert_eq!(dmacfg(0), None);
        assert_eq!(dmacfg(1500), None);
        assert_eq!(dmacfg(256 * 64), None);
        assert_eq!(BUF_BYTES % RX_BUF_UNIT, 0);
        assert_eq!(BUF_BYTES % 32, 0);
        // 02:00:5E:10:20:30: bottom 0x105E0002, top 0x3020.
        assert_eq!(
            mac_registers([0x02, 0x00, 0x5E, 0x10, 0x20, 0x30]),
            (0x105E_0002, 0x0000_3020)
        );
        assert_eq!(NWCTRL_TX_START, 0x200);
        assert_eq!(NWCTRL_RX_EN | NWCTRL_TX_EN, 0x0C);
    }

    #[test]
    fn rx_ring_is_given_to_the_controller_with_wrap_on_the_last() {
        let mut r = Ring([[0xFFFF_FFFF; 2]; 4]);
        let rx = RxRing::init(&mut r, addr);
        assert_eq!(rx.next(), 0);
        assert_eq!(r.0[0], [0x0200_1000, 0]);
        assert_eq!(r.0[1], [0x0200_1600, 0]);
        // The last: address 0x0200_1000 + 3 * 0x600 = 0x0200_2200, wrap.
        assert_eq!(r.0[3], [0x0200_2202, 0]);
        assert_eq!(rx.peek(&r), None);
    }

    #[test]
    fn rx_frames_are_read_in_ring_order_and_given_back() {
        let mut r = Ring([[0; 2]; 3]);
        let mut rx = RxRing::init(&mut r, addr);
        // A 60-byte frame in 0, a 1514-byte one in 1.
        r.hw_receive(0, RX_W1_SOF | RX_W1_EOF | 60);
        r.hw_receive(1, RX_W1_SOF | RX_W1_EOF | 1514);
        assert_eq!(rx.peek(&r), Some(Received::Frame { index: 0, len: 60 }));
        rx.release(&mut r);
        assert_eq!(r.0[0], [0x0200_1000, 0]);
        assert_eq!(
            rx.peek(&r),
            Some(Received::Frame {
                index: 1,
                len: 1514
            })
        );
        rx.release(&mut r);
        assert_eq!(rx.peek(&r), None);
        // Descriptor 2 is the last: its wrap bit survives the release and
        // the position returns to 0.
        r.hw_receive(2, RX_W1_SOF | RX_W1_EOF | 100);
        assert_eq!(rx.peek(&r), Some(Received::Frame { index: 2, len: 100 }));
        rx.release(&mut r);
        assert_eq!(r.0[2], [0x0200_1C02, 0]);
        assert_eq!(rx.next(), 0);
    }

    #[test]
    fn rx_partial_or_oversize_buffers_are_bad() {
        let mut r = Ring([[0; 2]; 2]);
        let rx = RxRing::init(&mut r, addr);
        for w1 in [
            RX_W1_SOF | 60,
            RX_W1_EOF | 60,
            RX_W1_SOF | RX_W1_EOF,
            RX_W1_SOF | RX_W1_EOF | 1537,
        ] {
            r.hw_receive(0, w1);
            assert_eq!(rx.peek(&r), Some(Received::Bad { index: 0 }), "{w1:#x}");
        }
    }

    #[test]
    fn tx_ring_sends_in_order_and_waits_for_the_controller() {
        let mut r = Ring([[0; 2]; 2]);
        let mut tx = TxRing::init(&mut r, addr);
        // Used (bit 31) and last (bit 15) on both, wrap (bit 30) on 1.
        assert_eq!(r.0[0], [0x0200_1000, 0x8000_8000]);
        assert_eq!(r.0[1], [0x0200_1600, 0xC000_8000]);
        assert_eq!(tx.free(&r), Some(0));
        assert_eq!(tx.submit(&mut r, 42), Ok(0));
        // Handed over: used clear, last, 42 bytes.
        assert_eq!(r.0[0][1], 0x0000_802A);
        assert_eq!(tx.submit(&mut r, 1514), Ok(1));
        assert_eq!(r.0[1][1], 0x4000_85EA);
        // Both in flight: nothing free until the controller is done.
        assert_eq!(tx.free(&r), None);
        assert_eq!(tx.submit(&mut r, 60), Err(TxError::Busy));
        r.hw_sent(0);
        assert_eq!(tx.submit(&mut r, 60), Ok(0));
        assert_eq!(tx.submit(&mut r, 0), Err(TxError::Length));
        assert_eq!(tx.submit(&mut r, 1515), Err(TxError::Length));
    }
}
