//! IRQ masking on the one core: critical sections that restore the mask
//! they found.
//!
//! `cortex_ar::interrupt::free` (cortex-ar 0.3) reads the CPSR I bit, which
//! is set while IRQs are masked, as "enabled": a critical section entered
//! with IRQs on left them masked, and the next one unmasked them. The main
//! loop then ran every other console command with the control interrupts
//! held off (clippy.toml forbids that function).

/// Whether IRQs are unmasked (CPSR I bit clear).
pub fn enabled() -> bool {
    let cpsr: u32;
    // SAFETY: reading CPSR has no side effect.
    unsafe { core::arch::asm!("mrs {}, cpsr", out(reg) cpsr, options(nomem, nostack)) };
    cpsr & (1 << 7) == 0
}

/// Runs `f` with IRQs masked, then unmasks them if they were unmasked.
pub fn free<T>(f: impl FnOnce() -> T) -> T {
    let was_on = enabled();
    cortex_ar::interrupt::disable();
    let r = f();
    if was_on {
        // SAFETY: restores the state found on entry; a critical section
        // around this one (if any) masked them, so `was_on` is false there.
        unsafe { cortex_ar::interrupt::enable() };
    }
    r
}
