//! AXI4-Lite tests of the Verilated `pl_top`: every register of the table
//! (`regmap`) against the RTL (reset value, access type, clamping,
//! rejection, byte strobes), unmapped addresses, and the handshake cases:
//! simultaneous AW/W, either one first, back to back, stalled responses.
use regmap::{self, Access, Register, BLOCKS};
use rtl_sim::mpdtc_vectors::Rng;
use rtl_sim::pl_top::{axi_addr, PlTopSim, OKAY, SLVERR};

/// Registers whose value moves on its own (not comparable to a constant).
fn is_live(r: &Register) -> bool {
    matches!(r.name, "PWM_COUNT" | "BOUNDARY_AGE")
}

fn err_addr() -> u16 {
    axi_addr(&regmap::TOP, &regmap::ERR)
}

#[test]
fn reset_values_match_the_table() {
    let mut sim = PlTopSim::new();
    for b in BLOCKS {
        for r in b.registers.iter().filter(|r| !is_live(r)) {
            let got = sim.read_ok(axi_addr(b, r));
            assert_eq!(got, r.reset, "{}.{} reset", b.name, r.name);
        }
    }
    assert_eq!(sim.read_ok(0), regmap::ID_VALUE);
}

/// Writes to every RW register follow `Register::apply_write` of the table
/// (mask, clamp, reject) and read back; rejected writes set ERR.BAD_VALUE.
#[test]
fn rw_registers_read_back_as_the_table_says() {
    let mut sim = PlTopSim::new();
    let mut rng = Rng(7);
    for b in BLOCKS {
        for r in b.registers.iter().filter(|r| r.access == Access::Rw) {
            let a = axi_addr(b, r);
            let mut cur = r.reset;
            // Corner values, then random ones of all magnitudes.
            let mut values = vec![0, 1, r.mask(), r.mask().wrapping_add(1), u32::MAX];
            for _ in 0..12 {
                let shift = rng.next_u64() % 32;
                values.push((rng.next_u64() as u32) >> shift);
            }
            for v in values {
                // Keep the watchdog far away: it would latch a fault and
                // hold GATE_EN at 0 (tested elsewhere).
                let v = if r.name == "WDG_TIMEOUT" {
                    v | 0x4000_0000
                } else {
                    v
                };
                let want = r.apply_write(cur, v);
                assert_eq!(sim.write(a, v), OKAY, "{} write {v:#x}", r.name);
                let got = sim.read_ok(a);
                let err = sim.read_ok(err_addr());
                match want {
                    Ok(w) => {
                        assert_eq!(got, w, "{} after writing {v:#x}", r.name);
                        assert_eq!(err, 0, "{} write {v:#x} flagged", r.name);
                        cur = w;
                    }
                    Err(_) => {
                        assert_eq!(got, cur, "{} rejected {v:#x} but changed", r.name);
                        assert_eq!(err, 1, "{} rejected {v:#x} without BAD_VALUE", r.name);
                        assert_eq!(sim.write(err_addr(), 1), OKAY);
                        assert_eq!(sim.read_ok(err_addr()), 0, "ERR W1C");
                    }
                }
            }
        }
    }
}

#[test]
fn ro_registers_ignore_writes_with_slverr() {
    let mut sim = PlTopSim::new();
    for b in BLOCKS {
        for r in b.registers.iter().filter(|r| r.access == Access::Ro) {
            let a = axi_addr(b, r);
            let before = sim.read_ok(a);
            assert_eq!(sim.write(a, !before), SLVERR, "{} write", r.name);
            if !is_live(r) {
                assert_eq!(sim.read_ok(a), before, "{} changed by a write", r.name);
            }
            assert_eq!(sim.read_ok(err_addr()), 2, "{}: ERR.BAD_ADDR", r.name);
            assert_eq!(sim.write(err_addr(), 2), OKAY);
        }
    }
    assert_eq!(sim.read_ok(err_addr()), 0);
}

#[test]
fn unmapped_and_unaligned_addresses_answer_slverr() {
    let mut sim = PlTopSim::new();
    // Holes between and after registers (MPDCC page too), an unaligned offset.
    for a in [
        0x2044u16, 0x2114, 0x702C, 0x706C, 0x001C, 0x0FFC, 0x3002, 0x6010, 0x1038, 0x1088, 0x1094,
    ] {
        assert_eq!(sim.read(a), (0, SLVERR), "read {a:#06x}");
        assert_eq!(sim.write(a, 0xFFFF_FFFF), SLVERR, "write {a:#06x}");
    }
    assert_eq!(sim.read_ok(err_addr()), 2);
    // Nothing else changed: the RW registers still hold their reset values.
    for b in BLOCKS {
        for r in b.registers.iter().filter(|r| r.access == Access::Rw) {
            assert_eq!(sim.read_ok(axi_addr(b, r)), r.reset, "{}", r.name);
        }
    }
}

#[test]
fn byte_strobes_merge() {
    let mut sim = PlTopSim::new();
    let a = axi_addr(&regmap::TOP, &regmap::SCRATCH);
    assert_eq!(sim.write(a, 0x1122_3344), OKAY);
    assert_eq!(sim.write_strb(a, 0xAABB_CCDD, 0b0101), OKAY);
    assert_eq!(sim.read_ok(a), 0x11BB_33DD);
    assert_eq!(sim.write_strb(a, 0, 0), OKAY);
    assert_eq!(sim.read_ok(a), 0x11BB_33DD);
    // The clamp applies to the merged word: DEAD_TIME (10 bits, max 1023),
    // byte 1 = 0x04 over 50 = 0x0432 = 1074 -> 1023.
    let dt = axi_addr(&regmap::PWM, &regmap::DEAD_TIME);
    assert_eq!(sim.write_strb(dt, 0x0000_0400, 0b0010), OKAY);
    assert_eq!(sim.read_ok(dt), 1023);
}

#[test]
fn aw_and_w_in_any_order() {
    let mut sim = PlTopSim::new();
    let a = axi_addr(&regmap::TOP, &regmap::SCRATCH);
    for (i, (aw, w)) in [(0, 0), (0, 3), (3, 0), (1, 2), (5, 1)]
        .into_iter()
        .enumerate()
    {
        let v = 0xC0DE_0000 + i as u32;
        assert_eq!(sim.write_skewed(a, v, 0xF, aw, w), OKAY, "aw {aw} w {w}");
        assert_eq!(sim.read_ok(a), v, "aw {aw} w {w}");
    }
}

/// Streams `n` writes with AWVALID/WVALID kept high and the next payload
/// presented as soon as the previous was accepted; BREADY follows `bready`.
/// Returns the cycles used and the responses.
fn stream_writes(
    sim: &mut PlTopSim,
    items: &[(u16, u32)],
    bready: impl Fn(u64) -> bool,
) -> (u64, usize) {
    let (mut next_aw, mut next_w, mut resps) = (0, 0, 0);
    let start = sim.cycles;
    while resps < items.len() {
        assert!(sim.cycles - start < 10_000, "stream hung");
        sim.inp.awvalid = u8::from(next_aw < items.len());
        sim.inp.wvalid = u8::from(next_w < items.len());
        if next_aw < items.len() {
            sim.inp.awaddr = items[next_aw].0;
        }
        if next_w < items.len() {
            sim.inp.wdata = items[next_w].1;
            sim.inp.wstrb = 0xF;
        }
        sim.inp.bready = u8::from(bready(sim.cycles));
        let o = sim.step();
        if sim.inp.awvalid == 1 && o.awready == 1 {
            next_aw += 1;
        }
        if sim.inp.wvalid == 1 && o.wready == 1 {
            next_w += 1;
        }
        if o.bvalid == 1 && sim.inp.bready == 1 {
            assert_eq!(o.bresp, OKAY);
            resps += 1;
            assert!(resps <= next_aw.min(next_w), "response before its transfer");
        }
    }
    sim.inp.awvalid = 0;
    sim.inp.wvalid = 0;
    (sim.cycles - start, resps)
}

#[test]
fn back_to_back_writes_one_per_three_cycles() {
    let mut sim = PlTopSim::new();
    let duties = [
        axi_addr(&regmap::PWM, &regmap::DUTY_A),
        axi_addr(&regmap::PWM, &regmap::DUTY_B),
        axi_addr(&regmap::PWM, &regmap::DUTY_C),
        axi_addr(&regmap::TOP, &regmap::SCRATCH),
    ];
    let items: Vec<(u16, u32)> = (0..32).map(|i| (duties[i % 4], 100 + i as u32)).collect();
    let (cycles, n) = stream_writes(&mut sim, &items, |_| true);
    assert_eq!(n, 32);
    // One write per three clocks (taken, on the register bus from
    // registers, decoded in the register file) plus the response's cycle.
    assert!(cycles <= 97, "32 writes took {cycles} cycles");
    for (k, a) in duties.iter().enumerate() {
        assert_eq!(sim.read_ok(*a), 100 + 28 + k as u32);
    }
}

#[test]
fn stalled_write_responses_lose_nothing() {
    let mut sim = PlTopSim::new();
    let a = axi_addr(&regmap::TOP, &regmap::SCRATCH);
    let h = axi_addr(&regmap::TOP, &regmap::HEARTBEAT);
    let items: Vec<(u16, u32)> = (0..20)
        .map(|i| (if i % 2 == 0 { a } else { h }, i as u32 * 7))
        .collect();
    // BREADY low 2 cycles out of 3: the slave must hold B and back-pressure.
    let (_, n) = stream_writes(&mut sim, &items, |c| c % 3 == 0);
    assert_eq!(n, 20);
    assert_eq!(sim.read_ok(a), 18 * 7);
    assert_eq!(sim.read_ok(h), 19 * 7);
}

#[test]
fn back_to_back_and_stalled_reads() {
    let mut sim = PlTopSim::new();
    let regs = [
        (axi_addr(&regmap::TOP, &regmap::ID), regmap::ID_VALUE),
        (
            axi_addr(&regmap::TOP, &regmap::VERSION),
            regmap::VERSION.reset,
        ),
        (
            axi_addr(&regmap::PWM, &regmap::PWM_PERIOD),
            regmap::PWM_PERIOD.reset,
        ),
        (
            axi_addr(&regmap::ADC, &regmap::ADC_PERIOD),
            regmap::ADC_PERIOD.reset,
        ),
    ];
    for stall in [false, true] {
        let (mut next, mut got) = (0usize, Vec::new());
        let start = sim.cycles;
        while got.len() < 16 {
            assert!(sim.cycles - start < 1000, "reads hung");
            sim.inp.arvalid = u8::from(next < 16);
            sim.inp.araddr = regs[next % 4].0;
            sim.inp.rready = u8::from(!stall || sim.cycles % 4 == 0);
            let o = sim.step();
            if sim.inp.arvalid == 1 && o.arready == 1 {
                next += 1;
            }
            if o.rvalid == 1 && sim.inp.rready == 1 {
                assert_eq!(o.rresp, OKAY);
                got.push(o.rdata);
            }
        }
        sim.inp.arvalid = 0;
        let want: Vec<u32> = (0..16).map(|i| regs[i % 4].1).collect();
        assert_eq!(got, want, "stall {stall}");
        if !stall {
            assert!(
                // one read per two clocks (the register file's two read
                // stages) plus the response's cycle
                sim.cycles - start <= 33,
                "16 reads took {} cycles",
                sim.cycles - start
            );
        }
    }
}

/// Random valid/ready timing on all five channels, reads and writes
/// interleaved, against a scoreboard of the RW registers.
#[test]
fn random_handshakes_against_a_scoreboard() {
    let mut sim = PlTopSim::new();
    let mut rng = Rng(42);
    let regs = [
        &regmap::SCRATCH,
        &regmap::HEARTBEAT,
        &regmap::DUTY_A,
        &regmap::DEAD_TIME,
        &regmap::PWM_PERIOD,
    ];
    let addr = |r: &Register| {
        let b = BLOCKS
            .iter()
            .find(|b| b.registers.iter().any(|x| x.name == r.name))
            .unwrap();
        axi_addr(b, r)
    };
    let mut model: Vec<u32> = regs.iter().map(|r| r.reset).collect();
    for _ in 0..400 {
        let k = (rng.next_u64() % regs.len() as u64) as usize;
        let v = (rng.next_u64() as u32) >> (rng.next_u64() % 32);
        if rng.next_u64() % 2 == 0 {
            let (d_aw, d_w) = ((rng.next_u64() % 4) as u32, (rng.next_u64() % 4) as u32);
            assert_eq!(sim.write_skewed(addr(regs[k]), v, 0xF, d_aw, d_w), OKAY);
            model[k] = regs[k].apply_write(model[k], v).unwrap();
        } else {
            assert_eq!(sim.read_ok(addr(regs[k])), model[k], "{}", regs[k].name);
        }
        // Random idle gaps with random READYs (no transfer in flight).
        for _ in 0..rng.next_u64() % 3 {
            sim.inp.bready = (rng.next_u64() % 2) as u8;
            sim.inp.rready = (rng.next_u64() % 2) as u8;
            sim.step();
        }
    }
    for (k, r) in regs.iter().enumerate() {
        assert_eq!(sim.read_ok(addr(r)), model[k], "{}", r.name);
    }
}
