use super::*;
use crate::pl::fake::FakePl;
use crate::servo::ServoError;
use models::pmsm::mpdtc_fixed::FixedParams;
use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use regmap::{self, ADC, ENC, FAULT, MPDTC, PWM};
use std::string::String;

#[test]
fn defaults_are_the_drives_defaults_and_round_trip() {
    let sc = ServoConfig::default();
    assert_eq!(Config::from_servo(&sc), Config::default());
    assert_eq!(Config::default().apply(&sc), sc);
    Config::default().check(&sc).unwrap();
}

#[test]
fn table_rows_are_well_formed() {
    for (i, p) in PARAMS.iter().enumerate() {
        assert!(p.min <= p.default && p.default <= p.max, "{}", p.name);
        assert_eq!(check_value(p, p.default), Ok(p.default), "{}", p.name);
        assert!(
            !p.unit.is_empty() && !p.description.is_empty(),
            "{}",
            p.name
        );
        for s in [p.name, p.unit, p.description] {
            assert!(!s.contains(['"', '\\']), "{s}");
        }
        assert!(
            p.name.bytes().all(|b| b.is_ascii_lowercase() || b == b'_'),
            "{}",
            p.name
        );
        assert_eq!(lookup(p.name).unwrap().0, i, "duplicate {}", p.name);
        if p.kind == Kind::Integer {
            assert!(p.max <= f64::from(u32::MAX), "{}", p.name);
        }
    }
}

#[test]
fn schema_is_one_json_array_of_the_table() {
    let mut s = String::new();
    write_schema(&mut s).unwrap();
    assert!(!s.contains('\n'));
    let v: serde_json::Value = serde_json::from_str(&s).unwrap();
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), N_PARAMS);
    for (r, p) in rows.iter().zip(PARAMS.iter()) {
        assert_eq!(r["name"], p.name);
        assert_eq!(r["unit"], p.unit);
        assert_eq!(r["min"].as_f64(), Some(p.min));
        assert_eq!(r["max"].as_f64(), Some(p.max));
        assert_eq!(r["default"].as_f64(), Some(p.default));
        assert_eq!(r["description"], p.description);
        assert_eq!(r["integer"], p.kind == Kind::Integer);
        assert_eq!(r["gates_off"], p.gates_off);
    }
}

#[test]
fn list_line_format() {
    let (_, p) = lookup("mpdtc_t_tol").unwrap();
    let mut s = String::new();
    write_list_line(&mut s, p, 0.05).unwrap();
    assert_eq!(
        s,
        "mpdtc_t_tol = 0.05 Nm  [0..0.5]  MPDTC torque tolerance band T_tol"
    );
}

#[test]
fn bad_values_change_nothing() {
    let base = ServoConfig::default();
    let mut c = Config::default();
    let before = c;
    for (name, v, want) in [
        ("nothing", 1.0, ConfigError::UnknownName),
        ("mpdtc_t_tol", f64::NAN, ConfigError::NotANumber),
        ("mpdtc_t_tol", f64::INFINITY, ConfigError::NotANumber),
        ("mpdtc_t_tol", f64::NEG_INFINITY, ConfigError::NotANumber),
        ("motor_pole_pairs", 7.5, ConfigError::NotWhole),
    ] {
        assert_eq!(c.set(&base, name, v), Err(want), "{name} {v}");
    }
    for (name, v) in [
        ("mpdtc_t_tol", -0.01),
        ("mpdtc_t_tol", 0.5001),
        ("motor_pole_pairs", 0.0),
        ("motor_pole_pairs", 65.0),
        ("dead_time", 1024.0),
        ("torque_limit", 0.0),
    ] {
        assert!(
            matches!(c.set(&base, name, v), Err(ConfigError::OutOfRange(_))),
            "{name} {v}"
        );
    }
    assert_eq!(parse_value("0.1Nm"), Err(ConfigError::NotANumber));
    assert_eq!(parse_value("abc"), Err(ConfigError::NotANumber));
    assert_eq!(parse_value("nan").map(f64::is_nan), Ok(true));
    assert_eq!(c, before);
}

#[test]
fn whole_configuration_is_checked() {
    let base = ServoConfig::default();
    let mut c = Config::default();
    // K Ts < 1: at 391-cycle ADC periods (Ts = 15.64 us) K = 60000 1/s is
    // 0.94; at 1000 cycles (40 us) it is 2.4 (the gain as set, not derived).
    c.set(&base, "mpdtc_k_auto", 0.0).unwrap();
    c.set(&base, "mpdtc_k", 60_000.0).unwrap();
    let before = c;
    let e = c.set(&base, "adc_period", 1000.0).unwrap_err();
    assert!(
        matches!(
            e,
            ConfigError::Invalid(ParamError {
                field: "k_int_per_s",
                ..
            })
        ),
        "{e:?}"
    );
    assert_eq!(c, before);
    // Observer gains that put the roots of eq. (16) outside the unit circle.
    let e = c.set(&base, "obs_kp", 1000.0).unwrap_err();
    assert!(matches!(e, ConfigError::Invalid(_)), "{e:?}");
    // enc_zero below enc_cpr.
    c.set(&base, "enc_cpr", 1000.0).unwrap();
    assert!(matches!(
        c.set(&base, "enc_zero", 1000.0),
        Err(ConfigError::Invalid(_))
    ));
    c.set(&base, "enc_zero", 999.0).unwrap();
    assert!(matches!(
        c.set(&base, "enc_cpr", 999.0),
        Err(ConfigError::Invalid(_))
    ));
    // 2047 counts of 10 mA: 20.47 A is in range of the board's ADC.
    assert_eq!(c.apply(&base).oc_limit_counts(), Some(1400));
    assert_eq!(c.get("enc_zero"), Some(999.0));
}

#[test]
fn the_drive_and_the_pl_registers_use_the_values() {
    let base = ServoConfig::default();
    let mut servo = Servo::new(&base).unwrap();
    let mut pl = FakePl::new();
    servo.init(&mut pl).unwrap();
    assert_eq!(pl.get(FAULT.addr(&regmap::OC_LIMIT)), 1400);
    let mut c = Config::default();
    for (n, v) in [
        ("adc_period", 500.0),
        ("foc_half_period", 4000.0),
        ("dead_time", 80.0),
        ("enc_cpr", 2000.0),
        ("current_limit", 10.0),
        ("watchdog_timeout", 300_000.0),
        ("mpdtc_align_time", 50_000.0),
        ("mpdtc_t_tol", 0.04),
        ("motor_r_s", 0.6),
    ] {
        c.set(&base, n, v).unwrap();
    }
    let sc = c.apply(&base);
    servo.reconfigure(&mut pl, &sc).unwrap();
    assert_eq!(servo.config(), &sc);
    assert_eq!(pl.get(ADC.addr(&regmap::ADC_PERIOD)), 500);
    assert_eq!(pl.get(PWM.addr(&regmap::PWM_PERIOD)), 4000);
    assert_eq!(pl.get(PWM.addr(&regmap::DEAD_TIME)), 80);
    assert_eq!(pl.get(ENC.addr(&regmap::ENC_CPR)), 2000);
    // 10 A / 10 mA per count.
    assert_eq!(pl.get(FAULT.addr(&regmap::OC_LIMIT)), 1000);
    assert_eq!(pl.get(FAULT.addr(&regmap::WDG_TIMEOUT)), 300_000);
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_ALIGN_TIME)), 50_000);
    // MPDTC period 4 x 500 cycles = 20 us: 50 kHz.
    servo
        .set_mode(&mut pl, crate::pl::top::Mode::Mpdtc)
        .unwrap();
    assert!((servo.control_rate_hz() - 50_000.0).abs() < 1e-6);
    // The core's parameters: an independent build of the same tuning.
    let mut motor = base.motor;
    motor.r_s_ohm = 0.6;
    let mp = MpdtcParams {
        control_period_s: 20e-6,
        t_tol_nm: 0.04,
        ..MpdtcParams::default()
    };
    let want = FixedParams::from_config(&MpdtcConfig::new(motor, mp).unwrap()).unwrap();
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_P_TOL)), want.tol as u32);
    assert_eq!(pl.get(MPDTC.addr(&regmap::MPDTC_P_A)) as i32, want.a);
}

#[test]
fn with_the_gates_on_only_the_torque_limit_changes() {
    use crate::pl::top::Mode;
    let base = ServoConfig::default();
    let mut servo = Servo::new(&base).unwrap();
    let mut pl = FakePl::new();
    servo.init(&mut pl).unwrap();
    servo.set_mode(&mut pl, Mode::Foc).unwrap();
    servo.enable(&mut pl).unwrap();
    servo.set_torque_ref(0.5).unwrap();
    let mut c = Config::default();
    c.set(&base, "mpdtc_t_tol", 0.04).unwrap();
    assert_eq!(
        servo.reconfigure(&mut pl, &c.apply(&base)),
        Err(ServoError::GatesOn)
    );
    assert_eq!(servo.config(), &base);
    let mut c = Config::default();
    c.set(&base, "torque_limit", 0.4).unwrap();
    // Below the present reference: refused.
    assert_eq!(
        servo.reconfigure(&mut pl, &c.apply(&base)),
        Err(ServoError::TorqueOutOfRange(0.5))
    );
    c.set(&base, "torque_limit", 0.6).unwrap();
    servo.reconfigure(&mut pl, &c.apply(&base)).unwrap();
    assert_eq!(servo.config().torque_limit_nm, 0.6);
    assert!(servo.set_torque_ref(0.61).is_err());
    assert!(servo.gates_on(&mut pl).unwrap());
}
