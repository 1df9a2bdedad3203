//! Panic and CPU exceptions: gates off first, then the message, then halt.
use crate::{pl, ps::uart};
use core::fmt::Write;

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    cortex_ar::interrupt::disable();
    // Safe state before anything that could fail or take time.
    pl::gates_safe();
    // SAFETY: UART1's register block; the console may not be up yet.
    let mut con = unsafe { uart::Uart::new(uart::UART1_BASE) };
    con.force_tx_enable();
    let _ = write!(con, "\r\nPANIC: {}\r\n", info.message());
    if let Some(loc) = info.location() {
        let _ = write!(
            con,
            "  at {}:{}:{}\r\n",
            loc.file(),
            loc.line(),
            loc.column()
        );
    }
    let _ = write!(con, "gates: off (safe state); firmware halted\r\n");
    loop {
        // SAFETY: wait for an interrupt, which stays masked: a low-power halt.
        unsafe { core::arch::asm!("wfi", options(nomem, nostack)) };
    }
}

#[cortex_a_rt::exception(Undefined)]
fn undefined(addr: usize) -> ! {
    panic!("undefined instruction at {addr:#010x}");
}

#[cortex_a_rt::exception(PrefetchAbort)]
fn prefetch_abort(addr: usize) -> ! {
    panic!("prefetch abort at {addr:#010x}");
}

#[cortex_a_rt::exception(DataAbort)]
fn data_abort(addr: usize) -> ! {
    panic!("data abort at {addr:#010x}");
}
