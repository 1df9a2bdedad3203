//! The PL as the PS sees it: devcfg (is it configured?) and the AXI GP0
//! register pages (docs/register-map.md) as a `RegisterBus`.
//!
//! GP0 is touched only after `drive::pl::presence` found our bitstream:
//! on a real Zynq an access to an unconfigured PL (or with the level
//! shifters off, or the PL in reset) hangs the bus. The one exception is
//! [`gates_safe`], which writes `GATE_CTRL` = 0 before detection too (first
//! thing at boot, once the vector table is in place), but only when the
//! GP0 guard passes and the PL carries our EMIO signature.
//!
//! The signature ([`emio_signature`]) is read without any AXI access to the
//! PL: the GPIO controller's `DATA_RO_2` (bank 2, EMIO GPIO 54..85), which
//! our `board_top` drives with the register map's `ID` value. So a foreign
//! design is recognised before GP0 is touched and never sees the boot's
//! write. It is read only after the guard passed: before that the word
//! means nothing, and QEMU (guard failing) does not model the controller.
//!
//! A configured PL that is not ours but copies the signature may still
//! answer GP0 with a bus error (DECERR/SLVERR: a data abort, asynchronous
//! for a store): the second line. The boot's accesses before detection run
//! as a *probe* ([`boot_probe`]): the data abort handler resumes after a
//! bus error taken during it (`drive::zynq::probe_resume`), GP0 is then
//! never touched again ([`GP0_BROKEN`]) and the drive reports `pl: absent`.
//! A bus error outside a probe halts with the gates off (`panic.rs`).
use core::sync::atomic::{AtomicBool, Ordering};
use drive::pl::presence::{self, Guard, Presence};
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::pwm::{GateCtrl, GateCtrlValue};
use volatile_register::RW;

/// Set once presence detection found our bitstream behind GP0.
static GP0_OK: AtomicBool = AtomicBool::new(false);
/// Set while [`boot_probe`] runs: a data abort then is a bus error of the
/// probe, survived.
static PROBING: AtomicBool = AtomicBool::new(false);
/// Set by the data abort handler for a bus error during a probe.
static PROBE_FAULT: AtomicBool = AtomicBool::new(false);
/// GP0 answered a probe with a bus error: never touched again.
static GP0_BROKEN: AtomicBool = AtomicBool::new(false);

/// Whether a probe runs (for the data abort handler).
pub fn probing() -> bool {
    PROBING.load(Ordering::SeqCst)
}

/// The data abort handler took a bus error during the probe.
pub fn note_probe_fault() {
    PROBE_FAULT.store(true, Ordering::SeqCst);
}

/// Runs `f`'s GP0 accesses as a probe; returns its result and whether a
/// bus error was taken. A store's response arrives by the `dsb`, and an
/// asynchronous abort it raised is taken at the `isb` (aborts unmasked),
/// inside the window.
fn probe<T>(f: impl FnOnce() -> T) -> (T, bool) {
    PROBE_FAULT.store(false, Ordering::SeqCst);
    PROBING.store(true, Ordering::SeqCst);
    let r = f();
    // SAFETY: barriers only.
    unsafe { core::arch::asm!("dsb", "isb", options(nostack)) };
    PROBING.store(false, Ordering::SeqCst);
    let fault = PROBE_FAULT.load(Ordering::SeqCst);
    if fault {
        GP0_BROKEN.store(true, Ordering::SeqCst);
    }
    (r, fault)
}

/// The boot's first GP0 access, `GATE_CTRL` = 0 ([`gates_safe`]), as a
/// probe: returns whether GP0 answered it with a bus error. Call with the
/// vector table in place and asynchronous aborts unmasked.
pub fn boot_probe() -> bool {
    probe(gates_safe).1
}

fn reg(addr: usize) -> &'static RW<u32> {
    // SAFETY: callers pass the address of a 32-bit device register.
    unsafe { &*(addr as *const RW<u32>) }
}

/// devcfg `INT_STS` (a PS register: always safe to read).
pub fn devcfg_int_sts() -> u32 {
    reg(presence::DEVCFG_INT_STS).read()
}

/// SLCR `PSS_IDCODE` (a PS register: always safe to read); tells a Zynq
/// from QEMU (`drive::pl::presence::platform`).
pub fn pss_idcode() -> u32 {
    reg(presence::SLCR_PSS_IDCODE).read()
}

/// The GP0 guard's words: devcfg `INT_STS`, SLCR `LVL_SHFTR_EN` and
/// `FPGA_RST_CTRL` (PS registers: always safe to read).
pub fn guard() -> Guard {
    Guard {
        int_sts: devcfg_int_sts(),
        lvl_shftr_en: reg(presence::SLCR_LVL_SHFTR_EN).read(),
        fpga_rst_ctrl: reg(presence::SLCR_FPGA_RST_CTRL).read(),
    }
}

/// Turns the GPIO controller's AMBA clock on (SLCR `APER_CLK_CTRL`
/// `GPIO_CPU_1XCLKACT`) unless it is on already: a read of a clock-gated
/// peripheral can hang the bus. The SLCR is unlocked only for the one write
/// and locked again, as `ps::l2c` leaves it. Nothing is written when the
/// clock is on already (after the first call; or when the FSBL's
/// `ps7_init` turned it on for the GPIO the PS7 configuration enables: not
/// measured on a board), so a later call from the panic path only reads.
fn gpio_clock_on() {
    let clk = reg(presence::SLCR_APER_CLK_CTRL);
    if clk.read() & presence::GPIO_CPU_1XCLKACT != 0 {
        return;
    }
    crate::ps::slcr::unlocked(|| {
        // SAFETY: a read-modify-write that only sets the GPIO's clock
        // enable, with the SLCR unlocked.
        unsafe { clk.modify(|v| v | presence::GPIO_CPU_1XCLKACT) }
    });
    // SAFETY: a barrier only: the clock is on before the controller is read.
    unsafe { core::arch::asm!("dsb", options(nostack)) };
}

/// The EMIO signature: GPIO `DATA_RO_2`, the PS7's EMIO GPIO inputs
/// 54..85 (a PS register: no AXI access to the PL), read only when `guard`
/// passes (before that the word means nothing); 0 otherwise, a value
/// `presence::gp0_access` ignores while the guard fails. Under QEMU the
/// guard fails, so neither the SLCR clock gate nor the GPIO controller
/// (not modelled by QEMU 7.2's `xilinx-zynq-a9`) is touched.
pub fn emio_signature(guard: &Guard) -> u32 {
    if guard.check().is_err() {
        return 0;
    }
    gpio_clock_on();
    reg(presence::GPIO_DATA_RO_2).read()
}

/// Whether GP0 may be touched now: the guard passes and the PL carries our
/// EMIO signature (PS reads only). `presence::gp0_access`.
fn gp0_reachable() -> Result<(), Presence> {
    let g = guard();
    presence::gp0_access(&g, emio_signature(&g))
}

/// Decides what is in the PL; GP0 is read only when the guard passes and
/// the EMIO signature is ours. Remembers whether GP0 may be used from now
/// on.
pub fn detect() -> Presence {
    if GP0_BROKEN.load(Ordering::SeqCst) {
        // The boot probe's bus error: a design that is not ours.
        return Presence::Foreign { id: 0 };
    }
    let g = guard();
    let signature = emio_signature(&g);
    let (p, fault) = probe(|| presence::detect_signed(&g, signature, &mut Gp0));
    let p = if fault {
        Presence::Foreign { id: 0 }
    } else {
        p
    };
    GP0_OK.store(p.usable(), Ordering::Release);
    p
}

/// GP0 as a register bus (volatile 32-bit accesses).
pub struct Gp0;

impl RegisterBus for Gp0 {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        if regmap::lookup(addr).is_none() {
            return Err(BusError::SlaveError);
        }
        Ok(reg(addr).read())
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        if regmap::lookup(addr).is_none() {
            return Err(BusError::SlaveError);
        }
        // SAFETY: a register of the map; the drivers decide the values.
        unsafe { reg(addr).write(value) };
        Ok(())
    }
}

/// Turns every gate of a configured PL off (clears `GATE_EN`): one store, no
/// read-modify-write, safe from any context including the panic and abort
/// handlers. With our bitstream found, at once; otherwise (before detection,
/// or a design detection did not recognise) only when the GP0 guard passes,
/// so that the store cannot hang the bus, and the EMIO signature is ours,
/// so that a foreign design never sees it. A design that copies our
/// signature but not our map may see a 0 written at `GATE_CTRL`'s offset:
/// the price of not waiting for `ID`.
pub fn gates_safe() {
    if GP0_BROKEN.load(Ordering::SeqCst) {
        // A bus error there already: a store now would abort again.
        return;
    }
    if GP0_OK.load(Ordering::Acquire) || gp0_reachable().is_ok() {
        // Only GATE_EN is writable in GATE_CTRL: all gates off.
        let _ = GateCtrl::write(&mut Gp0, GateCtrlValue::ZERO.with_gate_en(false));
        // GP0 is device memory: the store may wait in the write buffer;
        // the barrier makes it reach the PL before anything else.
        // SAFETY: a barrier only.
        unsafe { core::arch::asm!("dsb", options(nostack)) };
    }
}
