//! `defmt` global logger on UART0, rzcobs-framed (decode with `drivectl log`).
use crate::ps::{timer, uart::Uart};
use core::sync::atomic::{AtomicBool, Ordering};

static UART0: Uart = unsafe { Uart::new(crate::ps::uart::UART0_BASE) };
static TAKEN: AtomicBool = AtomicBool::new(false);
/// Whether IRQs were enabled when the logger was acquired.
static IRQ_WAS_ON: AtomicBool = AtomicBool::new(false);
static mut ENCODER: defmt::Encoder = defmt::Encoder::new();

defmt::timestamp!("{=u64:us}", timer::uptime_us());

fn write(bytes: &[u8]) {
    UART0.write_bytes(bytes);
}

#[defmt::global_logger]
struct Logger;

// SAFETY: acquire/release bracket every frame with IRQs masked (one core), so
// the encoder is never used re-entrantly; a nested acquire panics.
unsafe impl defmt::Logger for Logger {
    fn acquire() {
        let was_on = crate::irq::enabled();
        cortex_ar::interrupt::disable();
        if TAKEN.swap(true, Ordering::Acquire) {
            panic!("defmt logger taken re-entrantly");
        }
        IRQ_WAS_ON.store(was_on, Ordering::Relaxed);
        // SAFETY: exclusive access, see above.
        unsafe { (*core::ptr::addr_of_mut!(ENCODER)).start_frame(write) };
    }

    unsafe fn flush() {}

    unsafe fn release() {
        // SAFETY: exclusive access until TAKEN is cleared.
        unsafe { (*core::ptr::addr_of_mut!(ENCODER)).end_frame(write) };
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
