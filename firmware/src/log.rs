//! `defmt` global logger on UART0, rzcobs-framed (decode with `drivectl log`).
//!
//! A frame is encoded into a RAM ring (`drive::logring`) with the
//! interrupts masked, which takes microseconds; the periodic tick and the
//! console's idle loop move it to UART0 as far as the TX FIFO has room,
//! never waiting for the line (115200 baud: 86.8 us a byte). A frame that
//! does not fit is dropped whole and counted (`status`: `log:`).
use crate::ps::{timer, uart::Uart};
use core::sync::atomic::{AtomicBool, Ordering};
use drive::logring::LogRing;

static UART0: Uart = unsafe { Uart::new(crate::ps::uart::UART0_BASE) };
static TAKEN: AtomicBool = AtomicBool::new(false);
/// Whether IRQs were enabled when the logger was acquired.
static IRQ_WAS_ON: AtomicBool = AtomicBool::new(false);
static mut ENCODER: defmt::Encoder = defmt::Encoder::new();
/// Bytes of the ring: about 0.36 s of the line at 115200 baud.
pub const RING_BYTES: usize = 4096;
/// Touched only with the interrupts masked (one core): the logger between
/// acquire and release, `drain` and `dropped` inside `irq::free`.
static mut RING: LogRing<RING_BYTES> = LogRing::new();

defmt::timestamp!("{=u64:us}", timer::uptime_us());

fn ring() -> &'static mut LogRing<RING_BYTES> {
    // SAFETY: callers hold the interrupts masked (see `RING`), and none
    // keeps the reference past its own masked section.
    unsafe { &mut *core::ptr::addr_of_mut!(RING) }
}

fn write(bytes: &[u8]) {
    ring().push(bytes);
}

#[defmt::global_logger]
struct Logger;

// SAFETY: acquire/release bracket every frame with IRQs masked (one core), so
// the encoder and the ring are never used re-entrantly; a nested acquire
// panics.
unsafe impl defmt::Logger for Logger {
    fn acquire() {
        let was_on = crate::irq::enabled();
        cortex_ar::interrupt::disable();
        if TAKEN.swap(true, Ordering::Acquire) {
            panic!("defmt logger taken re-entrantly");
        }
        IRQ_WAS_ON.store(was_on, Ordering::Relaxed);
        ring().begin_frame();
        // SAFETY: exclusive access, see above.
        unsafe { (*core::ptr::addr_of_mut!(ENCODER)).start_frame(write) };
    }

    unsafe fn flush() {}

    unsafe fn release() {
        // SAFETY: exclusive access until TAKEN is cleared.
        unsafe { (*core::ptr::addr_of_mut!(ENCODER)).end_frame(write) };
        ring().end_frame();
        TAKEN.store(false, Ordering::Release);
        if IRQ_WAS_ON.load(Ordering::Relaxed) {
            // SAFETY: restoring the state found at acquire.
            unsafe { cortex_ar::interrupt::enable() };
        }
    }

    unsafe fn write(bytes: &[u8]) {
        // SAFETY: only called between acquire and release.
        unsafe { (*core::ptr::addr_of_mut!(ENCODER)).write(bytes, write) };
    }
}

/// Brings up UART0 as the log channel (no receive interrupt).
pub fn init(div: drive::zynq::UartDivisors) {
    UART0.init(div, false);
}

/// Moves waiting log bytes into UART0's TX FIFO while it has room (at most
/// its 64 bytes: a short masked section, no waiting on the line).
pub fn drain() {
    crate::irq::free(|| {
        if !TAKEN.load(Ordering::Acquire) {
            ring().drain(|b| UART0.try_write_byte(b));
        }
    });
}

/// Everything still in the ring, waiting on the line (the panic and abort
/// reports: the gates are off already, the drive halts after it).
pub fn drain_blocking() {
    crate::irq::free(|| {
        if !TAKEN.load(Ordering::Acquire) {
            ring().drain(|b| {
                UART0.write_byte(b);
                true
            });
        }
    });
}

/// Log frames dropped because the ring was full.
pub fn dropped() -> u32 {
    crate::irq::free(|| ring().dropped())
}

/// Guest instructions of encoding one `defmt` frame into the ring (what the
/// logger masks the interrupts for), the frame then taken back: for
/// `debug bench`.
pub fn bench_frame() {
    crate::irq::free(|| {
        defmt::info!(
            "console: a line of sixty characters, logged as a console line is: {=u32} {=u32}",
            123_456u32,
            789u32
        );
        ring().discard_frame();
    });
}
