//! Panic and CPU exceptions: gates off first, then the report, then halt.
//!
//! The aborts (data, prefetch) and the undefined instruction halt, they do
//! not recover: the interrupted code's state is unknown (an asynchronous
//! external abort, e.g. a bus error on a GP0 store, is reported
//! instructions after the store that caused it), and the drive must not
//! carry on with gates it may no longer control. The report names the
//! instruction's address and the fault status and address registers
//! (DFSR/DFAR for a data abort, IFSR/IFAR for a prefetch abort); the
//! gates are turned off before anything else (`pl::gates_safe`, safe
//! before detection too). Power-cycle or reset to restart.
use crate::{pl, ps::uart};
use core::fmt::Write;
use drive::zynq::{fault_status_name, fault_was_write};

/// The console UART, whatever state it is in.
fn console() -> uart::Uart {
    // SAFETY: UART1's register block; the console may not be up yet.
    let con = unsafe { uart::Uart::new(uart::UART1_BASE) };
    con.force_tx_enable();
    con
}

fn halt(con: &mut uart::Uart) -> ! {
    // The log frames still in the RAM ring (gates already off).
    crate::log::drain_blocking();
    match crate::control::gates_off_read_back() {
        Some(on) => {
            let _ = write!(con, "gate_en: {} (read back)\r\n", u8::from(on));
        }
        None => {
            let _ = write!(con, "gate_en: not read back (drive busy or absent)\r\n");
        }
    }
    let _ = write!(con, "gates: off (safe state); firmware halted\r\n");
    loop {
        // SAFETY: wait for an interrupt, which stays masked: a low-power halt.
        unsafe { core::arch::asm!("wfi", options(nomem, nostack)) };
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    cortex_ar::interrupt::disable();
    // Safe state before anything that could fail or take time.
    pl::gates_safe();
    let mut con = console();
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
    halt(&mut con)
}

/// CP15 fault registers: DFSR, DFAR, IFSR, IFAR.
fn fault_registers() -> [u32; 4] {
    let (dfsr, dfar, ifsr, ifar): (u32, u32, u32, u32);
    // SAFETY: reading the fault status and address registers has no effect.
    unsafe {
        core::arch::asm!(
            "mrc p15, 0, {0}, c5, c0, 0",
            "mrc p15, 0, {1}, c6, c0, 0",
            "mrc p15, 0, {2}, c5, c0, 1",
            "mrc p15, 0, {3}, c6, c0, 2",
            out(reg) dfsr,
            out(reg) dfar,
            out(reg) ifsr,
            out(reg) ifar,
            options(nomem, nostack)
        );
    }
    [dfsr, dfar, ifsr, ifar]
}

/// The common start of every exception report: IRQs masked, gates off.
fn exception_entry() -> uart::Uart {
    cortex_ar::interrupt::disable();
    pl::gates_safe();
    console()
}

#[cortex_a_rt::exception(Undefined)]
fn undefined(addr: usize) -> ! {
    let mut con = exception_entry();
    let _ = write!(con, "\r\nUNDEFINED INSTRUCTION at 0x{addr:08x}\r\n");
    halt(&mut con)
}

#[cortex_a_rt::exception(PrefetchAbort)]
fn prefetch_abort(addr: usize) -> ! {
    let mut con = exception_entry();
    let [_, _, ifsr, ifar] = fault_registers();
    let _ = write!(
        con,
        "\r\nPREFETCH ABORT at 0x{addr:08x}: IFSR 0x{ifsr:08x} ({}), IFAR 0x{ifar:08x}\r\n",
        fault_status_name(ifsr)
    );
    halt(&mut con)
}

/// A bus error during the boot's GP0 probe (`pl::boot_probe`) resumes (a
/// configured PL that is not ours: `pl: absent`); every other data abort
/// halts with the gates off.
#[cortex_a_rt::exception(DataAbort)]
unsafe fn data_abort(addr: usize) -> usize {
    let [dfsr, dfar, ..] = fault_registers();
    if let Some(resume) = drive::zynq::probe_resume(pl::probing(), dfsr, addr) {
        pl::note_probe_fault();
        return resume;
    }
    let mut con = exception_entry();
    let _ = write!(
        con,
        "\r\nDATA ABORT at 0x{addr:08x}: DFSR 0x{dfsr:08x} ({}, {}), DFAR 0x{dfar:08x}\r\n",
        fault_status_name(dfsr),
        if fault_was_write(dfsr) {
            "write"
        } else {
            "read"
        },
    );
    halt(&mut con)
}
