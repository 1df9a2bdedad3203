//! First power-up safety under QEMU: MMU and caches on with the memory
//! types the drivers need, a data abort that leaves the gates off and
//! reports its fault status.
use system_tests::*;

/// The region line of `debug mmu` for `name`.
fn region<'a>(r: &'a drivectl::link::Reply, name: &str) -> &'a str {
    let key = format!("region {name} ");
    r.lines
        .iter()
        .find(|l| l.starts_with(&key))
        .unwrap_or_else(|| panic!("no {name}: {r:?}"))
}

#[test]
fn caches_on_and_the_drivers_regions_have_their_memory_types() {
    let mut s = boot();
    let r = cmd(&mut s, "debug mmu");
    assert_ok(&r);
    assert_eq!(field(&r, "caches"), Some("on"), "{r:?}");
    // SCTLR read back from CP15: M (0), C (2), Z (11), I (12) set.
    let sctlr =
        u32::from_str_radix(field(&r, "sctlr").unwrap().trim_start_matches("0x"), 16).unwrap();
    assert_eq!(sctlr & 0x1805, 0x1805, "{sctlr:#x}");
    // Written whole (drive::mmu::SCTLR_BOOT), not ORed into.
    assert_eq!(sctlr, drive::mmu::SCTLR_BOOT, "{sctlr:#x}");
    // On: the board's PL310; absent: QEMU 7.2 has none (CACHE_ID reads 0).
    // Never off.
    let l2 = field(&r, "l2").unwrap();
    assert!(l2 == "on" || l2 == "absent", "{r:?}");
    // Hand-decoded section entries (ARMv7-A short descriptor, TEX remap
    // off): TEX 001 C B = normal write-back write-allocate; TEX 000 B with
    // XN = device; the entry's base is the address itself (flat map).
    let expect = [
        (
            "ddr-code",
            "normal write-back",
            "0x00101c0e",
            "pa 0x00100000",
        ),
        (
            "ddr-data",
            "normal write-back",
            "0x00901c0e",
            "pa 0x00900000",
        ),
        ("gp0-pl-regs", "device", "0x43c10c16", "pa 0x43c00000"),
        ("uart1", "device", "0xe0010c16", "pa 0xe0001000"),
        ("qspi", "device", "0xe0010c16", "pa 0xe000d000"),
        ("slcr-devcfg", "device", "0xf8010c16", "pa 0xf8007000"),
        ("a9-private", "device", "0xf8f10c16", "pa 0xf8f00000"),
        ("gp1-unused", "fault", "0x00000000", "translation faults"),
    ];
    for (name, kind, entry, pa) in expect {
        let l = region(&r, name);
        let (_, rest) = l.split_once(": ").unwrap();
        assert!(rest.starts_with(kind), "{l}");
        assert!(rest.contains(&format!("entry {entry}")), "{l}");
        assert!(rest.contains(pa), "{l}");
    }
}

#[test]
fn a_data_abort_turns_the_gates_off_and_reports_its_fault_status() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "enable"));
    assert_eq!(field(&cmd(&mut s, "status"), "gates"), Some("on"));
    s.send(b"debug abort\r").unwrap();
    let got = s
        .read_until(b"firmware halted\r\n", TIMEOUT)
        .expect("abort report");
    let text = String::from_utf8_lossy(&got);
    // A read of 0x8000_0000, which the table leaves unmapped: DFSR status
    // 0b00101 (translation fault, section), DFAR the address.
    assert!(
        text.contains("DATA ABORT at 0x") && text.contains("DFSR 0x00000005 (translation fault"),
        "{text}"
    );
    assert!(text.contains("read), DFAR 0x80000000"), "{text}");
    // GATE_EN read back from the simulated PL after the handler's write.
    assert!(text.contains("gate_en: 0 (read back)"), "{text}");
    assert!(
        text.contains("gates: off (safe state); firmware halted"),
        "{text}"
    );
    // Halted: no answer.
    s.send(b"version\r").unwrap();
    let after = s
        .drain_quiet(
            std::time::Duration::from_millis(500),
            std::time::Duration::from_secs(2),
        )
        .unwrap();
    assert!(!String::from_utf8_lossy(&after).contains("OK"), "{after:?}");
}

#[test]
fn the_first_enable_checks_the_sensors_and_passes_on_the_right_wiring() {
    let mut s = boot();
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "sensor_check"), Some("due"), "{st:?}");
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "enable"));
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
    assert_eq!(field(&st, "sensor_check"), Some("passed"), "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
    // On request, with its measurements: each vector drove its own channel
    // to the target (10 % of the 14 A trip) with the others at about
    // minus half of it.
    assert_ok(&cmd(&mut s, "disable"));
    let r = cmd(&mut s, "selftest sensors");
    assert_ok(&r);
    assert_eq!(field(&r, "sensor_check"), Some("pass"), "{r:?}");
    for (k, ch) in ["a", "b", "c"].iter().enumerate() {
        let l = r
            .lines
            .iter()
            .find(|l| l.starts_with(&format!("vector {ch}: ")))
            .unwrap_or_else(|| panic!("{r:?}"));
        let amps: Vec<f64> = l
            .split(", ")
            .map(|p| {
                let v = p.rsplit_once(" A").unwrap().0;
                v.rsplit(' ').next().unwrap().parse().unwrap()
            })
            .collect();
        for (j, a) in amps.iter().enumerate() {
            if j == k {
                assert!((1.4..1.6).contains(a), "{l}");
            } else {
                assert!((-1.0..-0.4).contains(a), "{l}");
            }
        }
    }
    // A few ms of PL time.
    let ms = num(&r, "duration");
    assert!(ms > 0.3 && ms < 3.0, "{ms} ms");
}

/// `enable` after the wiring fault `what`: refused with `ERR sensor-check`
/// naming it, gates off.
fn refused_on(what: &str, says: &str) {
    let mut s = boot();
    assert_ok(&cmd(&mut s, &format!("debug fault {what}")));
    assert_ok(&cmd(&mut s, "mode foc"));
    let r = cmd(&mut s, "enable");
    assert_err(&r, "sensor-check");
    let drivectl::link::Final::Err { message, .. } = &r.fin else {
        unreachable!()
    };
    assert!(message.contains(says), "{r:?}");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_eq!(field(&st, "sensor_check"), Some("due"), "{st:?}");
    // Still refused the next time.
    assert_err(&cmd(&mut s, "enable"), "sensor-check");
}

#[test]
fn swapped_current_channels_refuse_the_first_enable() {
    refused_on("adc-swap", "current channel a measures phase b");
}

#[test]
fn an_inverted_current_channel_refuses_the_first_enable() {
    refused_on("adc-invert", "current channel a inverted");
}

/// The logger masks the interrupts only while it encodes a frame into its
/// RAM ring (`drive::logring`): a frame of a console line's size costs at
/// most 2,000 guest instructions (QEMU `-icount shift=0`, `debug bench`),
/// 3 us at the A9's 666 MHz, far inside a 15.6 us FOC period. Written to
/// UART0 at 115200 baud with the interrupts off it held them off for
/// 86.8 us a byte past the 64-byte FIFO on a board (QEMU's UART has no
/// baud timing). The frames still reach UART0 (`console.rs`'s defmt test).
#[test]
fn a_log_frame_masks_the_interrupts_for_at_most_2000_instructions() {
    let mut q = drivectl::link::Qemu::new(elf());
    q.icount = true;
    let mut s = drivectl::link::Session::spawn_qemu(&q, std::time::Duration::from_secs(60))
        .expect("firmware boots");
    let r = cmd(&mut s, "debug bench");
    assert_ok(&r);
    let n = num(&r, "log_frame");
    assert!(n > 100.0 && n <= 2000.0, "{r:?}");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "log"), Some("0"), "{st:?}");
}
