//! Pure arithmetic for the Zynq-7000 PS peripherals the firmware programs
//! (kept here so that it is tested on the host).

/// Baud-rate generator setting of the Cadence UART (Zynq TRM, UG585 ch. 19):
/// `baud = ref_clk / (cd * (bdiv + 1))`, `cd` in 1..=65535, `bdiv` in 4..=254.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UartDivisors {
    /// `BAUDGEN.CD`.
    pub cd: u16,
    /// `BAUD_RATE_DIVIDER.BDIV`.
    pub bdiv: u8,
}

impl UartDivisors {
    /// The baud rate these divisors give from `ref_clk_hz`, Hz.
    pub fn baud(&self, ref_clk_hz: u32) -> u32 {
        ref_clk_hz / (u32::from(self.cd) * (u32::from(self.bdiv) + 1))
    }
}

/// The divisors closest to `baud`, or `None` when no setting is within
/// 2 % (the tolerance of an 8N1 frame, with margin for the far end).
pub fn uart_divisors(ref_clk_hz: u32, baud: u32) -> Option<UartDivisors> {
    if baud == 0 {
        return None;
    }
    let mut best: Option<(u64, UartDivisors)> = None;
    for bdiv in 4u32..=254 {
        let denom = u64::from(baud) * u64::from(bdiv + 1);
        let cd = ((u64::from(ref_clk_hz) + denom / 2) / denom).clamp(1, 65535);
        let actual = u64::from(ref_clk_hz) / (cd * u64::from(bdiv + 1));
        let err = actual.abs_diff(u64::from(baud));
        if best.is_none_or(|(e, _)| err < e) {
            best = Some((
                err,
                UartDivisors {
                    cd: cd as u16,
                    bdiv: bdiv as u8,
                },
            ));
        }
    }
    best.filter(|(err, _)| err * 50 <= u64::from(baud))
        .map(|(_, d)| d)
}

/// Load value of the A9 private timer for a periodic interrupt at `rate_hz`
/// from its clock `clk_hz` (the timer counts `load + 1` cycles per period).
/// `None` when the rate is zero or above the clock.
pub fn private_timer_load(clk_hz: u32, rate_hz: u32) -> Option<u32> {
    if rate_hz == 0 || rate_hz > clk_hz {
        return None;
    }
    Some(clk_hz / rate_hz - 1)
}

/// The fault of an ARMv7-A short-descriptor fault status register (DFSR or
/// IFSR): FS = bits 10 and 3:0 (ARMv7-A ARM B4.1.52, table B3-23), in
/// words for the abort report.
pub fn fault_status_name(fsr: u32) -> &'static str {
    match ((fsr >> 6) & 0x10) | (fsr & 0xF) {
        0b00001 => "alignment fault",
        0b00010 => "debug event",
        0b00011 | 0b00110 => "access flag fault",
        0b00101 => "translation fault (section: address unmapped)",
        0b00111 => "translation fault (page)",
        0b01000 => "synchronous external abort (bus error on a load)",
        0b01001 | 0b01011 => "domain fault",
        0b01101 | 0b01111 => "permission fault",
        0b01100 | 0b01110 => "external abort on a table walk",
        0b10110 => "asynchronous external abort (bus error on a store, imprecise)",
        0b11000 => "asynchronous parity error",
        0b00100 => "instruction cache maintenance fault",
        _ => "unknown fault status",
    }
}

/// Where a data abort taken during the boot's GP0 probe resumes, or `None`
/// (halt) for any other abort. Only an external abort (a bus error: a
/// design answering DECERR or SLVERR) is the probe's to survive: a
/// synchronous one (a load) resumes after the aborted instruction (A32:
/// `addr` + 4, its result discarded), an asynchronous one (a store,
/// reported later) at `addr`, the instruction it interrupted, not yet
/// executed. `addr` is the handler's address (the exception's return
/// address less 8).
pub fn probe_resume(probing: bool, dfsr: u32, addr: usize) -> Option<usize> {
    if !probing {
        return None;
    }
    match ((dfsr >> 6) & 0x10) | (dfsr & 0xF) {
        0b01000 => Some(addr + 4),
        0b10110 => Some(addr),
        _ => None,
    }
}

/// `ICDICFR` (two bits per interrupt, sixteen a register) with interrupt
/// `id`'s field set to level-sensitive, 1-N model (0b01: bit 1 clear =
/// level, bit 0 set as the reset value has it), the others as `old`.
pub fn icdicfr_level_high(old: u32, id: u32) -> u32 {
    let shift = 2 * (id % 16);
    (old & !(0b11 << shift)) | (0b01 << shift)
}

/// DFSR.WnR (bit 11): the aborted access was a write.
pub fn fault_was_write(dfsr: u32) -> bool {
    dfsr & (1 << 11) != 0
}

/// QSPI `CONFIG.Holdb_dr` (bit 19): the controller drives HOLD# (IO3) high
/// in I/O mode. `ps7_init` sets it; without it HOLD# floats low with the
/// JTAG boot straps and the flash ignores every command (UG585 B.20).
pub const QSPI_HOLDB_DR: u32 = 1 << 19;

/// QSPI `CONFIG` the firmware writes (chip-select bits 13:10 clear, the
/// driver adds them): master mode (0), baud divisor /8 (5:3 = 0b010),
/// 32-bit FIFO width (7:6 = 0b11, required), manual chip select (14),
/// `Holdb_dr` (19), flash interface mode (31).
pub const QSPI_CONFIG: u32 = 1 | (0b010 << 3) | (0b11 << 6) | (1 << 14) | QSPI_HOLDB_DR | (1 << 31);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn icdicfr_sets_one_field_to_level() {
        // IRQ_F2P[0] = 61: register 3 (IDs 48..63), bits 27:26.
        assert_eq!(icdicfr_level_high(0xFFFF_FFFF, 61), 0xF7FF_FFFF);
        assert_eq!(icdicfr_level_high(0, 61), 0x0400_0000);
        // UART1 = 82: register 5, bits 5:4; an edge setting is undone.
        assert_eq!(icdicfr_level_high(0b10 << 4, 82), 0b01 << 4);
    }

    #[test]
    fn only_a_bus_error_during_the_probe_resumes() {
        // DFSR FS: synchronous external abort 0b01000, asynchronous
        // 0b10110 (bit 10 set), translation fault 0b00101.
        let (sync_ext, async_ext, translation) = (0x008, 0x406 | (1 << 11), 0x005);
        assert_eq!(probe_resume(true, sync_ext, 0x1000), Some(0x1004));
        assert_eq!(probe_resume(true, async_ext, 0x1000), Some(0x1000));
        assert_eq!(probe_resume(true, translation, 0x1000), None);
        assert_eq!(probe_resume(false, sync_ext, 0x1000), None);
        assert_eq!(probe_resume(false, async_ext, 0x1000), None);
    }

    #[test]
    fn divisors_for_115200_from_50_and_100_mhz() {
        // Hand-computed: 50 MHz / (62 * 7) = 115207 Hz (+0.006 %).
        let d = uart_divisors(50_000_000, 115_200).unwrap();
        assert_eq!(d.baud(50_000_000), 115_207);
        let d = uart_divisors(100_000_000, 115_200).unwrap();
        assert!(d.baud(100_000_000).abs_diff(115_200) < 20);
    }

    #[test]
    fn impossible_rates_are_refused() {
        assert_eq!(uart_divisors(50_000_000, 0), None);
        // Above ref/5 no divisor pair reaches it.
        assert_eq!(uart_divisors(1_000_000, 900_000), None);
    }

    #[test]
    fn every_standard_rate_is_within_2_percent() {
        for baud in [
            9600, 19_200, 38_400, 57_600, 115_200, 230_400, 460_800, 921_600,
        ] {
            let d = uart_divisors(50_000_000, baud).unwrap();
            let err = d.baud(50_000_000).abs_diff(baud) as f64 / baud as f64;
            assert!(err < 0.02, "{baud}: {err}");
        }
    }

    #[test]
    fn timer_load() {
        // 333.333 MHz / 1 kHz: 333333 cycles, load one less.
        assert_eq!(private_timer_load(333_333_333, 1000), Some(333_332));
        assert_eq!(private_timer_load(1000, 0), None);
        assert_eq!(private_timer_load(1000, 2000), None);
    }

    #[test]
    fn fault_status_words() {
        // A load from a section the table leaves unmapped: FS 0b00101.
        assert_eq!(
            fault_status_name(0x005),
            "translation fault (section: address unmapped)"
        );
        // FS[4] is bit 10: an imprecise external abort on a store (WnR set).
        let dfsr = (1 << 10) | (1 << 11) | 0b0110;
        assert!(fault_status_name(dfsr).starts_with("asynchronous external abort"));
        assert!(fault_was_write(dfsr));
        assert!(!fault_was_write(0x005));
        assert_eq!(
            fault_status_name(0x008),
            "synchronous external abort (bus error on a load)"
        );
        assert_eq!(fault_status_name(0x400), "unknown fault status");
    }

    #[test]
    fn qspi_config_keeps_holdb_dr() {
        // Hand-assembled from UG585 B.20: 0x8000_0000 | 0x0008_0000 |
        // 0x0000_4000 | 0x0000_00C0 | 0x0000_0010 | 0x0000_0001.
        assert_eq!(QSPI_CONFIG, 0x8008_40D1);
        assert_ne!(QSPI_CONFIG & QSPI_HOLDB_DR, 0);
        // No chip select bits: the driver owns them.
        assert_eq!(QSPI_CONFIG & (0xF << 10), 0);
    }
}
