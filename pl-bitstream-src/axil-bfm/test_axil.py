"""pl_top's AXI4-Lite port driven by an independent bus-functional model
(cocotbext-axi's AxiLiteMaster) under cocotb on Icarus Verilog.

Every response and every register value is checked against the rules of
the register table, read at run time from the table itself (the JSON that
`cargo run -p regmap-gen --bin regmap-json` prints, path in $REGMAP_JSON):

- an access to an address that is not a register's (unmapped offset, or
  not word aligned), or a write to an RO register: SLVERR, ERR.BAD_ADDR set;
- RW: byte strobes merge into the current value (bits above the width read
  0), then the 32-bit word is masked to the width (all valid), clamped as
  a whole (clamp) or, above its bound, rejected (reject: OKAY, the
  register keeps its value, ERR.BAD_VALUE set);
- W1C ERR: a written 1 clears the flag; RO constants read their reset;
  other RO and W1C registers (core state) read 0 above their width;
- the one RW register the hardware may clear (GATE_CTRL) reads its
  written value or 0.

Traffic: AW/W skew in both orders and back-pressure on B and R (random
pause generators on every channel of the master), partial strobes (1-3
byte writes at and off word boundaries), unmapped and unaligned addresses,
and back-to-back bursts (many operations queued at once, no pauses).
"""
import json
import logging
import os
import random

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, RisingEdge, with_timeout
from cocotbext.axi import AxiLiteBus, AxiLiteMaster, AxiResp

SEED = int(os.environ.get("AXIL_SEED", "1"))
OPS = max(3, int(os.environ.get("AXIL_OPS", "300")))


class Table:
    """The register table and the expected state of the register file."""

    def __init__(self, path):
        with open(path) as f:
            t = json.load(f)
        self.base = t["base"]
        self.block_size = t["block_size"]
        self.regs = {}
        for b in t["blocks"]:
            for r in b["registers"]:
                r = dict(r)
                r["block"] = b["name"]
                r["addr"] = b["index"] * self.block_size + r["offset"]
                r["mask"] = (1 << r["width"]) - 1
                self.regs[r["addr"]] = r
        err = [r for r in self.regs.values() if r["hw"] == "errors"]
        assert len(err) == 1, "one ERR register"
        self.err = err[0]
        lsb = {f["name"]: f["lsb"] for f in self.err["fields"]}
        self.bad_value = 1 << lsb["BAD_VALUE"]
        self.bad_addr = 1 << lsb["BAD_ADDR"]
        # Expected values: stored RW registers and ERR.
        self.val = {a: r["reset"] for a, r in self.regs.items() if r["access"] == "RW"}
        self.val[self.err["addr"]] = 0
        self.span = len(t["blocks"]) * self.block_size

    def write(self, addr, data, nbytes):
        """Expected response of a single-word write of `nbytes` bytes of
        `data` (little endian, lane addr % 4 on) at byte address `addr`."""
        lane = addr % 4
        strb = ((1 << nbytes) - 1) << lane
        bytemask = sum(0xFF << (8 * i) for i in range(4) if strb >> i & 1)
        word = (data << (8 * lane)) & 0xFFFFFFFF
        r = self.regs.get(addr)
        if r is None or r["access"] == "RO":
            self.val[self.err["addr"]] |= self.bad_addr
            return AxiResp.SLVERR
        if r["hw"] == "errors":
            self.val[addr] &= ~(word & bytemask)
            return AxiResp.OKAY
        if r["access"] == "W1C":
            return AxiResp.OKAY
        merged = (self.val[addr] & ~bytemask) | (word & bytemask)
        inv = r["invalid"]
        if inv["kind"] == "all_valid":
            self.val[addr] = merged & r["mask"]
        elif inv["kind"] == "clamp":
            self.val[addr] = min(max(merged, inv["min"]), inv["max"]) & r["mask"]
        elif inv["kind"] == "reject":
            if merged > inv["max"]:
                self.val[self.err["addr"]] |= self.bad_value
            else:
                self.val[addr] = merged & r["mask"]
        else:
            raise AssertionError(inv)
        return AxiResp.OKAY

    def read(self, addr, got_resp, got):
        """Checks a read's response and value; updates what the hardware
        may change. Returns an error message or None."""
        r = self.regs.get(addr)
        if r is None:
            self.val[self.err["addr"]] |= self.bad_addr
            return None if got_resp == AxiResp.SLVERR else f"unmapped {addr:#x}: {got_resp!r}"
        if got_resp != AxiResp.OKAY:
            return f"{r['name']}: read answered {got_resp!r}"
        if got & ~r["mask"]:
            return f"{r['name']}: {got:#x} has bits above width {r['width']}"
        if r["hw"] == "const" and got != r["reset"]:
            return f"{r['name']}: constant reads {got:#x}, table {r['reset']:#x}"
        if addr in self.val:
            want = self.val[addr]
            if r["hw"] == "hw_clear" and got == 0:
                self.val[addr] = 0
            elif got != want:
                return f"{r['name']}: read {got:#x}, expected {want:#x}"
        return None


def random_value(rng, r):
    """A value for register `r`: around its bounds, or anything."""
    inv = r["invalid"] if r else {"kind": "all_valid"}
    pick = rng.random()
    if pick < 0.3:
        return rng.getrandbits(32)
    if inv["kind"] in ("clamp", "reject") and pick < 0.7:
        return max(0, inv["max"] + rng.randint(-2, 2))
    if r and pick < 0.85:
        return rng.randint(0, r["mask"])
    return rng.choice([0, 1, 0xFFFFFFFF, 0x80000000, 0xFFFF])


def random_addr(rng, t):
    """A register's address mostly; sometimes an unmapped offset, an
    unaligned one, or a register's address plus a lane."""
    pick = rng.random()
    if pick < 0.8:
        return rng.choice(list(t.regs))
    if pick < 0.9:
        while True:
            a = rng.randrange(0, t.span, 4)
            if a not in t.regs:
                return a
    return rng.choice(list(t.regs)) + rng.randint(1, 3)


def pauser(rng, p):
    """A pause pattern: paused with probability p each cycle."""
    while True:
        yield rng.random() < p


async def setup(dut):
    cocotb.start_soon(Clock(dut.clk, 10, units="ns").start())
    m = AxiLiteMaster(AxiLiteBus.from_prefix(dut, "s_axi"), dut.clk, dut.rst_n, reset_active_level=False)
    for c in (m.write_if, m.read_if):
        c.log.setLevel(logging.WARNING)
    dut.rst_n.value = 0
    await ClockCycles(dut.clk, 8)
    dut.rst_n.value = 1
    await ClockCycles(dut.clk, 4)
    return m


async def bus_monitor(dut, t, found, seen):
    """Watches the port every clock: records the registers whose read data
    has X/Z bits (bits nothing resets: on the FPGA they power up 0, in this
    simulation they are unknown), and counts what the traffic exercised:
    writes whose AW came before W, after W, in the same cycle, and cycles
    of B and R held off by the master."""
    pending = []
    aw, w = [], []
    cycle = 0
    while True:
        await RisingEdge(dut.clk)
        cycle += 1
        if dut.s_axi_arvalid.value == 1 and dut.s_axi_arready.value == 1:
            pending.append(int(dut.s_axi_araddr.value))
        if dut.s_axi_rvalid.value == 1:
            if dut.s_axi_rready.value == 1:
                a = pending.pop(0)
                if not dut.s_axi_rdata.value.is_resolvable:
                    r = t.regs.get(a)
                    found.add(r["name"] if r else f"{a:#x}")
            else:
                seen["r_held"] += 1
        if dut.s_axi_bvalid.value == 1 and dut.s_axi_bready.value == 0:
            seen["b_held"] += 1
        if dut.s_axi_awvalid.value == 1 and dut.s_axi_awready.value == 1:
            aw.append(cycle)
        if dut.s_axi_wvalid.value == 1 and dut.s_axi_wready.value == 1:
            w.append(cycle)
        while aw and w:
            c, d = aw.pop(0), w.pop(0)
            seen["aw_first" if c < d else "w_first" if d < c else "aw_w_same"] += 1


def set_pauses(m, rng, phase):
    """Pause patterns of the master's channels for a phase of the traffic:
    0 none (back to back), 1 AW held back more than W (W first), 2 W held
    back more than AW (AW first); B and R held off at random in 1 and 2."""
    chans = {"aw": m.write_if.aw_channel, "w": m.write_if.w_channel,
             "b": m.write_if.b_channel, "ar": m.read_if.ar_channel,
             "r": m.read_if.r_channel}
    p = {k: 0.0 for k in chans}
    if phase == 1:
        p.update(aw=0.7, w=0.1, b=0.4, r=0.4, ar=0.2)
    elif phase == 2:
        p.update(aw=0.1, w=0.7, b=0.6, r=0.6, ar=0.4)
    for k, c in chans.items():
        if p[k] > 0.0:
            c.set_pause_generator(pauser(random.Random(rng.getrandbits(32)), p[k]))
        else:
            # Clearing the generator keeps its last value: unpause too.
            c.clear_pause_generator()
            c.pause = False


@cocotb.test()
async def axil_random_traffic_follows_the_register_table(dut):
    t = Table(os.environ["REGMAP_JSON"])
    rng = random.Random(SEED)
    m = await setup(dut)
    errors = []
    unknown = set()
    seen = {"aw_first": 0, "w_first": 0, "aw_w_same": 0, "b_held": 0, "r_held": 0}
    cocotb.start_soon(bus_monitor(dut, t, unknown, seen))
    stats = {"writes": 0, "reads": 0, "slverr": 0, "okay": 0, "partial": 0, "rejected": 0, "clamped": 0}

    async def check_read(addr):
        # 500 cycles: far beyond any pause pattern's wait; a hang fails.
        resp = await with_timeout(m.read(addr, 4), 5000, "ns")
        stats["reads"] += 1
        stats["slverr" if resp.resp == AxiResp.SLVERR else "okay"] += 1
        e = t.read(addr, resp.resp, int.from_bytes(resp.data, "little"))
        if e:
            errors.append(e)

    async def do_write(addr, value, nbytes):
        want = t.write(addr, value, nbytes)
        data = (value & ((1 << (8 * nbytes)) - 1)).to_bytes(nbytes, "little")
        resp = await with_timeout(m.write(addr, data), 5000, "ns")
        stats["writes"] += 1
        stats["slverr" if resp.resp == AxiResp.SLVERR else "okay"] += 1
        if resp.resp != want:
            errors.append(f"write {addr:#x} = {value:#x} ({nbytes} B): {resp.resp!r}, expected {want!r}")

    # Reset values of every register.
    for a in sorted(t.regs):
        await check_read(a)
    assert not errors, errors[:10]

    # Every rule on every writable register: the bounds, bits above the
    # width, all ones, a one-byte write; each read back, ERR read and
    # cleared after each register.
    for a in sorted(t.regs):
        r = t.regs[a]
        if r["access"] != "RW":
            continue
        inv = r["invalid"]
        vals = [0, r["mask"], r["mask"] + 1, 0xFFFFFFFF]
        if inv["kind"] in ("clamp", "reject"):
            vals += [inv["max"] - 1, inv["max"], inv["max"] + 1]
        if inv["kind"] == "clamp":
            vals += [max(inv["min"], 1) - 1]
        for v in vals:
            await do_write(a, v & 0xFFFFFFFF, 4)
            await check_read(a)
        await do_write(a, 0xA5, 1)
        await check_read(a)
        await check_read(t.err["addr"])
        await do_write(t.err["addr"], 0xFFFFFFFF, 4)
    assert not errors, "\n".join(errors[:20])

    # Random single operations, each channel paused at random (AW before W,
    # W before AW, B and R held off), a third of the time without pauses.
    for k in range(OPS):
        if k % (OPS // 3) == 0:
            set_pauses(m, rng, k // (OPS // 3) % 3)
            dut._log.info("op %d at %d ns: %s", k, cocotb.utils.get_sim_time("ns"), seen)
        addr = random_addr(rng, t)
        r = t.regs.get(addr - addr % 4)
        if rng.random() < 0.55:
            lane = addr % 4
            nbytes = rng.randint(1, 4 - lane) if (rng.random() < 0.3 or lane) else 4
            if nbytes < 4:
                stats["partial"] += 1
            before = t.val.get(t.err["addr"])
            await do_write(addr, random_value(rng, r), nbytes)
            if t.val.get(t.err["addr"], 0) & t.bad_value and not before & t.bad_value:
                stats["rejected"] += 1
            if r and r["invalid"]["kind"] == "clamp":
                stats["clamped"] += 1
        else:
            await check_read(addr)
        if rng.random() < 0.05:
            # Read back ERR and sometimes clear it.
            await check_read(t.err["addr"])
            if rng.random() < 0.5:
                await do_write(t.err["addr"], 0xFFFFFFFF, 4)
        if len(errors) > 20:
            break

    # Back to back: many operations queued at once, no pauses (the master
    # issues one per clock). Writes to distinct RW registers, then reads
    # of every register.
    set_pauses(m, rng, 0)
    rw = [a for a, r in t.regs.items() if r["access"] == "RW" and r["hw"] != "hw_clear"]
    for burst in range(4):
        picks = rng.sample(rw, min(40, len(rw)))
        t0 = cocotb.utils.get_sim_time("ns")
        tasks = []
        for a in picks:
            v = random_value(rng, t.regs[a])
            tasks.append(cocotb.start_soon(do_write(a, v, 4)))
        for x in tasks:
            await x
        t1 = cocotb.utils.get_sim_time("ns")
        tasks = [cocotb.start_soon(check_read(a)) for a in picks]
        for x in tasks:
            await x
        t2 = cocotb.utils.get_sim_time("ns")
        dut._log.info("burst %d: %d writes in %d cycles, %d reads in %d cycles",
                      burst, len(picks), (t1 - t0) // 10, len(picks), (t2 - t1) // 10)
        # The slave sustains one write per 3 clocks (the write is issued
        # from registers, its address decode registered) and one read per
        # 2 (the two-stage read mux): docs/rtl.md.
        assert (t1 - t0) // 10 <= 3 * len(picks) + 10, (t1 - t0)
        assert (t2 - t1) // 10 <= 2 * len(picks) + 10, (t2 - t1)
    # Everything once more at the end.
    for a in sorted(t.regs):
        await check_read(a)
    dut._log.info("stats: %s", stats)
    dut._log.info("bus: %s", seen)
    dut._log.info("registers read with unknown (X) bits: %s", sorted(unknown))
    assert not errors, "\n".join(errors[:20])
    # The traffic had what it is for.
    assert min(seen.values()) > 10, seen
    assert stats["slverr"] > OPS // 20 and stats["partial"] > OPS // 20, stats
    assert stats["rejected"] >= 1 + OPS // 300 and stats["clamped"] > OPS // 100, stats
