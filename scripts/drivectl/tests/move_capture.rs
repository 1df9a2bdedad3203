//! The capture buffer's position, velocity and following-error channels
//! during a `move` on the host (the product's `Servo` on the simulated PL):
//! every sample of the record equals the servo's own state of the period it
//! belongs to, quantised to the channel's format, at the offset the record
//! promises (a `move` restarts and triggers an armed record).
use drive::pl::capture::{
    encode_following_error, encode_position, encode_velocity, CapState, Trigger, FERR_LSB_COUNTS,
    VELOCITY_LSB_REV_S,
};
use drive::pl::top::Mode;
use drivectl::motion::{run, setup};

#[test]
fn a_move_record_holds_the_servos_position_velocity_and_following_error() {
    // 16 and 4: 256 ms of record, the default gains' 200 ms move whole.
    for (mode, every) in [(Mode::Mpdtc, 16u32), (Mode::Mpdtc, 1), (Mode::Foc, 4)] {
        let (mut s, mut d) = setup(mode, &[("locked", 0.0)], 3e-3).unwrap();
        s.capture_arm(&mut d, Trigger::Manual, 0, every).unwrap();
        // Runs a while armed (the restart must empty the ring).
        run(&mut s, &mut d, 50, |_| false).unwrap();
        s.begin_move(&mut d, 1.0, 0.02).unwrap();
        let n = 1024 * every as usize + 8;
        let rows = run(&mut s, &mut d, n, |_| false).unwrap();
        let st = s.capture_status(&mut d).unwrap();
        assert_eq!(st.state, CapState::Done, "{mode:?} every {every}: {st:?}");
        assert_eq!((st.count, st.trig_index), (1024, 0), "{st:?}");
        let mut moved = 0.0_f64;
        for j in 0..1024usize {
            let x = s.capture_sample(&mut d, j as u32).unwrap();
            // Sample j: the state after control step (j + 1) every - 1 of
            // the move; rows[k] is after step k + 1 (k = -1: before it).
            let m = ((j + 1) * every as usize)
                .checked_sub(2)
                .map(|k| rows[k].motion);
            let (counts, v, fe) = m.map_or((0, 0.0, 0.0), |m| {
                (m.counts, m.velocity_rev_s, m.following_error_counts)
            });
            if m.is_none() {
                // Before the first step of the move: at rest in the torque
                // loop (position where setup left it).
                assert_eq!(x.following_error_counts, 0.0, "{x:?}");
                continue;
            }
            assert_eq!(x.position_counts as u32, encode_position(counts), "{j}");
            assert_eq!(
                (x.velocity_rev_s / VELOCITY_LSB_REV_S) as i32 as u32,
                encode_velocity(v),
                "{mode:?} sample {j}: {x:?} vs {m:?}"
            );
            assert_eq!(
                (x.following_error_counts / FERR_LSB_COUNTS) as i16 as u16,
                encode_following_error(fe),
                "{mode:?} sample {j}: {x:?} vs {m:?}"
            );
            moved = moved.max(f64::from(x.position_counts));
        }
        // Not a record of a rotor at rest: the move is in it.
        let span = 1024.0 * f64::from(every) / s.control_rate_hz();
        println!("{mode:?} every {every}: {span:.4} s recorded, {moved} counts reached");
        if span > 0.21 {
            assert!((moved - 4096.0).abs() <= 3.0, "{moved}");
        } else {
            assert!(moved > 0.0, "{moved}");
        }
    }
}
