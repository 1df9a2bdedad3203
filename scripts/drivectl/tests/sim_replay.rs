//! `drivectl sim replay` end to end: the binary's output against an
//! independent solution of the same ODE (RK4, 2.5 ns step, in the rotor dq
//! frame instead of the plant's closed form in alpha-beta), and its behaviour
//! on bad input (clear error with line number, no output file).
use std::path::{Path, PathBuf};
use std::process::Command;

const R: f64 = 0.555;
const L: f64 = 0.64e-3;
const PSI: f64 = 0.0092879;
const P: f64 = 7.0;
const UDC: f64 = 48.0;
const W: f64 = 700.0;
const T: f64 = 1.0 / 64_000.0;

fn cfg() -> String {
    format!(
        "r_s_ohm = {R}\nl_d_h = {L}\nl_q_h = {L}\npsi_pm_wb = {PSI}\npole_pairs = 7\n\
         u_dc_v = {UDC}\nomega_e_rad_s = {W}\nperiod_s = {T:e}\n"
    )
}

fn tmpdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("drivectl-replay-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn replay(motor: &Path, states: &Path, out: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_drivectl"))
        .args(["sim", "replay", "--motor"])
        .arg(motor)
        .arg("--switching")
        .arg(states)
        .arg("--out")
        .arg(out)
        .output()
        .unwrap()
}

/// Phase voltages to the star point of state bits, alpha-beta (amplitude-invariant),
/// written out from the circuit rather than through the library.
fn u_ab(s: u8) -> (f64, f64) {
    let (a, b, c) = (((s >> 2) & 1) as f64, ((s >> 1) & 1) as f64, (s & 1) as f64);
    let n = (a + b + c) / 3.0;
    let (va, vb, vc) = ((a - n) * UDC, (b - n) * UDC, (c - n) * UDC);
    ((2.0 * va - vb - vc) / 3.0, (vb - vc) / 3f64.sqrt())
}

/// RK4 of L di_dq/dt = u_dq - R i_dq -+ w L i_qd - (0, w psi), u_dq = Park(u_ab, theta).
fn rk4(states: &[u8]) -> Vec<(f64, f64)> {
    let f = |x: [f64; 2], th: f64, u: (f64, f64)| {
        let (ud, uq) = (
            th.cos() * u.0 + th.sin() * u.1,
            -th.sin() * u.0 + th.cos() * u.1,
        );
        [
            (ud - R * x[0] + W * L * x[1]) / L,
            (uq - R * x[1] - W * L * x[0] - W * PSI) / L,
        ]
    };
    let n = 6250; // 2.5 ns steps per 15.625 us period
    let h = T / n as f64;
    let (mut x, mut out) = ([0.0f64; 2], Vec::new());
    for (k, &s) in states.iter().enumerate() {
        let u = u_ab(s);
        for j in 0..n {
            let th = W * (k as f64 * T + j as f64 * h);
            let k1 = f(x, th, u);
            let k2 = f(
                [x[0] + 0.5 * h * k1[0], x[1] + 0.5 * h * k1[1]],
                th + 0.5 * h * W,
                u,
            );
            let k3 = f(
                [x[0] + 0.5 * h * k2[0], x[1] + 0.5 * h * k2[1]],
                th + 0.5 * h * W,
                u,
            );
            let k4 = f([x[0] + h * k3[0], x[1] + h * k3[1]], th + h * W, u);
            for i in 0..2 {
                x[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
        }
        out.push((x[0], x[1]));
    }
    out
}

#[test]
fn replay_matches_an_independent_rk4_solution() {
    let d = tmpdir("ok");
    // 300 periods of pseudo-random states (LCG), mostly zero vectors so the
    // current stays in a realistic range.
    let mut seed = 12345u32;
    let states: Vec<u8> = (0..300)
        .map(|_| {
            seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            let r = (seed >> 16) % 16;
            if r < 8 {
                r as u8
            } else {
                0
            }
        })
        .collect();
    let mut csv = String::from("t_s,switch_state_abc\n");
    for (k, s) in states.iter().enumerate() {
        csv.push_str(&format!(
            "{},{}{}{}\n",
            k as f64 * T,
            (s >> 2) & 1,
            (s >> 1) & 1,
            s & 1
        ));
    }
    std::fs::write(d.join("m.toml"), cfg()).unwrap();
    std::fs::write(d.join("s.csv"), csv).unwrap();
    let o = replay(&d.join("m.toml"), &d.join("s.csv"), &d.join("out.csv"));
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = std::fs::read_to_string(d.join("out.csv")).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("step,switch_state_abc,i_d,i_q,torque"));
    let want = rk4(&states);
    let mut n = 0;
    let mut max_i: f64 = 0.0;
    for (k, l) in lines.enumerate() {
        let f: Vec<&str> = l.split(',').collect();
        assert_eq!(f[0].parse::<usize>().unwrap(), k);
        let s = states[k];
        assert_eq!(f[1], format!("{}{}{}", (s >> 2) & 1, (s >> 1) & 1, s & 1));
        let (id, iq, te): (f64, f64, f64) = (
            f[2].parse().unwrap(),
            f[3].parse().unwrap(),
            f[4].parse().unwrap(),
        );
        let (wd, wq) = want[k];
        assert!(
            (id - wd).abs() < 1e-8 && (iq - wq).abs() < 1e-8,
            "row {k}: {id} {iq} vs {wd} {wq}"
        );
        assert!((te - 1.5 * P * PSI * wq).abs() < 1e-9, "row {k}");
        max_i = max_i.max(id.hypot(iq));
        n += 1;
    }
    assert_eq!(n, states.len());
    assert!(max_i > 1.0, "the test must exercise real currents: {max_i}");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn bad_input_gives_a_line_numbered_error_and_no_output() {
    let d = tmpdir("bad");
    std::fs::write(d.join("m.toml"), cfg()).unwrap();
    let cases = [
        ("state\n101\n", "line 1"),
        ("switch_state_abc\n101\n1x1\n", "line 3"),
        ("switch_state_abc\n101\nNaN\n", "line 3"),
    ];
    for (i, (csv, want)) in cases.iter().enumerate() {
        let s = d.join(format!("s{i}.csv"));
        std::fs::write(&s, csv).unwrap();
        let out = d.join(format!("out{i}.csv"));
        let o = replay(&d.join("m.toml"), &s, &out);
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.contains(want), "case {i}: {err}");
        assert!(
            !out.exists() && !d.join(format!("out{i}.csv.tmp")).exists(),
            "case {i}"
        );
    }
    // NaN in the motor file.
    std::fs::write(
        d.join("nan.toml"),
        cfg().replace("u_dc_v = 48", "u_dc_v = nan\n#"),
    )
    .unwrap();
    std::fs::write(d.join("ok.csv"), "switch_state_abc\n101\n").unwrap();
    let o = replay(&d.join("nan.toml"), &d.join("ok.csv"), &d.join("o.csv"));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && err.contains("line 6") && err.contains("u_dc_v"),
        "{err}"
    );
    assert!(!d.join("o.csv").exists());
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn example_files_replay() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let d = tmpdir("ex");
    let o = replay(
        &root.join("examples/pmsm-motor.toml"),
        &root.join("examples/pmsm-states.csv"),
        &d.join("out.csv"),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let rows = std::fs::read_to_string(d.join("out.csv"))
        .unwrap()
        .lines()
        .count();
    assert_eq!(rows, 1 + 18);
    let _ = std::fs::remove_dir_all(&d);
}
