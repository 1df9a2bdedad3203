//! GEM0, the first Gigabit Ethernet MAC (UG585 ch. 16), polled, as a
//! smoltcp `phy::Device`. The ring bookkeeping and register fields are
//! `drive::gem`'s; this module owns the memory and the register accesses.
//!
//! Memory: the descriptor rings and frame buffers are one static in the
//! `.dma` output section (memory.x), the MiB the MMU maps normal
//! non-cacheable (`drive::mmu::DMA_BASE`), in L1 and L2 alike, so the
//! controller and the CPU see each other's writes without cache
//! maintenance. Normal memory is still weakly ordered: a DMB orders the
//! descriptor's ownership read before the buffer's, and the buffer's
//! writes before the descriptor's hand-over; a DSB completes them before
//! the register write that starts the transmitter.
//!
//! The clocks (GEM0_CLK_CTRL, GEM0_RCLK_CTRL) and MIO pins are the FSBL's
//! (from the board's PS configuration); the PHY's autonegotiation is not
//! read: NWCFG says 100 Mb/s full duplex.
use drive::gem::{self, reg, Descriptors, Received, RxRing, TxRing, BUF_BYTES};
use smoltcp::phy::{self, DeviceCapabilities, Medium};
use smoltcp::time::Instant;

/// Receive descriptors (8 frames of backlog).
const RX_COUNT: usize = 8;
/// Transmit descriptors.
const TX_COUNT: usize = 4;

#[repr(C, align(64))]
struct Ring<const N: usize>([[u32; 2]; N]);

#[repr(C, align(64))]
struct Buffers<const N: usize>([[u8; BUF_BYTES]; N]);

#[repr(C)]
struct Dma {
    rx_desc: Ring<RX_COUNT>,
    tx_desc: Ring<TX_COUNT>,
    rx_buf: Buffers<RX_COUNT>,
    tx_buf: Buffers<TX_COUNT>,
}

/// The controller's memory. Not zeroed at start-up (NOLOAD): `Gem::init`
/// writes every descriptor before enabling the controller.
#[link_section = ".dma"]
static mut DMA: core::mem::MaybeUninit<Dma> = core::mem::MaybeUninit::uninit();

/// A descriptor ring in DMA memory, read and written volatile (the
/// controller changes it behind the compiler's back).
struct DescRing {
    base: *mut [u32; 2],
    count: usize,
}

impl Descriptors for DescRing {
    fn count(&self) -> usize {
        self.count
    }
    fn load(&self, i: usize, word: usize) -> u32 {
        debug_assert!(i < self.count && word < 2);
        // SAFETY: `base` points at `count` descriptors in `DMA`.
        unsafe { (self.base.add(i) as *const u32).add(word).read_volatile() }
    }
    fn store(&mut self, i: usize, word: usize, value: u32) {
        debug_assert!(i < self.count && word < 2);
        // SAFETY: as in `load`.
        unsafe {
            (self.base.add(i) as *mut u32)
                .add(word)
                .write_volatile(value)
        }
    }
}

fn regs_write(offset: usize, value: u32) {
    // SAFETY: a GEM0 register (offsets of `drive::gem::reg`); device memory.
    unsafe { ((gem::GEM0_BASE + offset) as *mut u32).write_volatile(value) }
}

fn dmb() {
    // SAFETY: barrier only.
    unsafe { core::arch::asm!("dmb", options(nostack, preserves_flags)) };
}

fn dsb() {
    // SAFETY: barrier only.
    unsafe { core::arch::asm!("dsb", options(nostack, preserves_flags)) };
}

/// NWCTRL while running: receiver, transmitter and MDIO on.
const NWCTRL_RUN: u32 = gem::NWCTRL_RX_EN | gem::NWCTRL_TX_EN | gem::NWCTRL_MDIO_EN;

struct RxSide {
    ring: RxRing,
    desc: DescRing,
    bufs: *const [u8; BUF_BYTES],
    /// Frames given back unread (not whole).
    bad: u32,
}

struct TxSide {
    ring: TxRing,
    desc: DescRing,
    bufs: *mut [u8; BUF_BYTES],
}

impl RxSide {
    /// Gives the current descriptor back and tells the controller: a
    /// write of NWCTRL with RX_EN makes QEMU's model re-read the ring and
    /// deliver what it queued while the ring was full; on the silicon the
    /// receiver reads the descriptor on the next frame anyway.
    fn release(&mut self) {
        self.ring.release(&mut self.desc);
        dsb();
        regs_write(reg::NWCTRL, NWCTRL_RUN);
    }
}

/// GEM0, running.
pub struct Gem {
    rx: RxSide,
    tx: TxSide,
}

impl Gem {
    /// Resets and starts GEM0 with station address `mac`. Call once (it
    /// takes the DMA memory).
    pub fn init(mac: [u8; 6]) -> Self {
        // SAFETY: called once (`net::init`); nothing else names `DMA`.
        let dma = unsafe { &mut *core::ptr::addr_of_mut!(DMA) }.as_mut_ptr();
        // SAFETY: field projections of the static, no reference created.
        let (rx_desc, tx_desc, rx_buf, tx_buf) = unsafe {
            (
                core::ptr::addr_of_mut!((*dma).rx_desc.0) as *mut [u32; 2],
                core::ptr::addr_of_mut!((*dma).tx_desc.0) as *mut [u32; 2],
                core::ptr::addr_of_mut!((*dma).rx_buf.0) as *mut [u8; BUF_BYTES],
                core::ptr::addr_of_mut!((*dma).tx_buf.0) as *mut [u8; BUF_BYTES],
            )
        };
        // Stopped, statistics cleared, interrupts off and acknowledged
        // (polled), status bits cleared.
        regs_write(reg::NWCTRL, gem::NWCTRL_CLEAR_STATS);
        regs_write(reg::IDR, 0x07FF_FFFF);
        regs_write(reg::ISR, 0x07FF_FFFF);
        regs_write(reg::TXSTATUS, 0xFF);
        regs_write(reg::RXSTATUS, 0x0F);
        let mut rxd = DescRing {
            base: rx_desc,
            count: RX_COUNT,
        };
        let mut txd = DescRing {
            base: tx_desc,
            count: TX_COUNT,
        };
        let rx_addr = |i: usize| (rx_buf as usize + i * BUF_BYTES) as u32;
        let tx_addr = |i: usize| (tx_buf as usize + i * BUF_BYTES) as u32;
        let rx_ring = RxRing::init(&mut rxd, rx_addr);
        let tx_ring = TxRing::init(&mut txd, tx_addr);
        dsb();
        let (lo, hi) = gem::mac_registers(mac);
        regs_write(reg::NWCFG, gem::NWCFG_VALUE);
        // BUF_BYTES is a multiple of 64 below 255 * 64 (a drive::gem test).
        regs_write(reg::DMACFG, gem::dmacfg(BUF_BYTES).unwrap_or(0));
        regs_write(reg::RXQBASE, rx_desc as u32);
        regs_write(reg::TXQBASE, tx_desc as u32);
        // Bottom first: writing the top enables the address filter entry.
        regs_write(reg::SPADDR1_BOT, lo);
        regs_write(reg::SPADDR1_TOP, hi);
        regs_write(reg::NWCTRL, NWCTRL_RUN);
        Self {
            rx: RxSide {
                ring: rx_ring,
                desc: rxd,
                bufs: rx_buf,
                bad: 0,
            },
            tx: TxSide {
                ring: tx_ring,
                desc: txd,
                bufs: tx_buf,
            },
        }
    }

    /// The next whole received frame: its descriptor index and length,
    /// bytes; buffers that do not hold a whole frame are given back.
    fn next_rx(&mut self) -> Option<(usize, usize)> {
        loop {
            match self.rx.ring.peek(&self.rx.desc)? {
                Received::Frame { index, len } => {
                    // The buffer's reads after the ownership bit's.
                    dmb();
                    return Some((index, len));
                }
                Received::Bad { index } => {
                    self.rx.bad = self.rx.bad.wrapping_add(1);
                    defmt::warn!(
                        "gem: receive descriptor {=usize} without a whole frame ({=u32} so far)",
                        index,
                        self.rx.bad
                    );
                    self.rx.release();
                }
            }
        }
    }
}

/// A received frame, handed to smoltcp.
pub struct RxToken<'a> {
    side: &'a mut RxSide,
    index: usize,
    len: usize,
}

/// Room for one frame to send.
pub struct TxToken<'a> {
    side: &'a mut TxSide,
}

impl phy::RxToken for RxToken<'_> {
    fn consume<R, F>(self, f: F) -> R
    where
        F: FnOnce(&[u8]) -> R,
    {
        // SAFETY: the controller filled buffer `index` (ownership bit set,
        // ordered by `next_rx`'s DMB) and does not touch it until
        // `release`; `len` is at most BUF_BYTES (`RxRing::peek`).
        let frame = unsafe {
            core::slice::from_raw_parts(self.side.bufs.add(self.index) as *const u8, self.len)
        };
        let r = f(frame);
        self.side.release();
        r
    }
}

impl phy::TxToken for TxToken<'_> {
    fn consume<R, F>(self, len: usize, f: F) -> R
    where
        F: FnOnce(&mut [u8]) -> R,
    {
        let side = self.side;
        let len = len.min(gem::MAX_FRAME);
        // `Gem::transmit`/`receive` only hand out a token when a
        // descriptor is free; were none free, the frame is built and lost.
        let Some(index) = side.ring.free(&side.desc) else {
            let mut scratch = [0u8; gem::MAX_FRAME];
            return f(&mut scratch[..len]);
        };
        // SAFETY: descriptor `index` is software's (used bit set), so is
        // its buffer; `len` is at most BUF_BYTES.
        let buf = unsafe { core::slice::from_raw_parts_mut(side.bufs.add(index) as *mut u8, len) };
        let r = f(buf);
        // The frame's bytes before the descriptor's hand-over, and both
        // before the start command.
        dmb();
        if side.ring.submit(&mut side.desc, len).is_ok() {
            dsb();
            regs_write(reg::NWCTRL, NWCTRL_RUN | gem::NWCTRL_TX_START);
        }
        r
    }
}

impl phy::Device for Gem {
    type RxToken<'a> = RxToken<'a>;
    type TxToken<'a> = TxToken<'a>;

    fn receive(&mut self, _timestamp: Instant) -> Option<(Self::RxToken<'_>, Self::TxToken<'_>)> {
        // An answer needs a free transmit descriptor: without one the
        // frame waits in the ring.
        self.tx.ring.free(&self.tx.desc)?;
        let (index, len) = self.next_rx()?;
        Some((
            RxToken {
                side: &mut self.rx,
                index,
                len,
            },
            TxToken { side: &mut self.tx },
        ))
    }

    fn transmit(&mut self, _timestamp: Instant) -> Option<Self::TxToken<'_>> {
        self.tx.ring.free(&self.tx.desc)?;
        Some(TxToken { side: &mut self.tx })
    }

    fn capabilities(&self) -> DeviceCapabilities {
        let mut caps = DeviceCapabilities::default();
        caps.medium = Medium::Ethernet;
        // Ethernet payload 1500 plus the 14-byte header (smoltcp counts
        // the header in the MTU for Ethernet).
        caps.max_transmission_unit = gem::MAX_FRAME;
        caps.max_burst_size = Some(TX_COUNT);
        caps
    }
}
