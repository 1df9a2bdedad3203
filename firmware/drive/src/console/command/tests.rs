//! The console grammar and replies against the real `Servo` on the fake PL.
use super::*;
use crate::pl::top::Mode;
use std::string::String;

fn ctx() -> Context {
    Context {
        version: "1.2.3",
        git_hash: "abc1234",
        profile: "release",
        status: Status {
            uptime_us: 12_000_042,
            ticks: 12_000,
            tick_hz: 1000,
            lines: 5,
            errors: 2,
            rx_overruns: 0,
            log_dropped: 0,
            net: NetStatus {
                ipv4: Some(([10, 0, 2, 15], 24)),
                dhcp: true,
                client: false,
                can: crate::can_gateway::Counts {
                    frames_in: 3,
                    frames_out: 2,
                    dropped: 1,
                    errors: 4,
                },
            },
        },
    }
}

/// Parses and executes `line` the way the firmware does.
fn reply(line: &str) -> String {
    reply_on(&mut TestDrive::new(), line)
}

fn reply_on(d: &mut TestDrive, line: &str) -> String {
    let mut out = String::new();
    match parse(line) {
        Ok(c) => {
            execute(c, &ctx(), d, &mut out).unwrap();
        }
        Err(e) => write_parse_error(&mut out, e).unwrap(),
    }
    out
}

/// Every reply ends with exactly one final line.
fn assert_one_final_line(r: &str) {
    let finals = r
        .split("\r\n")
        .filter(|l| *l == "OK" || l.starts_with("ERR "))
        .count();
    assert_eq!(finals, 1, "{r:?}");
    assert!(r.ends_with("\r\n"));
    let last = r.trim_end().rsplit("\r\n").next().unwrap();
    assert!(last == "OK" || last.starts_with("ERR "), "{r:?}");
}

#[test]
fn help_lists_every_command_with_its_arguments() {
    let r = reply("help");
    for s in COMMANDS {
        assert!(r.contains(s.name) && r.contains(s.args), "{}", s.name);
    }
    assert_one_final_line(&r);
    assert!(r.ends_with("OK\r\n"));
}

#[test]
fn help_on_one_command() {
    assert!(reply("help status").starts_with("  status"));
    // `help tel` gives the max rates the console carries (by hand: 73,728
    // B/s for telemetry over 17-byte frames for one channel).
    let r = reply("help tel");
    assert!(r.starts_with("  tel "), "{r}");
    assert!(
        r.contains("\r\nmax rate: 1 channel 4336 Hz, 2 channels 3510 Hz, "),
        "{r}"
    );
    assert!(!r.contains("10000"), "{r}");
    assert_one_final_line(&r);
    assert_eq!(
        reply("help nothing"),
        "ERR bad-args help: no command `nothing`\r\n"
    );
}

#[test]
fn mpdcc_command() {
    assert_eq!(
        reply("mpdcc"),
        "mpdcc: no run yet (`mpdcc run [<periods>]`)\r\nOK\r\n"
    );
    // The test drive has no MPDCC page.
    assert_eq!(
        reply("mpdcc run"),
        "ERR unsupported mpdcc: not available here\r\n"
    );
    for bad in ["mpdcc run 0", "mpdcc run 21", "mpdcc run x", "mpdcc go"] {
        assert!(reply(bad).starts_with("ERR bad-args mpdcc: "), "{bad}");
    }
    assert_eq!(parse("mpdcc run 20"), Ok(Command::Mpdcc(Some(20))));
    let r = crate::hil::HilReport {
        periods: 2,
        decisions: 2400,
        kinds: [2300, 96, 4],
        mean_cycles: 91.96,
        worst_cycles: 166,
        fsw_hz: 116.72,
        thd_percent: 7.791,
        max_i_err_pu: 0.12345,
    };
    let mut out = String::new();
    mpdcc::write_mpdcc(&mut out, &r).unwrap();
    assert_eq!(
        out,
        "mpdcc: 2 measured fundamental periods after 1 warm-up (plant on the PS, core on \
         the PL page)\r\n\
         decisions: 2400 (kept 2300, optimal 96, deadlock 4)\r\n\
         core_cycles: mean 92.0, worst 166 (PL clock cycles)\r\n\
         f_sw: 116.7 Hz\r\n\
         thd: 7.79 %\r\n\
         i_err_max: 0.1235 pu\r\n"
    );
}

#[test]
fn version_reply() {
    assert_eq!(
        reply("version"),
        "firmware 1.2.3 git abc1234 profile release\r\nOK\r\n"
    );
}

#[test]
fn status_reply_has_units() {
    let r = reply("  status  ");
    assert!(r.contains("uptime: 12.000042 s\r\n"), "{r}");
    assert!(r.contains("ticks: 12000 (rate 1000 Hz)\r\n"), "{r}");
    assert!(r.contains("gates: off (safe state)\r\n"), "{r}");
    assert!(
        r.contains("net: 10.0.2.15/24 (dhcp), socketcand tcp 29536: no client\r\n"),
        "{r}"
    );
    assert!(
        r.contains("can: 3 frames in, 2 frames out, 1 dropped, 4 errors\r\n"),
        "{r}"
    );
    assert_one_final_line(&r);
}

#[test]
fn unknown_command() {
    assert_eq!(
        reply("frobnicate 3"),
        "ERR unknown-command `frobnicate` (try `help`)\r\n"
    );
    // Names are case-sensitive.
    assert!(reply("HELP").starts_with("ERR unknown-command"));
}

#[test]
fn long_unknown_word_is_clipped_on_a_char_boundary() {
    let w = "é".repeat(40);
    let r = reply(&w);
    assert!(r.starts_with("ERR unknown-command `"), "{r}");
    assert!(r.contains("...`"), "{r}");
    assert!(r.len() < 80);
}

#[test]
fn arguments_are_checked() {
    assert_eq!(
        reply("version x"),
        "ERR bad-args version: takes no arguments\r\n"
    );
    assert_eq!(
        reply("status x y"),
        "ERR bad-args status: takes no arguments\r\n"
    );
    assert_eq!(
        reply("debug"),
        "ERR bad-args debug: expected `debug panic`, `debug abort`, `debug mmu`, `debug stall <ms>`, `debug bench`, `debug fault <f>`, `debug fault-time` or `debug flash-pace <ms>`\r\n"
    );
    assert_eq!(
        reply("help a b"),
        "ERR bad-args help: takes at most one argument\r\n"
    );
    assert_eq!(
        reply("status 1 2 3 4 5 6"),
        "ERR bad-args status: too many arguments\r\n"
    );
}

#[test]
fn debug_panic_asks_for_a_panic_and_prints_no_final_line() {
    let mut out = String::new();
    let a = execute(
        parse("debug panic").unwrap(),
        &ctx(),
        &mut TestDrive::new(),
        &mut out,
    )
    .unwrap();
    assert_eq!(a, Action::Panic);
    assert!(out.is_empty());
}

#[test]
fn every_table_entry_parses() {
    for s in COMMANDS {
        let line = if s.args.starts_with('[') || s.args.is_empty() {
            String::from(s.name)
        } else {
            std::format!("{} {}", s.name, s.args)
        };
        if !line.contains(['<', '|']) {
            assert!(parse(&line).is_ok(), "{line}");
        }
        // Every alternative of the synopsis, placeholders filled in.
        let args = s
            .args
            .replace("<Nm>", "0.1")
            .replace("<window_ms>", "2")
            .replace("<ms>", "5")
            .replace("<f>", "adc-stuck")
            .replace("<trigger>", "torque>0.2")
            .replace("<pre_samples>", "10")
            .replace("<every>", "4")
            .replace("<f_start_hz>", "100")
            .replace("<f_stop_hz>", "1000")
            .replace("<amplitude_nm>", "0.1")
            .replace("<points>", "4")
            .replace("<periods>", "2")
            .replace("<rate_hz>", "1000")
            .replace("<channels>", "torque,i_q")
            .replace("<rev/s>", "1")
            .replace("<rev>", "0.5")
            .replace("<Nm/rev>", "1")
            .replace("<Nm s/rev>", "0.01")
            .replace("<name> <value>", "j 1e-4")
            .replace(['[', ']'], "");
        for alt in args.split('|') {
            let line = std::format!("{} {}", s.name, alt);
            assert!(parse(&line).is_ok(), "{line}");
        }
    }
}

use crate::console::drive::{Bench, DriveError, DriveOps, DriveStatus, Injection, PlKind};
use crate::pl::fake::FakePl;
use crate::pl::fault::Faults;
use crate::servo::faults::FaultRecord;
use crate::servo::{Servo, ServoConfig, StepResult};

/// The console's view of a drive: the real `Servo` on the fake PL,
/// control periods run by hand.
struct TestDrive {
    servo: Servo,
    pl: FakePl,
    stalled_ms: u32,
    /// `mode mpdcc`'s loop (its progress set by hand).
    hil: Option<crate::hil::PacedStatus>,
    /// The CANopen device's state (set by hand).
    canopen: Option<crate::fieldbus::LinkStatus>,
}

impl TestDrive {
    fn new() -> Self {
        let mut servo = Servo::new(&ServoConfig::default()).unwrap();
        let mut pl = FakePl::new();
        servo.init(&mut pl).unwrap();
        Self {
            servo,
            pl,
            stalled_ms: 0,
            hil: None,
            canopen: None,
        }
    }
}

impl DriveOps for TestDrive {
    fn mode(&mut self) -> Mode {
        self.servo.mode()
    }
    fn set_mode(&mut self, m: Mode) -> Result<(), DriveError> {
        self.servo.set_mode(&mut self.pl, m)?;
        self.hil = None;
        Ok(())
    }
    fn set_mpdcc_mode(&mut self) -> Result<(), DriveError> {
        self.servo.set_mode(&mut self.pl, Mode::Off)?;
        self.hil = Some(Default::default());
        Ok(())
    }
    fn mpdcc_live(&mut self) -> Option<crate::hil::PacedStatus> {
        self.hil
    }
    fn canopen(&mut self) -> Option<crate::fieldbus::LinkStatus> {
        self.canopen
    }
    fn enable(&mut self) -> Result<(), DriveError> {
        Ok(self.servo.enable(&mut self.pl)?)
    }
    fn disable(&mut self) -> Result<(), DriveError> {
        Ok(self.servo.disable(&mut self.pl)?)
    }
    fn torque_ref(&mut self) -> f64 {
        self.servo.torque_ref_nm()
    }
    fn set_torque_ref(&mut self, nm: f64) -> Result<(), DriveError> {
        Ok(self.servo.set_torque_ref(nm)?)
    }
    fn step(&mut self, nm: f64, window_s: f64) -> Result<StepResult, DriveError> {
        self.servo.begin_step(&mut self.pl, nm, window_s)?;
        for _ in 0..2000 {
            self.servo.control_step(&mut self.pl).unwrap();
            if let Some(r) = self.servo.step_result() {
                return Ok(r);
            }
        }
        Err(DriveError::Timeout)
    }
    fn faults(&mut self) -> Result<Faults, DriveError> {
        Ok(self.servo.faults(&mut self.pl).unwrap())
    }
    fn clear_faults(&mut self) -> Result<Faults, DriveError> {
        Ok(self.servo.clear_faults(&mut self.pl)?)
    }
    fn stall(&mut self, ms: u32) -> Result<(), DriveError> {
        self.stalled_ms += ms;
        Ok(())
    }
    fn status(&mut self) -> DriveStatus {
        DriveStatus {
            mode: self.servo.mode(),
            mpdtc_autonomous: !self.servo.config().mpdtc_ps_fed,
            gates_on: self.servo.gates_on(&mut self.pl).unwrap(),
            faults: self.servo.faults(&mut self.pl).unwrap(),
            measured: self.servo.measured(),
            torque_ref_nm: self.servo.torque_ref_nm(),
            control_rate_hz: self.servo.control_rate_hz(),
            periods: self.servo.periods(),
            overruns: self.servo.overruns(),
            control_irq: self.servo.periods(),
            control_latency: crate::pl::irq::Latency {
                n: 2,
                min: 3,
                max: 9,
                sum: 12,
            },
            pl: PlKind::Simulated,
            sim_time_scale: Some(4.0),
            store: None,
            mpdcc: self.hil,
            motion: self.servo.motion_status(),
            aligning_left_s: self.servo.aligning_left_s(),
        }
    }
    fn bench(&mut self) -> Result<Bench, DriveError> {
        Err(DriveError::Unsupported)
    }
    fn config(&mut self) -> Result<ServoConfig, DriveError> {
        Ok(*self.servo.config())
    }
    fn fault_record(&mut self, k: usize) -> Result<(Option<FaultRecord>, u32), DriveError> {
        let h = self.servo.fault_history();
        Ok((h.records().nth(k).copied(), h.total))
    }
    fn inject(&mut self, f: Injection) -> Result<Option<Faults>, DriveError> {
        match f {
            Injection::AdcStuck => {
                crate::pl::adc::Adc(&mut self.pl)
                    .set_enabled(false)
                    .unwrap();
                Ok(None)
            }
            // The firmware's answers after its wait for the latch (the fake
            // PL latches nothing itself): overcurrent latched, the external
            // pulse not.
            Injection::Overcurrent | Injection::External
                if !self.servo.gates_on(&mut self.pl).unwrap() =>
            {
                Ok(None)
            }
            Injection::Overcurrent => Ok(Some(Faults(Faults::OVERCURRENT))),
            Injection::External => Err(DriveError::NotLatched(Faults::EXTERNAL)),
            _ => Err(DriveError::Unsupported),
        }
    }
    fn reconfigure(&mut self, cfg: &ServoConfig) -> Result<(), DriveError> {
        Ok(self.servo.reconfigure(&mut self.pl, cfg)?)
    }
    fn set_velocity(&mut self, v: f64) -> Result<(), DriveError> {
        Ok(self.servo.set_velocity(&mut self.pl, v)?)
    }
    fn set_position(&mut self, p: f64) -> Result<(), DriveError> {
        Ok(self.servo.set_position(&mut self.pl, p)?)
    }
    fn zero_position(&mut self) -> Result<(), DriveError> {
        Ok(self.servo.zero_position()?)
    }
    /// The move's start as the firmware's; the fake PL runs no control
    /// steps, so an accepted move can only time out here.
    fn run_move(
        &mut self,
        distance_rev: f64,
        window_s: f64,
    ) -> Result<crate::servo::motion::MoveResult, DriveError> {
        self.servo
            .begin_move(&mut self.pl, distance_rev, window_s)?;
        Err(DriveError::Timeout)
    }
    fn set_impedance(&mut self, c: &models::motion::law::Impedance) -> Result<(), DriveError> {
        Ok(self.servo.set_impedance(&mut self.pl, c)?)
    }
}

#[test]
fn outer_loop_commands_check_their_arguments_and_change_nothing() {
    let mut d = TestDrive::new();
    // Gates off: refused.
    assert!(reply_on(&mut d, "vel 1").starts_with("ERR gates-off vel:"));
    reply_on(&mut d, "mode foc");
    reply_on(&mut d, "enable");
    for (line, want) in [
        ("vel", "ERR bad-args vel: expected <rev/s>"),
        (
            "vel nan",
            "ERR bad-args vel: expected a finite number [rev/s]",
        ),
        (
            "vel 60",
            "ERR bad-args vel: 60 rev/s is beyond vel_limit (50 rev/s)",
        ),
        (
            "pos 2000",
            "ERR bad-args pos: 2000 rev is outside the soft limits [-1000..1000] rev",
        ),
        (
            "pos x",
            "ERR bad-args pos: expected a finite number [rev] or `zero`",
        ),
        ("imp 0 0 1 0", "ERR bad-args imp: expected <pos_rev>"),
        (
            "imp 0 0 -1 0 0",
            "ERR bad-args imp: kp -1 is outside [0..20]",
        ),
        ("imp 0 0 1 5 0", "ERR bad-args imp: kd 5 is outside [0..1]"),
        (
            "imp 0 0 1 0 inf",
            "ERR bad-args imp: expected five finite numbers",
        ),
        (
            "imp 0 0 1 0 2",
            "ERR bad-args imp: |torque_ff| (Nm) 2 is outside [0..1]",
        ),
        (
            "move 1 0",
            "ERR bad-args move: window must be a number of ms in (0, 500]",
        ),
        ("sim list", "ERR unsupported sim: not available here"),
        ("sim set j 1", "ERR unsupported sim: not available here"),
        (
            "sim set j x",
            "ERR bad-args sim: set: expected a finite number",
        ),
    ] {
        let r = reply_on(&mut d, line);
        assert!(r.starts_with(want), "{line}: {r}");
        assert_one_final_line(&r);
        assert!(
            reply_on(&mut d, "status").contains("loop: torque\r\n"),
            "{line}"
        );
    }
    assert_eq!(
        reply_on(&mut d, "vel 2.5"),
        "loop: velocity\r\nvelocity_target: 2.5000 rev/s\r\nOK\r\n"
    );
    let st = reply_on(&mut d, "status");
    for l in [
        "loop: velocity",
        "position: 0.000000 rev",
        "velocity: 0.0000 rev/s",
        "following_error: ",
    ] {
        assert!(st.contains(l), "{l}: {st}");
    }
    assert!(reply_on(&mut d, "pos 0.5").starts_with("loop: position\r\n"));
    // A state of the drive, not a bad argument.
    assert!(
        reply_on(&mut d, "pos zero").starts_with("ERR holding pos: the position or impedance loop")
    );
    assert!(reply_on(&mut d, "torque 0").ends_with("OK\r\n"));
    assert!(reply_on(&mut d, "status").contains("loop: torque\r\n"));
    assert_eq!(
        reply_on(&mut d, "pos zero"),
        "position: 0.000000 rev\r\nOK\r\n"
    );
    // The gates going off return to the torque loop.
    assert!(reply_on(&mut d, "imp 0 0 1 0.01 0").starts_with("loop: impedance\r\n"));
    reply_on(&mut d, "disable");
    assert!(reply_on(&mut d, "status").contains("loop: torque\r\n"));
}

#[test]
fn status_lists_the_drive_with_units() {
    let r = reply("status");
    for line in [
        "uptime: 12.000042 s",
        "ticks: 12000 (rate 1000 Hz)",
        "mode: off",
        "mpdtc_path: autonomous (PL front end, PS writes the torque reference)",
        "gates: off (safe state)",
        "fault: none",
        "torque: 0.0000 Nm",
        "torque_ref: 0.0000 Nm",
        "i_d: 0.000 A",
        "i_q: 0.000 A",
        "speed: 0.0 rad/s",
        "control_rate: 63939 Hz",
        "periods: 0",
        "overruns: 0",
        "control_irq: 0",
        "control_latency: min 3 mean 6.0 max 9 PL cycles (10 ns) after the boundary",
        "pl: simulated",
        "sim_time_scale: 4.00",
    ] {
        assert!(r.contains(&std::format!("{line}\r\n")), "{line}: {r}");
    }
    assert_one_final_line(&r);
}

#[test]
fn mode_enable_disable() {
    let mut d = TestDrive::new();
    assert_eq!(reply_on(&mut d, "mode"), "mode: off\r\nOK\r\n");
    assert_eq!(
        reply_on(&mut d, "enable"),
        "ERR mode-off enable: mode is off (set `mode foc` or `mode mpdtc` first)\r\n"
    );
    assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
    assert_eq!(reply_on(&mut d, "enable"), "gates: on\r\nOK\r\n");
    assert!(reply_on(&mut d, "status").contains("gates: on\r\n"));
    // A mode change turns the gates off.
    assert_eq!(
        reply_on(&mut d, "mode mpdtc"),
        "mode: mpdtc\r\ngates: off (safe state)\r\nOK\r\n"
    );
    assert!(reply_on(&mut d, "status").contains("gates: off (safe state)\r\n"));
    assert_eq!(
        reply_on(&mut d, "disable"),
        "gates: off (safe state)\r\nOK\r\n"
    );
}

/// `mode mpdcc`: the PMSM gates go off and stay off, the MPDCC page
/// belongs to the loop, `status` shows its progress; another mode ends it.
#[test]
fn mpdcc_mode_owns_the_page_and_keeps_the_gates_off() {
    let mut d = TestDrive::new();
    assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
    assert_eq!(reply_on(&mut d, "enable"), "gates: on\r\nOK\r\n");
    let r = reply_on(&mut d, "mode mpdcc");
    assert!(
        r.starts_with("mode: mpdcc\r\ngates: off (safe state)\r\nmpdcc_loop: started"),
        "{r}"
    );
    assert!(!d.servo.gates_on(&mut d.pl).unwrap());
    assert_eq!(d.servo.mode(), Mode::Off);
    assert_eq!(reply_on(&mut d, "mode"), "mode: mpdcc\r\nOK\r\n");
    for (line, name) in [
        ("enable", "enable"),
        ("step 0.2", "step"),
        ("sweep 10 100 0.1", "sweep"),
        ("mpdcc run", "mpdcc"),
    ] {
        let r = reply_on(&mut d, line);
        assert!(
            r.starts_with(&format!("ERR mpdcc-mode {name}: ")),
            "{line}: {r}"
        );
        assert_one_final_line(&r);
    }
    assert!(!d.servo.gates_on(&mut d.pl).unwrap());
    let mut h = crate::hil::PacedStatus::default();
    h.report.decisions = 1200;
    h.report.kinds = [900, 290, 10];
    h.report.mean_cycles = 99.04;
    h.report.worst_cycles = 173;
    h.late = 2;
    h.plant_time_s = 0.03;
    d.hil = Some(h);
    let st = reply_on(&mut d, "status");
    assert!(st.contains("\r\nmode: mpdcc\r\nmpdcc_loop: 1200 decisions (kept 900, optimal 290, deadlock 10), 2 late, plant time 30.000 ms\r\nmpdcc_cycles: mean 99.0, worst 173 PL cycles\r\nmpdcc_period: none measured yet"), "{st}");
    h.report.periods = 3;
    h.report.fsw_hz = 251.25;
    h.report.thd_percent = 4.567;
    h.report.max_i_err_pu = 0.12345;
    h.stopped = Some(crate::hil::HilError::Page(
        crate::pl::mpdcc::MpdccError::Timeout,
    ));
    d.hil = Some(h);
    let st = reply_on(&mut d, "status");
    assert!(st.contains("mpdcc_period: 3 measured; the last: f_sw 251.2 Hz, THD 4.57 %, max current error 0.1235 pu\r\nmpdcc_stopped: MPDCC page: "), "{st}");
    assert!(reply_on(&mut d, "mode off").ends_with("OK\r\n"));
    assert_eq!(reply_on(&mut d, "mode"), "mode: off\r\nOK\r\n");
    let st = reply_on(&mut d, "status");
    assert!(
        st.contains("\r\nmode: off\r\n") && !st.contains("mpdcc"),
        "{st}"
    );
}

#[test]
fn bad_mode_and_torque_arguments_change_nothing() {
    let mut d = TestDrive::new();
    assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
    assert!(reply_on(&mut d, "torque 0.25").ends_with("OK\r\n"));
    for bad in [
        "mode FOC",
        "mode 1",
        "mode foc mpdtc",
        "torque nan",
        "torque NaN",
        "torque inf",
        "torque -inf",
        "torque infinity",
        "torque 1.5",
        "torque -1.0001",
        "torque 1e3",
        "torque abc",
        "torque 0.1Nm",
        "torque 0.1 0.2",
    ] {
        let r = reply_on(&mut d, bad);
        assert!(r.starts_with("ERR bad-args "), "{bad}: {r}");
        assert_one_final_line(&r);
    }
    assert_eq!(reply_on(&mut d, "mode"), "mode: foc\r\nOK\r\n");
    assert_eq!(
        reply_on(&mut d, "torque"),
        "torque_ref: 0.2500 Nm\r\nOK\r\n"
    );
    assert_eq!(
        reply_on(&mut d, "torque -1"),
        "torque_ref: -1.0000 Nm\r\nOK\r\n"
    );
}

#[test]
fn step_needs_gates_and_prints_the_metrics() {
    let mut d = TestDrive::new();
    assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
    assert_eq!(
        reply_on(&mut d, "step 0.4"),
        "ERR gates-off step: gates are off (`enable` first)\r\n"
    );
    for bad in [
        "step",
        "step x",
        "step 0.4 0",
        "step 0.4 21",
        "step 0.4 -1",
        "step 2",
    ] {
        assert!(reply_on(&mut d, bad).starts_with("ERR bad-args "), "{bad}");
    }
    assert!(reply_on(&mut d, "enable").ends_with("OK\r\n"));
    let r = reply_on(&mut d, "step 0.4 1");
    // The fake PL has no motor: the torque stays 0, never settles.
    assert!(
        r.starts_with("settling_time: none (not settled within 1.00 ms)\r\n"),
        "{r}"
    );
    assert!(r.contains("overshoot: 0.0 %\r\n"), "{r}");
    assert!(r.contains("switching: ") && r.contains(" kHz\r\n"), "{r}");
    assert!(r.ends_with("final: 0.0000 Nm\r\nOK\r\n"), "{r}");
    assert_eq!(
        reply_on(&mut d, "torque"),
        "torque_ref: 0.4000 Nm\r\nOK\r\n"
    );
    // A step of zero (or below the resolution) has no settling time.
    for same in ["step 0.4", "step 0.42"] {
        let r = reply_on(&mut d, same);
        assert!(
            r.starts_with("ERR bad-args step: the reference is already 0.4000 Nm; a step to 0.4"),
            "{r}"
        );
        assert!(
            r.ends_with("is smaller than 0.0500 Nm and has no settling time\r\n"),
            "{r}"
        );
    }
    assert_eq!(
        reply_on(&mut d, "torque"),
        "torque_ref: 0.4000 Nm\r\nOK\r\n"
    );
}

#[test]
fn faults_are_listed_cleared_and_block_enable() {
    let mut d = TestDrive::new();
    d.pl.set(regmap::FAULT_STATUS_ADDR, Faults::WATCHDOG | 1);
    assert_eq!(
        reply_on(&mut d, "fault"),
        "fault: OVERCURRENT WATCHDOG\r\nOK\r\n"
    );
    assert!(reply_on(&mut d, "mode mpdtc").ends_with("OK\r\n"));
    assert_eq!(
        reply_on(&mut d, "enable"),
        "ERR fault-latched enable: fault latched: OVERCURRENT WATCHDOG (`fault clear` first)\r\n"
    );
    assert!(reply_on(&mut d, "status").contains("fault: OVERCURRENT WATCHDOG\r\n"));
    assert_eq!(
        reply_on(&mut d, "fault clear"),
        "fault: none\r\ngates: off (safe state)\r\nOK\r\n"
    );
    assert_eq!(reply_on(&mut d, "fault x").lines().count(), 1);
    assert_eq!(reply_on(&mut d, "enable"), "gates: on\r\nOK\r\n");
}

#[test]
fn debug_stall_and_bench_arguments() {
    let mut d = TestDrive::new();
    assert_eq!(
        reply_on(&mut d, "debug stall 300"),
        "stalled: 300 ms\r\nOK\r\n"
    );
    assert_eq!(d.stalled_ms, 300);
    for bad in [
        "debug stall",
        "debug stall 0",
        "debug stall -5",
        "debug stall 10001",
        "debug stall 1.5",
    ] {
        assert!(reply_on(&mut d, bad).starts_with("ERR bad-args "), "{bad}");
    }
    assert_eq!(d.stalled_ms, 300);
    assert_eq!(
        reply_on(&mut d, "debug bench"),
        "ERR unsupported debug: not available here\r\n"
    );
}

#[test]
fn config_list_get_set_reset_schema() {
    let mut d = TestDrive::new();
    let r = reply_on(&mut d, "config list");
    let lines: std::vec::Vec<&str> = r.trim_end().split("\r\n").collect();
    assert_eq!(lines.len(), crate::config::N_PARAMS + 1, "{r}");
    assert!(lines.contains(&"mpdtc_t_tol = 0.08 Nm  [0..0.5]  MPDTC torque tolerance band T_tol"));
    assert!(lines.contains(&"dead_time = 50 cycles  [0..1023]  inverter dead time (DEAD_TIME), PL clock cycles of 10 ns"));
    assert_one_final_line(&r);
    assert_eq!(
        reply_on(&mut d, "config get mpdtc_t_tol"),
        "mpdtc_t_tol = 0.08 Nm\r\nOK\r\n"
    );
    assert_eq!(
        reply_on(&mut d, "config set mpdtc_t_tol 0.05"),
        "mpdtc_t_tol = 0.05 Nm\r\nOK\r\n"
    );
    assert_eq!(
        reply_on(&mut d, "config get mpdtc_t_tol"),
        "mpdtc_t_tol = 0.05 Nm\r\nOK\r\n"
    );
    let r = reply_on(&mut d, "config schema");
    assert_eq!(r.matches("\r\n").count(), 2, "{r}");
    assert!(r.starts_with("[{\"name\":\"motor_r_s\""), "{r}");
    assert!(r.ends_with("]\r\nOK\r\n"), "{r}");
    assert_eq!(
        reply_on(&mut d, "config reset"),
        "config: defaults\r\nOK\r\n"
    );
    assert_eq!(
        reply_on(&mut d, "config get mpdtc_t_tol"),
        "mpdtc_t_tol = 0.08 Nm\r\nOK\r\n"
    );
}

#[test]
fn config_bad_input_changes_nothing() {
    let mut d = TestDrive::new();
    let before = *d.servo.config();
    for (bad, msg) in [
        ("config", "config: expected `config list|get <name>|set <name> <value>|reset|schema|save`"),
        ("config set mpdtc_t_tol", "config: expected `config list|get <name>|set <name> <value>|reset|schema|save`"),
        ("config get nothing", "config: nothing: no such parameter (see `config list`)"),
        ("config set nothing 1", "config: nothing: no such parameter (see `config list`)"),
        ("config set mpdtc_t_tol nan", "config: mpdtc_t_tol: expected a finite number"),
        ("config set mpdtc_t_tol inf", "config: mpdtc_t_tol: expected a finite number"),
        ("config set mpdtc_t_tol -inf", "config: mpdtc_t_tol: expected a finite number"),
        ("config set mpdtc_t_tol 0.1Nm", "config: mpdtc_t_tol: expected a finite number"),
        ("config set mpdtc_t_tol 0.6", "config: mpdtc_t_tol: out of range [0..0.5] Nm"),
        ("config set motor_pole_pairs 7.5", "config: motor_pole_pairs: expected a whole number"),
        ("config set obs_kp 1000", "config: obs_kp: invalid parameter `obs_kp_v_per_a`: observer unstable: roots of eq. (16) outside the unit circle"),
    ] {
        assert_eq!(
            reply_on(&mut d, bad),
            std::format!("ERR bad-args {msg}\r\n"),
            "{bad}"
        );
    }
    assert_eq!(d.servo.config(), &before);
    // With the gates on, only the torque limit may change.
    assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
    assert!(reply_on(&mut d, "enable").ends_with("OK\r\n"));
    assert_eq!(
        reply_on(&mut d, "config set mpdtc_t_tol 0.05"),
        "ERR gates-on config: needs the gates off (`disable` first)\r\n"
    );
    assert_eq!(d.servo.config(), &before);
    assert_eq!(
        reply_on(&mut d, "config set torque_limit 0.5"),
        "torque_limit = 0.5 Nm\r\nOK\r\n"
    );
    assert!(reply_on(&mut d, "torque 0.6").starts_with("ERR bad-args "));
    assert_eq!(
        reply_on(&mut d, "config reset"),
        "config: defaults\r\nOK\r\n"
    );
    assert_eq!(d.servo.config(), &before);
}

#[test]
fn selftest_debug_mmu_and_abort_where_unsupported() {
    assert_eq!(
        reply("selftest"),
        "ERR bad-args selftest: expected `selftest sensors`\r\n"
    );
    assert_eq!(
        reply("selftest sensors now"),
        "ERR bad-args selftest: expected `selftest sensors`\r\n"
    );
    // The test drive has no sensor check, MMU or abort: refused, nothing
    // printed before the final line.
    for line in ["selftest sensors", "debug mmu", "debug abort"] {
        let r = reply(line);
        assert!(r.starts_with("ERR unsupported "), "{line}: {r}");
        assert_one_final_line(&r);
    }
    assert_eq!(parse("debug abort"), Ok(Command::Debug(DebugCmd::Abort)));
    assert_eq!(parse("debug mmu"), Ok(Command::Debug(DebugCmd::Mmu)));
}

#[test]
fn debug_mmu_lines_by_hand() {
    use crate::mmu::{section_entry, Region, USED};
    let regions = core::array::from_fn(|i| {
        let a = USED[i].1;
        let r = crate::mmu::region_of(a);
        let par = if r == Region::Fault { 0xB } else { a & !0xFFF };
        (section_entry(a >> 20, r), par)
    });
    let m = drive::MmuReport {
        // M, C, Z, I and the reset-one bits QEMU shows.
        sctlr: 0x00c5_187d,
        l2_id: 0,
        l2_ctrl: 0,
        ttbr0: 0x0090_8048,
        regions,
    };
    let mut out = String::new();
    debug::write_mmu(&mut out, &m).unwrap();
    let lines: std::vec::Vec<&str> = out.split("\r\n").collect();
    assert_eq!(lines[0], "caches: on");
    assert_eq!(
        lines[1],
        "sctlr: 0x00c5187d (mmu on, d-cache on, i-cache on, branch prediction on)"
    );
    assert_eq!(
        lines[2],
        "l2: absent (PL310 CACHE_ID 0x00000000, CTRL 0x00000000)"
    );
    assert!(out.contains(
        "region uart1 0xe0001000: device, execute-never (entry 0xe0010c16, pa 0xe0001000)"
    ));
    assert!(out.contains(
        "region gp1-unused 0x80000000: fault (unmapped) (entry 0x00000000, translation faults)"
    ));
    // A PL310 left off is not `caches: on`; the D-cache off neither.
    let off = drive::MmuReport {
        l2_id: 0x4100_00C8,
        ..m
    };
    assert!(!off.caches_on());
    assert!(!drive::MmuReport {
        sctlr: 0x00c5_1879,
        ..m
    }
    .caches_on());
    assert!(drive::MmuReport { l2_ctrl: 1, ..off }.caches_on());
}

/// A board booted without a usable PL: what the firmware's drive answers
/// when presence detection found nothing it may drive.
struct NoPl;

impl DriveOps for NoPl {
    fn mode(&mut self) -> Mode {
        Mode::Off
    }
    fn set_mode(&mut self, _m: Mode) -> Result<(), DriveError> {
        Err(DriveError::Absent)
    }
    fn enable(&mut self) -> Result<(), DriveError> {
        Err(DriveError::Absent)
    }
    fn disable(&mut self) -> Result<(), DriveError> {
        Err(DriveError::Absent)
    }
    fn torque_ref(&mut self) -> f64 {
        0.0
    }
    fn set_torque_ref(&mut self, _nm: f64) -> Result<(), DriveError> {
        Err(DriveError::Absent)
    }
    fn step(&mut self, _nm: f64, _window_s: f64) -> Result<StepResult, DriveError> {
        Err(DriveError::Absent)
    }
    fn faults(&mut self) -> Result<Faults, DriveError> {
        Err(DriveError::Absent)
    }
    fn clear_faults(&mut self) -> Result<Faults, DriveError> {
        Err(DriveError::Absent)
    }
    fn stall(&mut self, _ms: u32) -> Result<(), DriveError> {
        Err(DriveError::Absent)
    }
    fn status(&mut self) -> DriveStatus {
        DriveStatus::absent(None)
    }
    fn bench(&mut self) -> Result<Bench, DriveError> {
        Err(DriveError::Unsupported)
    }
}

#[test]
fn board_without_bitstream_says_pl_absent_and_refuses_drive_commands() {
    use crate::pl::presence::{detect, platform, select, Guard, PCFG_DONE};
    let guard = |int_sts| Guard {
        int_sts,
        lvl_shftr_en: 0xF,
        fpga_rst_ctrl: 0,
    };
    // A ZedBoard booted without our bitstream: devcfg says unconfigured,
    // PSS_IDCODE is an XC7Z020's (GP0 is not read: no bus is passed).
    let mut gp0 = FakePl::new();
    let sel = select(detect(&guard(0), &mut gp0), platform(0x3372_7093));
    assert_eq!(PlKind::of(sel, false), PlKind::Absent);
    assert_eq!(PlKind::of(sel, false).to_string(), "absent");
    // The same reads under QEMU (PSS_IDCODE 0): the simulated PL.
    let qemu = select(detect(&guard(0), &mut gp0), platform(0));
    assert_eq!(PlKind::of(qemu, false), PlKind::Simulated);
    assert_eq!(PlKind::of(qemu, true), PlKind::RtlCosim);
    // A foreign bitstream on the board: absent as well.
    gp0.set(regmap::TOP.addr(&regmap::ID), 0x1234_5678);
    let foreign = select(detect(&guard(PCFG_DONE), &mut gp0), platform(0x3372_7093));
    assert_eq!(PlKind::of(foreign, false), PlKind::Absent);

    let mut d = NoPl;
    let mut out = String::new();
    execute(parse("status").unwrap(), &ctx(), &mut d, &mut out).unwrap();
    assert!(out.contains("pl: absent\r\n"), "{out:?}");
    assert!(!out.contains("simulated"), "{out:?}");
    for line in [
        "enable",
        "mode foc",
        "torque 0.1",
        "step 0.2",
        "fault",
        "debug stall 5",
    ] {
        let mut out = String::new();
        execute(parse(line).unwrap(), &ctx(), &mut d, &mut out).unwrap();
        assert_one_final_line(&out);
        assert!(out.starts_with("ERR pl-absent "), "{line}: {out:?}");
        assert!(out.contains("bitstream"), "{line}: the hint: {out:?}");
    }
}

#[test]
fn position_commands_during_the_mpdtc_alignment_answer_aligning_and_change_nothing() {
    let mut d = TestDrive::new();
    reply_on(&mut d, "mode mpdtc");
    assert!(reply_on(&mut d, "enable").ends_with("OK\r\n"));
    let st = reply_on(&mut d, "status");
    // The configured 0.2 s, none of it gone yet.
    assert!(
        st.contains("alignment: running, at most 200 ms left (pos, vel, imp wait for its end)\r\n"),
        "{st}"
    );
    for (line, cmd) in [
        ("pos zero", "pos"),
        ("pos 0.5", "pos"),
        ("vel 1", "vel"),
        ("imp 0 0 1 0.01 0", "imp"),
    ] {
        let r = reply_on(&mut d, line);
        assert_eq!(
            r,
            std::format!(
                "ERR aligning {cmd}: the MPDTC's rotor alignment still turns the rotor (at most \
                 200 ms left, less once it is still); nothing changed, retry after it\r\n"
            ),
            "{line}"
        );
        assert_eq!(reply_on(&mut d, "status"), st, "{line}");
    }
    // FOC has no alignment.
    reply_on(&mut d, "mode foc");
    reply_on(&mut d, "enable");
    assert!(!reply_on(&mut d, "status").contains("alignment:"));
    assert!(reply_on(&mut d, "pos zero").ends_with("OK\r\n"));
}

/// The caller counts a line as an error from what `execute` returns: it
/// must say `Refused` exactly when the reply's final line is `ERR`, for
/// the drive's own refusals (state, limits) as much as for the grammar's.
#[test]
fn execute_says_refused_exactly_when_the_reply_ends_with_err() {
    let mut d = TestDrive::new();
    let mut refused = 0;
    let lines = [
        "version",
        "enable",       // mode off: ERR mode-off
        "step 0.2",     // gates off
        "help nope",    // no such command
        "capture dump", // no record
        "tel status",   // no stream in this build
        "mode foc",
        "enable",
        "torque 0.1",
        "pos 0.5",
        "pos zero", // holding
        "vel 1e9",  // beyond vel_limit
        "pos 1e9",  // beyond the soft limits
        "torque 0",
        "status",
    ];
    for line in lines {
        let mut out = String::new();
        let a = execute(parse(line).unwrap(), &ctx(), &mut d, &mut out).unwrap();
        assert_one_final_line(&out);
        let last = out.trim_end().rsplit("\r\n").next().unwrap();
        let err = last.starts_with("ERR ");
        assert_eq!(a == Action::Refused, err, "{line}: {out:?}");
        assert_eq!(a == Action::None, !err, "{line}: {out:?}");
        refused += usize::from(err);
    }
    // The ERR replies of the list above, counted by hand.
    assert_eq!(refused, 8);
}

/// A `move` or `pos` beyond the soft limits (default +-1000 rev) is
/// refused as such before anything else, gates on or off: one `ERR` line
/// with the limits and units, and nothing changes.
#[test]
fn move_and_pos_beyond_the_soft_limits_are_refused_first_and_change_nothing() {
    let mut d = TestDrive::new();
    let want_move = "ERR bad-args move: outside the soft limits [-1000..1000] rev (pos_min, \
                     pos_max): a move by 1000000000 rev from 0.000000 rev would end at \
                     1000000000.000000 rev; nothing changed\r\n";
    let want_pos = "ERR bad-args pos: 1000000000 rev is outside the soft limits [-1000..1000] rev \
         (pos_min, pos_max)\r\n";
    for setup in [None, Some("mode foc"), Some("enable")] {
        if let Some(l) = setup {
            reply_on(&mut d, l);
        }
        let before = reply_on(&mut d, "status");
        assert_eq!(reply_on(&mut d, "move 1e9"), want_move, "{setup:?}");
        assert_eq!(reply_on(&mut d, "pos 1e9"), want_pos, "{setup:?}");
        // One step back inside: the end is checked, not the distance.
        assert!(
            reply_on(&mut d, "move -1000.5").starts_with("ERR bad-args move: outside the soft"),
            "{setup:?}"
        );
        assert_eq!(reply_on(&mut d, "status"), before, "{setup:?}");
    }
    // The last setup took effect: the refusals above came with the gates on.
    assert!(reply_on(&mut d, "status").contains("gates: on\r\n"));
}

/// `gp0_guard:` says a failed guard is expected only where the simulated
/// PL (or the co-simulated RTL) answers, which presence detection picks
/// only in an emulator; on a board the failure stands without the note.
#[test]
fn gp0_guard_failure_is_called_expected_only_under_the_emulator() {
    use crate::pl::presence::{Guard, PCFG_DONE};
    // What QEMU reads (the banner and `status` print it).
    let qemu = Guard {
        int_sts: 0,
        lvl_shftr_en: 0,
        fpga_rst_ctrl: 0x01f3_3f0f,
    };
    let line = |g: &Guard, pl: PlKind| {
        let mut out = String::new();
        info::write_guard(&mut out, g, pl).unwrap();
        out
    };
    let fail = "gp0_guard: fail: devcfg INT_STS.PCFG_DONE clear (PL not configured) (INT_STS \
                0x00000000, LVL_SHFTR_EN 0x0, FPGA_RST_CTRL 0x01f33f0f)";
    let sim = line(&qemu, PlKind::Simulated);
    assert!(sim.starts_with(fail), "{sim}");
    assert!(
        sim.contains(
            "; expected under QEMU (PSS_IDCODE reads as an emulator's): no real PL \
                      behind GP0, so GP0 is left alone and the simulated PL answers"
        ),
        "{sim}"
    );
    assert!(line(&qemu, PlKind::RtlCosim).contains("the co-simulated RTL"));
    // A board without our bitstream reads the same words: no QEMU note.
    assert_eq!(line(&qemu, PlKind::Absent), std::format!("{fail}\r\n"));
    // A passing guard never gets it.
    let board = Guard {
        int_sts: PCFG_DONE,
        lvl_shftr_en: 0xF,
        fpga_rst_ctrl: 0,
    };
    let pass = line(&board, PlKind::Bitstream(0x0001_0000));
    assert!(
        pass.starts_with("gp0_guard: pass (") && !pass.contains("QEMU"),
        "{pass}"
    );
}

/// `debug fault` with the gates on answers once the fault latched, naming
/// it, or `ERR timeout` naming the fault that did not latch.
#[test]
fn debug_fault_reports_the_latched_fault_or_that_it_did_not_latch() {
    let mut d = TestDrive::new();
    assert_eq!(
        reply_on(&mut d, "debug fault overcurrent"),
        "injected\r\nOK\r\n"
    );
    reply_on(&mut d, "mode foc");
    reply_on(&mut d, "enable");
    assert_eq!(
        reply_on(&mut d, "debug fault overcurrent"),
        "injected\r\nfault: OVERCURRENT\r\nOK\r\n"
    );
    assert_eq!(
        reply_on(&mut d, "debug fault external"),
        "ERR timeout debug: EXTERNAL did not latch within 4 control periods of the injection \
         (gates still on)\r\n"
    );
    // Hand-checked bits: FAULT_STATUS bit 0 is OVERCURRENT, bit 1 EXTERNAL.
    assert_eq!((Faults::OVERCURRENT, Faults::EXTERNAL), (1, 2));
}

/// While a CANopen master owns the motor, every command that moves it or
/// changes how it is driven is refused with `canopen-owns` and changes
/// nothing; queries, `disable`, `config get` and `status` answer, and
/// `status` shows the device.
#[test]
fn a_canopen_master_owns_the_motor() {
    use canopen::cia402::State;
    use canopen::nmt::NmtState;
    let mut d = TestDrive::new();
    assert!(reply_on(&mut d, "mode foc").ends_with("OK\r\n"));
    let mut st = crate::fieldbus::LinkStatus {
        node_id: 1,
        nmt: NmtState::Operational,
        state: State::OperationEnabled,
        mode: 8,
        counters: Default::default(),
        owns: true,
    };
    st.counters.syncs = 12;
    d.canopen = Some(st);
    for line in [
        "enable",
        "mode mpdtc",
        "torque 0.1",
        "step 0.2",
        "vel 1",
        "pos 1",
        "pos zero",
        "imp 0 0 1 0 0",
        "move 1",
        "sweep 100 1000 0.1",
        "calibrate all",
        "selftest sensors",
        "config set mpdtc_t_tol 0.05",
        "config reset",
    ] {
        let r = reply_on(&mut d, line);
        let name = line.split(' ').next().unwrap();
        assert!(
            r.starts_with(&format!(
                "ERR canopen-owns {name}: a CANopen master commands the motor"
            )),
            "{line}: {r}"
        );
        assert_one_final_line(&r);
    }
    assert_eq!(d.servo.mode(), Mode::Foc);
    assert_eq!(
        reply_on(&mut d, "config get mpdtc_t_tol"),
        "mpdtc_t_tol = 0.08 Nm\r\nOK\r\n"
    );
    for line in ["mode", "torque", "disable", "fault", "config list", "tel"] {
        let r = reply_on(&mut d, line);
        assert!(!r.contains("canopen-owns"), "{line}: {r}");
    }
    let r = reply_on(&mut d, "status");
    assert!(
        r.contains("\r\ncanopen: node 1, nmt operational, cia402 operation-enabled, mode 8 (csp), syncs 12, rpdos 0, tpdos 0, sdos 0, errors 0, owns the motor\r\n"),
        "{r}"
    );
    // Out of operation enabled, the console commands again.
    d.canopen = Some(crate::fieldbus::LinkStatus {
        state: State::SwitchOnDisabled,
        owns: false,
        ..st
    });
    assert!(reply_on(&mut d, "mode mpdtc").ends_with("OK\r\n"));
}
