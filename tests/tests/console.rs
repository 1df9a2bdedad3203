//! The firmware console under QEMU: every command, every error path, and
//! that the console keeps answering after each error.
use drivectl::link::PROMPT;
use std::time::Duration;
use system_tests::{assert_err, boot, boot_with, cmd, elf, field, TIMEOUT};

#[test]
fn help_lists_every_command_of_the_grammar() {
    let mut s = boot();
    let r = cmd(&mut s, "help");
    assert!(r.is_ok(), "{r:?}");
    // The same table the firmware was built from.
    for spec in drive::console::COMMANDS {
        assert!(
            r.lines
                .iter()
                .any(|l| l.trim_start().starts_with(spec.name) && l.contains(spec.args)),
            "help misses {}: {r:?}",
            spec.name
        );
    }
}

#[test]
fn version_names_crate_version_git_hash_and_profile() {
    let mut s = boot();
    let r = cmd(&mut s, "version");
    assert!(r.is_ok(), "{r:?}");
    assert_eq!(r.lines.len(), 1, "{r:?}");
    let words: Vec<&str> = r.lines[0].split(' ').collect();
    assert_eq!(words[0], "firmware");
    assert_eq!(words[1], env!("CARGO_PKG_VERSION"));
    assert_eq!(words[2], "git");
    let hash = words[3].trim_end_matches("-dirty");
    assert!(
        hash == "unknown" || (hash.len() == 12 && hash.chars().all(|c| c.is_ascii_hexdigit())),
        "{r:?}"
    );
    assert_eq!(&words[4..], ["profile", "release"]);
}

#[test]
fn status_ticks_advance_with_uptime() {
    let mut s = boot();
    let a = cmd(&mut s, "status");
    std::thread::sleep(Duration::from_millis(300));
    let b = cmd(&mut s, "status");
    let ticks = |r| field(r, "ticks").unwrap().parse::<u64>().unwrap();
    let uptime = |r| field(r, "uptime").unwrap().parse::<f64>().unwrap();
    let (t0, t1) = (ticks(&a), ticks(&b));
    let (u0, u1) = (uptime(&a), uptime(&b));
    assert!(t1 > t0, "ticks did not advance: {a:?} {b:?}");
    assert!(u1 > u0, "uptime did not advance: {a:?} {b:?}");
    // The tick and the uptime come from two timers on one clock: at
    // 1000 Hz there can be no more ticks than elapsed milliseconds (QEMU may
    // drop periods of a starved host, so fewer is possible).
    let expected = (u1 - u0) * 1000.0;
    assert!(
        (t1 - t0) as f64 <= expected + 2.0,
        "ticks {t0}->{t1} vs uptime {u0}->{u1}"
    );
    assert_eq!(field(&b, "gates"), Some("off"), "{b:?}");
    // QEMU has no bitstream (devcfg says the PL is unconfigured): the
    // firmware drives the simulated PL.
    assert!(b.lines.contains(&"pl: simulated".to_string()), "{b:?}");
    // The GP0 guard fails under QEMU (no PL behind GP0) and says that this
    // is expected there.
    let guard = b
        .lines
        .iter()
        .find(|l| l.starts_with("gp0_guard: "))
        .expect("a gp0_guard line");
    assert!(guard.starts_with("gp0_guard: fail: "), "{guard}");
    assert!(
        guard.contains("; expected under QEMU (PSS_IDCODE reads as an emulator's)"),
        "{guard}"
    );
}

#[test]
fn unknown_command_then_the_console_still_answers() {
    let mut s = boot();
    let r = cmd(&mut s, "frobnicate 12");
    assert_err(&r, "unknown-command");
    assert!(cmd(&mut s, "version").is_ok());
}

#[test]
fn bad_arguments_are_reported() {
    let mut s = boot();
    assert_err(&cmd(&mut s, "status now"), "bad-args");
    assert_err(&cmd(&mut s, "debug"), "bad-args");
    assert!(cmd(&mut s, "help status").is_ok());
}

/// `status`'s console counters count what was sent: every `ERR` reply is an
/// error, the drive's refusals (mode, gates, no record) as much as the
/// grammar's and the line editor's.
#[test]
fn status_counts_every_err_reply_as_an_error() {
    let mut s = boot();
    let lines = [
        ("version", None),
        ("frobnicate", Some("unknown-command")),
        ("st\u{1}atus", Some("bad-char")),
        ("enable", Some("mode-off")),
        ("step 0.2", Some("gates-off")),
        ("help nope", Some("bad-args")),
        ("capture dump", Some("bad-args")),
    ];
    for (line, want) in lines {
        let r = cmd(&mut s, line);
        match want {
            None => assert!(r.is_ok(), "{line}: {r:?}"),
            Some(code) => assert_err(&r, code),
        }
    }
    let st = cmd(&mut s, "status");
    // The seven lines above and `status` itself; six of them refused.
    assert!(
        st.lines
            .iter()
            .any(|l| l == "console: 8 lines, 6 errors, 0 rx overruns"),
        "{st:?}"
    );
}

#[test]
fn overlong_line_is_rejected_and_the_console_recovers() {
    let mut s = boot();
    let long = "x".repeat(drive::console::LINE_MAX * 3);
    let r = cmd(&mut s, &long);
    assert_err(&r, "line-too-long");
    assert!(cmd(&mut s, "version").is_ok());
}

#[test]
fn empty_lines_only_print_a_prompt() {
    let mut s = boot();
    // (An LF right after a CR completes a CRLF, so the order matters.)
    for ending in ["\n", "\r\n", "   \r", "\t\r"] {
        s.send(ending.as_bytes()).unwrap();
        let got = s.read_until(PROMPT.as_bytes(), TIMEOUT).unwrap();
        let text = String::from_utf8_lossy(&got);
        assert!(
            !text.contains("OK") && !text.contains("ERR"),
            "{ending:?}: {text:?}"
        );
    }
    assert!(cmd(&mut s, "version").is_ok());
}

#[test]
fn crlf_and_backspace_over_the_wire() {
    let mut s = boot();
    s.send(b"verx\x7fsion\r\n").unwrap();
    let got = s.read_until(PROMPT.as_bytes(), TIMEOUT).unwrap();
    let text = String::from_utf8_lossy(&got);
    assert!(text.contains("\r\nfirmware "), "{text:?}");
    assert!(text.ends_with("OK\r\ndrive> "), "{text:?}");
}

#[test]
fn non_utf8_and_control_bytes_get_errors_not_panics() {
    let mut s = boot();
    assert_err(&cmd(&mut s, "st\u{1}atus"), "bad-char");
    s.send(b"ver\xff\xfesion\r").unwrap();
    let text =
        String::from_utf8_lossy(&s.read_until(PROMPT.as_bytes(), TIMEOUT).unwrap()).into_owned();
    assert!(text.contains("ERR bad-encoding"), "{text:?}");
    assert!(cmd(&mut s, "version").is_ok());
}

#[test]
fn ten_kilobytes_of_random_bytes_then_version() {
    let mut s = boot();
    // The workspace's test generator, fixed seed: the same garbage every run.
    let mut rng = models::testrng::Rng(0x9e37_79b9);
    let garbage: Vec<u8> = (0..10 * 1024).map(|_| rng.next_u64() as u8).collect();
    s.send(&garbage).unwrap();
    // End whatever line the garbage left open, then a marker line whose
    // unique error reply shows that every earlier byte has been processed.
    s.send(b"\r\x03help sync-marker-42\r").unwrap();
    let noise = s
        .read_until(b"help: no command `sync-marker-42`\r\ndrive> ", TIMEOUT)
        .unwrap();
    assert!(
        noise.len() > 1000,
        "the firmware said little to 10 kB of input"
    );
    let r = cmd(&mut s, "version");
    assert!(r.is_ok(), "{r:?}");
    assert!(r.lines[0].starts_with("firmware "), "{r:?}");
    // Nothing was lost on the way in: QEMU's UART applies back-pressure.
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "console").map(|_| ()), Some(()));
    assert!(
        st.lines.iter().any(|l| l.ends_with(" 0 rx overruns")),
        "{st:?}"
    );
}

#[test]
fn panic_turns_gates_off_prints_message_and_location_and_halts() {
    let mut s = boot();
    s.send(b"debug panic\r").unwrap();
    let got = s
        .read_until(b"firmware halted\r\n", TIMEOUT)
        .expect("panic report");
    let text = String::from_utf8_lossy(&got);
    assert!(
        text.contains("PANIC: `debug panic` requested on the console"),
        "{text}"
    );
    assert!(text.contains("  at firmware/src/app.rs:"), "{text}");
    assert!(text.contains("gates: off (safe state)"), "{text}");
    // Halted: no prompt, no answer.
    s.send(b"version\r").unwrap();
    let after = s
        .drain_quiet(Duration::from_millis(500), Duration::from_secs(2))
        .unwrap();
    assert!(!String::from_utf8_lossy(&after).contains("OK"), "{after:?}");
}

#[test]
fn defmt_log_on_uart0_decodes_with_the_elf() {
    let dir = std::env::temp_dir().join(format!("drive-defmt-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let raw = dir.join("defmt.bin");
    {
        let mut s = boot_with(Some(raw.clone()));
        assert!(cmd(&mut s, "status").is_ok());
    }
    let table = drivectl::defmt_log::LogTable::load(&elf()).unwrap();
    let mut out = Vec::new();
    let frames = table
        .decode(std::fs::File::open(&raw).unwrap(), &mut out, None)
        .unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(frames >= 2, "{text}");
    assert!(text.contains("INFO boot: firmware"), "{text}");
    assert!(text.contains("INFO console: status"), "{text}");
    assert!(!text.contains("malformed"), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The README's one-liner: input piped straight into `scripts/qemu`.
#[test]
fn piped_input_into_scripts_qemu() {
    use std::io::Write;
    use std::process::{Command, Stdio};
    let script = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scripts/qemu");
    let mut child = Command::new("timeout")
        .arg("30")
        .arg(script)
        .arg(elf())
        .env(
            "DRIVE_DEFMT_RAW",
            std::env::temp_dir().join("drive-piped-defmt.bin"),
        )
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(b"version\r\nstatus\r\n")
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{out:?}");
    let text = String::from_utf8_lossy(&out.stdout);
    let oks = text.matches("\r\nOK\r\n").count();
    assert_eq!(oks, 2, "{text}");
    assert!(text.contains("\r\nfirmware "), "{text}");
    assert!(text.contains("\r\nticks: "), "{text}");
}

/// The serial-port path of `drivectl` (what a board uses), end to end: QEMU
/// puts the console UART on a pseudo-terminal, `drivectl` opens it with the
/// `serialport` crate at 115200 8N1.
#[test]
fn serial_port_link_through_a_pty() {
    use drivectl::link::{Qemu, Session};
    use std::io::{BufRead, BufReader};
    use std::process::{Command, Stdio};
    let q = Qemu::new(elf());
    let mut child = Command::new("qemu-system-arm")
        .args(q.args("pty"))
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // QEMU announces on stdout: "char device redirected to /dev/pts/N (label serial1)".
    let mut lines = BufReader::new(child.stdout.take().unwrap()).lines();
    let pty = loop {
        let line = lines
            .next()
            .expect("QEMU names its pty before exiting")
            .unwrap();
        if let Some(rest) = line.split("redirected to ").nth(1) {
            break rest.split_whitespace().next().unwrap().to_string();
        }
    };
    let result = std::panic::catch_unwind(|| {
        let mut s = Session::open_serial(&pty, 115_200, TIMEOUT).expect("open the pty");
        let r = cmd(&mut s, "version");
        assert!(r.is_ok() && r.lines[0].starts_with("firmware "), "{r:?}");
        assert_err(&cmd(&mut s, "nope"), "unknown-command");
    });
    let _ = child.kill();
    let _ = child.wait();
    result.unwrap();
}
