//! `rtl-check mpdtc --seed S --vectors N`: runs N vectors (seed S) through
//! the Verilated `mpdtc_core` and `mpdtc_fixed::decide` and prints a one-line
//! JSON summary. `rtl-check frontend ...` does the same for
//! `mpdtc_frontend` and `frontend_fixed::frontend` (plus the largest
//! cos/sin error against libm, in COEF LSB). Exit status 1 on any mismatch,
//! 2 on bad arguments.
//! `rtl-check mpdcc-lane --seed S --vectors N`: the same for the MPDCC
//! explorer's search lane (`mpdcc_lane` against `models::mpdcc::mpdcc_fixed::lane`).
//! `rtl-check mpdcc --seed S --vectors N [--explorers N] [--ii I]`: N
//! decisions through `mpdcc_core` against `MpdccFixed::decide_raw` (decision,
//! kind, `L*`, candidates, `J`, `J_dl`, cycle count). Default: `pl_top`'s
//! configuration (`regmap::MPDCC_EXPLORERS` explorers, `II =
//! regmap::MPDCC_II`, shared search lanes); `--ii 1` the full-rate datapath.
//! `rtl-check mpdcc-explorer --seed S --vectors N`: N decision states, every
//! candidate through `mpdcc_explorer` against `models::mpdcc::mpdcc_fixed::explore`.
use std::process::ExitCode;
use std::time::Instant;

use rtl_sim::mpdcc_core::CoreConfig;

fn usage() -> ExitCode {
    eprintln!(
        "usage: rtl-check mpdtc|frontend|mpdcc|mpdcc-lane|mpdcc-explorer [--seed S] [--vectors N] [--explorers N (mpdcc, 1..6, default {})] [--ii I (mpdcc: 1 full rate or {} shared lanes, default {})]   (defaults: seed 1, 100000 vectors)",
        regmap::MPDCC_EXPLORERS,
        CoreConfig::PlTop.ii(),
        CoreConfig::PlTop.ii()
    );
    ExitCode::from(2)
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let core = match args.first().map(String::as_str) {
        Some(c @ ("mpdtc" | "frontend" | "mpdcc" | "mpdcc-lane" | "mpdcc-explorer")) => {
            c.to_string()
        }
        _ => return usage(),
    };
    let (mut seed, mut vectors) = (1u64, 100_000u64);
    let mut explorers = u64::from(regmap::MPDCC_EXPLORERS);
    let mut config = CoreConfig::PlTop;
    let mut it = args[1..].iter();
    while let Some(a) = it.next() {
        let val = it.next().and_then(|v| v.parse::<u64>().ok());
        match (a.as_str(), val) {
            ("--seed", Some(v)) => seed = v,
            ("--vectors", Some(v)) if v > 0 => vectors = v,
            ("--explorers", Some(v)) if core == "mpdcc" && (1..=6).contains(&v) => explorers = v,
            ("--ii", Some(1)) if core == "mpdcc" => config = CoreConfig::FullRate,
            ("--ii", Some(v)) if core == "mpdcc" && v == u64::from(CoreConfig::PlTop.ii()) => {
                config = CoreConfig::PlTop
            }
            _ => return usage(),
        }
    }
    let t0 = Instant::now();
    if core == "mpdcc" {
        return mpdcc(seed, vectors, explorers as u32, config, t0);
    }
    if core == "mpdcc-lane" {
        return mpdcc_lane(seed, vectors, t0);
    }
    if core == "mpdcc-explorer" {
        return mpdcc_explorer(seed, vectors, t0);
    }
    if core == "frontend" {
        let s = rtl_sim::mpdtc_frontend::check(seed, vectors);
        println!(
            "{{\"core\":\"frontend\",\"seed\":{seed},\"vectors\":{},\"mismatches\":{},\"latency_cycles\":{},\
             \"first_mismatch\":{},\"max_trig_err_lsb\":{:.3},\"seconds\":{:.2}}}",
            s.vectors,
            s.mismatches,
            json_opt(s.latency_cycles.map(u64::from)),
            json_opt(s.first_mismatch),
            s.max_trig_err_lsb,
            t0.elapsed().as_secs_f64()
        );
        return verdict(s.mismatches == 0 && s.latency_cycles.is_some());
    }
    let s = rtl_sim::mpdtc_vectors::check(seed, vectors);
    println!(
        "{{\"core\":\"mpdtc\",\"seed\":{seed},\"vectors\":{},\"mismatches\":{},\"latency_cycles\":{},\
         \"initiation_interval_cycles\":{},\"first_mismatch\":{},\"in_band_decisions\":{},\"ties\":{},\"seconds\":{:.2}}}",
        s.vectors,
        s.mismatches,
        json_opt(s.latency_cycles.map(u64::from)),
        json_opt(s.latency_cycles.map(u64::from)),
        json_opt(s.first_mismatch),
        s.in_band_decisions,
        s.ties,
        t0.elapsed().as_secs_f64()
    );
    verdict(s.mismatches == 0 && s.latency_cycles.is_some())
}

fn mpdcc_lane(seed: u64, vectors: u64, t0: Instant) -> ExitCode {
    let s = rtl_sim::mpdcc_vectors::check_lane(seed, vectors);
    println!(
        "{{\"core\":\"mpdcc_lane\",\"seed\":{seed},\"vectors\":{},\"mismatches\":{},\"latency_cycles\":{},\
         \"initiation_interval_cycles\":1,\"first_mismatch\":{},\"lj_zero\":{},\"lj_finite\":{},\"lj_horizon\":{},\"seconds\":{:.2}}}",
        s.vectors,
        s.mismatches,
        json_opt(s.latency_cycles.map(u64::from)),
        json_opt(s.first_mismatch),
        s.classes[0],
        s.classes[1],
        s.classes[2],
        t0.elapsed().as_secs_f64()
    );
    verdict(s.mismatches == 0 && s.latency_cycles.is_some())
}

fn mpdcc_explorer(seed: u64, vectors: u64, t0: Instant) -> ExitCode {
    let s = rtl_sim::mpdcc_vectors::check_explorer(seed, vectors);
    println!(
        "{{\"core\":\"mpdcc_explorer\",\"seed\":{seed},\"vectors\":{},\"candidates\":{},\"mismatches\":{},\
         \"latency_cycles\":{},\"initiation_interval_cycles\":1,\"first_mismatch\":{},\"l_star_zero\":{},\
         \"l_star_finite\":{},\"l_star_horizon\":{},\"seconds\":{:.2}}}",
        s.states,
        s.candidates,
        s.mismatches,
        json_opt(s.latency_cycles.map(u64::from)),
        json_opt(s.first_mismatch),
        s.classes[0],
        s.classes[1],
        s.classes[2],
        t0.elapsed().as_secs_f64()
    );
    verdict(s.mismatches == 0 && s.latency_cycles.is_some())
}

fn mpdcc(seed: u64, vectors: u64, explorers: u32, config: CoreConfig, t0: Instant) -> ExitCode {
    let s = rtl_sim::mpdcc_vectors::check_core(seed, vectors, explorers, config);
    println!(
        "{{\"core\":\"mpdcc\",\"seed\":{seed},\"vectors\":{},\"mismatches\":{},\"explorers\":{},\"ii\":{},\
         \"worst_case_cycles\":{},\"mean_cycles\":{:.1},\"first_mismatch\":{},\"kept\":{},\"optimal\":{},\
         \"deadlock\":{},\"seconds\":{:.2}}}",
        s.vectors,
        s.mismatches,
        s.explorers,
        config.ii(),
        s.worst_case_cycles,
        s.mean_cycles,
        json_opt(s.first_mismatch),
        s.kinds[0],
        s.kinds[1],
        s.kinds[2],
        t0.elapsed().as_secs_f64()
    );
    verdict(s.mismatches == 0)
}

/// A JSON number, or `null`.
fn json_opt(x: Option<u64>) -> String {
    x.map_or("null".to_string(), |v| v.to_string())
}

/// Exit status of a check: success only when it passed.
fn verdict(passed: bool) -> ExitCode {
    if passed {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
