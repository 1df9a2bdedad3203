//! Boot sequence, interrupt dispatch and the console loop.
use crate::ps::{gic, mmu, timer, uart::Uart};
use crate::{control, log, net::Net, pl, rx::Ring};
use core::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use drive::console::{self, Action, Context, LineEditor, Status, PROMPT};

/// Console line: fast enough for the telemetry stream (docs/telemetry.md).
const BAUD: u32 = drive::telemetry::CONSOLE_BAUD;
/// Log line (defmt on UART0).
const LOG_BAUD: u32 = 115_200;
/// UART reference clock set by the FSBL, from the board file.
const UART_REF_CLK_HZ: u32 = crate::board::UART_REF_CLK_HZ;
/// Rate of the periodic timer interrupt, Hz.
pub const TICK_HZ: u32 = 1000;

static CONSOLE: Uart = unsafe { Uart::new(crate::ps::uart::UART1_BASE) };
static RX: Ring = Ring::new();
static TICKS: AtomicU32 = AtomicU32::new(0);
/// Set by the interrupt when it masked UART1's receive interrupt because the
/// ring was full; the main loop unmasks it once half the ring is free.
static RX_PAUSED: AtomicBool = AtomicBool::new(false);

extern "C" {
    static _vector_table: u32;
}

/// Whether Ctrl-C (0x03) arrived on the console: a long command (`calibrate`)
/// runs with IRQs masked, so it reads the UART's FIFO itself; other bytes
/// go to the ring as the interrupt would put them. Handed to
/// `control::FwDrive` (this module owns the UART and the ring).
fn ctrl_c_pending() -> bool {
    let mut seen = false;
    while !RX.is_full() {
        let Some(b) = CONSOLE.read_byte() else { break };
        if b == 0x03 {
            seen = true;
        } else {
            RX.push(b);
        }
    }
    seen
}

fn set_vbar() {
    // SAFETY: the vector table is cortex-a-rt's, 32-byte aligned at the
    // start of .text; VBAR only matters once an exception is taken.
    unsafe {
        let vt = core::ptr::addr_of!(_vector_table) as u32;
        core::arch::asm!("mcr p15, 0, {}, c12, c0, 0", "isb", in(reg) vt, options(nostack));
    }
}

#[cortex_a_rt::entry]
fn main() -> ! {
    // The vectors before any GP0 access: an FSBL's handlers would hang on
    // a bus error of a design that is not ours.
    set_vbar();
    // Asynchronous (imprecise) aborts, e.g. a bus error on a GP0 store,
    // are taken, not left pending: during the boot probe the handler
    // resumes, afterwards it turns the gates off and halts.
    // SAFETY: the vector table is in place (VBAR above).
    unsafe { core::arch::asm!("cpsie a", options(nomem, nostack)) };
    // Gates off first: the probe's store (GP0 unused after a bus error).
    let gp0_bus_error = pl::boot_probe();
    mmu::enable();
    // The divisors are a compile-time fact of the board: a failure here is
    // a build error in disguise, caught by the host test of the same call.
    let div = drive::zynq::uart_divisors(UART_REF_CLK_HZ, BAUD).expect("baud divisors");
    CONSOLE.init(div, true);
    let log_div = drive::zynq::uart_divisors(UART_REF_CLK_HZ, LOG_BAUD).expect("baud divisors");
    log::init(log_div);
    timer::start_global();
    gic::init();
    gic::enable(gic::IRQ_PRIVATE_TIMER);
    gic::enable(gic::IRQ_UART1);
    let boot = control::init();
    let load = drive::zynq::private_timer_load(timer::PERIPHCLK_HZ, TICK_HZ).expect("tick rate");
    timer::start_private(load);
    // SAFETY: handlers and their data are ready; not inside a critical section.
    unsafe { cortex_ar::interrupt::enable() };

    defmt::info!(
        "boot: firmware {=str} git {=str}",
        env!("CARGO_PKG_VERSION"),
        env!("FW_GIT_HASH")
    );
    if gp0_bus_error {
        defmt::warn!("boot: GP0 answered GATE_CTRL with a bus error: not our design, GP0 unused");
    }
    // The global timer's count at this point differs from boot to boot
    // on the silicon: TCP's initial sequence numbers.
    let net = Net::init(timer::uptime_us(), timer::global_count());
    let mut con = CONSOLE;
    banner(&mut con, &boot, gp0_bus_error);
    run_console(&mut con, net)
}

fn banner(con: &mut Uart, boot: &control::Boot, gp0_bus_error: bool) {
    use core::fmt::Write;
    let _ = write!(
        con,
        "\r\npredictive servo drive, firmware {} (git {}, {})\r\n",
        env!("CARGO_PKG_VERSION"),
        env!("FW_GIT_HASH"),
        env!("FW_PROFILE"),
    );
    let _ = write!(
        con,
        "pl: {} (devcfg INT_STS 0x{:08x}, PSS_IDCODE 0x{:08x})\r\n\
         console on UART1 at {} 8N1; defmt log on UART0 at {} 8N1; type `help`\r\n{}",
        boot.pl, boot.devcfg_int_sts, boot.pss_idcode, BAUD, LOG_BAUD, PROMPT
    );
    if gp0_bus_error {
        let _ = write!(
            con,
            "\r\ngp0: the PL answered the boot's GATE_CTRL write with a bus error \
             (a design that is not ours); GP0 is not touched again\r\n{PROMPT}"
        );
    }
}

fn run_console(con: &mut Uart, mut net: Net) -> ! {
    let mut editor = LineEditor::new();
    let (mut lines, mut errors) = (0u32, 0u32);
    let mut drive = control::FwDrive::new(ctrl_c_pending);
    loop {
        drive.background();
        // Between console bytes, outside any interrupt: the control step
        // is not delayed, and the console waits at most one pass.
        net.poll(timer::uptime_us());
        log::drain();
        let Some(b) = next_byte() else { continue };
        let echo_to = *con;
        let Some(result) = editor.feed(b, &mut |e| echo_to.write_bytes(e)) else {
            continue;
        };
        match result {
            Ok(line) if line.trim().is_empty() => {}
            Ok(line) => {
                lines += 1;
                let ok = match console::parse(line) {
                    Ok(cmd) => {
                        defmt::info!("console: {=str}", line);
                        let ctx = context(lines, errors, net.status());
                        match console::execute(cmd, &ctx, &mut drive, con) {
                            Ok(Action::Panic) => panic!("`debug panic` requested on the console"),
                            Ok(Action::None) => true,
                            // The command's own `ERR` line (a state, a limit,
                            // the PL): sent like a parse error's, counted
                            // like one.
                            Ok(Action::Refused) => false,
                            // The UART writer does not fail; were it to, the
                            // reply is incomplete: not a success either.
                            Err(_) => false,
                        }
                    }
                    Err(e) => {
                        let _ = console::write_parse_error(con, e);
                        false
                    }
                };
                if !ok {
                    errors += 1;
                }
            }
            Err(e) => {
                lines += 1;
                errors += 1;
                defmt::warn!("console: rejected line");
                let _ = console::write_line_error(con, e);
            }
        }
        // The command's log frames toward UART0 before the prompt (the
        // tick moves whatever the FIFO had no room for).
        log::drain();
        con.write_bytes(PROMPT.as_bytes());
    }
}

fn context(lines: u32, errors: u32, net: drive::console::NetStatus) -> Context {
    Context {
        version: env!("CARGO_PKG_VERSION"),
        git_hash: env!("FW_GIT_HASH"),
        profile: env!("FW_PROFILE"),
        status: Status {
            uptime_us: timer::uptime_us(),
            ticks: TICKS.load(Ordering::Relaxed),
            tick_hz: TICK_HZ,
            lines,
            errors,
            rx_overruns: RX.overruns.load(Ordering::Relaxed),
            log_dropped: log::dropped(),
            net,
        },
    }
}

/// The next received byte; sleeps until an interrupt when there is none.
fn next_byte() -> Option<u8> {
    if RX_PAUSED.load(Ordering::Acquire) && RX.len() <= RX.capacity() / 2 {
        RX_PAUSED.store(false, Ordering::Release);
        CONSOLE.set_rx_irq(true);
    }
    if let Some(b) = RX.pop() {
        return Some(b);
    }
    // Nothing typed: telemetry frames go out now, between replies.
    if crate::telemetry::pump(&CONSOLE, 4) {
        return None;
    }
    // Check and sleep with IRQs masked so that a byte arriving in between
    // still wakes the WFI (a pending IRQ ends WFI even while masked).
    cortex_ar::interrupt::disable();
    if RX.is_empty() {
        // SAFETY: WFI has no memory effects.
        unsafe { core::arch::asm!("wfi", options(nomem, nostack)) };
    }
    // SAFETY: re-enabling what `main` enabled; not in a critical section.
    unsafe { cortex_ar::interrupt::enable() };
    RX.pop()
}

#[cortex_a_rt::irq]
fn irq_handler() {
    loop {
        let iar = gic::acknowledge();
        let id = gic::interrupt_id(iar);
        match id {
            gic::SPURIOUS => break,
            gic::IRQ_PRIVATE_TIMER => {
                timer::ack_private();
                TICKS.fetch_add(1, Ordering::Relaxed);
                control::on_tick();
                log::drain();
            }
            gic::IRQ_GLOBAL_TIMER => control::on_pl_tick(),
            control::IRQ_CONTROL => control::on_control(),
            gic::IRQ_UART1 => {
                let isr = CONSOLE.take_isr();
                if isr & crate::ps::uart::ISR_ROVR != 0 {
                    RX.overruns.fetch_add(1, Ordering::Relaxed);
                }
                while !RX.is_full() {
                    let Some(b) = CONSOLE.read_byte() else { break };
                    RX.push(b);
                }
                if RX.is_full() {
                    CONSOLE.set_rx_irq(false);
                    RX_PAUSED.store(true, Ordering::Release);
                }
            }
            _ => {}
        }
        gic::end(iar);
    }
}
