//! Co-simulation of the firmware against the Verilog: the Verilated
//! `pl_top` coupled to the plant by `simpl::SimDrive` (the same
//! inverter, PMSM and ADC/encoder code as the simulated PL, through the
//! [`PlModel`] trait: no second copy of the coupling), served to the
//! firmware under QEMU over the bridge protocol of `simpl::cosim`.
//!
//! [`RtlPl`] is the Verilated `pl_top` as a [`PlModel`]: one clock cycle
//! per simulated cycle (no closed-form skips), an AXI4-Lite read in three
//! cycles (the register-bus strobe in the first), a write in four (the
//! register file's decoded write in the third), the converter answering
//! each `adc_cnv_o` pulse `conv + 1` cycles later with the word the plant
//! set. `pl_top` has no port for the PWM period start (the FOC's control
//! boundary), so a shadow `SimPl` runs in lock step with the same inputs
//! and supplies that event and `CTRL.MODE`; the gates, every read's data
//! and response come from the RTL, and the shadow is checked against them
//! on every cycle ([`RtlPl::mismatches`]; the equivalence itself is
//! `tests/simpl_equiv.rs`).
use crate::pl_top::{PlTopSim, OKAY};
use regmap::bus::BusError;
use regmap::BASE_ADDR;
use simpl::adc::Converter;
use simpl::cosim::{cycle_after_write, serve_cycle, Op, Reply, Request, Status, REQUEST_LEN};
use simpl::gates::GateOutputs;
use simpl::pl::{Events, Pins, SimPl};
use simpl::{PlModel, SimConfig, SimDrive};

/// What the shadow model does in a cycle.
#[derive(Clone, Copy)]
enum Shadow {
    Idle,
    Read(usize),
    Write(usize, u32),
}

/// The Verilated `pl_top` as a [`PlModel`].
pub struct RtlPl {
    rtl: PlTopSim,
    shadow: SimPl,
    pins: Pins,
    /// The RTL's gate outputs after the last edge (`pt_peek` once a cycle).
    gates_q: (u8, u8),
    /// Idle cycles the shadow still has to run: it runs them in one
    /// `SimPl::run` (closed form) before anything else reads or drives it.
    shadow_owed: u64,
    /// Further idle cycles the shadow may owe with the pins unchanged
    /// (`SimPl::quiet_cycles` at its present cycle plus `shadow_owed`, less
    /// those owed); `None`: not known (after a step, an access, a pin change).
    shadow_quiet: Option<u64>,
    cycles: u64,
    mismatches: u64,
    first_mismatch: Option<String>,
}

impl RtlPl {
    /// A fresh `pl_top` out of reset; the converter answers `conv + 1`
    /// cycles after each convert pulse.
    pub fn new(conv: u32) -> Self {
        Self::with_converter(Converter::new(conv))
    }

    /// A fresh `pl_top` out of reset with converter `conv` (the shadow
    /// model gets an identical one).
    pub fn with_converter(conv: Converter) -> Self {
        let mut rtl = PlTopSim::new();
        rtl.adc = Some(conv);
        let o = rtl.peek();
        Self {
            rtl,
            shadow: SimPl::with_converter(conv),
            pins: Pins::default(),
            gates_q: (o.gate_hi, o.gate_lo),
            shadow_owed: 0,
            shadow_quiet: None,
            cycles: 0,
            mismatches: 0,
            first_mismatch: None,
        }
    }

    /// Cycles in which the shadow model disagreed with the RTL (gates or
    /// read data): 0 unless the RTL and `simpl` diverged.
    pub fn mismatches(&self) -> u64 {
        self.mismatches
    }

    /// The first disagreement, if any.
    pub fn first_mismatch(&self) -> Option<&str> {
        self.first_mismatch.as_deref()
    }

    fn mismatch(&mut self, what: String) {
        self.mismatches += 1;
        if self.first_mismatch.is_none() {
            self.first_mismatch = Some(what);
        }
    }

    /// Runs the cycles the shadow owes (with the pins it had).
    fn shadow_flush(&mut self) {
        if self.shadow_owed > 0 {
            let (n, _) = self.shadow.run(self.shadow_owed, &Events::default());
            debug_assert_eq!(n, self.shadow_owed);
            self.shadow_owed = 0;
        }
    }

    /// The shadow's cycle: stepped, or owed when it is one in which nothing
    /// but counters change (no event, the gates as they are), which the
    /// shadow then runs in closed form with the others owed. The same
    /// result as stepping it every cycle, at a fraction of the cost.
    fn shadow_cycle(&mut self, p: Pins, sh: Shadow) -> (Events, Option<Result<u32, BusError>>) {
        if self.shadow.pins != p || !matches!(sh, Shadow::Idle) {
            self.shadow_flush();
            self.shadow.pins = p;
            self.shadow_quiet = None;
        }
        match sh {
            Shadow::Idle => {
                let q = match self.shadow_quiet {
                    Some(q) => q,
                    None => self.shadow.quiet_cycles(),
                };
                if q > 0 {
                    self.shadow_owed += 1;
                    self.shadow_quiet = Some(q - 1);
                    return (Events::default(), None);
                }
                self.shadow_flush();
                let ev = self.shadow.run(1, &Events::ALL).1;
                self.shadow_quiet = None;
                (ev, None)
            }
            Shadow::Read(a) => {
                let (r, ev) = self.shadow.read(a);
                (ev, Some(r))
            }
            Shadow::Write(a, v) => {
                let (r, ev) = self.shadow.write(a, v);
                (ev, Some(r.map(|()| 0)))
            }
        }
    }

    /// One clock cycle of both models with the AXI inputs already set;
    /// returns the RTL's outputs before the edge, the cycle's events and
    /// the shadow's bus result.
    fn cycle(
        &mut self,
        sh: Shadow,
    ) -> (crate::pl_top::PtOut, Events, Option<Result<u32, BusError>>) {
        let p = self.pins;
        self.rtl.inp.enc_a = u8::from(p.enc_a);
        self.rtl.inp.enc_b = u8::from(p.enc_b);
        self.rtl.inp.enc_z = u8::from(p.enc_z);
        self.rtl.inp.fault_ext_n = u8::from(p.fault_ext_n);
        self.rtl.adc_data = p.adc_word;
        let g0 = self.gates_q;
        let o = self.rtl.step();
        let after = self.rtl.peek();
        let (sev, res) = self.shadow_cycle(p, sh);
        self.cycles += 1;
        let g = (after.gate_hi, after.gate_lo);
        self.gates_q = g;
        let sg = self.shadow.gates();
        if g != (sg.hi, sg.lo) {
            let c = self.cycles;
            self.mismatch(format!(
                "cycle {c}: gates rtl {g:?}, model ({}, {})",
                sg.hi, sg.lo
            ));
        }
        let ev = Events {
            gates: g != g0,
            adc_convert: after.adc_cnv == 1,
            adc_average: o.adc_avg_valid == 1,
            pwm_period: sev.pwm_period,
            control_boundary: sev.control_boundary,
        };
        (o, ev, res)
    }

    fn axi(addr: usize) -> Option<u16> {
        let rel = addr.checked_sub(BASE_ADDR)?;
        u16::try_from(rel).ok().filter(|r| *r < 0x8000)
    }

    fn check_bus(
        &mut self,
        what: &str,
        addr: usize,
        rtl: Result<u32, BusError>,
        model: Option<Result<u32, BusError>>,
    ) {
        if model != Some(rtl) {
            self.mismatch(format!("{what} {addr:#x}: rtl {rtl:x?}, model {model:x?}"));
        }
    }
}

impl PlModel for RtlPl {
    fn cycles(&self) -> u64 {
        self.cycles
    }
    fn gates(&self) -> GateOutputs {
        let (hi, lo) = self.gates_q;
        GateOutputs { hi, lo }
    }
    fn pins_mut(&mut self) -> &mut Pins {
        &mut self.pins
    }
    fn set_adc_fitted(&mut self, fitted: bool) {
        // The shadow's owed cycles ran with the converter as it was.
        self.shadow_flush();
        self.shadow_quiet = None;
        PlModel::set_adc_fitted(&mut self.shadow, fitted);
        if let Some(c) = &mut self.rtl.adc {
            c.set_fitted(fitted);
        }
    }
    fn run(&mut self, max: u64, stop: &Events) -> (u64, Events) {
        let mut all = Events::default();
        let mut n = 0;
        while n < max {
            let (_, ev, _) = self.cycle(Shadow::Idle);
            n += 1;
            all.gates |= ev.gates;
            all.adc_convert |= ev.adc_convert;
            all.adc_average |= ev.adc_average;
            all.pwm_period |= ev.pwm_period;
            all.control_boundary |= ev.control_boundary;
            if ev.hits(stop) {
                break;
            }
        }
        (n, all)
    }
    fn read(&mut self, addr: usize) -> (Result<u32, BusError>, Events) {
        // Outside the GP0 window: no AXI transfer reaches pl_top.
        let Some(rel) = Self::axi(addr) else {
            return (Err(BusError::SlaveError), Events::default());
        };
        self.rtl.inp.araddr = rel;
        self.rtl.inp.arvalid = 1;
        self.rtl.inp.rready = 1;
        let (_, e1, model) = self.cycle(Shadow::Read(addr));
        self.rtl.inp.arvalid = 0;
        // the register file's second read stage, then R
        let (_, e2, _) = self.cycle(Shadow::Idle);
        let (o, e3, _) = self.cycle(Shadow::Idle);
        let e2 = merge(e2, e3);
        let r = if o.rvalid != 1 {
            Err(BusError::SlaveError)
        } else if o.rresp == OKAY {
            Ok(o.rdata)
        } else {
            Err(BusError::SlaveError)
        };
        self.check_bus("read", addr, r, model);
        (r, merge(e1, e2))
    }
    fn write(&mut self, addr: usize, value: u32) -> (Result<(), BusError>, Events) {
        let Some(rel) = Self::axi(addr) else {
            return (Err(BusError::SlaveError), Events::default());
        };
        self.rtl.inp.awaddr = rel;
        self.rtl.inp.wdata = value;
        self.rtl.inp.wstrb = 0xF;
        self.rtl.inp.awvalid = 1;
        self.rtl.inp.wvalid = 1;
        self.rtl.inp.bready = 1;
        // AW and W taken, the register-bus write the next cycle, the
        // register file's decoded write (the shadow's write) the cycle
        // after, then B
        let (_, e0, _) = self.cycle(Shadow::Idle);
        self.rtl.inp.awvalid = 0;
        self.rtl.inp.wvalid = 0;
        let (_, e1, _) = self.cycle(Shadow::Idle);
        let (_, e2, model) = self.cycle(Shadow::Write(addr, value));
        let e1 = merge(merge(e0, e1), e2);
        let (o, e2, _) = self.cycle(Shadow::Idle);
        let r = if o.bvalid == 1 && o.bresp == OKAY {
            Ok(0)
        } else {
            Err(BusError::SlaveError)
        };
        self.check_bus("write", addr, r, model);
        (r.map(|_| ()), merge(e1, e2))
    }
    fn work(&self) -> (u64, u64) {
        (self.cycles, 0)
    }
}

fn merge(a: Events, b: Events) -> Events {
    Events {
        gates: a.gates | b.gates,
        adc_convert: a.adc_convert | b.adc_convert,
        adc_average: a.adc_average | b.adc_average,
        pwm_period: a.pwm_period | b.pwm_period,
        control_boundary: a.control_boundary | b.control_boundary,
    }
}

/// The host end of the bridge: the co-simulated drive and the time
/// mapping of `simpl::cosim`.
pub struct Bridge {
    drive: SimDrive<RtlPl>,
    /// (guest time, PL cycle) of the first request.
    origin: Option<(u64, u64)>,
    boundaries: u32,
    last_boundary: Option<u64>,
    /// Requests served.
    pub requests: u64,
    /// Posted writes among them (no reply).
    pub posted: u64,
    /// Posted writes that did not end as the guest assumed (OKAY, at
    /// `cycle_after_write`): 0 unless the guest posted where it must wait.
    pub posted_errors: u64,
    /// Control-period boundaries seen in all.
    pub periods: u64,
}

impl Bridge {
    /// The drive with the default simulated motor (`SimConfig::default()`).
    pub fn new() -> Self {
        let cfg = SimConfig::default();
        let pl = RtlPl::with_converter(cfg.converter());
        let drive = SimDrive::with_pl(&cfg, pl).expect("default motor parameters");
        Self {
            drive,
            origin: None,
            boundaries: 0,
            last_boundary: None,
            requests: 0,
            posted: 0,
            posted_errors: 0,
            periods: 0,
        }
    }

    /// The co-simulated drive.
    pub fn drive(&self) -> &SimDrive<RtlPl> {
        &self.drive
    }

    /// The co-simulated drive, mutable (host tests drive it directly).
    pub fn drive_mut(&mut self) -> &mut SimDrive<RtlPl> {
        &mut self.drive
    }

    /// Runs the PL up to PL cycle `target` (never backwards), noting the
    /// control-period boundaries.
    fn run_to(&mut self, target: u64) {
        loop {
            let left = target.saturating_sub(self.drive.pl_cycles());
            let adv = self.drive.advance_to_boundary(left);
            if adv.control_periods > 0 {
                self.boundaries = self.boundaries.saturating_add(adv.control_periods);
                self.periods += u64::from(adv.control_periods);
                self.last_boundary = Some(self.drive.pl_cycles());
            }
            if self.drive.pl_cycles() >= target {
                break;
            }
        }
    }

    /// Serves one request record; the reply to send (`None`: a posted
    /// write, which gets none).
    pub fn handle(&mut self, raw: &[u8; REQUEST_LEN]) -> Option<Reply> {
        self.requests += 1;
        let Ok(req) = Request::decode(raw) else {
            return Some(self.reply(Status::BadRequest, 0));
        };
        if req.op != Op::PostedWrite {
            return Some(self.serve(&req));
        }
        self.posted += 1;
        let now = self.drive.pl_cycles();
        let origin = *self.origin.get_or_insert((req.guest, now));
        let r = self.serve(&Request {
            op: Op::Write,
            ..req
        });
        if r.status != Status::Ok || r.pl_cycles != cycle_after_write(origin, req.guest, now) {
            self.posted_errors += 1;
        }
        None
    }

    /// Serves one request.
    pub fn serve(&mut self, req: &Request) -> Reply {
        // The simulated motor's parameters: no guest time, the PL stays.
        match req.op {
            Op::SimSet => {
                let row = models::pmsm::sim_motor::SIM_PARAMS.get(req.addr as usize);
                let v = f64::from_bits(req.guest);
                return match row.map(|p| self.drive.sim_set(p.name, v)) {
                    Some(Ok(())) => self.reply(Status::Ok, 0),
                    _ => self.reply(Status::SlaveError, 0),
                };
            }
            Op::GatesOff => {
                let now = self.drive.pl_cycles();
                let off = self
                    .drive
                    .gates_off_since()
                    .map_or(u32::MAX, |c| u32::try_from(now - c).unwrap_or(u32::MAX));
                return self.reply(Status::Ok, off);
            }
            Op::SimReset => {
                let d = models::pmsm::sim_motor::SimMotor::default();
                return match self.drive.apply_sim_motor(&d) {
                    Ok(()) => self.reply(Status::Ok, 0),
                    Err(_) => self.reply(Status::SlaveError, 0),
                };
            }
            Op::State => return self.reply(Status::Ok, 0),
            _ => {}
        }
        let now = self.drive.pl_cycles();
        let origin = *self.origin.get_or_insert((req.guest, now));
        self.run_to(serve_cycle(origin, req.guest, now));
        let addr = req.addr as usize;
        match req.op {
            Op::Read => match regmap::bus::RegisterBus::read(&mut self.drive, addr) {
                Ok(v) => self.reply(Status::Ok, v),
                Err(_) => self.reply(Status::SlaveError, 0),
            },
            Op::Write => match regmap::bus::RegisterBus::write(&mut self.drive, addr, req.data) {
                Ok(()) => self.reply(Status::Ok, 0),
                Err(_) => self.reply(Status::SlaveError, 0),
            },
            Op::SimSet | Op::SimReset | Op::GatesOff | Op::State | Op::PostedWrite => {
                self.reply(Status::BadRequest, 0)
            }
            Op::Sync => {
                // `run_to` above also collected the boundaries crossed
                // during the accesses since the last sync.
                let r = self.reply(Status::Ok, 0);
                self.boundaries = 0;
                r
            }
        }
    }

    fn reply(&self, status: Status, data: u32) -> Reply {
        let now = self.drive.pl_cycles();
        Reply {
            status,
            data,
            boundaries: self.boundaries,
            since_boundary: self
                .last_boundary
                .map_or(u32::MAX, |b| u32::try_from(now - b).unwrap_or(u32::MAX)),
            pl_cycles: now,
        }
    }
}

impl Default for Bridge {
    fn default() -> Self {
        Self::new()
    }
}
