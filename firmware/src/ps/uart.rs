//! Cadence UART (UG585 ch. 19): 8N1, polled transmit, interrupt-driven receive.
use core::fmt;
use volatile_register::{RO, RW, WO};

/// Register block (offsets 0x00..0x34).
#[repr(C)]
pub struct Regs {
    pub cr: RW<u32>,
    pub mr: RW<u32>,
    pub ier: WO<u32>,
    pub idr: WO<u32>,
    pub imr: RO<u32>,
    pub isr: RW<u32>,
    pub baudgen: RW<u32>,
    pub rxtout: RW<u32>,
    pub rxwm: RW<u32>,
    pub modemcr: RW<u32>,
    pub modemsr: RW<u32>,
    pub sr: RO<u32>,
    pub fifo: RW<u32>,
    pub bauddiv: RW<u32>,
}
const _: () = assert!(core::mem::size_of::<Regs>() == 0x38);

pub const UART0_BASE: usize = 0xE000_0000;
pub const UART1_BASE: usize = 0xE000_1000;

// CR bits.
const CR_RXRST: u32 = 1 << 0;
const CR_TXRST: u32 = 1 << 1;
const CR_RXEN: u32 = 1 << 2;
const CR_TXEN: u32 = 1 << 4;
// MR: 8 data bits (CHRL = 0b00), no parity (PAR = 0b100), 1 stop bit, normal mode.
const MR_8N1: u32 = 0b100 << 3;
// SR / ISR bits.
const SR_REMPTY: u32 = 1 << 1;
const SR_TFUL: u32 = 1 << 4;
pub const ISR_RTRIG: u32 = 1 << 0;
pub const ISR_ROVR: u32 = 1 << 5;
pub const ISR_TIMEOUT: u32 = 1 << 8;

/// One UART.
#[derive(Clone, Copy)]
pub struct Uart {
    base: usize,
}

impl Uart {
    /// # Safety
    /// `base` must be the address of a Cadence UART register block.
    pub const unsafe fn new(base: usize) -> Self {
        Self { base }
    }

    fn regs(&self) -> &'static Regs {
        // SAFETY: `new` requires a valid register block; MMIO lives forever.
        unsafe { &*(self.base as *const Regs) }
    }

    /// Resets both FIFOs, sets 8N1 at the given divisors and enables TX and RX.
    /// `rx_irq`: interrupt on every received byte (and on overrun).
    pub fn init(&self, div: drive::zynq::UartDivisors, rx_irq: bool) {
        let r = self.regs();
        // SAFETY: plain register writes with documented values.
        unsafe {
            r.idr.write(0x1fff);
            r.cr.write(CR_RXRST | CR_TXRST);
            r.mr.write(MR_8N1);
            r.baudgen.write(u32::from(div.cd));
            r.bauddiv.write(u32::from(div.bdiv));
            r.rxwm.write(1);
            r.rxtout.write(10);
            r.isr.write(0x1fff);
            if rx_irq {
                r.ier.write(ISR_RTRIG | ISR_ROVR | ISR_TIMEOUT);
            }
            r.cr.write(CR_RXEN | CR_TXEN);
        }
    }

    /// Masks (`false`) or unmasks (`true`) the receive interrupts: while
    /// masked, bytes wait in the 64-byte RX FIFO (flow control towards the
    /// sender where the link has it, as QEMU's does).
    pub fn set_rx_irq(&self, on: bool) {
        let r = self.regs();
        let bits = ISR_RTRIG | ISR_ROVR | ISR_TIMEOUT;
        // SAFETY: interrupt enable/disable registers.
        unsafe {
            if on {
                r.ier.write(bits)
            } else {
                r.idr.write(bits)
            }
        };
    }

    /// Enables the transmitter whatever state the UART is in (panic path).
    pub fn force_tx_enable(&self) {
        // SAFETY: setting TXEN only.
        unsafe { self.regs().cr.modify(|v| (v & !(1 << 5)) | CR_TXEN) };
    }

    /// Blocks until the byte fits the TX FIFO.
    pub fn write_byte(&self, b: u8) {
        let r = self.regs();
        while r.sr.read() & SR_TFUL != 0 {}
        // SAFETY: writing a data byte to the FIFO.
        unsafe { r.fifo.write(u32::from(b)) };
    }

    /// Puts `b` into the TX FIFO if it has room; `false` (nothing
    /// written) when it is full.
    pub fn try_write_byte(&self, b: u8) -> bool {
        let r = self.regs();
        if r.sr.read() & SR_TFUL != 0 {
            return false;
        }
        // SAFETY: writing a data byte to the FIFO.
        unsafe { r.fifo.write(u32::from(b)) };
        true
    }

    pub fn write_bytes(&self, bytes: &[u8]) {
        for &b in bytes {
            self.write_byte(b);
        }
    }

    /// A received byte, if any.
    pub fn read_byte(&self) -> Option<u8> {
        let r = self.regs();
        if r.sr.read() & SR_REMPTY != 0 {
            None
        } else {
            Some(r.fifo.read() as u8)
        }
    }

    /// Reads and clears the interrupt status.
    pub fn take_isr(&self) -> u32 {
        let r = self.regs();
        let isr = r.isr.read();
        // SAFETY: write-one-to-clear of the bits just read.
        unsafe { r.isr.write(isr) };
        isr
    }
}

impl fmt::Write for Uart {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        self.write_bytes(s.as_bytes());
        Ok(())
    }
}
