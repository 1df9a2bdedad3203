//! CAN frames over Ethernet: a TCP client speaks socketcand to the
//! firmware's server on GEM0 (QEMU's user network, the port forwarded by
//! `drivectl`), and the drive's CANopen node answers. The expected frames
//! are CiA 301's bytes, computed by hand.
use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};
use system_tests::{assert_ok, boot_with_can, boot_with_can_on, cmd, TIMEOUT};

/// The repository's root and the venv's python with python-can and
/// canopen (made by `scripts/setup`).
fn venv_python() -> (std::path::PathBuf, std::path::PathBuf) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let python = root.join("target/socketcand-venv/bin/python");
    assert!(
        python.is_file(),
        "{} missing: run scripts/setup (python-can and canopen)",
        python.display()
    );
    (root, python)
}

/// A python master `script` (PORT, EDS) started and past its `RUNNING`
/// line; its output stays open, so that its later lines do not break the
/// pipe.
fn spawn_master(
    root: &std::path::Path,
    python: &std::path::Path,
    script: &str,
    port: u16,
) -> (
    std::process::Child,
    std::io::BufReader<std::process::ChildStdout>,
) {
    use std::io::BufRead;
    let mut child = std::process::Command::new(python)
        .arg(root.join(script))
        .arg(port.to_string())
        .arg(root.join("docs/canopen/drive.eds"))
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("python runs");
    let mut out = std::io::BufReader::new(child.stdout.take().unwrap());
    let mut line = String::new();
    out.read_line(&mut line).unwrap();
    assert_eq!(line.trim(), "RUNNING");
    (child, out)
}

/// A socketcand connection: `< ... >` messages in, commands out.
struct Client {
    tcp: TcpStream,
    buf: Vec<u8>,
}

impl Client {
    fn connect(port: u16) -> Self {
        let tcp = TcpStream::connect(("127.0.0.1", port)).expect("connect to the forwarded port");
        tcp.set_read_timeout(Some(Duration::from_millis(200)))
            .unwrap();
        Self {
            tcp,
            buf: Vec::new(),
        }
    }

    fn send(&mut self, cmd: &str) {
        self.tcp.write_all(cmd.as_bytes()).unwrap();
    }

    /// The next whole `< ... >` message, within `t`.
    fn next(&mut self, t: Duration) -> Option<String> {
        let end = Instant::now() + t;
        loop {
            if let Some(start) = self.buf.iter().position(|&b| b == b'<') {
                if let Some(len) = self.buf[start..].iter().position(|&b| b == b'>') {
                    let msg = self.buf[start..=start + len].to_vec();
                    self.buf.drain(..=start + len);
                    return Some(String::from_utf8(msg).expect("ASCII"));
                }
            }
            if Instant::now() > end {
                return None;
            }
            let mut b = [0u8; 512];
            match self.tcp.read(&mut b) {
                Ok(0) => return None,
                Ok(n) => self.buf.extend_from_slice(&b[..n]),
                Err(e)
                    if matches!(
                        e.kind(),
                        std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
                    ) => {}
                Err(e) => panic!("read: {e}"),
            }
        }
    }

    /// The next message that is not a frame of another COB-ID (heartbeats
    /// come every second); a frame's ID and data fields for `< frame ...>`.
    fn expect_frame(&mut self, cob_id: &str) -> String {
        let end = Instant::now() + TIMEOUT;
        while Instant::now() < end {
            let Some(m) = self.next(Duration::from_secs(1)) else {
                continue;
            };
            let f: Vec<&str> = m.split_whitespace().collect();
            // `< frame ID SECS.USECS DATA >`; DATA absent for 0 bytes.
            assert_eq!(f[1], "frame", "{m}");
            if f[2] == cob_id {
                return if f.len() == 6 {
                    f[4].to_string()
                } else {
                    String::new()
                };
            }
        }
        panic!("no frame {cob_id} within {TIMEOUT:?}");
    }

    /// The next message, which must be `want` exactly.
    fn expect(&mut self, want: &str) {
        let got = self.next(TIMEOUT);
        assert_eq!(got.as_deref(), Some(want));
    }
}

#[test]
fn sdo_and_nmt_over_socketcand() {
    let (mut console, port) = boot_with_can();
    let mut c = Client::connect(port);
    // The handshake python-can's `socketcand` interface does.
    c.expect("< hi >");
    c.send("< open can0 >");
    c.expect("< ok >");
    c.send("< rawmode >");
    c.expect("< ok >");

    // SDO expedited upload of 0x1000:00 from node 1: request on 0x601,
    // ccs 2 (0x40), index 0x1000 little-endian, sub-index 0.
    c.send("< send 601 8 40 00 10 00 00 00 00 00 >");
    // Response on 0x581: 0x43 (scs 2, expedited, size given, 4 bytes),
    // 00 10, 00, then the device type 0x00020192 (CiA 402 servo drive)
    // little-endian.
    assert_eq!(c.expect_frame("581"), "4300100092010200");

    // 0x1018:00, the identity's highest sub-index: 4, one byte (0x4F: 3
    // bytes unused).
    c.send("< send 601 8 40 18 10 00 00 00 00 00 >");
    assert_eq!(c.expect_frame("581"), "4F18100004000000");

    // An object the drive does not have (0x2FFF): abort 0x06020000.
    c.send("< send 601 8 40 FF 2F 00 00 00 00 00 >");
    assert_eq!(c.expect_frame("581"), "80FF2F0000000206");

    // A malformed command: an error, nothing sent on.
    c.send("< send 601 9 1 2 3 4 5 6 7 8 9 >");
    c.expect("< error syntax error >");

    // The console answers while the connection is open, and shows it:
    // QEMU's DHCP server leases 10.0.2.15/24; three frames went to the
    // node, the malformed command is the one error.
    let st = cmd(&mut console, "status");
    assert_ok(&st);
    let line = |prefix: &str| {
        st.lines
            .iter()
            .find(|l| l.starts_with(prefix))
            .unwrap_or_else(|| panic!("no {prefix} line: {st:?}"))
            .clone()
    };
    assert_eq!(
        line("net: "),
        "net: 10.0.2.15/24 (dhcp), socketcand tcp 29536: client connected"
    );
    let can = line("can: ");
    assert!(can.starts_with("can: 3 frames in, "), "{can}");
    assert!(can.ends_with(", 1 errors"), "{can}");

    // NMT start node 1 (0x01, node 1 on COB-ID 0): the heartbeat on 0x701
    // turns from pre-operational (0x7F) to operational (0x05).
    c.send("< send 000 2 1 1 >");
    let end = Instant::now() + TIMEOUT;
    loop {
        let hb = c.expect_frame("701");
        if hb == "05" {
            break;
        }
        assert_eq!(hb, "7F", "heartbeat before the start arrived");
        assert!(Instant::now() < end, "no operational heartbeat");
    }
}

#[test]
fn a_second_client_after_the_first_left() {
    let (_console, port) = boot_with_can();
    {
        let mut c = Client::connect(port);
        c.expect("< hi >");
    }
    // The server listens again once the first connection closed.
    let end = Instant::now() + TIMEOUT;
    loop {
        let mut c = Client::connect(port);
        if c.next(Duration::from_secs(2)).as_deref() == Some("< hi >") {
            c.send("< open can0 >");
            c.expect("< ok >");
            break;
        }
        assert!(Instant::now() < end, "no greeting for a second client");
    }
}

/// An independent master: unmodified python-can (`socketcand` interface)
/// and canopen from PyPI, in the venv `scripts/setup` makes
/// (tests/python/socketcand_canopen.py says what it checks).
#[test]
fn python_can_and_canopen_read_the_device_type() {
    let (root, python) = venv_python();
    let (_console, port) = boot_with_can();
    let out = std::process::Command::new("timeout")
        .arg("60")
        .arg(&python)
        .arg(root.join("tests/python/socketcand_canopen.py"))
        .arg(port.to_string())
        .output()
        .expect("python runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "{text}");
    // The script's own checks passed; its report has the value read.
    assert!(text.contains("0x1000:00 = 92010200"), "{text}");
    assert!(text.contains("heartbeat state = OPERATIONAL"), "{text}");
}

/// A client that sends far more than the server's 2 KiB buffers hold,
/// with garbage between the commands: the console keeps answering while
/// it arrives, and afterwards the node answers a new request. Lines the
/// socket had no room for are dropped, not waited for.
#[test]
fn a_flood_of_commands_and_garbage_leaves_the_console_and_the_node_answering() {
    let (mut console, port) = boot_with_can();
    let mut c = Client::connect(port);
    c.expect("< hi >");
    c.send("< open can0 >");
    c.expect("< ok >");
    c.send("< rawmode >");
    c.expect("< ok >");
    let mut flood = Vec::new();
    for i in 0..600u32 {
        flood.extend_from_slice(b"< send 601 8 40 00 10 00 00 00 00 00 >");
        // Bytes of every value, a stray '<' and an overlong command now
        // and then.
        flood.extend((0..23u32).map(|k| ((i * 31 + k * 7) % 256) as u8));
        if i % 50 == 0 {
            flood.extend(std::iter::repeat_n(b'7', 200));
            flood.push(b'>');
        }
    }
    let mut writer = c.tcp.try_clone().unwrap();
    let sent = flood.len();
    let t = std::thread::spawn(move || writer.write_all(&flood));
    // The console answers while the flood arrives.
    for _ in 0..3 {
        assert_ok(&cmd(&mut console, "status"));
    }
    t.join()
        .unwrap()
        .expect("the server takes all of the flood");
    assert!(sent > 30_000, "{sent} bytes");
    // Whatever the garbage left open is closed by a '>', then 0x1018:04
    // (serial number 0: 0x43, 18 10, 04, 00 00 00 00), which no earlier
    // answer looks like.
    c.send(" > < send 601 8 40 18 10 04 00 00 00 00 >");
    let end = Instant::now() + TIMEOUT;
    loop {
        assert!(
            Instant::now() < end,
            "no answer to the request after the flood"
        );
        let Some(m) = c.next(Duration::from_secs(1)) else {
            continue;
        };
        if m.starts_with("< frame 581 ") && m.ends_with(" 4318100400000000 >") {
            break;
        }
    }
    assert_ok(&cmd(&mut console, "status"));
}

/// A robot's controller as CiA 402 master: unmodified python-canopen
/// (tests/python/cia402_csp.py) imports the committed EDS, reads every
/// object in it, maps the PDOs, takes the drive to Operation enabled in
/// cyclic synchronous position and streams 2,000 set-points, one per
/// SYNC, each answered by exactly one TPDO; the position ends within a
/// count of the last set-point, the drive counted the same frames with 0
/// overruns; six refusals come with CiA 301's abort codes, and homing
/// (method 37) zeroes the position.
#[test]
fn python_canopen_drives_the_servo_in_csp_for_2000_syncs() {
    csp_with_python(false, 2000);
}

/// The same master against the Verilated `pl_top` (co-simulation), for
/// 300 SYNCs: the RTL's encoder, ADC and PWM under the same dictionary.
#[test]
fn python_canopen_drives_the_co_simulated_rtl_in_csp() {
    csp_with_python(true, 300);
}

fn csp_with_python(rtl: bool, syncs: u32) {
    let (root, python) = venv_python();
    let (mut console, port) = boot_with_can_on(rtl);
    // The simulated rotor free (it is held at standstill by default).
    assert_ok(&cmd(&mut console, "sim set locked 0"));
    let out = std::process::Command::new("timeout")
        .arg("300")
        .arg(&python)
        .arg(root.join("tests/python/cia402_csp.py"))
        .arg(port.to_string())
        .arg(root.join("docs/canopen/drive.eds"))
        .arg(syncs.to_string())
        .output()
        .expect("python runs");
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains(&format!("SYNCs {syncs}, TPDOs {syncs}, missing 0, extra 0")),
        "{text}"
    );
    let read: usize = text
        .split("EDS objects read: ")
        .nth(1)
        .and_then(|r| r.split(',').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no EDS count: {text}"));
    assert!(read >= 190, "{read} EDS objects: {text}");
    // Six refusals with their abort codes, then homing to 0.
    assert_eq!(text.matches("\nrefused: ").count(), 6, "{text}");
    assert!(
        text.contains("0x2000 (motor_r_s) with the gates on: 0x08000022"),
        "{text}"
    );
    // Within a count of 0: the velocity loop holds the rotor after the
    // new zero, as it holds it anywhere.
    let home: i64 = text
        .split("homing: statusword ")
        .nth(1)
        .and_then(|r| r.split("position ").nth(1))
        .and_then(|r| r.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no homing position: {text}"));
    assert!(home.abs() <= 1, "homed at {home}: {text}");
    let st = cmd(&mut console, "status");
    let s = st.lines.join("\n");
    assert!(s.contains("\noverruns: 0\n"), "{s}");
    let pl = if rtl {
        "pl: rtl co-simulation"
    } else {
        "pl: simulated"
    };
    assert!(s.contains(pl), "{s}");
    assert!(
        s.contains(&format!(
            "mode 6 (hm), syncs {syncs}, rpdos {syncs}, tpdos {syncs},"
        )),
        "{s}"
    );
    println!("{text}");
}

/// A master killed while it drives the motor: its heartbeat stops, the
/// drive's consumer (0x1016) times out and the drive quick-stops (0x6007
/// = 3): the velocity loop brakes, the gates go off, the CiA 402 state is
/// Switch on disabled, and the console commands again.
#[test]
fn a_killed_master_quick_stops_the_motor() {
    let (root, python) = venv_python();
    let (mut console, port) = boot_with_can();
    assert_ok(&cmd(&mut console, "sim set locked 0"));
    let (mut child, _out) = spawn_master(&root, &python, "tests/python/cia402_heartbeat.py", port);
    // The master owns the motor meanwhile.
    let r = cmd(&mut console, "enable");
    assert!(
        matches!(&r.fin, drivectl::link::Final::Err { code, .. } if code == "canopen-owns"),
        "{r:?}"
    );
    child.kill().unwrap();
    let _ = child.wait();
    // 300 ms of drive time without a heartbeat (about 1 s of wall time
    // under QEMU), then the quick stop.
    let end = Instant::now() + TIMEOUT;
    loop {
        let s = cmd(&mut console, "status").lines.join("\n");
        if s.contains("cia402 switch-on-disabled") {
            assert!(s.contains("gates: off"), "{s}");
            assert!(s.contains("errors 1"), "the heartbeat EMCY: {s}");
            break;
        }
        assert!(Instant::now() < end, "no quick stop: {s}");
        std::thread::sleep(Duration::from_millis(200));
    }
    assert_ok(&cmd(&mut console, "mode foc"));
}

/// The vendor impedance mode (-1) commanded by python-canopen holds the
/// rotor like a spring: with 2 N m/rev of stiffness about the start, a
/// constant load of 0.1 N m (`sim set load_torque`, opposing positive
/// motion) deflects it by 0.05 rev, 205 counts of 4096.
#[test]
fn python_canopen_impedance_mode_holds_against_a_load() {
    let (root, python) = venv_python();
    let (mut console, port) = boot_with_can();
    assert_ok(&cmd(&mut console, "sim set locked 0"));
    let (mut child, _out) = spawn_master(&root, &python, "tests/python/cia402_impedance.py", port);
    let counts = |console: &mut drivectl::link::Session| -> f64 {
        let r = cmd(console, "status");
        r.lines
            .iter()
            .find_map(|l| l.strip_prefix("position_counts: "))
            .and_then(|v| v.split_whitespace().next())
            .and_then(|v| v.parse().ok())
            .expect("position_counts")
    };
    let start = counts(&mut console);
    assert_ok(&cmd(&mut console, "sim set load_torque 0.1"));
    // Settled within 10 % after the damping's transient.
    let end = Instant::now() + TIMEOUT;
    let mut last = start;
    loop {
        std::thread::sleep(Duration::from_millis(500));
        let p = counts(&mut console);
        let settled = (p - last).abs() <= 1.0;
        last = p;
        if settled && ((p - start) + 204.8).abs() <= 20.0 {
            break;
        }
        assert!(Instant::now() < end, "deflection {} counts", p - start);
    }
    child.kill().unwrap();
    let _ = child.wait();
    assert_ok(&cmd(&mut console, "disable"));
}
