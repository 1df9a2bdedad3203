//! `drivectl ui` in a real browser: Debian's Chromium (headless) through
//! chromedriver's WebDriver protocol (W3C, plain HTTP/JSON), against the
//! release firmware in QEMU. The page loads; the live plot streams without
//! a click (its button offers `stop`) and its axes carry units; a value set
//! in the configuration editor reads back with `config get` typed into the
//! page's console; an out-of-range value and a non-number are refused in
//! the page and the drive keeps its value; a `step` run from the page plots
//! its record with the torques and the currents on axes of their own, and
//! the experiment buttons are off while it runs (a sweep clicked meanwhile
//! does not start) and back on after it, also after a refused step; a sweep
//! over the page's default range finds a -3 dB bandwidth; a console command
//! gets its reply. At 1280x800 and 1920x1080 every panel lies inside the
//! viewport and the document does not scroll sideways. Saves screenshots
//! to `target/ui/drive-page.png` (the README's), and
//! `target/ui/drive-page-1280x800.png`, `-1920x1080.png`.
//!
//! Needs `chromium`, `chromium-driver` (scripts/setup) and the release
//! firmware; `scripts/test` runs it (`--include-ignored`).
use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::os::unix::process::CommandExt;
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// Kills a process group when dropped (the test's children and theirs:
/// QEMU under `drivectl ui`, Chromium under chromedriver).
struct Group(Child);

impl Drop for Group {
    fn drop(&mut self) {
        // SAFETY: kill(2) on the group this test created.
        unsafe { libc::kill(-(self.0.id() as i32), libc::SIGKILL) };
        let _ = self.0.wait();
    }
}

fn spawn_group(c: &mut Command) -> Group {
    Group(
        c.process_group(0)
            .spawn()
            .unwrap_or_else(|e| panic!("{c:?}: {e} (run scripts/setup)")),
    )
}

fn free_port() -> u16 {
    let l = std::net::TcpListener::bind("127.0.0.1:0").unwrap();
    l.local_addr().unwrap().port()
}

/// One HTTP/1.1 request to chromedriver; the JSON body of the answer.
fn http(port: u16, method: &str, path: &str, body: Option<&Value>) -> std::io::Result<Value> {
    let mut s = TcpStream::connect(("127.0.0.1", port))?;
    s.set_read_timeout(Some(Duration::from_secs(120)))?;
    let body = body.map(Value::to_string).unwrap_or_default();
    write!(
        s,
        "{method} {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nContent-Type: application/json\r\n\
         Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    )?;
    // chromedriver keeps the connection open: read by Content-Length.
    let mut r = BufReader::new(s);
    let mut len = None;
    loop {
        let mut line = String::new();
        if r.read_line(&mut line)? == 0 || line == "\r\n" {
            break;
        }
        let l = line.to_ascii_lowercase();
        if let Some(v) = l.strip_prefix("content-length:") {
            len = v.trim().parse::<usize>().ok();
        }
    }
    let mut body = vec![0u8; len.unwrap_or(0)];
    r.read_exact(&mut body)?;
    let payload = String::from_utf8_lossy(&body);
    Ok(serde_json::from_str(&payload).unwrap_or(Value::Null))
}

struct Browser {
    port: u16,
    session: String,
}

impl Browser {
    fn call(&self, method: &str, path: &str, body: Option<Value>) -> Value {
        let p = format!("/session/{}{path}", self.session);
        let v = http(self.port, method, &p, body.as_ref()).expect("chromedriver answers");
        if v["value"].get("error").is_some() {
            panic!("{method} {path}: {}", v["value"]);
        }
        v["value"].clone()
    }
    fn js(&self, script: &str) -> Value {
        self.call(
            "POST",
            "/execute/sync",
            Some(json!({"script": script, "args": []})),
        )
    }
    /// `script`'s value after two animation frames: the layout, the resize
    /// observers and the plots' redraws that a window change causes are
    /// done by then.
    fn js_after_frames(&self, script: &str) -> Value {
        let body = format!(
            "const done = arguments[arguments.length - 1];\n\
             const f = () => {{ {script} }};\n\
             requestAnimationFrame(() => requestAnimationFrame(() => done(f())));"
        );
        self.call(
            "POST",
            "/execute/async",
            Some(json!({"script": body, "args": []})),
        )
    }
    fn screenshot(&self, path: &std::path::Path) {
        let png = self.call("GET", "/screenshot", None);
        let png = decode_base64(png.as_str().expect("base64 PNG"));
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        std::fs::write(path, &png).unwrap();
        eprintln!("screenshot: {} ({} bytes)", path.display(), png.len());
    }
    fn el(&self, css: &str) -> String {
        let v = self.call(
            "POST",
            "/element",
            Some(json!({"using": "css selector", "value": css})),
        );
        v.as_object()
            .and_then(|o| o.values().next())
            .and_then(Value::as_str)
            .unwrap_or_else(|| panic!("no element {css}"))
            .to_string()
    }
    fn click(&self, css: &str) {
        let e = self.el(css);
        self.call("POST", &format!("/element/{e}/click"), Some(json!({})));
    }
    fn type_into(&self, css: &str, text: &str) {
        let e = self.el(css);
        self.call("POST", &format!("/element/{e}/clear"), Some(json!({})));
        self.call(
            "POST",
            &format!("/element/{e}/value"),
            Some(json!({"text": text})),
        );
    }
    fn text(&self, css: &str) -> String {
        let e = self.el(css);
        self.call("GET", &format!("/element/{e}/text"), None)
            .as_str()
            .unwrap_or("")
            .to_string()
    }
    /// Waits until `f` holds (at most `secs` seconds).
    fn wait_for(&self, what: &str, secs: u64, mut f: impl FnMut(&Self) -> bool) {
        let end = Instant::now() + Duration::from_secs(secs);
        while !f(self) {
            assert!(Instant::now() < end, "timeout waiting for {what}");
            std::thread::sleep(Duration::from_millis(200));
        }
    }
    /// Types `line` into the page's console and waits for its final line.
    fn console(&self, line: &str) -> String {
        let before = self.js("return document.getElementById('console-log').textContent.length");
        let before = before.as_u64().unwrap_or(0) as usize;
        self.type_into("#console-input", &format!("{line}\n"));
        let mut out = String::new();
        self.wait_for(&format!("reply to {line}"), 60, |b| {
            let log = b
                .js("return document.getElementById('console-log').textContent")
                .as_str()
                .unwrap_or("")
                .to_string();
            out = log.get(before..).unwrap_or("").to_string();
            out.starts_with(&format!("> {line}\n"))
                && (out.contains("\nOK\n") || out.contains("\nERR "))
        });
        out
    }
}

fn decode_base64(s: &str) -> Vec<u8> {
    let val = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        _ => 63,
    };
    let bytes: Vec<u8> = s.bytes().filter(|&c| c != b'=' && c != b'\n').collect();
    let mut out = Vec::with_capacity(bytes.len() * 3 / 4);
    for ch in bytes.chunks(4) {
        let v: Vec<u32> = ch.iter().map(|&c| u32::from(val(c))).collect();
        let w = v.iter().fold(0u32, |a, &x| a << 6 | x) << (6 * (4 - v.len()));
        out.extend_from_slice(&w.to_be_bytes()[1..v.len()]);
    }
    out
}

/// The layout as the test checks it: the window's inner size, the
/// viewport's width without a scroll bar, the document's width, and the
/// boxes of the panels (each section) and of the parts inside a section
/// (the drive's status and fault boxes, plots, text boxes, the table, the
/// rows of controls), each with its section's box.
const LAYOUT_JS: &str = "
  const box = (e) => { const r = e.getBoundingClientRect();
    return { left: r.left, right: r.right, top: r.top, bottom: r.bottom }; };
  const boxes = [];
  for (const s of document.querySelectorAll('main > section')) {
    boxes.push(Object.assign({ name: '#' + s.id, panel: null }, box(s)));
    const parts = s.querySelectorAll('.cols > div, pre, .uplot, .scroll-x, .row');
    parts.forEach((e, k) => boxes.push(Object.assign({
      name: '#' + s.id + ' ' + (e.id ? '#' + e.id : e.tagName.toLowerCase() + '.' + e.className + '[' + k + ']'),
      panel: box(s) }, box(e))));
  }
  return { inner: [window.innerWidth, window.innerHeight],
           viewport: document.documentElement.clientWidth,
           document: document.documentElement.scrollWidth, boxes };";

#[test]
#[ignore = "needs chromium and chromium-driver (scripts/setup); scripts/test runs it"]
fn the_page_drives_the_firmware_in_a_real_browser() {
    // Canonical: Chromium's profile path must not hold `..` (chromedriver
    // then cannot find the DevTools port file).
    let target = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../target")
        .canonicalize()
        .expect("target directory");
    let elf = drivectl::link::default_elf();
    assert!(elf.is_file(), "build the firmware first (cargo fw-build)");
    let flash = target.join("run/tests/ui-browser.img");
    let _ = std::fs::remove_file(&flash);
    std::fs::create_dir_all(flash.parent().unwrap()).unwrap();

    // The page's server against QEMU, on a free loopback port.
    let mut ui = spawn_group(
        Command::new(env!("CARGO_BIN_EXE_drivectl"))
            .args(["ui", "--fresh", "--listen", "127.0.0.1:0", "--flash"])
            .arg(&flash)
            .arg("--elf")
            .arg(&elf)
            .stdout(Stdio::piped())
            .stdin(Stdio::null()),
    );
    let mut first = String::new();
    // Kept open to the end: drivectl dies of SIGPIPE on a closed stdout.
    let mut ui_out = BufReader::new(ui.0.stdout.take().unwrap());
    ui_out.read_line(&mut first).unwrap();
    assert!(first.contains("loopback only"), "{first}");
    let url = first
        .split_whitespace()
        .find(|w| w.starts_with("http://127.0.0.1:"))
        .unwrap_or_else(|| panic!("no address in {first:?}"))
        .to_string();

    // Chromium through chromedriver, headless, a fresh profile.
    let port = free_port();
    let _driver = spawn_group(
        Command::new("chromedriver")
            .arg(format!("--port={port}"))
            .stdout(Stdio::null())
            .stderr(Stdio::null()),
    );
    let t0 = Instant::now();
    while http(port, "GET", "/status", None).map_or(true, |v| v["value"]["ready"] != true) {
        assert!(
            t0.elapsed() < Duration::from_secs(20),
            "chromedriver not ready"
        );
        std::thread::sleep(Duration::from_millis(100));
    }
    let profile = target.join(format!("ui/chromium-profile-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&profile);
    std::fs::create_dir_all(&profile).unwrap();
    // Debian's /usr/bin/chromium is a shell wrapper; the browser itself:
    let chromium = ["/usr/lib/chromium/chromium", "/usr/bin/chromium"]
        .into_iter()
        .find(|p| std::path::Path::new(p).is_file())
        .expect("chromium installed (scripts/setup)");
    let caps = json!({"capabilities": {"alwaysMatch": {
        "browserName": "chrome",
        "goog:chromeOptions": {
            "binary": chromium,
            "args": [
                "--headless=new", "--no-sandbox", "--disable-gpu",
                "--disable-background-networking", "--disable-component-update",
                "--disable-sync", "--no-first-run", "--window-size=1500,1900",
                format!("--user-data-dir={}", profile.display()),
            ],
        },
    }}});
    let v = http(port, "POST", "/session", Some(&caps)).expect("new session");
    let session = v["value"]["sessionId"]
        .as_str()
        .unwrap_or_else(|| panic!("no session: {v}"))
        .to_string();
    let b = Browser { port, session };

    // The page loads: channels from `tel list`, the editor from the schema.
    b.call("POST", "/url", Some(json!({"url": url})));
    b.wait_for("the page to load", 60, |b| {
        b.js("return document.body.dataset.ready") == json!("1")
    });
    assert_eq!(b.js("return typeof uPlot"), json!("function"));
    assert!(b.text("#cfg-table").contains("torque_limit"));

    // Live plot: it streams from the page's start, no click; the button
    // offers to stop it. The point count grows.
    assert_eq!(b.text("#tel-run"), "stop");
    let points = |b: &Browser| {
        b.js("return tel.plot ? tel.plot.data[0].length : 0")
            .as_u64()
            .unwrap_or(0)
    };
    b.wait_for("telemetry points", 60, |b| points(b) > 20);
    let n1: u64 = b.text("#tel-points").parse().unwrap();
    b.wait_for("more telemetry points", 60, |b| {
        b.text("#tel-points").parse::<u64>().unwrap_or(0) > n1 + 20
    });
    assert_eq!(b.text("#tel-lost"), "0");
    // Its axes: drive time in s; the default channels (i_q in A, torque
    // and torque_ref in N m, in `tel list`'s order) on one axis per unit.
    let axes = b.js("return tel.plot.axes.map((a) => [a.scale, a.label])");
    assert_eq!(
        axes,
        json!([["x", "drive time [s]"], ["A", "A"], ["Nm", "N m"]]),
        "live plot axes"
    );
    let series = b.js("return tel.plot.series.slice(1).map((s) => [s.label, s.scale])");
    assert_eq!(
        series,
        json!([
            ["i_q [A]", "A"],
            ["torque [N m]", "Nm"],
            ["torque_ref [N m]", "Nm"]
        ]),
        "live plot series"
    );

    // A parameter set in the editor reads back through the console.
    b.type_into("#cfg-torque_limit", "0.8");
    b.click("#cfg-set-torque_limit");
    b.wait_for("the set to be acknowledged", 30, |b| {
        b.text("#cfg-msg-torque_limit") == "set"
    });
    let r = b.console("config get torque_limit");
    assert!(r.contains("torque_limit = 0.8 Nm"), "{r}");

    // Out of range (the schema says 0.01..5 Nm) and not a number: refused
    // in the page, nothing sent,
    // the drive keeps 0.8.
    for bad in ["6", "abc"] {
        b.type_into("#cfg-torque_limit", bad);
        b.click("#cfg-set-torque_limit");
        let m = b.text("#cfg-msg-torque_limit");
        assert!(m.starts_with("refused:"), "{bad}: {m}");
        let log = b.text("#console-log");
        assert!(
            !log.contains(&format!("config set torque_limit {bad}")),
            "{log}"
        );
    }
    let r = b.console("config get torque_limit");
    assert!(r.contains("torque_limit = 0.8 Nm"), "{r}");

    // A step from the page: FOC, gates on, then the record's plot. The
    // experiment buttons go off with the click: read in the script that
    // clicks, so that the step cannot have ended in between.
    b.js("document.getElementById('mode').value = 'foc'");
    b.click("#mode-set");
    b.click("#enable");
    b.wait_for("gates on", 30, |b| b.text("#status").contains("gates: on"));
    b.type_into("#step-nm", "0.4");
    const DISABLED: &str = "return ['step-run', 'sweep-run', 'capture-run']\
                            .map((id) => document.getElementById(id).disabled)";
    // A sweep and a capture clicked during the step (same script: the step
    // is still running) do not start.
    let during = b.js(&format!(
        "document.getElementById('step-run').click();
         document.getElementById('sweep-run').click();
         document.getElementById('capture-run').click(); {DISABLED}"
    ));
    assert_eq!(during, json!([true, true, true]), "buttons during the step");
    b.wait_for("the step's plot", 120, |b| {
        b.js("return Number(document.getElementById('step-plot').dataset.points || 0)")
            .as_u64()
            .unwrap_or(0)
            > 100
    });
    assert!(
        b.text("#step-result").contains("settling"),
        "{}",
        b.text("#step-result")
    );
    b.wait_for("the buttons back on after the step", 10, |b| {
        b.js(DISABLED) == json!([false, false, false])
    });
    assert_eq!(b.text("#sweep-result"), "");
    assert_eq!(b.text("#capture-result"), "");
    let log = b.text("#console-log");
    assert!(
        !log.contains("> sweep") && !log.contains("> capture arm manual"),
        "{log}"
    );
    // Torque and its reference on the left axis in N m, the currents on
    // the right one in A (uPlot's sides: 1 right, 2 bottom, 3 left).
    const STEP_PLOT: &str = "const p = plots.get(document.getElementById('step-plot'));";
    let axes = b.js(&format!(
        "{STEP_PLOT} return p.axes.map((a) => [a.scale, a.label, a.side])"
    ));
    assert_eq!(
        axes,
        json!([
            ["x", "time from trigger [ms]", 2],
            ["Nm", "N m", 3],
            ["A", "A", 1]
        ]),
        "step plot axes"
    );
    let series = b.js(&format!(
        "{STEP_PLOT} return p.series.slice(1).map((s) => [s.label, s.scale])"
    ));
    assert_eq!(
        series,
        json!([
            ["torque [N m]", "Nm"],
            ["torque_ref [N m]", "Nm"],
            ["i_d [A]", "A"],
            ["i_q [A]", "A"]
        ]),
        "step plot series"
    );
    // The 0.4 N m step spans most of its axis (on the currents' axis it was
    // a tenth of it), and the currents' axis holds i_q.
    let r = b.js(&format!(
        "{STEP_PLOT} const max = (a) => Math.max(...a.filter((x) => x != null));
         return [p.scales.Nm.min, p.scales.Nm.max, max(p.data[2]),
                 p.scales.A.min, p.scales.A.max, max(p.data[4])]"
    ));
    let r: Vec<f64> = r
        .as_array()
        .expect("six numbers")
        .iter()
        .map(|x| x.as_f64().expect("a number"))
        .collect();
    let (nm_span, ref_max, iq_max) = (r[1] - r[0], r[2], r[5]);
    assert!((ref_max - 0.4).abs() < 1e-6, "torque_ref max {ref_max} N m");
    assert!(
        ref_max / nm_span > 0.5,
        "0.4 N m on an axis spanning {nm_span} N m"
    );
    assert!(
        iq_max > 1.0 && iq_max <= r[4],
        "i_q max {iq_max} A on the axis {}..{} A",
        r[3],
        r[4]
    );

    // A sweep over the page's default range (FOC, 0.3 N m) finds the
    // torque loop's -3 dB bandwidth inside that range.
    let value = |id: &str| {
        b.js(&format!(
            "return Number(document.getElementById('{id}').value)"
        ))
        .as_f64()
        .unwrap()
    };
    let (f0, f1) = (value("sweep-f0"), value("sweep-f1"));
    let t_sweep = Instant::now();
    let during = b.js(&format!(
        "document.getElementById('sweep-run').click(); {DISABLED}"
    ));
    assert_eq!(
        during,
        json!([true, true, true]),
        "buttons during the sweep"
    );
    b.wait_for("the sweep's answer", 120, |b| {
        let r = b.text("#sweep-result");
        r.starts_with("bandwidth") || r.starts_with("ERR") || r.starts_with("link")
    });
    let res = b.text("#sweep-result");
    eprintln!(
        "sweep {f0}..{f1} Hz: {res} ({:.1} s)",
        t_sweep.elapsed().as_secs_f64()
    );
    let bw: f64 = res
        .strip_prefix("bandwidth: ")
        .and_then(|x| x.strip_suffix(" Hz"))
        .and_then(|x| x.parse().ok())
        .unwrap_or_else(|| panic!("no bandwidth in {res:?}"));
    assert!(f0 < bw && bw < f1, "{bw} Hz outside {f0}..{f1} Hz");
    let axes = b.js("return ['sweep-gain', 'sweep-phase'].map((id) =>
           plots.get(document.getElementById(id)).axes.map((a) => a.label))");
    assert_eq!(
        axes,
        json!([["frequency [Hz]", "dB"], ["frequency [Hz]", "deg"]])
    );
    b.wait_for("the buttons back on after the sweep", 10, |b| {
        b.js(DISABLED) == json!([false, false, false])
    });

    // A console command typed in the page gets its reply.
    let r = b.console("version");
    assert!(r.contains("firmware") && r.ends_with("OK\n"), "{r}");

    // The screenshot the README shows.
    b.wait_for("more points after the step", 60, |b| points(b) > 100);
    b.js("window.scrollTo(0, 0)");
    b.screenshot(&target.join("ui/drive-page.png"));

    // Every panel inside the viewport, no sideways scrolling, at the
    // smallest size the page is for and at a common large one; each
    // panel's parts inside it.
    for (w, h) in [(1280, 800), (1920, 1080)] {
        b.call(
            "POST",
            "/window/rect",
            Some(json!({"width": w, "height": h})),
        );
        let v = b.js_after_frames(LAYOUT_JS);
        let vw = v["viewport"].as_f64().unwrap();
        let doc = v["document"].as_f64().unwrap();
        // The window's size; headless Chromium keeps room for its (unseen)
        // toolbar in the height.
        let inner = (v["inner"][0].as_f64(), v["inner"][1].as_f64());
        assert_eq!(inner.0, Some(f64::from(w)), "window {w}x{h}: {v}");
        assert!(
            inner
                .1
                .is_some_and(|ih| ih > 0.7 * f64::from(h) && ih <= f64::from(h)),
            "window {w}x{h}: {v}"
        );
        eprintln!("window {w}x{h}: viewport {vw} x {:?} px", inner.1);
        assert!(vw > 0.95 * f64::from(w), "{w}x{h}: viewport {vw} px");
        assert!(doc <= vw, "{w}x{h}: document {doc} px wide in {vw} px");
        let boxes = v["boxes"].as_array().unwrap();
        let names: Vec<&str> = boxes.iter().filter_map(|x| x["name"].as_str()).collect();
        for panel in [
            "#tel",
            "#drive",
            "#drive #status",
            "#drive #faults",
            "#drive #fault-history",
            "#experiments",
            "#config",
            "#console",
            "#console #console-log",
        ] {
            assert!(names.contains(&panel), "{w}x{h}: no {panel} in {names:?}");
        }
        // The live plot, the step's and the sweep's two.
        let n_plots = names.iter().filter(|n| n.contains("div.uplot")).count();
        assert_eq!(n_plots, 4, "{w}x{h}: {names:?}");
        for bx in boxes {
            let f = |k: &str| bx[k].as_f64().unwrap();
            let (name, panel) = (bx["name"].as_str().unwrap(), &bx["panel"]);
            eprintln!(
                "{w}x{h}: {name}: x {:.0}..{:.0} px, y {:.0}..{:.0} px",
                f("left"),
                f("right"),
                f("top"),
                f("bottom")
            );
            assert!(f("right") > f("left"), "{w}x{h}: {name} empty: {bx}");
            assert!(
                f("left") >= 0.0 && f("right") <= vw,
                "{w}x{h}: {name} outside the viewport (0..{vw} px): {bx}"
            );
            if !panel.is_null() {
                let p = |k: &str| panel[k].as_f64().unwrap();
                assert!(
                    f("left") >= p("left") && f("right") <= p("right"),
                    "{w}x{h}: {name} outside its panel: {bx}"
                );
            }
        }
        b.js("window.scrollTo(0, 0)");
        b.screenshot(&target.join(format!("ui/drive-page-{w}x{h}.png")));
    }
    // A refused step (no number) ends the experiment too: buttons back on.
    // Last: the screenshots above show the 0.4 N m step.
    b.type_into("#step-nm", "");
    b.click("#step-run");
    b.wait_for("the refused step's answer", 30, |b| {
        b.text("#step-result").starts_with("ERR")
    });
    b.wait_for("the buttons back on after the refusal", 10, |b| {
        b.js(DISABLED) == json!([false, false, false])
    });

    b.call("DELETE", "", None);
    let _ = std::fs::remove_dir_all(&profile);
    drop(ui);
    drop(ui_out);
}
