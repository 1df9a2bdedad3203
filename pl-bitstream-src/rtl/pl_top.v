// pl_top: the PL design behind the PS's AXI GP0 port.
//
//   AXI4-Lite slave (15-bit address = 8 pages of 4 KiB at 0x43C0_0000)
//     -> axil_slave -> pl_regs (generated from the register map, one port per
//        field: docs/register-map.md)
//   adc_frontend  -> raw samples to fault_block, averages to registers
//   encoder_qei   <- sync2(A, B, Z)
//   fault_block   <- raw samples, sync2(external fault), heartbeat, watchdog,
//                    encoder_qei's illegal steps and the ADC result timer
//                    (both judged while GATE_EN = 1)
//   pwm_center    -> switching state in mode FOC-PWM
//   mpdtc_seq     -> in mode MPDTC with MPDTC_CTRL.MANUAL = 0: the paper's
//                    control sequence IDLE, INITIAL (rotor alignment), SAMPLE,
//                    MPDTC, PWM around mpdtc_core (see mpdtc_seq.v); gates
//                    only while the sequence is out of IDLE
//   mpdcc_core    -> one MPDCC decision per MPDCC_START write, on a snapshot
//                    of the MPDCC page's inputs and constants (MPDCC_N
//                    explorers); result, cycle count, decision and deadlock
//                    counters back to the page (observes only: nothing of it
//                    reaches the gates)
//   mpdtc_frontend-> with MPDTC_CTRL.AUTO = 1, at every averaged ADC sample:
//                    encoder angle and speed, sin/cos, ADC offset/gain,
//                    Clarke/Park -> the core's inputs 9 cycles later, which
//                    start the core in SAMPLE (the autonomous loop: the PS
//                    writes only MPDTC_IN_T_REF); MPDTC_FE_* registers
//   mpdtc_core    -> S[k+1] to mpdtc_seq (inputs from the front end with
//                    AUTO = 1, else from MPDTC_IN_*; parameters MPDTC_P_*;
//                    started by the sequence, or by MPDTC_START while the
//                    sequence is IDLE and AUTO = 0); PWM.SW_STATE drives the
//                    gates instead when MPDTC_CTRL.MANUAL = 1 (reset)
//   capture_buf   <- PS-written i_d, i_q, torque, torque reference,
//                    position, velocity and following error, the selected
//                    switching state and a selectable channel, one
//                    sample per CAP_DECIM + 1 averaged ADC results (CAPTURE
//                    page)
//   gate_driver   <- selected state, DEAD_TIME, enable = GATE_EN && mode != off
//                    (&& sequence out of IDLE in mode MPDTC without MANUAL),
//                    fault = fault_block trip (all gates off at the next edge)
// Reset: s_axi_aresetn_i (active low, synchronous, from the PS reset block).
// Safety chain: a fault condition present in cycle t (over-current on a raw
// sample, synchronised external fault, watchdog expired, illegal encoder
// step or raw ADC sample overdue while GATE_EN = 1) or any latched
// fault turns every gate off at the edge ending cycle t; the fault latches
// and also clears GATE_EN, so gates stay off until software clears
// FAULT_STATUS and sets GATE_EN again. The external pin adds the 2 cycles
// of its synchroniser.
`default_nettype none

module pl_top #(
    parameter integer MPDCC_N = 1,  // explorer units of mpdcc_core (1..6)
    // clocks per candidate of each explorer (1: full rate; 4: two shared
    // search lanes, 927 cycles for 216 candidates at N = 1, docs/rtl.md)
    parameter integer MPDCC_II = 4
) (
    input  wire        clk_i,
    input  wire        s_axi_aresetn_i,
    input  wire [14:0] s_axi_awaddr_i,
    input  wire        s_axi_awvalid_i,
    output wire        s_axi_awready_o,
    input  wire [31:0] s_axi_wdata_i,
    input  wire [ 3:0] s_axi_wstrb_i,
    input  wire        s_axi_wvalid_i,
    output wire        s_axi_wready_o,
    output wire [ 1:0] s_axi_bresp_o,
    output wire        s_axi_bvalid_o,
    input  wire        s_axi_bready_i,
    input  wire [14:0] s_axi_araddr_i,
    input  wire        s_axi_arvalid_i,
    output wire        s_axi_arready_o,
    output wire [31:0] s_axi_rdata_o,
    output wire [ 1:0] s_axi_rresp_o,
    output wire        s_axi_rvalid_o,
    input  wire        s_axi_rready_i,
    // inverter gates, bit 2 = leg a
    output wire [ 2:0] gate_hi_o,
    output wire [ 2:0] gate_lo_o,
    // gate-driver enable pin: 1 only while GATE_EN = 1 and nothing trips
    // (registered, glitch-free; low while the PL is unconfigured thanks to
    // the power board's pull-down)
    output wire        gate_en_o,
    // ADC (asynchronous converter interface, see adc_frontend)
    output wire        adc_cnv_o,
    input  wire        adc_drdy_i,
    input  wire [35:0] adc_data_i,
    // incremental encoder and external fault (asynchronous pins)
    input  wire        enc_a_i,
    input  wire        enc_b_i,
    input  wire        enc_z_i,
    input  wire        fault_ext_ni,
    // one-cycle strobe: a new averaged current sample is in ADC_IA..IC
    // (trigger for a PL controller or a PS interrupt)
    output wire        adc_avg_valid_o,
    // Control interrupt to the PS's IRQ_F2P[0] (GIC SPI 61), a level
    // (ctrl_irq: IRQ_EN, IRQ_STATUS, BOUNDARY_AGE)
    output wire        irq_o
);
`include "regmap.vh"
    wire rst = !s_axi_aresetn_i;

    wire        wr;
    wire [14:0] wr_addr;
    wire [31:0] wr_data;
    wire [ 3:0] wr_strb;
    wire        wr_err;
    wire        rd;
    wire [14:0] rd_addr;
    wire [31:0] rd_data;
    wire        rd_err;

    axil_slave #(
        .AW(15)
    ) u_axil (
        .clk_i      (clk_i),
        .rst_i      (rst),
        .s_awaddr_i (s_axi_awaddr_i),
        .s_awvalid_i(s_axi_awvalid_i),
        .s_awready_o(s_axi_awready_o),
        .s_wdata_i  (s_axi_wdata_i),
        .s_wstrb_i  (s_axi_wstrb_i),
        .s_wvalid_i (s_axi_wvalid_i),
        .s_wready_o (s_axi_wready_o),
        .s_bresp_o  (s_axi_bresp_o),
        .s_bvalid_o (s_axi_bvalid_o),
        .s_bready_i (s_axi_bready_i),
        .s_araddr_i (s_axi_araddr_i),
        .s_arvalid_i(s_axi_arvalid_i),
        .s_arready_o(s_axi_arready_o),
        .s_rdata_o  (s_axi_rdata_o),
        .s_rresp_o  (s_axi_rresp_o),
        .s_rvalid_o (s_axi_rvalid_o),
        .s_rready_i (s_axi_rready_i),
        .wr_o       (wr),
        .wr_addr_o  (wr_addr),
        .wr_data_o  (wr_data),
        .wr_strb_o  (wr_strb),
        .wr_err_i   (wr_err),
        .rd_o       (rd),
        .rd_addr_o  (rd_addr),
        .rd_data_i  (rd_data),
        .rd_err_i   (rd_err)
    );

    wire [ 1:0] ctrl_mode;
    wire        gate_en;
    wire [ 9:0] dead_time;
    wire [15:0] pwm_period;
    wire [15:0] duty_a;
    wire [15:0] duty_b;
    wire [15:0] duty_c;
    wire [ 2:0] sw_state;
    wire        adc_en;
    wire [15:0] adc_period;
    wire [15:0] enc_cpr;
    wire [23:0] enc_window;
    wire [10:0] oc_limit;
    wire [31:0] wdg_timeout;
    wire        heartbeat;
    wire [ 4:0] fault_clr;
    wire        mp_manual, mp_clr, mp_start, mp_auto;
    wire [24:0] mp_id, mp_iq, mp_u0, mp_u0_half, mp_u0_h, mp_psi_l, mp_kinv_t;
    // Non-negative CUR values: 24 register bits, the core's sign bit is 0.
    wire [23:0] mp_tol, mp_int_lim, mp_eta_lim;
    wire [17:0] mp_cos0, mp_sin0, mp_cos1, mp_sin1, mp_cos2, mp_sin2, mp_w_ts, mp_t_ref;
    wire [17:0] mp_a, mp_lambda, mp_k_int, mp_kp_o, mp_ki_o;
    wire        mp_int_cond;
    wire [71:0] mp_w2;
    wire [ 2:0] align_vec;
    wire [15:0] align_period, align_on;
    wire [31:0] align_time;
    // Front end: registers, results, and the core inputs of the active path.
    wire [31:0] fe_ang_scale, fe_spd_scale;
    wire [17:0] fe_age0, fe_age1, fe_age2, fe_gain_a, fe_gain_b, fe_gain_c;
    wire [15:0] fe_off_a, fe_off_b, fe_off_c;
    wire        fe_valid;
    wire [24:0] fe_id, fe_iq;
    wire [17:0] fe_cos0, fe_sin0, fe_cos1, fe_sin1, fe_cos2, fe_sin2, fe_w_ts, fe_t_ref;
    reg  [ 3:0] fe_busy_q;
    wire [24:0] in_id, in_iq;
    wire [17:0] in_cos0, in_sin0, in_cos1, in_sin1, in_cos2, in_sin2, in_w_ts, in_t_ref;
    wire [ 1:0] adc_avg;
    wire        seq_start, seq_clr, seq_drive, seq_sampled, seq_aligned;
    wire [ 2:0] seq_s, seq_state;
    wire [ 7:0] seq_overruns;
    wire [15:0] seq_periods, seq_align_pos;
    wire        core_ready, core_valid;
    wire [ 2:0] core_s_next;
    wire [24:0] core_iq_ref;
    reg  [ 2:0] core_s_q;
    reg  [15:0] core_done_q;
    reg  [24:0] core_iq_ref_q;

    wire [ 2:0] pwm_s;
    wire [15:0] pwm_count;
    wire        pwm_down;
    wire        smp_valid;
    wire [11:0] smp_a;
    wire [11:0] smp_b;
    wire [11:0] smp_c;
    wire [15:0] avg_a;
    wire [15:0] avg_b;
    wire [15:0] avg_c;
    wire [31:0] avg_count;
    wire [15:0] enc_pos;
    wire [15:0] enc_speed;
    wire [15:0] enc_index;
    wire [15:0] enc_pos_sample;
    wire [ 4:0] fault_status;
    wire [ 4:0] fault_raw;
    wire        enc_illegal;
    wire        trip;
    wire        enc_a;
    wire        enc_b;
    wire        enc_z;
    wire        fault_ext_n;
    // Capture ring size: the register map's CAPTURE_DEPTH.
    localparam integer CAP_AW = $clog2(RM_CAP_DEPTH_RESET);
    wire [ 1:0] cap_source;
    wire [ 9:0] cap_pre;
    wire [ 7:0] cap_decim;
    wire [15:0] cap_step, cap_thr_level;
    wire [ 2:0] cap_thr_ch, cap_sel;
    wire        cap_thr_edge, cap_arm, cap_trig;
    wire [15:0] cap_in_id, cap_in_iq, cap_in_torque, cap_in_tref;
    wire [31:0] cap_in_pos, cap_in_vel;
    wire [15:0] cap_in_ferr;
    wire [ 9:0] cap_rd_index;
    wire [ 1:0] cap_state;
    wire [CAP_AW:0] cap_count, cap_trig_index;
    wire [162:0] cap_rd;
    reg  [15:0] cap_sel_ch;

    // MPDCC page: the inputs and constants as one word vector (16-bit words
    // 0..38 in page order, then s(k-1) and n_use), its snapshot, the results.
    localparam integer MC_WORDS = 39;
    localparam integer MC_W = 16 * MC_WORDS + 9 + 3;
    localparam [31:0] MC_CONFIG = RM_MPDCC_CONFIG_RESET;
    wire [MC_W-1:0] mc_in;
    reg  [MC_W-1:0] mc_snap_q;
    wire        mc_start_we;
    wire        mc_core_busy, mc_done;
    reg         mc_go_q, mc_busy_q, mc_done_q;
    reg  [15:0] mc_count_q, mc_deadlocks_q;
    wire [ 8:0] mc_s;
    wire [ 1:0] mc_kind;
    wire [ 7:0] mc_l_star, mc_candidates;
    wire [31:0] mc_cost, mc_j_dl;
    wire [15:0] mc_cycles;

    // Switching-state source by mode (CTRL.MODE).
    wire sel_pwm = {30'd0, ctrl_mode} == RM_MODE_FOC_PWM;
    wire sel_state = {30'd0, ctrl_mode} == RM_MODE_MPDTC;
    // Mode MPDTC: PWM.SW_STATE when MANUAL, else the control sequence, whose
    // drive enable is low in IDLE and whenever its run condition is false.
    wire [ 2:0] mpdtc_state = mp_manual ? sw_state : seq_s;
    wire [ 2:0] state_sel = sel_pwm ? pwm_s : sel_state ? mpdtc_state : 3'b000;
    wire drive_en = gate_en && (sel_pwm || (sel_state && (mp_manual || seq_drive)));
    // The gate driver's enable: drive_en without the terms of the sequence's
    // run condition that only a trip clears (trip and a latched fault, part
    // of trip), since its fault input turns every gate off on a trip
    // anyway: the same gates (asserted below), but the trip reaches the
    // gate legs through one input, not also through seq_run, seq_drive and
    // drive_en (8.18 ns estimated before, the longest path outside the
    // MPDCC core).
    wire gate_drive_en = gate_en && (sel_pwm
                         || (sel_state && (mp_manual || (!mp_clr && seq_state != 3'd0))));
    wire fault_any = |fault_status;
    wire [ 1:0] irq_en;
    wire [ 2:0] irq_status, irq_clr;
    wire [15:0] boundary_age;
    wire seq_run = sel_state && gate_en && !mp_manual && !mp_clr && !fault_any && !trip;

    // Simulation only (rtl-sim's Verilated pl_top defines SIM_REGS_CLOCK_GATE):
    // the register file is clocked only when one of its registers can change,
    // so Verilator skips its write decode and 126 write merges at the other
    // edges (about half of the model's evaluation time, docs/speed.md). Its
    // registers change only in reset, at a write strobe (the decode stage),
    // the edge after it (the registered write; rg_wr_q: a strobe in the
    // previous cycle), at a read strobe (the read stage, ERR.BAD_ADDR) and
    // when a fault clears a set GATE_CTRL; the write-data stage it also
    // loads then holds the bus's value from one write to the next. So the
    // outputs are the same edge for edge. The enable is sampled on the
    // falling edge (the harness applies a cycle's inputs with the clock low),
    // stable across the rising one.
`ifdef SIM_REGS_CLOCK_GATE
    reg  rg_ce_q = 1'b1, rg_wr_q = 1'b0;
    always @(negedge clk_i) begin
        rg_wr_q <= wr;
        rg_ce_q <= rst || wr || rg_wr_q || rd || (fault_any && gate_en);
    end
    wire rg_clk = clk_i && rg_ce_q;
`else
    wire rg_clk = clk_i;
`endif

    // The generated register file: one port per field (docs/register-map.md).
    pl_regs u_regs (
        .clk_i                      (rg_clk),
        .rst_i                      (rst),
        .wr_i                       (wr),
        .wr_addr_i                  (wr_addr),
        .wr_data_i                  (wr_data),
        .wr_strb_i                  (wr_strb),
        .wr_err_o                   (wr_err),
        .rd_i                       (rd),
        .rd_addr_i                  (rd_addr),
        .rd_data_o                  (rd_data),
        .rd_err_o                   (rd_err),
        // TOP
        .ctrl_mode_o                (ctrl_mode),
        .status_mode_i              (ctrl_mode),
        .status_gates_active_i      (drive_en && !trip),
        .status_fault_i             (fault_any),
        .heartbeat_we_o             (heartbeat),
        .scratch_o                  (),
        .irq_en_boundary_o          (irq_en[0]),
        .irq_en_fault_o             (irq_en[1]),
        .irq_status_boundary_i      (irq_status[0]),
        .irq_status_fault_i         (irq_status[1]),
        .irq_status_missed_i        (irq_status[2]),
        .irq_status_boundary_clr_o  (irq_clr[0]),
        .irq_status_fault_clr_o     (irq_clr[1]),
        .irq_status_missed_clr_o    (irq_clr[2]),
        .boundary_age_i             (boundary_age),
        // MPDTC
        .mpdtc_ctrl_manual_o        (mp_manual),
        .mpdtc_ctrl_state_clr_o     (mp_clr),
        .mpdtc_ctrl_auto_o          (mp_auto),
        .mpdtc_start_we_o           (mp_start),
        .mpdtc_status_busy_i        (!core_ready),
        .mpdtc_status_s_next_i      (core_s_q),
        .mpdtc_status_done_count_i  (core_done_q),
        .mpdtc_in_id_o              (mp_id),
        .mpdtc_in_iq_o              (mp_iq),
        .mpdtc_in_cos0_o            (mp_cos0),
        .mpdtc_in_sin0_o            (mp_sin0),
        .mpdtc_in_cos1_o            (mp_cos1),
        .mpdtc_in_sin1_o            (mp_sin1),
        .mpdtc_in_cos2_o            (mp_cos2),
        .mpdtc_in_sin2_o            (mp_sin2),
        .mpdtc_in_w_ts_o            (mp_w_ts),
        .mpdtc_in_t_ref_o           (mp_t_ref),
        .mpdtc_p_a_o                (mp_a),
        .mpdtc_p_lambda_o           (mp_lambda),
        .mpdtc_p_u0_o               (mp_u0),
        .mpdtc_p_u0_half_o          (mp_u0_half),
        .mpdtc_p_u0_h_o             (mp_u0_h),
        .mpdtc_p_psi_l_o            (mp_psi_l),
        .mpdtc_p_kinv_t_o           (mp_kinv_t),
        .mpdtc_p_tol_o              (mp_tol),
        .mpdtc_p_k_int_o            (mp_k_int),
        .mpdtc_p_int_lim_o          (mp_int_lim),
        .mpdtc_p_int_cond_o         (mp_int_cond),
        .mpdtc_p_kp_o_o             (mp_kp_o),
        .mpdtc_p_ki_o_o             (mp_ki_o),
        .mpdtc_p_eta_lim_o          (mp_eta_lim),
        .mpdtc_p_w2_0_o             (mp_w2[17:0]),
        .mpdtc_p_w2_1_o             (mp_w2[35:18]),
        .mpdtc_p_w2_2_o             (mp_w2[53:36]),
        .mpdtc_p_w2_3_o             (mp_w2[71:54]),
        .mpdtc_iq_ref_i             (core_iq_ref_q),
        .mpdtc_seq_status_state_i   (seq_state),
        .mpdtc_seq_status_sampled_i (seq_sampled),
        .mpdtc_seq_status_aligned_i (seq_aligned),
        .mpdtc_seq_status_overruns_i(seq_overruns),
        .mpdtc_seq_status_periods_i (seq_periods),
        .mpdtc_align_vec_o          (align_vec),
        .mpdtc_align_period_o       (align_period),
        .mpdtc_align_on_o           (align_on),
        .mpdtc_align_time_o         (align_time),
        .mpdtc_align_pos_i          (seq_align_pos),
        // MPDCC
        .mpdcc_start_we_o           (mc_start_we),
        .mpdcc_status_busy_i        (mc_busy_q),
        .mpdcc_status_done_i        (mc_done_q),
        .mpdcc_status_count_i       (mc_count_q),
        .mpdcc_n_use_o              (mc_in[MC_W-1 -: 3]),
        .mpdcc_config_explorers_i   (MPDCC_N[3:0]),
        // L, N_bar and the nodes are fixed in the explorer RTL; the table
        // states them (its reset value of MPDCC_CONFIG).
        .mpdcc_config_lambda_i      (MC_CONFIG[RM_MPDCC_CONFIG_LAMBDA_LSB +: 4]),
        .mpdcc_config_m_bits_i      (MC_CONFIG[RM_MPDCC_CONFIG_M_BITS_LSB +: 4]),
        .mpdcc_config_nodes_i       (MC_CONFIG[RM_MPDCC_CONFIG_NODES_LSB +: 4]),
        .mpdcc_s_prev_a_o           (mc_in[16*MC_WORDS +: 3]),
        .mpdcc_s_prev_b_o           (mc_in[16*MC_WORDS+3 +: 3]),
        .mpdcc_s_prev_c_o           (mc_in[16*MC_WORDS+6 +: 3]),
        .mpdcc_i_a_o                (mc_in[0 +: 16]),
        .mpdcc_i_b_o                (mc_in[16 +: 16]),
        .mpdcc_psi_a_o              (mc_in[32 +: 16]),
        .mpdcc_psi_b_o              (mc_in[48 +: 16]),
        .mpdcc_v_n_o                (mc_in[64 +: 16]),
        .mpdcc_v_ph_a_o             (mc_in[80 +: 16]),
        .mpdcc_v_ph_b_o             (mc_in[96 +: 16]),
        .mpdcc_v_ph_c_o             (mc_in[112 +: 16]),
        .mpdcc_iref_a_o             (mc_in[128 +: 16]),
        .mpdcc_iref_b_o             (mc_in[144 +: 16]),
        .mpdcc_omega_r_o            (mc_in[160 +: 16]),
        .mpdcc_omega_s_o            (mc_in[176 +: 16]),
        .mpdcc_c_tau_o              (mc_in[192 +: 16]),
        .mpdcc_c_r_o                (mc_in[208 +: 16]),
        .mpdcc_c_w_o                (mc_in[224 +: 16]),
        .mpdcc_c_p_o                (mc_in[240 +: 16]),
        .mpdcc_c_s_o                (mc_in[256 +: 16]),
        .mpdcc_c_3_o                (mc_in[272 +: 16]),
        .mpdcc_c_d_o                (mc_in[288 +: 16]),
        .mpdcc_c_n_o                (mc_in[304 +: 16]),
        .mpdcc_c_ph_o               (mc_in[320 +: 16]),
        .mpdcc_s3h_o                (mc_in[336 +: 16]),
        .mpdcc_v_ph_ref_o           (mc_in[352 +: 16]),
        .mpdcc_c_tau1_o             (mc_in[368 +: 16]),
        .mpdcc_c_r1_o               (mc_in[384 +: 16]),
        .mpdcc_c_w1_o               (mc_in[400 +: 16]),
        .mpdcc_c_s1_o               (mc_in[416 +: 16]),
        .mpdcc_vdc_half_o           (mc_in[432 +: 16]),
        .mpdcc_g3_o                 (mc_in[448 +: 16]),
        .mpdcc_gd_o                 (mc_in[464 +: 16]),
        .mpdcc_g3_1_o               (mc_in[480 +: 16]),
        .mpdcc_bnd_ia_o             (mc_in[496 +: 16]),
        .mpdcc_bnd_ib_o             (mc_in[512 +: 16]),
        .mpdcc_bnd_ic_o             (mc_in[528 +: 16]),
        .mpdcc_bnd_vn_o             (mc_in[544 +: 16]),
        .mpdcc_bnd_vpa_o            (mc_in[560 +: 16]),
        .mpdcc_bnd_vpb_o            (mc_in[576 +: 16]),
        .mpdcc_bnd_vpc_o            (mc_in[592 +: 16]),
        .mpdcc_lambda_n_o           (mc_in[608 +: 16]),
        .mpdcc_decision_s_a_i       (mc_s[2:0]),
        .mpdcc_decision_s_b_i       (mc_s[5:3]),
        .mpdcc_decision_s_c_i       (mc_s[8:6]),
        .mpdcc_decision_kind_i      (mc_kind),
        .mpdcc_decision_l_star_i    (mc_l_star),
        .mpdcc_cost_i               (mc_cost),
        .mpdcc_j_dl_i               (mc_j_dl),
        .mpdcc_cycles_cycles_i      (mc_cycles),
        .mpdcc_cycles_candidates_i  (mc_candidates),
        .mpdcc_deadlocks_i          (mc_deadlocks_q),
        .mpdtc_fe_ang_scale_o       (fe_ang_scale),
        .mpdtc_fe_spd_scale_o       (fe_spd_scale),
        .mpdtc_fe_age0_o            (fe_age0),
        .mpdtc_fe_age1_o            (fe_age1),
        .mpdtc_fe_age2_o            (fe_age2),
        .mpdtc_fe_off_a_o           (fe_off_a),
        .mpdtc_fe_off_b_o           (fe_off_b),
        .mpdtc_fe_off_c_o           (fe_off_c),
        .mpdtc_fe_gain_a_o          (fe_gain_a),
        .mpdtc_fe_gain_b_o          (fe_gain_b),
        .mpdtc_fe_gain_c_o          (fe_gain_c),
        .mpdtc_fe_id_i              (fe_id),
        .mpdtc_fe_iq_i              (fe_iq),
        // PWM
        .gate_ctrl_gate_en_o        (gate_en),
        .gate_ctrl_hw_clr_i         (fault_any),
        .dead_time_o                (dead_time),
        .pwm_period_o               (pwm_period),
        .duty_a_o                   (duty_a),
        .duty_b_o                   (duty_b),
        .duty_c_o                   (duty_c),
        .sw_state_o                 (sw_state),
        .gate_status_hi_i           (gate_hi_o),
        .gate_status_lo_i           (gate_lo_o),
        .gate_status_state_i        (state_sel),
        .pwm_count_count_i          (pwm_count),
        .pwm_count_down_i           (pwm_down),
        // ADC
        .adc_ctrl_enable_o          (adc_en),
        .adc_period_o               (adc_period),
        .adc_ia_i                   (avg_a),
        .adc_ib_i                   (avg_b),
        .adc_ic_i                   (avg_c),
        .adc_count_i                (avg_count),
        .adc_avg_log2_o                (adc_avg),
        // ENC
        .enc_cpr_o                  (enc_cpr),
        .enc_pos_i                  (enc_pos),
        .enc_speed_i                (enc_speed),
        .enc_window_o               (enc_window),
        .enc_index_i                (enc_index),
        .enc_pos_sample_i           (enc_pos_sample),
        // FAULT
        .fault_status_overcurrent_i    (fault_status[0]),
        .fault_status_external_i       (fault_status[1]),
        .fault_status_watchdog_i       (fault_status[2]),
        .fault_status_overcurrent_clr_o(fault_clr[0]),
        .fault_status_external_clr_o   (fault_clr[1]),
        .fault_status_watchdog_clr_o   (fault_clr[2]),
        .fault_status_encoder_loss_i   (fault_status[3]),
        .fault_status_adc_stuck_i      (fault_status[4]),
        .fault_status_encoder_loss_clr_o(fault_clr[3]),
        .fault_status_adc_stuck_clr_o  (fault_clr[4]),
        .fault_raw_i                (fault_raw),
        .oc_limit_o                 (oc_limit),
        .wdg_timeout_o              (wdg_timeout),
        // CAPTURE
        .cap_source_o               (cap_source),
        .cap_pre_o                  (cap_pre),
        .cap_decim_o                (cap_decim),
        .cap_step_o                 (cap_step),
        .cap_thr_ch_o               (cap_thr_ch),
        .cap_thr_level_o            (cap_thr_level),
        .cap_thr_edge_o             (cap_thr_edge),
        .cap_sel_o                  (cap_sel),
        .cap_arm_we_o               (cap_arm),
        .cap_trig_we_o              (cap_trig),
        .cap_status_state_i         (cap_state),
        .cap_status_trig_index_i    ({{(10 - CAP_AW) {1'b0}}, cap_trig_index}),
        .cap_status_count_i         ({{(10 - CAP_AW) {1'b0}}, cap_count}),
        .cap_in_id_o                (cap_in_id),
        .cap_in_iq_o                (cap_in_iq),
        .cap_in_torque_o            (cap_in_torque),
        .cap_in_tref_o              (cap_in_tref),
        .cap_rd_index_o             (cap_rd_index),
        .cap_data0_i_d_i            (cap_rd[15:0]),
        .cap_data0_i_q_i            (cap_rd[31:16]),
        .cap_data1_torque_i         (cap_rd[47:32]),
        .cap_data1_tref_i           (cap_rd[63:48]),
        .cap_data2_sw_i             (cap_rd[82:80]),
        .cap_data2_sel_i            (cap_rd[79:64]),
        .cap_in_pos_o               (cap_in_pos),
        .cap_in_vel_o               (cap_in_vel),
        .cap_in_ferr_o              (cap_in_ferr),
        .cap_data3_i                (cap_rd[114:83]),
        .cap_data4_i                (cap_rd[146:115]),
        .cap_data5_i                (cap_rd[162:147])
    );

    // Selectable channel (CAP_SEL; the register rejects values above 4).
    always @(*) begin
        case (cap_sel)
            3'd0: cap_sel_ch = avg_a;
            3'd1: cap_sel_ch = avg_b;
            3'd2: cap_sel_ch = avg_c;
            3'd3: cap_sel_ch = enc_pos;
            default: cap_sel_ch = enc_speed;
        endcase
    end

    // The control-period boundary, when the control step's sample is ready:
    // the PWM counter bottom in mode FOC-PWM (the duties load there; the
    // ADC average of the period before is in), else the new ADC average.
    wire ctrl_boundary = sel_pwm ? (pwm_down && pwm_count == 16'd0) : adc_avg_valid_o;
    ctrl_irq u_irq (
        .clk_i     (clk_i),
        .rst_i     (rst),
        .boundary_i(ctrl_boundary),
        .fault_i   (fault_any),
        .en_i      (irq_en),
        .clr_i     (irq_clr),
        .status_o  (irq_status),
        .irq_o     (irq_o),
        .age_o     (boundary_age)
    );

`ifdef FORMAL
    // capture_buf only observes (nothing of it reaches the gates or the
    // faults) and its pointer logic has its own proof; leaving it out of
    // this one keeps the pl_top proof and its mutants fast.
    assign cap_state = 2'd0;
    assign cap_count = {(CAP_AW + 1) {1'b0}};
    assign cap_trig_index = {(CAP_AW + 1) {1'b0}};
    assign cap_rd = 163'd0;
    wire unused_cap = ^{cap_arm, cap_trig, cap_source, cap_pre, cap_decim, cap_step, cap_thr_ch,
        cap_thr_level, cap_thr_edge, cap_sel_ch, cap_in_id, cap_in_iq, cap_in_torque, cap_in_tref,
        cap_rd_index, cap_in_pos, cap_in_vel, cap_in_ferr};
`else
    // capture_buf runs one clock behind its inputs: every input but the read
    // index is registered here, the trigger channel (CAP_THR_CH over the
    // channels, CAP_SEL's among them) selected before its register, so its
    // trigger comparisons start at registers (one clock at 100 MHz,
    // docs/rtl.md). A sample is taken, and a write to the page acts, one
    // clock later; the read port follows CAP_RD_INDEX without delay.
    reg [15:0] cap_thr_now;
    always @(*) begin
        case (cap_thr_ch)
            3'd0: cap_thr_now = cap_in_id;
            3'd1: cap_thr_now = cap_in_iq;
            3'd2: cap_thr_now = cap_in_torque;
            3'd3: cap_thr_now = cap_in_tref;
            default: cap_thr_now = cap_sel_ch;
        endcase
    end
    reg         cap_arm_q, cap_trig_q, cap_sample_q, cap_fault_q, cap_thr_edge_q;
    reg  [ 1:0] cap_source_q;
    reg  [ 9:0] cap_pre_q;
    reg  [ 7:0] cap_decim_q;
    reg  [15:0] cap_step_q, cap_thr_level_q, cap_thr_now_q;
    reg         cap_thr_ge_q, cap_thr_le_q;
    reg  [15:0] cap_id_q, cap_iq_q, cap_torque_q, cap_tref_q, cap_ch_sel_q, cap_ferr_q;
    reg  [ 2:0] cap_sw_q;
    reg  [31:0] cap_pos_q, cap_vel_q;
    always @(posedge clk_i) begin
        if (rst) begin
            cap_arm_q       <= 1'b0;
            cap_trig_q      <= 1'b0;
            cap_sample_q    <= 1'b0;
            cap_fault_q     <= 1'b0;
            cap_thr_edge_q  <= 1'b0;
            cap_source_q    <= 2'd0;
            cap_pre_q       <= 10'd0;
            cap_decim_q     <= 8'd0;
            cap_step_q      <= 16'd0;
            cap_thr_level_q <= 16'd0;
            cap_thr_now_q   <= 16'd0;
            cap_thr_ge_q    <= 1'b1;
            cap_thr_le_q    <= 1'b1;
            cap_id_q        <= 16'd0;
            cap_iq_q        <= 16'd0;
            cap_torque_q    <= 16'd0;
            cap_tref_q      <= 16'd0;
            cap_ch_sel_q    <= 16'd0;
            cap_ferr_q      <= 16'd0;
            cap_sw_q        <= 3'd0;
            cap_pos_q       <= 32'd0;
            cap_vel_q       <= 32'd0;
        end else begin
            cap_arm_q       <= cap_arm;
            cap_trig_q      <= cap_trig;
            cap_sample_q    <= adc_avg_valid_o;
            cap_fault_q     <= fault_any;
            cap_thr_edge_q  <= cap_thr_edge;
            cap_source_q    <= cap_source;
            cap_pre_q       <= cap_pre;
            cap_decim_q     <= cap_decim;
            cap_step_q      <= cap_step;
            cap_thr_level_q <= cap_thr_level;
            cap_thr_now_q   <= cap_thr_now;
            cap_thr_ge_q    <= $signed(cap_thr_now) >= $signed(cap_thr_level);
            cap_thr_le_q    <= $signed(cap_thr_now) <= $signed(cap_thr_level);
            cap_id_q        <= cap_in_id;
            cap_iq_q        <= cap_in_iq;
            cap_torque_q    <= cap_in_torque;
            cap_tref_q      <= cap_in_tref;
            cap_ch_sel_q    <= cap_sel_ch;
            cap_ferr_q      <= cap_in_ferr;
            cap_sw_q        <= state_sel;
            cap_pos_q       <= cap_in_pos;
            cap_vel_q       <= cap_in_vel;
        end
    end
    capture_buf #(
        .AW(CAP_AW)
    ) u_cap (
        .clk_i       (clk_i),
        .rst_i       (rst),
        .arm_i       (cap_arm_q),
        .trig_i      (cap_trig_q),
        .source_i    (cap_source_q),
        .pre_i       ({6'd0, cap_pre_q}),
        .decim_i     (cap_decim_q),
        .step_i      (cap_step_q),
        .thr_now_i   (cap_thr_now_q),
        .thr_ge_i    (cap_thr_ge_q),
        .thr_le_i    (cap_thr_le_q),
        .thr_level_i (cap_thr_level_q),
        .thr_edge_i  (cap_thr_edge_q),
        .sample_i    (cap_sample_q),
        .fault_i     (cap_fault_q),
        .ch_id_i     (cap_id_q),
        .ch_iq_i     (cap_iq_q),
        .ch_torque_i (cap_torque_q),
        .ch_tref_i   (cap_tref_q),
        .ch_sel_i    (cap_ch_sel_q),
        .ch_sw_i     (cap_sw_q),
        .ch_pos_i    (cap_pos_q),
        .ch_vel_i    (cap_vel_q),
        .ch_ferr_i   (cap_ferr_q),
        .rd_index_i  ({6'd0, cap_rd_index}),
        .state_o     (cap_state),
        .count_o     (cap_count),
        .trig_index_o(cap_trig_index),
        .rd_data_o   (cap_rd)
    );
`endif

    mpdtc_seq u_seq (
        .clk_i         (clk_i),
        .rst_i         (rst),
        .run_i         (seq_run),
        .sample_i      (adc_avg_valid_o),
        .auto_i        (mp_auto),
        .start_i       (mp_auto ? fe_valid : mp_start),
        .core_ready_i  (core_ready),
        .core_valid_i  (core_valid),
        .core_s_i      (core_s_next),
        .align_vec_i   (align_vec),
        .align_period_i(align_period),
        .align_on_i    (align_on),
        .align_time_i  (align_time),
        .enc_pos_i     (enc_pos),
        .core_start_o  (seq_start),
        .core_clr_o    (seq_clr),
        .drive_o       (seq_drive),
        .s_o           (seq_s),
        .state_o       (seq_state),
        .sampled_o     (seq_sampled),
        .aligned_o     (seq_aligned),
        .overruns_o    (seq_overruns),
        .periods_o     (seq_periods),
        .align_pos_o   (seq_align_pos)
    );

    // The front end (MPDTC_CTRL.AUTO = 1): one run per averaged sample, at
    // most one in flight (a sample that comes while it is busy, possible
    // only right after an ADC restart, is skipped). Its inputs are captured
    // at the strobe: ADC_IA..IC, ENC_POS/SPEED, MPDTC_IN_T_REF, the
    // registers and the alignment position of this run.
    // mpdtc_frontend's LATENCY (regmap::MPDTC_FE_LATENCY_CYCLES).
    localparam [3:0] FE_LAT = 4'd9;
    wire fe_start = mp_auto && adc_avg_valid_o && fe_busy_q == 4'd0;
    always @(posedge clk_i) begin
        if (rst) fe_busy_q <= 4'd0;
        else if (fe_start) fe_busy_q <= FE_LAT;
        else if (fe_busy_q != 4'd0) fe_busy_q <= fe_busy_q - 4'd1;
    end

    // Simulation only (rtl-sim's Verilated pl_top defines SIM_FE_CLOCK_GATE):
    // the front end is clocked only in reset, at a start and for FE_SETTLE
    // edges after either, so Verilator skips its stages (about half of the
    // model's remaining clock-edge code, docs/speed.md) for the other 1,500
    // or so cycles of a control period. Its registers are the captured
    // inputs (loaded only at a start), the valid pipeline (all zero 9 edges
    // after a start) and stages that recompute from those (the deepest, the
    // Park sums, 10 edges after the start; the table reads once the valid
    // pipeline is zero): 16 edges after a start or a reset every register's
    // next value is its present one, so a skipped edge changes nothing and
    // the outputs are the same edge for edge. The enable is sampled on the
    // falling edge (the harness applies a cycle's inputs with the clock low),
    // stable across the rising one.
`ifdef SIM_FE_CLOCK_GATE
    localparam [4:0] FE_SETTLE = 5'd16;
    reg  fe_ce_q = 1'b1;
    reg  [4:0] fe_settle_q = FE_SETTLE;
    always @(negedge clk_i) begin
        fe_settle_q <= (rst || fe_start) ? FE_SETTLE
                     : (fe_settle_q != 5'd0) ? fe_settle_q - 5'd1 : 5'd0;
        fe_ce_q     <= rst || fe_start || fe_settle_q != 5'd0;
    end
    wire fe_clk = clk_i && fe_ce_q;
`else
    wire fe_clk = clk_i;
`endif
    mpdtc_frontend u_fe (
        .clk_i      (fe_clk),
        .rst_i      (rst),
        .in_valid_i (fe_start),
        .pos_i      (enc_pos),
        .speed_i    (enc_speed),
        .adc_a_i    (avg_a),
        .adc_b_i    (avg_b),
        .adc_c_i    (avg_c),
        .t_ref_i    (mp_t_ref),
        .cpr_i      (enc_cpr),
        .align_pos_i(seq_align_pos),
        .ang_scale_i(fe_ang_scale),
        .spd_scale_i(fe_spd_scale),
        .age0_i     (fe_age0),
        .age1_i     (fe_age1),
        .age2_i     (fe_age2),
        .off_a_i    (fe_off_a),
        .off_b_i    (fe_off_b),
        .off_c_i    (fe_off_c),
        .gain_a_i   (fe_gain_a),
        .gain_b_i   (fe_gain_b),
        .gain_c_i   (fe_gain_c),
        .out_valid_o(fe_valid),
        .i_d_o      (fe_id),
        .i_q_o      (fe_iq),
        .cos0_o     (fe_cos0),
        .sin0_o     (fe_sin0),
        .cos1_o     (fe_cos1),
        .sin1_o     (fe_sin1),
        .cos2_o     (fe_cos2),
        .sin2_o     (fe_sin2),
        .w_ts_o     (fe_w_ts),
        .t_ref_o    (fe_t_ref),
        .phi_o      (),
        .dphi_o     (),
        .i_alpha_o  (),
        .i_beta_o   ()
    );

    // Core inputs: the front end's (they hold until its next run) or the
    // PS-written MPDTC_IN_* registers.
    assign in_id   = mp_auto ? fe_id : mp_id;
    assign in_iq   = mp_auto ? fe_iq : mp_iq;
    assign in_cos0 = mp_auto ? fe_cos0 : mp_cos0;
    assign in_sin0 = mp_auto ? fe_sin0 : mp_sin0;
    assign in_cos1 = mp_auto ? fe_cos1 : mp_cos1;
    assign in_sin1 = mp_auto ? fe_sin1 : mp_sin1;
    assign in_cos2 = mp_auto ? fe_cos2 : mp_cos2;
    assign in_sin2 = mp_auto ? fe_sin2 : mp_sin2;
    assign in_w_ts = mp_auto ? fe_w_ts : mp_w_ts;
    assign in_t_ref = mp_auto ? fe_t_ref : mp_t_ref;

    // The MPDTC core: started by the sequence (SAMPLE), or by an MPDTC_START
    // write while the sequence is IDLE and AUTO = 0 (ignored while busy or
    // while MPDTC_CTRL.STATE_CLR holds the state at zero); the sequence's
    // INITIAL also holds the state at zero.
    // Simulation only (rtl-sim's Verilated pl_top defines SIM_MPDTC_CLOCK_GATE):
    // the core is clocked only in reset, at a start, while busy, while
    // out_valid_o is high (it falls one edge after busy), and when a state
    // load (st_load_i) can change its state, so Verilator skips its
    // logic for the other 1,500 or so cycles of a control period and during
    // the alignment (which holds st_load_i). Idle, the core changes no
    // register but its free-running ones (_r, _rr, the multiplier pool),
    // which no output reads and which every stage recomputes inside its own
    // window before it loads (mpdtc_core's header); a load gives the state
    // the constants below, so once one has happened with the core idle
    // (mt_ld_q), the state holds them until the next decision (mt_zero_q:
    // cleared while busy) and a further load changes nothing. So the
    // outputs are the same edge for edge. The enable is sampled on the
    // falling edge (the harness applies a cycle's inputs with the clock low),
    // stable across the rising one.
`ifdef SIM_MPDTC_CLOCK_GATE
    reg  mt_ce_q = 1'b1, mt_ld_q = 1'b0, mt_zero_q = 1'b0;
    wire mt_load = mp_clr || seq_clr;
    // The state holds the load's constants before this edge.
    wire mt_zero = (mt_zero_q || mt_ld_q) && core_ready && !rst;
    wire mt_ce = rst || seq_start || !core_ready || core_valid || (mt_load && !mt_zero);
    always @(negedge clk_i) begin
        mt_zero_q <= mt_zero;
        mt_ld_q   <= mt_load && core_ready && mt_ce;  // a load at this edge
        mt_ce_q   <= mt_ce;
    end
    wire mt_clk = clk_i && mt_ce_q;
`else
    wire mt_clk = clk_i;
`endif
    mpdtc_core u_mpdtc (
        .clk_i           (mt_clk),
        .rst_i           (rst),
        .in_valid_i      (seq_start && !mp_clr),
        .in_ready_o      (core_ready),
        .i_d_i           (in_id),
        .i_q_i           (in_iq),
        .cos0_i          (in_cos0),
        .sin0_i          (in_sin0),
        .cos1_i          (in_cos1),
        .sin1_i          (in_sin1),
        .cos2_i          (in_cos2),
        .sin2_i          (in_sin2),
        .w_ts_i          (in_w_ts),
        .t_ref_i         (in_t_ref),
        .p_a_i           (mp_a),
        .p_lambda_i      (mp_lambda),
        .p_u0_i          (mp_u0),
        .p_u0_half_i     (mp_u0_half),
        .p_u0_h_i        (mp_u0_h),
        .p_psi_l_i       (mp_psi_l),
        .p_kinv_t_i      (mp_kinv_t),
        .p_tol_i         ({1'b0, mp_tol}),
        .p_k_int_i       (mp_k_int),
        .p_int_lim_i     ({1'b0, mp_int_lim}),
        .p_int_cond_i    (mp_int_cond),
        .p_kp_o_i        (mp_kp_o),
        .p_ki_o_i        (mp_ki_o),
        .p_eta_lim_i     ({1'b0, mp_eta_lim}),
        .p_w2_i          (mp_w2),
        .st_load_i       (mp_clr || seq_clr),
        .st_s_applied_i  (3'd0),
        .st_s_prev_i     (3'd0),
        .st_eta_d_i      (25'sd0),
        .st_eta_q_i      (25'sd0),
        .st_x_i          (25'sd0),
        .st_band_i       (1'b0),
        .st_iq_ref_prev_i(25'sd0),
        .st_i_hat_d_i    (25'sd0),
        .st_i_hat_q_i    (25'sd0),
        .st_nu_d_i       (25'sd0),
        .st_nu_q_i       (25'sd0),
        .out_valid_o     (core_valid),
        .s_next_o        (core_s_next),
        .iq_ref_o        (core_iq_ref),
        .eta_d_o         (),
        .eta_q_o         (),
        .i1_d_o          (),
        .i1_q_o          (),
        .i2_d_o          (),
        .i2_q_o          (),
        .err_o           (),
        .cost2_o         (),
        .st_s_applied_o  (),
        .st_s_prev_o     (),
        .st_eta_d_o      (),
        .st_eta_q_o      (),
        .st_x_o          (),
        .st_band_o       (),
        .st_iq_ref_prev_o(),
        .st_i_hat_d_o    (),
        .st_i_hat_q_o    (),
        .st_nu_d_o       (),
        .st_nu_q_o       ()
    );

    // S[k+1] of the last decision, for MPDTC_STATUS (the sequence applies it).
    always @(posedge clk_i) begin
        if (rst || mp_clr) begin
            core_s_q      <= 3'd0;
            core_iq_ref_q <= 25'd0;
        end else if (core_valid) begin
            core_s_q      <= core_s_next;
            core_iq_ref_q <= core_iq_ref;
        end
        if (rst) core_done_q <= 16'd0;
        else if (core_valid) core_done_q <= core_done_q + 16'd1;
    end

    // The MPDCC core (paper 001). An MPDCC_START write while idle takes the
    // snapshot at its edge and starts the core the next cycle, so the PS may
    // write the next inputs during a decision; the core's inputs must hold
    // from its start to its done strobe. BUSY covers the start cycle and the
    // done cycle; DONE and the counters change with BUSY's fall.
    always @(posedge clk_i) begin
        if (rst) begin
            mc_go_q <= 1'b0;
            mc_busy_q <= 1'b0;
            mc_done_q <= 1'b0;
            mc_count_q <= 16'd0;
            mc_deadlocks_q <= 16'd0;
        end else begin
            mc_go_q <= 1'b0;
            if (mc_start_we && !mc_busy_q) begin
                mc_go_q <= 1'b1;
                mc_busy_q <= 1'b1;
                mc_done_q <= 1'b0;
            end else if (mc_done) begin
                mc_busy_q <= 1'b0;
                mc_done_q <= 1'b1;
                mc_count_q <= mc_count_q + 16'd1;
                if (mc_kind == 2'd2) mc_deadlocks_q <= mc_deadlocks_q + 16'd1;
            end
        end
    end

    // Simulation only (rtl-sim's Verilated pl_top defines SIM_MPDCC_CLOCK_GATE):
    // the core is clocked only in reset, at an MPDCC_START write and while
    // MC_BUSY, so Verilator skips
    // its logic between decisions. Idle, the core only clears done_o (one
    // edge after done, still inside MC_BUSY) and shifts pipeline data that no
    // valid bit marks (its formal properties: nothing in flight when idle),
    // so its outputs are the same edge for edge. The enable is sampled on the
    // falling edge, stable across the rising one.
`ifdef SIM_MPDCC_CLOCK_GATE
    reg  mc_ce_q = 1'b1;
    always @(negedge clk_i) mc_ce_q <= rst || mc_busy_q || mc_start_we;
    wire mc_clk = clk_i && mc_ce_q;
`else
    wire mc_clk = clk_i;
`endif
    // The snapshot (taken at the start's edge): in the core's clock domain,
    // so that the simulation settles the logic it feeds only while the core
    // can run (the gate above also opens at an MPDCC_START write, where the
    // idle core changes nothing).
    always @(posedge mc_clk) begin
        if (rst) mc_snap_q <= {MC_W{1'b0}};
        else if (mc_start_we && !mc_busy_q) mc_snap_q <= mc_in;
    end
    mpdcc_core #(
        .N(MPDCC_N),
        .II(MPDCC_II)
    ) u_mpdcc (
        .clk_i       (mc_clk),
        .rst_i       (rst),
        .start_i     (mc_go_q),
        .busy_o      (mc_core_busy),
        .n_use_i     (mc_snap_q[MC_W-1 -: 3]),
        .s_prev_i    (mc_snap_q[16*MC_WORDS +: 9]),
        .i_a_i       (mc_snap_q[0 +: 16]),
        .i_b_i       (mc_snap_q[16 +: 16]),
        .psi_a_i     (mc_snap_q[32 +: 16]),
        .psi_b_i     (mc_snap_q[48 +: 16]),
        .v_n_i       (mc_snap_q[64 +: 16]),
        .v_ph_i      (mc_snap_q[80 +: 48]),
        .ir_a_i      (mc_snap_q[128 +: 16]),
        .ir_b_i      (mc_snap_q[144 +: 16]),
        .omega_r_i   (mc_snap_q[160 +: 16]),
        .omega_s_i   (mc_snap_q[176 +: 16]),
        .c_tau_i     (mc_snap_q[192 +: 16]),
        .c_r_i       (mc_snap_q[208 +: 16]),
        .c_w_i       (mc_snap_q[224 +: 16]),
        .c_p_i       (mc_snap_q[240 +: 16]),
        .c_s_i       (mc_snap_q[256 +: 16]),
        .c_3_i       (mc_snap_q[272 +: 16]),
        .c_d_i       (mc_snap_q[288 +: 16]),
        .c_n_i       (mc_snap_q[304 +: 16]),
        .c_ph_i      (mc_snap_q[320 +: 16]),
        .s3h_i       (mc_snap_q[336 +: 16]),
        .v_ph_ref_i  (mc_snap_q[352 +: 16]),
        .c_tau1_i    (mc_snap_q[368 +: 16]),
        .c_r1_i      (mc_snap_q[384 +: 16]),
        .c_w1_i      (mc_snap_q[400 +: 16]),
        .c_s1_i      (mc_snap_q[416 +: 16]),
        .vdc_half_i  (mc_snap_q[432 +: 16]),
        .g3_i        (mc_snap_q[448 +: 16]),
        .gd_i        (mc_snap_q[464 +: 16]),
        .g3_1_i      (mc_snap_q[480 +: 16]),
        .bnd_i       (mc_snap_q[496 +: 112]),
        .lambda_n_i  (mc_snap_q[608 +: 16]),
        .done_o      (mc_done),
        .s_o         (mc_s),
        .kind_o      (mc_kind),
        .l_star_o    (mc_l_star),
        .cost_o      (mc_cost),
        .j_dl_o      (mc_j_dl),
        .candidates_o(mc_candidates),
        .cycles_o    (mc_cycles)
    );
    wire unused_mc = mc_core_busy;

    sync2 #(.RESET_VAL(1'b0)) u_sync_a (.clk_i(clk_i), .rst_i(rst), .d_i(enc_a_i), .q_o(enc_a));
    sync2 #(.RESET_VAL(1'b0)) u_sync_b (.clk_i(clk_i), .rst_i(rst), .d_i(enc_b_i), .q_o(enc_b));
    sync2 #(.RESET_VAL(1'b0)) u_sync_z (.clk_i(clk_i), .rst_i(rst), .d_i(enc_z_i), .q_o(enc_z));
    sync2 #(.RESET_VAL(1'b1)) u_sync_f (
        .clk_i(clk_i),
        .rst_i(rst),
        .d_i  (fault_ext_ni),
        .q_o  (fault_ext_n)
    );

    adc_frontend u_adc (
        .clk_i         (clk_i),
        .rst_i         (rst),
        .en_i          (adc_en),
        .period_i      (adc_period),
        .avg_log2_i    (adc_avg),
        .adc_cnv_o     (adc_cnv_o),
        .adc_drdy_i    (adc_drdy_i),
        .adc_data_i    (adc_data_i),
        .sample_valid_o(smp_valid),
        .sample_ia_o   (smp_a),
        .sample_ib_o   (smp_b),
        .sample_ic_o   (smp_c),
        .avg_valid_o   (adc_avg_valid_o),
        .avg_ia_o      (avg_a),
        .avg_ib_o      (avg_b),
        .avg_ic_o      (avg_c),
        .avg_count_o   (avg_count)
    );

    encoder_qei u_enc (
        .clk_i      (clk_i),
        .rst_i      (rst),
        .a_i        (enc_a),
        .b_i        (enc_b),
        .z_i        (enc_z),
        .cpr_i      (enc_cpr),
        .window_i   (enc_window),
        .sample_i   (ctrl_boundary),
        .pos_o      (enc_pos),
        .speed_o    (enc_speed),
        .index_cnt_o(enc_index),
        .pos_sample_o(enc_pos_sample),
        .illegal_o  (enc_illegal)
    );

    fault_block u_fault (
        .clk_i         (clk_i),
        .rst_i         (rst),
        .sample_valid_i(smp_valid),
        .ia_i          (smp_a),
        .ib_i          (smp_b),
        .ic_i          (smp_c),
        .oc_limit_i    (oc_limit),
        .ext_fault_i   (!fault_ext_n),
        .heartbeat_i   (heartbeat),
        .wdg_timeout_i (wdg_timeout),
        .run_i         (gate_en),
        .enc_illegal_i (enc_illegal),
        .adc_en_i      (adc_en),
        .adc_period_i  (adc_period),
        .clr_i         (fault_clr),
        .status_o      (fault_status),
        .raw_o         (fault_raw),
        .trip_o        (trip)
    );

    pwm_center u_pwm (
        .clk_i   (clk_i),
        .rst_i   (rst),
        .period_i(pwm_period),
        .duty_a_i(duty_a),
        .duty_b_i(duty_b),
        .duty_c_i(duty_c),
        .s_o     (pwm_s),
        .count_o (pwm_count),
        .down_o  (pwm_down)
    );

    gate_driver #(
        .DT_W(10)
    ) u_gates (
        .clk_i    (clk_i),
        .rst_i    (rst),
        .en_i     (gate_drive_en),
        .fault_i  (trip),
        .s_i      (state_sel),
        .dt_i     (dead_time),
        .gate_hi_o(gate_hi_o),
        .gate_lo_o(gate_lo_o)
    );

    reg gate_en_q;
    always @(posedge clk_i) begin
        if (rst) gate_en_q <= 1'b0;
        else gate_en_q <= gate_en && !trip;
    end
    assign gate_en_o = gate_en_q;

`ifdef FORMAL
    // Top-level safety properties. The gate_leg properties (interlock, dead
    // time, fault/disable off in the next clock) and the fault_block and
    // axil_slave properties are proved here too, in this context.
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;
    always @(*) begin
        if (!f_past_valid) assume (rst);
    end
    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst)) begin
            // A latched fault holds GATE_EN at 0.
            if ($past(fault_any)) assert (!gate_en);
            // Any fault source, or a latched fault, turns every gate off at
            // the next clock.
            if ($past(trip)) assert (gate_hi_o == 3'b000 && gate_lo_o == 3'b000);
            if ($past(!fault_ext_n)) assert (gate_hi_o == 3'b000 && gate_lo_o == 3'b000);
            if ($past(fault_raw[2])) assert (gate_hi_o == 3'b000 && gate_lo_o == 3'b000);
            if ($past(fault_any)) assert (gate_hi_o == 3'b000 && gate_lo_o == 3'b000);
            // ... and the source is latched: gates stay off until cleared.
            if ($past(!fault_ext_n || fault_raw[2])) assert (fault_any);
            if ($past(fault_any && fault_clr == 5'b00000)) assert (fault_any);
            // Mode off or GATE_EN = 0 also turns every gate off.
            if ($past(!drive_en)) assert (gate_hi_o == 3'b000 && gate_lo_o == 3'b000);
            // The control sequence: back in IDLE one clock after its run
            // condition fails (any fault or trip, GATE_EN = 0, mode or
            // MANUAL change), and in mode MPDTC with MANUAL = 0 the gates are
            // off one clock after any cycle the sequence is IDLE.
            if ($past(fault_any || trip || !gate_en || !sel_state)) assert (seq_state == 3'd0);
            if ($past(sel_state && !mp_manual && seq_state == 3'd0))
                assert (gate_hi_o == 3'b000 && gate_lo_o == 3'b000);
            // No leg has both gates on.
            assert ((gate_hi_o & gate_lo_o) == 3'b000);
            // The gate driver's enable is drive_en whenever nothing trips.
            if ($past(!trip)) assert ($past(gate_drive_en == drive_en));
            // The gate-driver enable pin follows GATE_EN and drops with any
            // trip at the next clock, like the gates.
            if ($past(trip || !gate_en)) assert (!gate_en_o);
        end
    end
`endif
endmodule

`default_nettype wire
