//! `mpdtc_frontend` against `frontend_fixed::frontend`: bit-exact on every
//! output, fixed latency, cos/sin within the written error bound.
use models::pmsm::frontend_fixed::{frontend, FrontendInputs};
use rtl_sim::mpdtc_frontend::{check, drive_params, FrontendSim};

#[test]
fn random_vectors_are_bit_exact() {
    let s = check(3, 20_000);
    assert_eq!(s.mismatches, 0, "{s:?}");
    assert_eq!(s.latency_cycles, Some(9), "{s:?}");
    // Written bound: 2.0e-5 = 1.32 COEF LSB.
    assert!(s.max_trig_err_lsb <= 1.32, "{s:?}");
}

/// A hand-computed period through the RTL: count 512 past the alignment
/// with 4 pole pairs is half an electrical turn; a = 1 A, b = 0, c = -1 A
/// (128 counts at 16/2048 A per count) give i_d = -1 A, i_q = -1/sqrt 3 A.
#[test]
fn half_turn_by_hand() {
    let p = drive_params(4, 100, 15.625e-6);
    let inp = FrontendInputs {
        pos: 612,
        speed: 0,
        adc: [128, 0, -128],
        t_ref: 0,
    };
    let mut sim = FrontendSim::new();
    let got = sim.run(&inp, &p).out;
    assert_eq!(got, frontend(&inp, &p));
    assert_eq!(got.phi, 1 << 31);
    assert_eq!(got.core.trig[0], (-65536, 0), "cos pi, sin pi (speed 0)");
    let (id, iq) = got.core.i_dq;
    assert!((id as f64 / 65536.0 + 1.0).abs() < 1e-4, "{id}");
    assert!(
        (iq as f64 / 65536.0 + 1.0 / 3f64.sqrt()).abs() < 1e-4,
        "{iq}"
    );
}

/// i_d and i_q are registers of the PS (MPDTC_FE_ID/IQ): they hold the last
/// result until the edge that raises `out_valid`, also when the new
/// period's currents and angle differ (a free-running last stage shows the
/// new currents with the old angle first).
#[test]
fn currents_hold_the_last_result_until_out_valid() {
    let p = drive_params(4, 100, 15.625e-6);
    let mut sim = FrontendSim::new();
    let mut last = None;
    for (pos, adc) in [
        (612, [128, 0, -128]),
        (1000, [-300, 200, 100]),
        (100, [5, -5, 0]),
    ] {
        let inp = FrontendInputs {
            pos,
            speed: 40,
            adc,
            t_ref: 0,
        };
        let r = sim.run(&inp, &p);
        assert_eq!(r.out, frontend(&inp, &p));
        assert!(r.currents_held, "i_d/i_q changed before out_valid");
        assert_ne!(Some(r.out.core.i_dq), last, "periods with new currents");
        last = Some(r.out.core.i_dq);
    }
}
