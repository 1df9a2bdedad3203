//! The PL-only layer: `pl_top` behind its register bus, without the plant.
//!
//! Inputs are pin levels ([`Pins`]: encoder A/B/Z, external fault, the ADC
//! converter's data word) and elapsed PL cycles; outputs are the six gate
//! levels, with the cycle of each edge, and the register reads.
//!
//! Time base: one unit = one PL clock cycle (10 ns at 100 MHz).
//! [`SimPl::cycles`] counts the cycles simulated since reset was released.
//! A bus access occupies one cycle: the cycle of the register-bus strobe
//! (`wr`/`rd` of `axil_slave`), i.e. a read returns the registers as they
//! are at the start of that cycle, and a write takes effect at its end,
//! together with everything else that happens in that cycle.
//!
//! Event-driven: [`SimPl::run`] steps the full cycle-exact logic only in
//! cycles where something other than a counter changes (a gate edge, a
//! dead-time end, a PWM comparator, bottom or top, an ADC conversion, a
//! sample, an average, a sequence step, a core result, a watchdog expiry,
//! a pin change through its synchroniser); it jumps over the cycles in
//! between in closed form (each block's `quiet`/`skip`).

use super::adc::{Adc, Converter};
use super::capture::{CapIn, Capture, Sample};
use super::core::{sext, Core};
use super::enc::{Encoder, Sync2};
use super::fault::{Fault, FaultIn};
use super::frontend::Frontend;
use super::mpdcc::{MpdccBlock, Words};
use super::pwm::Pwm;
use super::regs::{slot, slot_of, Regs, WriteResult};
use super::seq::{Seq, SeqIn};
use super::NEVER;
use crate::gates::{DeadTime, GateDriver, GateInputs, GateOutputs, DEAD_TIME_MAX_CYCLES};
use crate::irq::CtrlIrq;
use models::pmsm::frontend_fixed::{FrontendInputs, FrontendParams};
use models::pmsm::mpdtc_fixed::{FixedInputs, FixedParams};
use regmap::bus::BusError;
use regmap::{self as rm, mode, ADC, CAPTURE, ENC, FAULT, MPDCC, MPDTC, PWM, TOP};

const S_CTRL: usize = slot_of(&TOP, &rm::CTRL);
const S_ERR: usize = slot_of(&TOP, &rm::ERR);
const S_HEARTBEAT: usize = slot_of(&TOP, &rm::HEARTBEAT);
const S_IRQ_EN: usize = slot_of(&TOP, &rm::IRQ_EN);
const S_IRQ_STATUS: usize = slot_of(&TOP, &rm::IRQ_STATUS);
const S_GATE_CTRL: usize = slot_of(&PWM, &rm::GATE_CTRL);
const S_DEAD_TIME: usize = slot_of(&PWM, &rm::DEAD_TIME);
const S_PWM_PERIOD: usize = slot_of(&PWM, &rm::PWM_PERIOD);
const S_DUTY: [usize; 3] = [
    slot_of(&PWM, &rm::DUTY_A),
    slot_of(&PWM, &rm::DUTY_B),
    slot_of(&PWM, &rm::DUTY_C),
];
const S_SW_STATE: usize = slot_of(&PWM, &rm::SW_STATE);
const S_ADC_CTRL: usize = slot_of(&ADC, &rm::ADC_CTRL);
const S_ADC_PERIOD: usize = slot_of(&ADC, &rm::ADC_PERIOD);
const S_ADC_AVG_LOG2: usize = slot_of(&ADC, &rm::ADC_AVG_LOG2);
const S_ENC_CPR: usize = slot_of(&ENC, &rm::ENC_CPR);
const S_ENC_WINDOW: usize = slot_of(&ENC, &rm::ENC_WINDOW);
const S_FAULT_STATUS: usize = slot_of(&FAULT, &rm::FAULT_STATUS);
const S_OC_LIMIT: usize = slot_of(&FAULT, &rm::OC_LIMIT);
const S_WDG_TIMEOUT: usize = slot_of(&FAULT, &rm::WDG_TIMEOUT);
const S_MPDTC_CTRL: usize = slot_of(&MPDTC, &rm::MPDTC_CTRL);
const S_MPDTC_START: usize = slot_of(&MPDTC, &rm::MPDTC_START);
const S_ALIGN_VEC: usize = slot_of(&MPDTC, &rm::MPDTC_ALIGN_VEC);
const S_ALIGN_PERIOD: usize = slot_of(&MPDTC, &rm::MPDTC_ALIGN_PERIOD);
const S_ALIGN_ON: usize = slot_of(&MPDTC, &rm::MPDTC_ALIGN_ON);
const S_ALIGN_TIME: usize = slot_of(&MPDTC, &rm::MPDTC_ALIGN_TIME);
const S_CAP_SOURCE: usize = slot_of(&CAPTURE, &rm::CAP_SOURCE);
const S_CAP_PRE: usize = slot_of(&CAPTURE, &rm::CAP_PRE);
const S_CAP_DECIM: usize = slot_of(&CAPTURE, &rm::CAP_DECIM);
const S_CAP_STEP: usize = slot_of(&CAPTURE, &rm::CAP_STEP);
const S_CAP_THR_CH: usize = slot_of(&CAPTURE, &rm::CAP_THR_CH);
const S_CAP_THR_LEVEL: usize = slot_of(&CAPTURE, &rm::CAP_THR_LEVEL);
const S_CAP_THR_EDGE: usize = slot_of(&CAPTURE, &rm::CAP_THR_EDGE);
const S_CAP_SEL: usize = slot_of(&CAPTURE, &rm::CAP_SEL);
const S_CAP_ARM: usize = slot_of(&CAPTURE, &rm::CAP_ARM);
const S_CAP_TRIG: usize = slot_of(&CAPTURE, &rm::CAP_TRIG);
const S_CAP_IN_ID: usize = slot_of(&CAPTURE, &rm::CAP_IN_ID);
const S_CAP_IN_IQ: usize = slot_of(&CAPTURE, &rm::CAP_IN_IQ);
const S_CAP_IN_TORQUE: usize = slot_of(&CAPTURE, &rm::CAP_IN_TORQUE);
const S_CAP_IN_TREF: usize = slot_of(&CAPTURE, &rm::CAP_IN_TREF);
const S_CAP_RD_INDEX: usize = slot_of(&CAPTURE, &rm::CAP_RD_INDEX);
const S_CAP_IN_POS: usize = slot_of(&CAPTURE, &rm::CAP_IN_POS);
const S_CAP_IN_VEL: usize = slot_of(&CAPTURE, &rm::CAP_IN_VEL);
const S_CAP_IN_FERR: usize = slot_of(&CAPTURE, &rm::CAP_IN_FERR);

const S_MPDCC_START: usize = slot_of(&MPDCC, &rm::MPDCC_START);
const S_MPDCC_N_USE: usize = slot_of(&MPDCC, &rm::MPDCC_N_USE);
const S_MPDCC_S_PREV: usize = slot_of(&MPDCC, &rm::MPDCC_S_PREV);
/// Slots of `n` MPDCC-page words from register `first` of the page on.
const fn mc_slots<const N: usize>(first: usize) -> [usize; N] {
    let mut out = [0; N];
    let mut i = 0;
    while i < N {
        out[i] = slot_of(&MPDCC, MPDCC.registers[first + i]);
        i += 1;
    }
    out
}
/// `MPDCC_I_A` .. `MPDCC_OMEGA_S` (the page's registers 5..17).
const S_MPDCC_STATE: [usize; 12] = mc_slots(5);
/// `MPDCC_C_TAU` .. `MPDCC_LAMBDA_N` (the page's registers 17..44).
const S_MPDCC_CONSTS: [usize; 27] = mc_slots(17);

const A_ID: usize = TOP.addr(&rm::ID);
const A_VERSION: usize = TOP.addr(&rm::VERSION);
const A_STATUS: usize = TOP.addr(&rm::STATUS);
const A_IRQ_STATUS: usize = TOP.addr(&rm::IRQ_STATUS);
const A_BOUNDARY_AGE: usize = TOP.addr(&rm::BOUNDARY_AGE);
const A_GATE_STATUS: usize = PWM.addr(&rm::GATE_STATUS);
const A_PWM_COUNT: usize = PWM.addr(&rm::PWM_COUNT);
const A_ADC_IA: usize = ADC.addr(&rm::ADC_IA);
const A_ADC_IB: usize = ADC.addr(&rm::ADC_IB);
const A_ADC_IC: usize = ADC.addr(&rm::ADC_IC);
const A_ADC_COUNT: usize = ADC.addr(&rm::ADC_COUNT);
const A_ENC_POS: usize = ENC.addr(&rm::ENC_POS);
const A_ENC_SPEED: usize = ENC.addr(&rm::ENC_SPEED);
const A_ENC_INDEX: usize = ENC.addr(&rm::ENC_INDEX);
const A_ENC_POS_SAMPLE: usize = ENC.addr(&rm::ENC_POS_SAMPLE);
const A_FAULT_STATUS: usize = FAULT.addr(&rm::FAULT_STATUS);
const A_FAULT_RAW: usize = FAULT.addr(&rm::FAULT_RAW);
const A_MPDTC_STATUS: usize = MPDTC.addr(&rm::MPDTC_STATUS);
const A_MPDTC_LATENCY: usize = MPDTC.addr(&rm::MPDTC_LATENCY);
const A_MPDTC_IQ_REF: usize = MPDTC.addr(&rm::MPDTC_IQ_REF);
const A_SEQ_STATUS: usize = MPDTC.addr(&rm::MPDTC_SEQ_STATUS);
const A_ALIGN_POS: usize = MPDTC.addr(&rm::MPDTC_ALIGN_POS);
const A_MPDCC_STATUS: usize = MPDCC.addr(&rm::MPDCC_STATUS);
const A_MPDCC_CONFIG: usize = MPDCC.addr(&rm::MPDCC_CONFIG);
const A_MPDCC_DECISION: usize = MPDCC.addr(&rm::MPDCC_DECISION);
const A_MPDCC_COST: usize = MPDCC.addr(&rm::MPDCC_COST);
const A_MPDCC_J_DL: usize = MPDCC.addr(&rm::MPDCC_J_DL);
const A_MPDCC_CYCLES: usize = MPDCC.addr(&rm::MPDCC_CYCLES);
const A_MPDCC_DEADLOCKS: usize = MPDCC.addr(&rm::MPDCC_DEADLOCKS);
const A_FE_ID: usize = MPDTC.addr(&rm::MPDTC_FE_ID);
const A_FE_IQ: usize = MPDTC.addr(&rm::MPDTC_FE_IQ);
const A_CAP_STATUS: usize = CAPTURE.addr(&rm::CAP_STATUS);
const A_CAP_DATA0: usize = CAPTURE.addr(&rm::CAP_DATA0);
const A_CAP_DATA1: usize = CAPTURE.addr(&rm::CAP_DATA1);
const A_CAP_DATA2: usize = CAPTURE.addr(&rm::CAP_DATA2);
const A_CAP_DEPTH: usize = CAPTURE.addr(&rm::CAP_DEPTH);
const A_CAP_DATA3: usize = CAPTURE.addr(&rm::CAP_DATA3);
const A_CAP_DATA4: usize = CAPTURE.addr(&rm::CAP_DATA4);
const A_CAP_DATA5: usize = CAPTURE.addr(&rm::CAP_DATA5);

const DT_MAX: DeadTime = match DeadTime::new(DEAD_TIME_MAX_CYCLES) {
    Ok(d) => d,
    Err(_) => panic!("dead time range"),
};

/// Slot of an MPDTC-page input/parameter register.
const fn mp(reg: &rm::Register) -> usize {
    slot_of(&MPDTC, reg)
}

/// Pin levels and the converter's data, as the board drives them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pins {
    /// Encoder A.
    pub enc_a: bool,
    /// Encoder B.
    pub enc_b: bool,
    /// Encoder index Z.
    pub enc_z: bool,
    /// External fault input, active low (`true` = no fault).
    pub fault_ext_n: bool,
    /// ADC data `{ia, ib, ic}` (12 bits each, ia in bits 35..24), latched
    /// by the converter's `drdy` (see [`super::adc::adc_word`]).
    pub adc_word: u64,
}

impl Default for Pins {
    fn default() -> Self {
        Self {
            enc_a: false,
            enc_b: false,
            enc_z: false,
            fault_ext_n: true,
            adc_word: 0,
        }
    }
}

/// What happened in a stepped cycle (flags; also used as a stop mask).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Events {
    /// The gate outputs changed at the end of the cycle.
    pub gates: bool,
    /// The cycle's edge raised the ADC convert pulse: the converter samples
    /// its input now (the start of the next cycle).
    pub adc_convert: bool,
    /// The averaged-sample strobe was high in the cycle: a new ADC average
    /// (the MPDTC control-period boundary).
    pub adc_average: bool,
    /// The PWM counter was at its bottom: the duties loaded at the cycle's
    /// edge and a PWM period starts (the FOC control-period boundary).
    pub pwm_period: bool,
    /// The control-period boundary of the mode in force in the cycle
    /// (`pl_top`'s `ctrl_boundary`, which sets `IRQ_STATUS.BOUNDARY`): the
    /// PWM bottom in FOC-PWM, else the new ADC average. Judged by the PL
    /// cycle by cycle; the two events above alone cannot tell it across a
    /// bus access that changes the mode (a PWM bottom in the cycles of a
    /// write of `CTRL.MODE` comes before the new mode takes effect).
    pub control_boundary: bool,
}

impl Events {
    /// Every event.
    pub const ALL: Self = Self {
        gates: true,
        adc_convert: true,
        adc_average: true,
        pwm_period: true,
        control_boundary: true,
    };

    /// Any flag set in both.
    pub fn hits(&self, mask: &Self) -> bool {
        (self.gates && mask.gates)
            || (self.adc_convert && mask.adc_convert)
            || (self.adc_average && mask.adc_average)
            || (self.pwm_period && mask.pwm_period)
            || (self.control_boundary && mask.control_boundary)
    }

    /// Adds the events of `o` (either's).
    pub fn merge(&mut self, o: &Self) {
        self.gates |= o.gates;
        self.adc_convert |= o.adc_convert;
        self.adc_average |= o.adc_average;
        self.pwm_period |= o.pwm_period;
        self.control_boundary |= o.control_boundary;
    }
}

/// Bus strobe of a cycle.
enum Strobe {
    None,
    Read { err: bool },
    Write(WriteResult),
}

/// Combinational values of `pl_top` in the present cycle.
struct Comb {
    sel_pwm: bool,
    gate_en: bool,
    mp_clr: bool,
    fault_in: FaultIn,
    trip: bool,
    fault_any: bool,
    seq_in: SeqIn,
    state_sel: u8,
    drive_en: bool,
    core_in_valid: bool,
    core_load: bool,
    /// MPDTC_CTRL.AUTO: the core's inputs come from the front end.
    auto: bool,
    /// The front end starts at this cycle's edge.
    fe_start: bool,
}

/// `pl_top` without the plant.
#[derive(Debug, Clone)]
pub struct SimPl {
    regs: Regs,
    pwm: Pwm,
    gates: GateDriver,
    adc: Adc,
    enc_sync: [Sync2; 3],
    enc: Encoder,
    ext_sync: Sync2,
    fault: Fault,
    seq: Seq,
    fe: Frontend,
    core: Core,
    core_s: u8,
    core_iq_ref: i32,
    core_done: u16,
    cap: Capture,
    /// `capture_buf`'s inputs of the cycle before: `pl_top` registers them
    /// (all but the read index), so the buffer runs one clock behind.
    cap_prev: CapIn,
    mpdcc: MpdccBlock,
    irq: CtrlIrq,
    cycles: u64,
    /// Pin levels applied from the next cycle on.
    pub pins: Pins,
    /// Cycles simulated one by one (events and bus accesses).
    pub stepped: u64,
    /// Quiet spans jumped over in closed form.
    pub skips: u64,
}

impl SimPl {
    /// `pl_top` right after reset; the converter answers each convert pulse
    /// `conv_cycles + 1` cycles later with a one-cycle data-ready.
    pub fn new(conv_cycles: u32) -> Self {
        Self::with_converter(Converter::new(conv_cycles))
    }

    /// `pl_top` right after reset with the converter `conv`.
    pub fn with_converter(conv: Converter) -> Self {
        Self {
            regs: Regs::default(),
            pwm: Pwm::default(),
            gates: GateDriver::default(),
            adc: Adc::new(conv),
            enc_sync: [Sync2::new(false); 3],
            enc: Encoder::default(),
            ext_sync: Sync2::new(true),
            fault: Fault::default(),
            seq: Seq::default(),
            fe: Frontend::default(),
            core: Core::default(),
            core_s: 0,
            core_iq_ref: 0,
            core_done: 0,
            cap: Capture::default(),
            cap_prev: CapIn::default(),
            mpdcc: MpdccBlock::new(),
            irq: CtrlIrq::default(),
            cycles: 0,
            pins: Pins::default(),
            stepped: 0,
            skips: 0,
        }
    }

    /// Fits or removes the ADC card's converter (from the next cycle on).
    pub fn set_adc_fitted(&mut self, fitted: bool) {
        self.adc.conv.set_fitted(fitted);
    }

    /// PL cycles simulated since reset.
    pub fn cycles(&self) -> u64 {
        self.cycles
    }

    /// Gate outputs now (bit 2 = leg a).
    pub fn gates(&self) -> GateOutputs {
        self.gates.outputs()
    }

    /// The control interrupt line `irq_o` (to `IRQ_F2P[0]`).
    pub fn irq_line(&self) -> bool {
        self.irq.irq
    }

    /// `CTRL.MODE`.
    pub fn mode(&self) -> u32 {
        self.r(S_CTRL)
    }

    fn r(&self, s: usize) -> u32 {
        self.regs.get(s)
    }

    fn comb(&self, start: bool) -> Comb {
        let ctrl = self.r(S_CTRL);
        let sel_pwm = ctrl == mode::FOC_PWM;
        let sel_state = ctrl == mode::MPDTC;
        let gate_en = self.r(S_GATE_CTRL) & 1 != 0;
        let mp_ctrl = self.r(S_MPDTC_CTRL);
        let manual = mp_ctrl & 1 != 0;
        let mp_clr = mp_ctrl & 2 != 0;
        let auto = mp_ctrl & 4 != 0;
        let fault_in = FaultIn {
            sample_valid: self.adc.sv,
            sample: self.adc.sample,
            oc_limit: self.r(S_OC_LIMIT) as u16,
            ext: !self.ext_sync.q,
            wdg_timeout: self.r(S_WDG_TIMEOUT),
            run: gate_en,
            enc_illegal: self.enc.illegal(self.enc_sync[0].q, self.enc_sync[1].q),
            adc_en: self.r(S_ADC_CTRL) & 1 != 0,
            adc_period: self.r(S_ADC_PERIOD) as u16,
        };
        let trip = self.fault.trip(&fault_in);
        let fault_any = self.fault.status != 0;
        let run = sel_state && gate_en && !manual && !mp_clr && !fault_any && !trip;
        let core_valid = self.core.valid();
        let seq_in = SeqIn {
            run,
            sample: self.adc.av,
            auto,
            start: if auto { self.fe.valid() } else { start },
            core_ready: self.core.ready(),
            core_valid,
            core_s: self.core.pending.s_next,
            align_vec: self.r(S_ALIGN_VEC) as u8,
            align_period: self.r(S_ALIGN_PERIOD) as u16,
            align_on: self.r(S_ALIGN_ON) as u16,
            align_time: self.r(S_ALIGN_TIME),
            enc_pos: self.enc.pos,
        };
        let mpdtc_state = if manual {
            self.r(S_SW_STATE) as u8
        } else {
            self.seq.s(&seq_in)
        };
        let state_sel = if sel_pwm {
            self.pwm.s()
        } else if sel_state {
            mpdtc_state
        } else {
            0
        };
        let drive_en = gate_en && (sel_pwm || (sel_state && (manual || self.seq.drive(run))));
        Comb {
            sel_pwm,
            gate_en,
            mp_clr,
            core_in_valid: self.seq.core_start(&seq_in) && !mp_clr,
            core_load: mp_clr || self.seq.core_clr(),
            auto,
            fe_start: auto && self.adc.av && self.fe.idle(),
            fault_in,
            trip,
            fault_any,
            seq_in,
            state_sel,
            drive_en,
        }
    }

    /// `capture_buf`'s inputs in the present cycle.
    fn cap_inputs(&self, c: &Comb, arm: bool, trig: bool) -> CapIn {
        let sel = match self.r(S_CAP_SEL) {
            0 => self.adc.avg_reg(0),
            1 => self.adc.avg_reg(1),
            2 => self.adc.avg_reg(2),
            3 => u32::from(self.enc.pos),
            _ => u32::from(self.enc.speed as u16),
        };
        CapIn {
            arm,
            trig,
            source: self.r(S_CAP_SOURCE),
            pre: self.r(S_CAP_PRE),
            decim: self.r(S_CAP_DECIM),
            step: self.r(S_CAP_STEP),
            thr_ch: self.r(S_CAP_THR_CH),
            thr_level: self.r(S_CAP_THR_LEVEL) as u16,
            falling: self.r(S_CAP_THR_EDGE) & 1 != 0,
            sample: self.adc.av,
            fault: c.fault_any,
            ch: Sample {
                i_d: self.r(S_CAP_IN_ID) as u16,
                i_q: self.r(S_CAP_IN_IQ) as u16,
                torque: self.r(S_CAP_IN_TORQUE) as u16,
                tref: self.r(S_CAP_IN_TREF) as u16,
                sel: sel as u16,
                sw: c.state_sel,
                pos: self.r(S_CAP_IN_POS),
                vel: self.r(S_CAP_IN_VEL),
                ferr: self.r(S_CAP_IN_FERR) as u16,
            },
            rd_index: self.r(S_CAP_RD_INDEX),
        }
    }

    fn dead_time(&self) -> DeadTime {
        // DEAD_TIME is clamped to the driver's range by the table.
        DeadTime::new(self.r(S_DEAD_TIME) as u16).unwrap_or(DT_MAX)
    }

    /// The front end's inputs and registers in the present cycle (its
    /// ports' widths are applied by the model).
    fn fe_inputs(&self) -> (FrontendInputs, FrontendParams) {
        let r = |reg: &rm::Register| self.r(mp(reg));
        let inp = FrontendInputs {
            pos: u32::from(self.enc.pos),
            speed: i32::from(self.enc.speed),
            adc: [0, 1, 2].map(|k| self.adc.avg_reg(k) as i32),
            t_ref: r(&rm::MPDTC_IN_T_REF) as i32,
        };
        let p = FrontendParams {
            cpr: self.r(S_ENC_CPR),
            align_pos: u32::from(self.seq.align_pos),
            ang_scale: r(&rm::MPDTC_FE_ANG_SCALE),
            spd_scale: r(&rm::MPDTC_FE_SPD_SCALE),
            age: [&rm::MPDTC_FE_AGE0, &rm::MPDTC_FE_AGE1, &rm::MPDTC_FE_AGE2].map(|x| r(x) as i32),
            adc_off: [
                &rm::MPDTC_FE_OFF_A,
                &rm::MPDTC_FE_OFF_B,
                &rm::MPDTC_FE_OFF_C,
            ]
            .map(|x| r(x) as i32),
            adc_gain: [
                &rm::MPDTC_FE_GAIN_A,
                &rm::MPDTC_FE_GAIN_B,
                &rm::MPDTC_FE_GAIN_C,
            ]
            .map(|x| r(x) as i32),
        };
        (inp, p)
    }

    fn core_inputs(&self, auto: bool) -> (FixedInputs, FixedParams) {
        let c = |reg: &rm::Register| sext(self.r(mp(reg)), 18);
        let w = |reg: &rm::Register| sext(self.r(mp(reg)), 25);
        let inp = if auto {
            self.fe.out.core
        } else {
            FixedInputs {
                i_dq: (w(&rm::MPDTC_IN_ID), w(&rm::MPDTC_IN_IQ)),
                trig: [
                    (c(&rm::MPDTC_IN_COS0), c(&rm::MPDTC_IN_SIN0)),
                    (c(&rm::MPDTC_IN_COS1), c(&rm::MPDTC_IN_SIN1)),
                    (c(&rm::MPDTC_IN_COS2), c(&rm::MPDTC_IN_SIN2)),
                ],
                w_ts: c(&rm::MPDTC_IN_W_TS),
                t_ref: c(&rm::MPDTC_IN_T_REF),
            }
        };
        let p = FixedParams {
            a: c(&rm::MPDTC_P_A),
            lambda: c(&rm::MPDTC_P_LAMBDA),
            u0: w(&rm::MPDTC_P_U0),
            u0_half: w(&rm::MPDTC_P_U0_HALF),
            u0_h: w(&rm::MPDTC_P_U0_H),
            psi_l: w(&rm::MPDTC_P_PSI_L),
            kinv_t: w(&rm::MPDTC_P_KINV_T),
            tol: w(&rm::MPDTC_P_TOL),
            k_int: c(&rm::MPDTC_P_K_INT),
            int_lim: w(&rm::MPDTC_P_INT_LIM),
            int_conditional: self.r(mp(&rm::MPDTC_P_INT_COND)) & 1 != 0,
            kp_o: c(&rm::MPDTC_P_KP_O),
            ki_o: c(&rm::MPDTC_P_KI_O),
            eta_lim: w(&rm::MPDTC_P_ETA_LIM),
            w2: [
                c(&rm::MPDTC_P_W2_0),
                c(&rm::MPDTC_P_W2_1),
                c(&rm::MPDTC_P_W2_2),
                c(&rm::MPDTC_P_W2_3),
            ],
        };
        (inp, p)
    }

    /// The MPDCC page's words as the registers hold them now.
    fn mpdcc_words(&self) -> Words {
        Words {
            n_use: self.r(S_MPDCC_N_USE),
            s_prev: self.r(S_MPDCC_S_PREV),
            state: S_MPDCC_STATE.map(|s| self.r(s) as u16),
            consts: S_MPDCC_CONSTS.map(|s| self.r(s) as u16),
        }
    }

    /// One full clock cycle with a bus strobe; returns its events.
    fn step(&mut self, strobe: Strobe) -> Events {
        let w = |s: usize| matches!(strobe, Strobe::Write(WriteResult::Stored { slot, .. }) if slot == s);
        let heartbeat = w(S_HEARTBEAT);
        let start = w(S_MPDTC_START);
        let c = self.comb(start);
        let cap_in = self.cap_inputs(&c, w(S_CAP_ARM), w(S_CAP_TRIG));
        let fe_in = c.fe_start.then(|| self.fe_inputs());
        let mut ev = Events {
            adc_average: self.adc.av,
            pwm_period: self.pwm.bottom(),
            ..Events::default()
        };
        // ctrl_irq: the boundary of the mode in force (pl_top).
        let boundary = if c.sel_pwm {
            ev.pwm_period
        } else {
            ev.adc_average
        };
        ev.control_boundary = boundary;
        let irq_clr = match strobe {
            Strobe::Write(WriteResult::Cleared { slot, value }) if slot == S_IRQ_STATUS => {
                self.irq.status & !(value as u8)
            }
            _ => 0,
        };
        self.irq
            .step(boundary, c.fault_any, self.r(S_IRQ_EN), irq_clr);
        // Gate driver.
        let before = self.gates.outputs();
        let gi = GateInputs {
            rst: false,
            en: c.drive_en,
            fault: c.trip,
            state: c.state_sel,
            dead_time: self.dead_time(),
        };
        let after = self.gates.step(&gi).unwrap_or(before);
        ev.gates = after != before;
        // PWM, ADC, encoder, fault.
        self.pwm.step(
            self.r(S_PWM_PERIOD) as u16,
            S_DUTY.map(|s| self.r(s) as u16),
        );
        ev.adc_convert = self.adc.step(
            self.r(S_ADC_CTRL) & 1 != 0,
            self.r(S_ADC_PERIOD) as u16,
            self.r(S_ADC_AVG_LOG2),
            self.pins.adc_word,
        );
        let q = self.enc_sync.map(|s| s.q);
        self.enc.step(
            q[0],
            q[1],
            q[2],
            self.r(S_ENC_CPR) as u16,
            self.r(S_ENC_WINDOW),
            boundary,
        );
        let pins = [self.pins.enc_a, self.pins.enc_b, self.pins.enc_z];
        for (s, p) in self.enc_sync.iter_mut().zip(pins) {
            s.step(p);
        }
        let status_after_clear = match strobe {
            Strobe::Write(WriteResult::Cleared { slot, value }) if slot == S_FAULT_STATUS => {
                value as u8
            }
            _ => self.fault.status,
        };
        self.fault.step(&c.fault_in, status_after_clear, heartbeat);
        self.ext_sync.step(self.pins.fault_ext_n);
        // Sequence, core and the result latch of pl_top.
        self.seq.step(&c.seq_in);
        let valid = self.core.valid();
        let result = self.core.pending;
        if c.core_in_valid && self.core.ready() {
            let (inp, p) = self.core_inputs(c.auto);
            self.core.step(true, c.core_load, &inp, &p);
        } else {
            self.core.step(
                false,
                c.core_load,
                &FixedInputs::default(),
                &FixedParams::default(),
            );
        }
        self.fe.step(fe_in.as_ref().map(|(i, p)| (i, p)));
        if c.mp_clr {
            self.core_s = 0;
            self.core_iq_ref = 0;
        } else if valid {
            self.core_s = result.s_next;
            self.core_iq_ref = result.iq_ref;
        }
        if valid {
            self.core_done = self.core_done.wrapping_add(1);
        }
        let delayed = CapIn {
            rd_index: cap_in.rd_index,
            ..self.cap_prev
        };
        self.cap.step(&delayed);
        self.cap_prev = cap_in;
        if w(S_MPDCC_START) {
            let words = self.mpdcc_words();
            self.mpdcc.step(Some(&words));
        } else {
            self.mpdcc.step(None);
        }
        // Register file.
        let mut err_set = 0;
        match strobe {
            Strobe::None => {}
            Strobe::Read { err } => err_set |= u32::from(err) << 1,
            Strobe::Write(WriteResult::SlaveError) => err_set |= 2,
            Strobe::Write(WriteResult::Rejected) => err_set |= 1,
            Strobe::Write(WriteResult::Stored { slot, value }) => self.regs.v[slot] = value,
            Strobe::Write(WriteResult::Cleared { slot, value }) => {
                if slot == S_ERR {
                    self.regs.v[S_ERR] = value;
                }
            }
        }
        self.regs.v[S_ERR] |= err_set;
        if c.fault_any {
            self.regs.v[S_GATE_CTRL] = 0;
        }
        self.cycles += 1;
        self.stepped += 1;
        ev
    }

    /// Cycles from now in which nothing but counters change.
    fn quiet(&self) -> u64 {
        let c = self.comb(false);
        if c.fault_any && c.gate_en {
            return 0;
        }
        if c.mp_clr && (self.core_s != 0 || self.core_iq_ref != 0) {
            return 0;
        }
        // capture_buf's input registers settle in one clock.
        if self.cap_inputs(&c, false, false) != self.cap_prev {
            return 0;
        }
        let pins = [self.pins.enc_a, self.pins.enc_b, self.pins.enc_z];
        if !self.enc_sync.iter().zip(pins).all(|(s, p)| s.settled(p))
            || !self.ext_sync.settled(self.pins.fault_ext_n)
        {
            return 0;
        }
        let dt = self.dead_time();
        let en = c.drive_en && !c.trip;
        let mut k = NEVER;
        for (bit, leg) in self.gates.legs.iter().enumerate() {
            k = k.min(leg_quiet(
                leg.hi,
                leg.lo,
                leg.off_cycles,
                en,
                (c.state_sel >> bit) & 1 == 1,
                dt,
            ));
        }
        let q = self.enc_sync.map(|s| s.q);
        k.min(self.pwm.quiet(c.sel_pwm))
            .min(self.adc.quiet(self.r(S_ADC_CTRL) & 1 != 0))
            .min(self.enc.quiet(q[0], q[1], q[2], self.r(S_ENC_WINDOW)))
            .min(self.fault.quiet(&c.fault_in))
            .min(self.seq.quiet(&c.seq_in))
            .min(self.core.quiet(c.core_load))
            .min(self.mpdcc.quiet())
            .min(self.fe.quiet())
            .min(self.irq.quiet(c.fault_any, self.r(S_IRQ_EN)))
    }

    fn skip(&mut self, k: u64) {
        for leg in &mut self.gates.legs {
            if !leg.hi && !leg.lo {
                leg.off_cycles =
                    (u64::from(leg.off_cycles) + k).min(u64::from(DEAD_TIME_MAX_CYCLES)) as u16;
            }
        }
        self.pwm.skip(k);
        self.adc.skip(self.r(S_ADC_CTRL) & 1 != 0, k);
        self.enc.skip(k);
        self.fault.skip(k, self.r(S_GATE_CTRL) & 1 != 0);
        self.seq.skip(k);
        self.core.skip(k);
        self.mpdcc.skip(k);
        self.fe.skip(k);
        self.irq.skip(k);
        self.cap.skip(self.r(S_CAP_RD_INDEX), self.r(S_CAP_STEP));
        self.cycles += k;
        self.skips += 1;
    }

    /// Cycles from now in which nothing but counters change with the pins
    /// as they are: no event, the gates as now ([`Self::run`] skips them in
    /// closed form). A lock-step user (the co-simulation's shadow model) may
    /// run them later in one `run`, as long as the pins stay.
    pub fn quiet_cycles(&self) -> u64 {
        self.quiet()
    }

    /// Runs up to `max` cycles without bus accesses; returns after the first
    /// cycle whose events hit `stop`, or after `max` cycles: the cycles run
    /// and the events of the stepped cycles (merged).
    pub fn run(&mut self, max: u64, stop: &Events) -> (u64, Events) {
        let mut done = 0;
        let mut all = Events::default();
        while done < max {
            let q = self.quiet();
            if q > 0 {
                let k = q.min(max - done);
                self.skip(k);
                done += k;
                continue;
            }
            let ev = self.step(Strobe::None);
            done += 1;
            all.merge(&ev);
            if ev.hits(stop) {
                break;
            }
        }
        (done, all)
    }

    /// Runs `n` cycles one by one (the reference the event-driven
    /// [`Self::run`] must equal; for tests).
    pub fn run_cycle_by_cycle(&mut self, n: u64) {
        for _ in 0..n {
            self.step(Strobe::None);
        }
    }

    /// The register value a read of `addr` returns in the present cycle
    /// (`None`: SLVERR).
    pub fn peek(&self, addr: usize) -> Option<u32> {
        let c = self.comb(false);
        let fault_any = c.fault_any;
        let g = self.gates.outputs();
        let v = match addr {
            A_ID => rm::ID_VALUE,
            A_VERSION => rm::VERSION.reset,
            A_STATUS => {
                (u32::from(fault_any) << 3)
                    | (u32::from(c.drive_en && !c.trip) << 2)
                    | self.r(S_CTRL)
            }
            A_IRQ_STATUS => u32::from(self.irq.status),
            A_BOUNDARY_AGE => u32::from(self.irq.age),
            A_GATE_STATUS => {
                (u32::from(c.state_sel) << 6) | (u32::from(g.lo) << 3) | u32::from(g.hi)
            }
            A_PWM_COUNT => (u32::from(self.pwm.down) << 16) | u32::from(self.pwm.count),
            A_ADC_IA => self.adc.avg_reg(0),
            A_ADC_IB => self.adc.avg_reg(1),
            A_ADC_IC => self.adc.avg_reg(2),
            A_ADC_COUNT => self.adc.count,
            A_ENC_POS => u32::from(self.enc.pos),
            A_ENC_SPEED => u32::from(self.enc.speed as u16),
            A_ENC_INDEX => u32::from(self.enc.index),
            A_ENC_POS_SAMPLE => u32::from(self.enc.pos_sample),
            A_FAULT_STATUS => u32::from(self.fault.status),
            A_FAULT_RAW => u32::from(self.fault.raw(&c.fault_in)),
            A_MPDTC_STATUS => {
                (u32::from(self.core_done) << 16)
                    | (u32::from(self.core_s) << 1)
                    | u32::from(!self.core.ready())
            }
            A_MPDTC_LATENCY => rm::MPDTC_LATENCY.reset,
            A_MPDTC_IQ_REF => (self.core_iq_ref as u32) & rm::MPDTC_IQ_REF.mask(),
            A_SEQ_STATUS => self.seq.status(),
            A_ALIGN_POS => u32::from(self.seq.align_pos),
            A_MPDCC_STATUS => self.mpdcc.status(),
            A_MPDCC_CONFIG => rm::MPDCC_CONFIG_VALUE,
            A_MPDCC_DECISION => self.mpdcc.out.decision,
            A_MPDCC_COST => self.mpdcc.out.cost,
            A_MPDCC_J_DL => self.mpdcc.out.j_dl,
            A_MPDCC_CYCLES => self.mpdcc.out.cycles,
            A_MPDCC_DEADLOCKS => self.mpdcc.deadlocks(),
            A_FE_ID => (self.fe.out.core.i_dq.0 as u32) & rm::MPDTC_FE_ID.mask(),
            A_FE_IQ => (self.fe.out.core.i_dq.1 as u32) & rm::MPDTC_FE_IQ.mask(),
            A_CAP_STATUS => self.cap.status(),
            A_CAP_DATA0 => (u32::from(self.cap.rd.i_q) << 16) | u32::from(self.cap.rd.i_d),
            A_CAP_DATA1 => (u32::from(self.cap.rd.tref) << 16) | u32::from(self.cap.rd.torque),
            A_CAP_DATA2 => (u32::from(self.cap.rd.sel) << 16) | u32::from(self.cap.rd.sw),
            A_CAP_DEPTH => rm::CAP_DEPTH.reset,
            A_CAP_DATA3 => self.cap.rd.pos,
            A_CAP_DATA4 => self.cap.rd.vel,
            A_CAP_DATA5 => u32::from(self.cap.rd.ferr),
            _ => return slot(addr).map(|s| self.r(s)),
        };
        Some(v)
    }

    /// Bus read at absolute address `addr`: one cycle (see the module doc).
    pub fn read(&mut self, addr: usize) -> (Result<u32, BusError>, Events) {
        let v = self.peek(addr);
        let ev = self.step(Strobe::Read { err: v.is_none() });
        (v.ok_or(BusError::SlaveError), ev)
    }

    /// Bus write of `value` (all byte strobes) to absolute address `addr`:
    /// one cycle (see the module doc).
    pub fn write(&mut self, addr: usize, value: u32) -> (Result<(), BusError>, Events) {
        let res = self.regs.decode_write(addr, value, |s| {
            if s == S_FAULT_STATUS {
                u32::from(self.fault.status)
            } else if s == S_IRQ_STATUS {
                u32::from(self.irq.status)
            } else {
                self.regs.get(s)
            }
        });
        let ev = self.step(Strobe::Write(res));
        let r = if res == WriteResult::SlaveError {
            Err(BusError::SlaveError)
        } else {
            Ok(())
        };
        (r, ev)
    }
}

/// Cycles from now in which a gate leg keeps its outputs, with constant
/// inputs (`en` = enabled and no fault, `upper` = requested switch).
fn leg_quiet(hi: bool, lo: bool, off: u16, en: bool, upper: bool, dt: DeadTime) -> u64 {
    let (on, other) = if upper { (hi, lo) } else { (lo, hi) };
    if !en {
        if hi || lo {
            0
        } else {
            NEVER
        }
    } else if on {
        NEVER
    } else if other {
        0
    } else {
        u64::from(dt.effective_cycles().saturating_sub(off))
    }
}
