// Generated from firmware/regmap/src/lib.rs by `cargo run -p regmap-gen`;
// do not edit (a test fails when this file is stale).
//
// pl_regs: the PL register file behind axil_slave. Register-bus side:
// wr_i/rd_i are one-cycle strobes; a write takes effect and wr_err_o
// answers it the cycle after wr_i; rd_err_o is combinational and
// rd_data_o answers rd_i the next cycle. Write rules (as the table's
// Register::apply_write): byte strobes merge into the current value,
// then the 32-bit word is masked to the width (all valid), clamped as a
// whole to the table's bounds, or rejected (above the bound: the
// register keeps its value and ERR.BAD_VALUE is set).
// Unmapped offsets, and writes to RO registers, answer SLVERR and set
// ERR.BAD_ADDR. W1C flags clear on a written 1.
//
// Ports towards the cores, one per field (a register without fields is
// one port), named <register>[_<field>] in lower case: RW fields are
// outputs _o of the stored bits; RO fields are inputs _i; W1C flags kept
// in a core are inputs _i with a one-cycle output _clr_o of the written
// ones; a strobe register gives only _we_o (one cycle per write); a
// register the hardware can clear has an input _hw_clr_i that holds it at
// 0 and wins over a write. RO constants and ERR have no port.
`default_nettype none

module pl_regs (
    input  wire        clk_i,
    input  wire        rst_i,
    // register bus
    input  wire        wr_i,
    input  wire [14:0] wr_addr_i,
    input  wire [31:0] wr_data_i,
    input  wire [ 3:0] wr_strb_i,
    output wire        wr_err_o,
    input  wire        rd_i,
    input  wire [14:0] rd_addr_i,
    output reg  [31:0] rd_data_o,
    output reg         rd_err_o,
    // block TOP
    output wire   [1:0] ctrl_mode_o,
    input  wire   [1:0] status_mode_i,
    input  wire         status_gates_active_i,
    input  wire         status_fault_i,
    output wire         heartbeat_we_o,
    output wire  [31:0] scratch_o,
    output wire         irq_en_boundary_o,
    output wire         irq_en_fault_o,
    input  wire         irq_status_boundary_i,
    input  wire         irq_status_fault_i,
    input  wire         irq_status_missed_i,
    output wire         irq_status_boundary_clr_o,
    output wire         irq_status_fault_clr_o,
    output wire         irq_status_missed_clr_o,
    input  wire  [15:0] boundary_age_i,
    // block MPDTC
    output wire         mpdtc_ctrl_manual_o,
    output wire         mpdtc_ctrl_state_clr_o,
    output wire         mpdtc_ctrl_auto_o,
    output wire         mpdtc_start_we_o,
    input  wire         mpdtc_status_busy_i,
    input  wire   [2:0] mpdtc_status_s_next_i,
    input  wire  [15:0] mpdtc_status_done_count_i,
    output wire  [24:0] mpdtc_in_id_o,
    output wire  [24:0] mpdtc_in_iq_o,
    output wire  [17:0] mpdtc_in_cos0_o,
    output wire  [17:0] mpdtc_in_sin0_o,
    output wire  [17:0] mpdtc_in_cos1_o,
    output wire  [17:0] mpdtc_in_sin1_o,
    output wire  [17:0] mpdtc_in_cos2_o,
    output wire  [17:0] mpdtc_in_sin2_o,
    output wire  [17:0] mpdtc_in_w_ts_o,
    output wire  [17:0] mpdtc_in_t_ref_o,
    output wire  [17:0] mpdtc_p_a_o,
    output wire  [17:0] mpdtc_p_lambda_o,
    output wire  [24:0] mpdtc_p_u0_o,
    output wire  [24:0] mpdtc_p_u0_half_o,
    output wire  [24:0] mpdtc_p_u0_h_o,
    output wire  [24:0] mpdtc_p_psi_l_o,
    output wire  [24:0] mpdtc_p_kinv_t_o,
    output wire  [23:0] mpdtc_p_tol_o,
    output wire  [17:0] mpdtc_p_k_int_o,
    output wire  [23:0] mpdtc_p_int_lim_o,
    output wire         mpdtc_p_int_cond_o,
    output wire  [17:0] mpdtc_p_kp_o_o,
    output wire  [17:0] mpdtc_p_ki_o_o,
    output wire  [23:0] mpdtc_p_eta_lim_o,
    output wire  [17:0] mpdtc_p_w2_0_o,
    output wire  [17:0] mpdtc_p_w2_1_o,
    output wire  [17:0] mpdtc_p_w2_2_o,
    output wire  [17:0] mpdtc_p_w2_3_o,
    input  wire  [24:0] mpdtc_iq_ref_i,
    input  wire   [2:0] mpdtc_seq_status_state_i,
    input  wire         mpdtc_seq_status_sampled_i,
    input  wire         mpdtc_seq_status_aligned_i,
    input  wire   [7:0] mpdtc_seq_status_overruns_i,
    input  wire  [15:0] mpdtc_seq_status_periods_i,
    output wire   [2:0] mpdtc_align_vec_o,
    output wire  [15:0] mpdtc_align_period_o,
    output wire  [15:0] mpdtc_align_on_o,
    output wire  [31:0] mpdtc_align_time_o,
    input  wire  [15:0] mpdtc_align_pos_i,
    output wire  [31:0] mpdtc_fe_ang_scale_o,
    output wire  [31:0] mpdtc_fe_spd_scale_o,
    output wire  [17:0] mpdtc_fe_age0_o,
    output wire  [17:0] mpdtc_fe_age1_o,
    output wire  [17:0] mpdtc_fe_age2_o,
    output wire  [15:0] mpdtc_fe_off_a_o,
    output wire  [15:0] mpdtc_fe_off_b_o,
    output wire  [15:0] mpdtc_fe_off_c_o,
    output wire  [17:0] mpdtc_fe_gain_a_o,
    output wire  [17:0] mpdtc_fe_gain_b_o,
    output wire  [17:0] mpdtc_fe_gain_c_o,
    input  wire  [24:0] mpdtc_fe_id_i,
    input  wire  [24:0] mpdtc_fe_iq_i,
    // block MPDCC
    output wire         mpdcc_start_we_o,
    input  wire         mpdcc_status_busy_i,
    input  wire         mpdcc_status_done_i,
    input  wire  [15:0] mpdcc_status_count_i,
    output wire   [2:0] mpdcc_n_use_o,
    input  wire   [3:0] mpdcc_config_explorers_i,
    input  wire   [3:0] mpdcc_config_lambda_i,
    input  wire   [3:0] mpdcc_config_m_bits_i,
    input  wire   [3:0] mpdcc_config_nodes_i,
    output wire   [2:0] mpdcc_s_prev_a_o,
    output wire   [2:0] mpdcc_s_prev_b_o,
    output wire   [2:0] mpdcc_s_prev_c_o,
    output wire  [15:0] mpdcc_i_a_o,
    output wire  [15:0] mpdcc_i_b_o,
    output wire  [15:0] mpdcc_psi_a_o,
    output wire  [15:0] mpdcc_psi_b_o,
    output wire  [15:0] mpdcc_v_n_o,
    output wire  [15:0] mpdcc_v_ph_a_o,
    output wire  [15:0] mpdcc_v_ph_b_o,
    output wire  [15:0] mpdcc_v_ph_c_o,
    output wire  [15:0] mpdcc_iref_a_o,
    output wire  [15:0] mpdcc_iref_b_o,
    output wire  [15:0] mpdcc_omega_r_o,
    output wire  [15:0] mpdcc_omega_s_o,
    output wire  [15:0] mpdcc_c_tau_o,
    output wire  [15:0] mpdcc_c_r_o,
    output wire  [15:0] mpdcc_c_w_o,
    output wire  [15:0] mpdcc_c_p_o,
    output wire  [15:0] mpdcc_c_s_o,
    output wire  [15:0] mpdcc_c_3_o,
    output wire  [15:0] mpdcc_c_d_o,
    output wire  [15:0] mpdcc_c_n_o,
    output wire  [15:0] mpdcc_c_ph_o,
    output wire  [15:0] mpdcc_s3h_o,
    output wire  [15:0] mpdcc_v_ph_ref_o,
    output wire  [15:0] mpdcc_c_tau1_o,
    output wire  [15:0] mpdcc_c_r1_o,
    output wire  [15:0] mpdcc_c_w1_o,
    output wire  [15:0] mpdcc_c_s1_o,
    output wire  [15:0] mpdcc_vdc_half_o,
    output wire  [15:0] mpdcc_g3_o,
    output wire  [15:0] mpdcc_gd_o,
    output wire  [15:0] mpdcc_g3_1_o,
    output wire  [15:0] mpdcc_bnd_ia_o,
    output wire  [15:0] mpdcc_bnd_ib_o,
    output wire  [15:0] mpdcc_bnd_ic_o,
    output wire  [15:0] mpdcc_bnd_vn_o,
    output wire  [15:0] mpdcc_bnd_vpa_o,
    output wire  [15:0] mpdcc_bnd_vpb_o,
    output wire  [15:0] mpdcc_bnd_vpc_o,
    output wire  [15:0] mpdcc_lambda_n_o,
    input  wire   [2:0] mpdcc_decision_s_a_i,
    input  wire   [2:0] mpdcc_decision_s_b_i,
    input  wire   [2:0] mpdcc_decision_s_c_i,
    input  wire   [1:0] mpdcc_decision_kind_i,
    input  wire   [7:0] mpdcc_decision_l_star_i,
    input  wire  [31:0] mpdcc_cost_i,
    input  wire  [31:0] mpdcc_j_dl_i,
    input  wire  [15:0] mpdcc_cycles_cycles_i,
    input  wire   [7:0] mpdcc_cycles_candidates_i,
    input  wire  [15:0] mpdcc_deadlocks_i,
    // block PWM
    output wire         gate_ctrl_gate_en_o,
    input  wire         gate_ctrl_hw_clr_i,
    output wire   [9:0] dead_time_o,
    output wire  [15:0] pwm_period_o,
    output wire  [15:0] duty_a_o,
    output wire  [15:0] duty_b_o,
    output wire  [15:0] duty_c_o,
    output wire   [2:0] sw_state_o,
    input  wire   [2:0] gate_status_hi_i,
    input  wire   [2:0] gate_status_lo_i,
    input  wire   [2:0] gate_status_state_i,
    input  wire  [15:0] pwm_count_count_i,
    input  wire         pwm_count_down_i,
    // block ADC
    output wire         adc_ctrl_enable_o,
    output wire  [15:0] adc_period_o,
    input  wire  [15:0] adc_ia_i,
    input  wire  [15:0] adc_ib_i,
    input  wire  [15:0] adc_ic_i,
    input  wire  [31:0] adc_count_i,
    output wire   [1:0] adc_avg_log2_o,
    // block ENC
    output wire  [15:0] enc_cpr_o,
    input  wire  [15:0] enc_pos_i,
    input  wire  [15:0] enc_speed_i,
    output wire  [23:0] enc_window_o,
    input  wire  [15:0] enc_index_i,
    input  wire  [15:0] enc_pos_sample_i,
    // block FAULT
    input  wire         fault_status_overcurrent_i,
    input  wire         fault_status_external_i,
    input  wire         fault_status_watchdog_i,
    input  wire         fault_status_encoder_loss_i,
    input  wire         fault_status_adc_stuck_i,
    output wire         fault_status_overcurrent_clr_o,
    output wire         fault_status_external_clr_o,
    output wire         fault_status_watchdog_clr_o,
    output wire         fault_status_encoder_loss_clr_o,
    output wire         fault_status_adc_stuck_clr_o,
    input  wire   [4:0] fault_raw_i,
    output wire  [10:0] oc_limit_o,
    output wire  [31:0] wdg_timeout_o,
    // block CAPTURE
    output wire   [1:0] cap_source_o,
    output wire   [9:0] cap_pre_o,
    output wire   [7:0] cap_decim_o,
    output wire  [15:0] cap_step_o,
    output wire   [2:0] cap_thr_ch_o,
    output wire  [15:0] cap_thr_level_o,
    output wire         cap_thr_edge_o,
    output wire   [2:0] cap_sel_o,
    output wire         cap_arm_we_o,
    output wire         cap_trig_we_o,
    input  wire   [1:0] cap_status_state_i,
    input  wire  [10:0] cap_status_trig_index_i,
    input  wire  [10:0] cap_status_count_i,
    output wire  [15:0] cap_in_id_o,
    output wire  [15:0] cap_in_iq_o,
    output wire  [15:0] cap_in_torque_o,
    output wire  [15:0] cap_in_tref_o,
    output wire   [9:0] cap_rd_index_o,
    input  wire  [15:0] cap_data0_i_d_i,
    input  wire  [15:0] cap_data0_i_q_i,
    input  wire  [15:0] cap_data1_torque_i,
    input  wire  [15:0] cap_data1_tref_i,
    input  wire   [2:0] cap_data2_sw_i,
    input  wire  [15:0] cap_data2_sel_i,
    output wire  [31:0] cap_in_pos_o,
    output wire  [31:0] cap_in_vel_o,
    output wire  [15:0] cap_in_ferr_o,
    input  wire  [31:0] cap_data3_i,
    input  wire  [31:0] cap_data4_i,
    input  wire  [15:0] cap_data5_i
);

    // Byte-strobe merge of a write over the current (zero-extended) value,
    // as one mask (a per-byte loop costs the Verilated model about a quarter
    // of its time: every register's merge is evaluated on every clock).
    function automatic [31:0] merge(input [31:0] old, input [31:0] data, input [3:0] strb);
        reg [31:0] m;
        begin
            m = {{8{strb[3]}}, {8{strb[2]}}, {8{strb[1]}}, {8{strb[0]}}};
            merge = (data & m) | (old & ~m);
        end
    endfunction

    function automatic [31:0] clamp(input [31:0] v, input [31:0] lo, input [31:0] hi);
        begin
            if (v < lo) clamp = lo;
            else if (v > hi) clamp = hi;
            else clamp = v;
        end
    endfunction

    // Storage.
    reg   [1:0] ctrl_q;
    reg   [1:0] err_q;
    reg  [31:0] heartbeat_q;
    reg  [31:0] scratch_q;
    reg   [1:0] irq_en_q;
    reg   [2:0] mpdtc_ctrl_q;
    reg  [31:0] mpdtc_start_q;
    reg  [24:0] mpdtc_in_id_q;
    reg  [24:0] mpdtc_in_iq_q;
    reg  [17:0] mpdtc_in_cos0_q;
    reg  [17:0] mpdtc_in_sin0_q;
    reg  [17:0] mpdtc_in_cos1_q;
    reg  [17:0] mpdtc_in_sin1_q;
    reg  [17:0] mpdtc_in_cos2_q;
    reg  [17:0] mpdtc_in_sin2_q;
    reg  [17:0] mpdtc_in_w_ts_q;
    reg  [17:0] mpdtc_in_t_ref_q;
    reg  [17:0] mpdtc_p_a_q;
    reg  [17:0] mpdtc_p_lambda_q;
    reg  [24:0] mpdtc_p_u0_q;
    reg  [24:0] mpdtc_p_u0_half_q;
    reg  [24:0] mpdtc_p_u0_h_q;
    reg  [24:0] mpdtc_p_psi_l_q;
    reg  [24:0] mpdtc_p_kinv_t_q;
    reg  [23:0] mpdtc_p_tol_q;
    reg  [17:0] mpdtc_p_k_int_q;
    reg  [23:0] mpdtc_p_int_lim_q;
    reg         mpdtc_p_int_cond_q;
    reg  [17:0] mpdtc_p_kp_o_q;
    reg  [17:0] mpdtc_p_ki_o_q;
    reg  [23:0] mpdtc_p_eta_lim_q;
    reg  [17:0] mpdtc_p_w2_0_q;
    reg  [17:0] mpdtc_p_w2_1_q;
    reg  [17:0] mpdtc_p_w2_2_q;
    reg  [17:0] mpdtc_p_w2_3_q;
    reg   [2:0] mpdtc_align_vec_q;
    reg  [15:0] mpdtc_align_period_q;
    reg  [15:0] mpdtc_align_on_q;
    reg  [31:0] mpdtc_align_time_q;
    reg  [31:0] mpdtc_fe_ang_scale_q;
    reg  [31:0] mpdtc_fe_spd_scale_q;
    reg  [17:0] mpdtc_fe_age0_q;
    reg  [17:0] mpdtc_fe_age1_q;
    reg  [17:0] mpdtc_fe_age2_q;
    reg  [15:0] mpdtc_fe_off_a_q;
    reg  [15:0] mpdtc_fe_off_b_q;
    reg  [15:0] mpdtc_fe_off_c_q;
    reg  [17:0] mpdtc_fe_gain_a_q;
    reg  [17:0] mpdtc_fe_gain_b_q;
    reg  [17:0] mpdtc_fe_gain_c_q;
    reg         mpdcc_start_q;
    reg   [2:0] mpdcc_n_use_q;
    reg   [8:0] mpdcc_s_prev_q;
    reg  [15:0] mpdcc_i_a_q;
    reg  [15:0] mpdcc_i_b_q;
    reg  [15:0] mpdcc_psi_a_q;
    reg  [15:0] mpdcc_psi_b_q;
    reg  [15:0] mpdcc_v_n_q;
    reg  [15:0] mpdcc_v_ph_a_q;
    reg  [15:0] mpdcc_v_ph_b_q;
    reg  [15:0] mpdcc_v_ph_c_q;
    reg  [15:0] mpdcc_iref_a_q;
    reg  [15:0] mpdcc_iref_b_q;
    reg  [15:0] mpdcc_omega_r_q;
    reg  [15:0] mpdcc_omega_s_q;
    reg  [15:0] mpdcc_c_tau_q;
    reg  [15:0] mpdcc_c_r_q;
    reg  [15:0] mpdcc_c_w_q;
    reg  [15:0] mpdcc_c_p_q;
    reg  [15:0] mpdcc_c_s_q;
    reg  [15:0] mpdcc_c_3_q;
    reg  [15:0] mpdcc_c_d_q;
    reg  [15:0] mpdcc_c_n_q;
    reg  [15:0] mpdcc_c_ph_q;
    reg  [15:0] mpdcc_s3h_q;
    reg  [15:0] mpdcc_v_ph_ref_q;
    reg  [15:0] mpdcc_c_tau1_q;
    reg  [15:0] mpdcc_c_r1_q;
    reg  [15:0] mpdcc_c_w1_q;
    reg  [15:0] mpdcc_c_s1_q;
    reg  [15:0] mpdcc_vdc_half_q;
    reg  [15:0] mpdcc_g3_q;
    reg  [15:0] mpdcc_gd_q;
    reg  [15:0] mpdcc_g3_1_q;
    reg  [15:0] mpdcc_bnd_ia_q;
    reg  [15:0] mpdcc_bnd_ib_q;
    reg  [15:0] mpdcc_bnd_ic_q;
    reg  [15:0] mpdcc_bnd_vn_q;
    reg  [15:0] mpdcc_bnd_vpa_q;
    reg  [15:0] mpdcc_bnd_vpb_q;
    reg  [15:0] mpdcc_bnd_vpc_q;
    reg  [15:0] mpdcc_lambda_n_q;
    reg         gate_ctrl_q;
    reg   [9:0] dead_time_q;
    reg  [15:0] pwm_period_q;
    reg  [15:0] duty_a_q;
    reg  [15:0] duty_b_q;
    reg  [15:0] duty_c_q;
    reg   [2:0] sw_state_q;
    reg         adc_ctrl_q;
    reg  [15:0] adc_period_q;
    reg   [1:0] adc_avg_log2_q;
    reg  [15:0] enc_cpr_q;
    reg  [23:0] enc_window_q;
    reg  [10:0] oc_limit_q;
    reg  [31:0] wdg_timeout_q;
    reg   [1:0] cap_source_q;
    reg   [9:0] cap_pre_q;
    reg   [7:0] cap_decim_q;
    reg  [15:0] cap_step_q;
    reg   [2:0] cap_thr_ch_q;
    reg  [15:0] cap_thr_level_q;
    reg         cap_thr_edge_q;
    reg   [2:0] cap_sel_q;
    reg         cap_arm_q;
    reg         cap_trig_q;
    reg  [15:0] cap_in_id_q;
    reg  [15:0] cap_in_iq_q;
    reg  [15:0] cap_in_torque_q;
    reg  [15:0] cap_in_tref_q;
    reg   [9:0] cap_rd_index_q;
    reg  [31:0] cap_in_pos_q;
    reg  [31:0] cap_in_vel_q;
    reg  [15:0] cap_in_ferr_q;

    // Write decode stage (one clock each at 100 MHz, docs/rtl.md): every
    // register's address match is registered with the data and strobes; the
    // write takes effect, and wr_err_o answers it, the cycle after wr_i.
    reg        wr_q;
    reg [31:0] wr_data_q;
    reg [ 3:0] wr_strb_q;
    reg        hit_ctrl_q;
    reg        hit_err_q;
    reg        hit_heartbeat_q;
    reg        hit_scratch_q;
    reg        hit_irq_en_q;
    reg        hit_irq_status_q;
    reg        hit_mpdtc_ctrl_q;
    reg        hit_mpdtc_start_q;
    reg        hit_mpdtc_in_id_q;
    reg        hit_mpdtc_in_iq_q;
    reg        hit_mpdtc_in_cos0_q;
    reg        hit_mpdtc_in_sin0_q;
    reg        hit_mpdtc_in_cos1_q;
    reg        hit_mpdtc_in_sin1_q;
    reg        hit_mpdtc_in_cos2_q;
    reg        hit_mpdtc_in_sin2_q;
    reg        hit_mpdtc_in_w_ts_q;
    reg        hit_mpdtc_in_t_ref_q;
    reg        hit_mpdtc_p_a_q;
    reg        hit_mpdtc_p_lambda_q;
    reg        hit_mpdtc_p_u0_q;
    reg        hit_mpdtc_p_u0_half_q;
    reg        hit_mpdtc_p_u0_h_q;
    reg        hit_mpdtc_p_psi_l_q;
    reg        hit_mpdtc_p_kinv_t_q;
    reg        hit_mpdtc_p_tol_q;
    reg        hit_mpdtc_p_k_int_q;
    reg        hit_mpdtc_p_int_lim_q;
    reg        hit_mpdtc_p_int_cond_q;
    reg        hit_mpdtc_p_kp_o_q;
    reg        hit_mpdtc_p_ki_o_q;
    reg        hit_mpdtc_p_eta_lim_q;
    reg        hit_mpdtc_p_w2_0_q;
    reg        hit_mpdtc_p_w2_1_q;
    reg        hit_mpdtc_p_w2_2_q;
    reg        hit_mpdtc_p_w2_3_q;
    reg        hit_mpdtc_align_vec_q;
    reg        hit_mpdtc_align_period_q;
    reg        hit_mpdtc_align_on_q;
    reg        hit_mpdtc_align_time_q;
    reg        hit_mpdtc_fe_ang_scale_q;
    reg        hit_mpdtc_fe_spd_scale_q;
    reg        hit_mpdtc_fe_age0_q;
    reg        hit_mpdtc_fe_age1_q;
    reg        hit_mpdtc_fe_age2_q;
    reg        hit_mpdtc_fe_off_a_q;
    reg        hit_mpdtc_fe_off_b_q;
    reg        hit_mpdtc_fe_off_c_q;
    reg        hit_mpdtc_fe_gain_a_q;
    reg        hit_mpdtc_fe_gain_b_q;
    reg        hit_mpdtc_fe_gain_c_q;
    reg        hit_mpdcc_start_q;
    reg        hit_mpdcc_n_use_q;
    reg        hit_mpdcc_s_prev_q;
    reg        hit_mpdcc_i_a_q;
    reg        hit_mpdcc_i_b_q;
    reg        hit_mpdcc_psi_a_q;
    reg        hit_mpdcc_psi_b_q;
    reg        hit_mpdcc_v_n_q;
    reg        hit_mpdcc_v_ph_a_q;
    reg        hit_mpdcc_v_ph_b_q;
    reg        hit_mpdcc_v_ph_c_q;
    reg        hit_mpdcc_iref_a_q;
    reg        hit_mpdcc_iref_b_q;
    reg        hit_mpdcc_omega_r_q;
    reg        hit_mpdcc_omega_s_q;
    reg        hit_mpdcc_c_tau_q;
    reg        hit_mpdcc_c_r_q;
    reg        hit_mpdcc_c_w_q;
    reg        hit_mpdcc_c_p_q;
    reg        hit_mpdcc_c_s_q;
    reg        hit_mpdcc_c_3_q;
    reg        hit_mpdcc_c_d_q;
    reg        hit_mpdcc_c_n_q;
    reg        hit_mpdcc_c_ph_q;
    reg        hit_mpdcc_s3h_q;
    reg        hit_mpdcc_v_ph_ref_q;
    reg        hit_mpdcc_c_tau1_q;
    reg        hit_mpdcc_c_r1_q;
    reg        hit_mpdcc_c_w1_q;
    reg        hit_mpdcc_c_s1_q;
    reg        hit_mpdcc_vdc_half_q;
    reg        hit_mpdcc_g3_q;
    reg        hit_mpdcc_gd_q;
    reg        hit_mpdcc_g3_1_q;
    reg        hit_mpdcc_bnd_ia_q;
    reg        hit_mpdcc_bnd_ib_q;
    reg        hit_mpdcc_bnd_ic_q;
    reg        hit_mpdcc_bnd_vn_q;
    reg        hit_mpdcc_bnd_vpa_q;
    reg        hit_mpdcc_bnd_vpb_q;
    reg        hit_mpdcc_bnd_vpc_q;
    reg        hit_mpdcc_lambda_n_q;
    reg        hit_gate_ctrl_q;
    reg        hit_dead_time_q;
    reg        hit_pwm_period_q;
    reg        hit_duty_a_q;
    reg        hit_duty_b_q;
    reg        hit_duty_c_q;
    reg        hit_sw_state_q;
    reg        hit_adc_ctrl_q;
    reg        hit_adc_period_q;
    reg        hit_adc_avg_log2_q;
    reg        hit_enc_cpr_q;
    reg        hit_enc_window_q;
    reg        hit_fault_status_q;
    reg        hit_oc_limit_q;
    reg        hit_wdg_timeout_q;
    reg        hit_cap_source_q;
    reg        hit_cap_pre_q;
    reg        hit_cap_decim_q;
    reg        hit_cap_step_q;
    reg        hit_cap_thr_ch_q;
    reg        hit_cap_thr_level_q;
    reg        hit_cap_thr_edge_q;
    reg        hit_cap_sel_q;
    reg        hit_cap_arm_q;
    reg        hit_cap_trig_q;
    reg        hit_cap_in_id_q;
    reg        hit_cap_in_iq_q;
    reg        hit_cap_in_torque_q;
    reg        hit_cap_in_tref_q;
    reg        hit_cap_rd_index_q;
    reg        hit_cap_in_pos_q;
    reg        hit_cap_in_vel_q;
    reg        hit_cap_in_ferr_q;
    always @(posedge clk_i) begin
        if (rst_i) begin
            wr_q      <= 1'b0;
            wr_data_q <= 32'd0;
            wr_strb_q <= 4'd0;
            hit_ctrl_q <= 1'b0;
            hit_err_q <= 1'b0;
            hit_heartbeat_q <= 1'b0;
            hit_scratch_q <= 1'b0;
            hit_irq_en_q <= 1'b0;
            hit_irq_status_q <= 1'b0;
            hit_mpdtc_ctrl_q <= 1'b0;
            hit_mpdtc_start_q <= 1'b0;
            hit_mpdtc_in_id_q <= 1'b0;
            hit_mpdtc_in_iq_q <= 1'b0;
            hit_mpdtc_in_cos0_q <= 1'b0;
            hit_mpdtc_in_sin0_q <= 1'b0;
            hit_mpdtc_in_cos1_q <= 1'b0;
            hit_mpdtc_in_sin1_q <= 1'b0;
            hit_mpdtc_in_cos2_q <= 1'b0;
            hit_mpdtc_in_sin2_q <= 1'b0;
            hit_mpdtc_in_w_ts_q <= 1'b0;
            hit_mpdtc_in_t_ref_q <= 1'b0;
            hit_mpdtc_p_a_q <= 1'b0;
            hit_mpdtc_p_lambda_q <= 1'b0;
            hit_mpdtc_p_u0_q <= 1'b0;
            hit_mpdtc_p_u0_half_q <= 1'b0;
            hit_mpdtc_p_u0_h_q <= 1'b0;
            hit_mpdtc_p_psi_l_q <= 1'b0;
            hit_mpdtc_p_kinv_t_q <= 1'b0;
            hit_mpdtc_p_tol_q <= 1'b0;
            hit_mpdtc_p_k_int_q <= 1'b0;
            hit_mpdtc_p_int_lim_q <= 1'b0;
            hit_mpdtc_p_int_cond_q <= 1'b0;
            hit_mpdtc_p_kp_o_q <= 1'b0;
            hit_mpdtc_p_ki_o_q <= 1'b0;
            hit_mpdtc_p_eta_lim_q <= 1'b0;
            hit_mpdtc_p_w2_0_q <= 1'b0;
            hit_mpdtc_p_w2_1_q <= 1'b0;
            hit_mpdtc_p_w2_2_q <= 1'b0;
            hit_mpdtc_p_w2_3_q <= 1'b0;
            hit_mpdtc_align_vec_q <= 1'b0;
            hit_mpdtc_align_period_q <= 1'b0;
            hit_mpdtc_align_on_q <= 1'b0;
            hit_mpdtc_align_time_q <= 1'b0;
            hit_mpdtc_fe_ang_scale_q <= 1'b0;
            hit_mpdtc_fe_spd_scale_q <= 1'b0;
            hit_mpdtc_fe_age0_q <= 1'b0;
            hit_mpdtc_fe_age1_q <= 1'b0;
            hit_mpdtc_fe_age2_q <= 1'b0;
            hit_mpdtc_fe_off_a_q <= 1'b0;
            hit_mpdtc_fe_off_b_q <= 1'b0;
            hit_mpdtc_fe_off_c_q <= 1'b0;
            hit_mpdtc_fe_gain_a_q <= 1'b0;
            hit_mpdtc_fe_gain_b_q <= 1'b0;
            hit_mpdtc_fe_gain_c_q <= 1'b0;
            hit_mpdcc_start_q <= 1'b0;
            hit_mpdcc_n_use_q <= 1'b0;
            hit_mpdcc_s_prev_q <= 1'b0;
            hit_mpdcc_i_a_q <= 1'b0;
            hit_mpdcc_i_b_q <= 1'b0;
            hit_mpdcc_psi_a_q <= 1'b0;
            hit_mpdcc_psi_b_q <= 1'b0;
            hit_mpdcc_v_n_q <= 1'b0;
            hit_mpdcc_v_ph_a_q <= 1'b0;
            hit_mpdcc_v_ph_b_q <= 1'b0;
            hit_mpdcc_v_ph_c_q <= 1'b0;
            hit_mpdcc_iref_a_q <= 1'b0;
            hit_mpdcc_iref_b_q <= 1'b0;
            hit_mpdcc_omega_r_q <= 1'b0;
            hit_mpdcc_omega_s_q <= 1'b0;
            hit_mpdcc_c_tau_q <= 1'b0;
            hit_mpdcc_c_r_q <= 1'b0;
            hit_mpdcc_c_w_q <= 1'b0;
            hit_mpdcc_c_p_q <= 1'b0;
            hit_mpdcc_c_s_q <= 1'b0;
            hit_mpdcc_c_3_q <= 1'b0;
            hit_mpdcc_c_d_q <= 1'b0;
            hit_mpdcc_c_n_q <= 1'b0;
            hit_mpdcc_c_ph_q <= 1'b0;
            hit_mpdcc_s3h_q <= 1'b0;
            hit_mpdcc_v_ph_ref_q <= 1'b0;
            hit_mpdcc_c_tau1_q <= 1'b0;
            hit_mpdcc_c_r1_q <= 1'b0;
            hit_mpdcc_c_w1_q <= 1'b0;
            hit_mpdcc_c_s1_q <= 1'b0;
            hit_mpdcc_vdc_half_q <= 1'b0;
            hit_mpdcc_g3_q <= 1'b0;
            hit_mpdcc_gd_q <= 1'b0;
            hit_mpdcc_g3_1_q <= 1'b0;
            hit_mpdcc_bnd_ia_q <= 1'b0;
            hit_mpdcc_bnd_ib_q <= 1'b0;
            hit_mpdcc_bnd_ic_q <= 1'b0;
            hit_mpdcc_bnd_vn_q <= 1'b0;
            hit_mpdcc_bnd_vpa_q <= 1'b0;
            hit_mpdcc_bnd_vpb_q <= 1'b0;
            hit_mpdcc_bnd_vpc_q <= 1'b0;
            hit_mpdcc_lambda_n_q <= 1'b0;
            hit_gate_ctrl_q <= 1'b0;
            hit_dead_time_q <= 1'b0;
            hit_pwm_period_q <= 1'b0;
            hit_duty_a_q <= 1'b0;
            hit_duty_b_q <= 1'b0;
            hit_duty_c_q <= 1'b0;
            hit_sw_state_q <= 1'b0;
            hit_adc_ctrl_q <= 1'b0;
            hit_adc_period_q <= 1'b0;
            hit_adc_avg_log2_q <= 1'b0;
            hit_enc_cpr_q <= 1'b0;
            hit_enc_window_q <= 1'b0;
            hit_fault_status_q <= 1'b0;
            hit_oc_limit_q <= 1'b0;
            hit_wdg_timeout_q <= 1'b0;
            hit_cap_source_q <= 1'b0;
            hit_cap_pre_q <= 1'b0;
            hit_cap_decim_q <= 1'b0;
            hit_cap_step_q <= 1'b0;
            hit_cap_thr_ch_q <= 1'b0;
            hit_cap_thr_level_q <= 1'b0;
            hit_cap_thr_edge_q <= 1'b0;
            hit_cap_sel_q <= 1'b0;
            hit_cap_arm_q <= 1'b0;
            hit_cap_trig_q <= 1'b0;
            hit_cap_in_id_q <= 1'b0;
            hit_cap_in_iq_q <= 1'b0;
            hit_cap_in_torque_q <= 1'b0;
            hit_cap_in_tref_q <= 1'b0;
            hit_cap_rd_index_q <= 1'b0;
            hit_cap_in_pos_q <= 1'b0;
            hit_cap_in_vel_q <= 1'b0;
            hit_cap_in_ferr_q <= 1'b0;
        end else begin
            wr_q      <= wr_i;
            wr_data_q <= wr_data_i;
            wr_strb_q <= wr_strb_i;
            hit_ctrl_q <= wr_i && wr_addr_i == 15'h0008;
            hit_err_q <= wr_i && wr_addr_i == 15'h0010;
            hit_heartbeat_q <= wr_i && wr_addr_i == 15'h0014;
            hit_scratch_q <= wr_i && wr_addr_i == 15'h0018;
            hit_irq_en_q <= wr_i && wr_addr_i == 15'h0040;
            hit_irq_status_q <= wr_i && wr_addr_i == 15'h0044;
            hit_mpdtc_ctrl_q <= wr_i && wr_addr_i == 15'h1000;
            hit_mpdtc_start_q <= wr_i && wr_addr_i == 15'h1004;
            hit_mpdtc_in_id_q <= wr_i && wr_addr_i == 15'h1010;
            hit_mpdtc_in_iq_q <= wr_i && wr_addr_i == 15'h1014;
            hit_mpdtc_in_cos0_q <= wr_i && wr_addr_i == 15'h1018;
            hit_mpdtc_in_sin0_q <= wr_i && wr_addr_i == 15'h101c;
            hit_mpdtc_in_cos1_q <= wr_i && wr_addr_i == 15'h1020;
            hit_mpdtc_in_sin1_q <= wr_i && wr_addr_i == 15'h1024;
            hit_mpdtc_in_cos2_q <= wr_i && wr_addr_i == 15'h1028;
            hit_mpdtc_in_sin2_q <= wr_i && wr_addr_i == 15'h102c;
            hit_mpdtc_in_w_ts_q <= wr_i && wr_addr_i == 15'h1030;
            hit_mpdtc_in_t_ref_q <= wr_i && wr_addr_i == 15'h1034;
            hit_mpdtc_p_a_q <= wr_i && wr_addr_i == 15'h1040;
            hit_mpdtc_p_lambda_q <= wr_i && wr_addr_i == 15'h1044;
            hit_mpdtc_p_u0_q <= wr_i && wr_addr_i == 15'h1048;
            hit_mpdtc_p_u0_half_q <= wr_i && wr_addr_i == 15'h104c;
            hit_mpdtc_p_u0_h_q <= wr_i && wr_addr_i == 15'h1050;
            hit_mpdtc_p_psi_l_q <= wr_i && wr_addr_i == 15'h1054;
            hit_mpdtc_p_kinv_t_q <= wr_i && wr_addr_i == 15'h1058;
            hit_mpdtc_p_tol_q <= wr_i && wr_addr_i == 15'h105c;
            hit_mpdtc_p_k_int_q <= wr_i && wr_addr_i == 15'h1060;
            hit_mpdtc_p_int_lim_q <= wr_i && wr_addr_i == 15'h1064;
            hit_mpdtc_p_int_cond_q <= wr_i && wr_addr_i == 15'h1068;
            hit_mpdtc_p_kp_o_q <= wr_i && wr_addr_i == 15'h106c;
            hit_mpdtc_p_ki_o_q <= wr_i && wr_addr_i == 15'h1070;
            hit_mpdtc_p_eta_lim_q <= wr_i && wr_addr_i == 15'h1074;
            hit_mpdtc_p_w2_0_q <= wr_i && wr_addr_i == 15'h1078;
            hit_mpdtc_p_w2_1_q <= wr_i && wr_addr_i == 15'h107c;
            hit_mpdtc_p_w2_2_q <= wr_i && wr_addr_i == 15'h1080;
            hit_mpdtc_p_w2_3_q <= wr_i && wr_addr_i == 15'h1084;
            hit_mpdtc_align_vec_q <= wr_i && wr_addr_i == 15'h10a4;
            hit_mpdtc_align_period_q <= wr_i && wr_addr_i == 15'h10a8;
            hit_mpdtc_align_on_q <= wr_i && wr_addr_i == 15'h10ac;
            hit_mpdtc_align_time_q <= wr_i && wr_addr_i == 15'h10b0;
            hit_mpdtc_fe_ang_scale_q <= wr_i && wr_addr_i == 15'h10b8;
            hit_mpdtc_fe_spd_scale_q <= wr_i && wr_addr_i == 15'h10bc;
            hit_mpdtc_fe_age0_q <= wr_i && wr_addr_i == 15'h10c0;
            hit_mpdtc_fe_age1_q <= wr_i && wr_addr_i == 15'h10c4;
            hit_mpdtc_fe_age2_q <= wr_i && wr_addr_i == 15'h10c8;
            hit_mpdtc_fe_off_a_q <= wr_i && wr_addr_i == 15'h10cc;
            hit_mpdtc_fe_off_b_q <= wr_i && wr_addr_i == 15'h10d0;
            hit_mpdtc_fe_off_c_q <= wr_i && wr_addr_i == 15'h10d4;
            hit_mpdtc_fe_gain_a_q <= wr_i && wr_addr_i == 15'h10d8;
            hit_mpdtc_fe_gain_b_q <= wr_i && wr_addr_i == 15'h10dc;
            hit_mpdtc_fe_gain_c_q <= wr_i && wr_addr_i == 15'h10e0;
            hit_mpdcc_start_q <= wr_i && wr_addr_i == 15'h2000;
            hit_mpdcc_n_use_q <= wr_i && wr_addr_i == 15'h2008;
            hit_mpdcc_s_prev_q <= wr_i && wr_addr_i == 15'h2010;
            hit_mpdcc_i_a_q <= wr_i && wr_addr_i == 15'h2014;
            hit_mpdcc_i_b_q <= wr_i && wr_addr_i == 15'h2018;
            hit_mpdcc_psi_a_q <= wr_i && wr_addr_i == 15'h201c;
            hit_mpdcc_psi_b_q <= wr_i && wr_addr_i == 15'h2020;
            hit_mpdcc_v_n_q <= wr_i && wr_addr_i == 15'h2024;
            hit_mpdcc_v_ph_a_q <= wr_i && wr_addr_i == 15'h2028;
            hit_mpdcc_v_ph_b_q <= wr_i && wr_addr_i == 15'h202c;
            hit_mpdcc_v_ph_c_q <= wr_i && wr_addr_i == 15'h2030;
            hit_mpdcc_iref_a_q <= wr_i && wr_addr_i == 15'h2034;
            hit_mpdcc_iref_b_q <= wr_i && wr_addr_i == 15'h2038;
            hit_mpdcc_omega_r_q <= wr_i && wr_addr_i == 15'h203c;
            hit_mpdcc_omega_s_q <= wr_i && wr_addr_i == 15'h2040;
            hit_mpdcc_c_tau_q <= wr_i && wr_addr_i == 15'h2080;
            hit_mpdcc_c_r_q <= wr_i && wr_addr_i == 15'h2084;
            hit_mpdcc_c_w_q <= wr_i && wr_addr_i == 15'h2088;
            hit_mpdcc_c_p_q <= wr_i && wr_addr_i == 15'h208c;
            hit_mpdcc_c_s_q <= wr_i && wr_addr_i == 15'h2090;
            hit_mpdcc_c_3_q <= wr_i && wr_addr_i == 15'h2094;
            hit_mpdcc_c_d_q <= wr_i && wr_addr_i == 15'h2098;
            hit_mpdcc_c_n_q <= wr_i && wr_addr_i == 15'h209c;
            hit_mpdcc_c_ph_q <= wr_i && wr_addr_i == 15'h20a0;
            hit_mpdcc_s3h_q <= wr_i && wr_addr_i == 15'h20a4;
            hit_mpdcc_v_ph_ref_q <= wr_i && wr_addr_i == 15'h20a8;
            hit_mpdcc_c_tau1_q <= wr_i && wr_addr_i == 15'h20ac;
            hit_mpdcc_c_r1_q <= wr_i && wr_addr_i == 15'h20b0;
            hit_mpdcc_c_w1_q <= wr_i && wr_addr_i == 15'h20b4;
            hit_mpdcc_c_s1_q <= wr_i && wr_addr_i == 15'h20b8;
            hit_mpdcc_vdc_half_q <= wr_i && wr_addr_i == 15'h20bc;
            hit_mpdcc_g3_q <= wr_i && wr_addr_i == 15'h20c0;
            hit_mpdcc_gd_q <= wr_i && wr_addr_i == 15'h20c4;
            hit_mpdcc_g3_1_q <= wr_i && wr_addr_i == 15'h20c8;
            hit_mpdcc_bnd_ia_q <= wr_i && wr_addr_i == 15'h20cc;
            hit_mpdcc_bnd_ib_q <= wr_i && wr_addr_i == 15'h20d0;
            hit_mpdcc_bnd_ic_q <= wr_i && wr_addr_i == 15'h20d4;
            hit_mpdcc_bnd_vn_q <= wr_i && wr_addr_i == 15'h20d8;
            hit_mpdcc_bnd_vpa_q <= wr_i && wr_addr_i == 15'h20dc;
            hit_mpdcc_bnd_vpb_q <= wr_i && wr_addr_i == 15'h20e0;
            hit_mpdcc_bnd_vpc_q <= wr_i && wr_addr_i == 15'h20e4;
            hit_mpdcc_lambda_n_q <= wr_i && wr_addr_i == 15'h20e8;
            hit_gate_ctrl_q <= wr_i && wr_addr_i == 15'h3000;
            hit_dead_time_q <= wr_i && wr_addr_i == 15'h3004;
            hit_pwm_period_q <= wr_i && wr_addr_i == 15'h3008;
            hit_duty_a_q <= wr_i && wr_addr_i == 15'h300c;
            hit_duty_b_q <= wr_i && wr_addr_i == 15'h3010;
            hit_duty_c_q <= wr_i && wr_addr_i == 15'h3014;
            hit_sw_state_q <= wr_i && wr_addr_i == 15'h3018;
            hit_adc_ctrl_q <= wr_i && wr_addr_i == 15'h4000;
            hit_adc_period_q <= wr_i && wr_addr_i == 15'h4004;
            hit_adc_avg_log2_q <= wr_i && wr_addr_i == 15'h4018;
            hit_enc_cpr_q <= wr_i && wr_addr_i == 15'h5000;
            hit_enc_window_q <= wr_i && wr_addr_i == 15'h500c;
            hit_fault_status_q <= wr_i && wr_addr_i == 15'h6000;
            hit_oc_limit_q <= wr_i && wr_addr_i == 15'h6008;
            hit_wdg_timeout_q <= wr_i && wr_addr_i == 15'h600c;
            hit_cap_source_q <= wr_i && wr_addr_i == 15'h7000;
            hit_cap_pre_q <= wr_i && wr_addr_i == 15'h7004;
            hit_cap_decim_q <= wr_i && wr_addr_i == 15'h7008;
            hit_cap_step_q <= wr_i && wr_addr_i == 15'h700c;
            hit_cap_thr_ch_q <= wr_i && wr_addr_i == 15'h7010;
            hit_cap_thr_level_q <= wr_i && wr_addr_i == 15'h7014;
            hit_cap_thr_edge_q <= wr_i && wr_addr_i == 15'h7018;
            hit_cap_sel_q <= wr_i && wr_addr_i == 15'h701c;
            hit_cap_arm_q <= wr_i && wr_addr_i == 15'h7020;
            hit_cap_trig_q <= wr_i && wr_addr_i == 15'h7024;
            hit_cap_in_id_q <= wr_i && wr_addr_i == 15'h7030;
            hit_cap_in_iq_q <= wr_i && wr_addr_i == 15'h7034;
            hit_cap_in_torque_q <= wr_i && wr_addr_i == 15'h7038;
            hit_cap_in_tref_q <= wr_i && wr_addr_i == 15'h703c;
            hit_cap_rd_index_q <= wr_i && wr_addr_i == 15'h7040;
            hit_cap_in_pos_q <= wr_i && wr_addr_i == 15'h7054;
            hit_cap_in_vel_q <= wr_i && wr_addr_i == 15'h7058;
            hit_cap_in_ferr_q <= wr_i && wr_addr_i == 15'h705c;
        end
    end

    // Write decode, and the word each write leaves (merged, clamped).
    wire w_ctrl = hit_ctrl_q;
    wire [31:0] n_ctrl = merge({30'd0, ctrl_q}, wr_data_q, wr_strb_q);
    wire bad_ctrl = n_ctrl > 32'h00000002;
    wire w_err = hit_err_q;
    wire [31:0] n_err = merge(32'd0, wr_data_q, wr_strb_q);
    wire w_heartbeat = hit_heartbeat_q;
    wire [31:0] n_heartbeat = merge(heartbeat_q, wr_data_q, wr_strb_q);
    wire w_scratch = hit_scratch_q;
    wire [31:0] n_scratch = merge(scratch_q, wr_data_q, wr_strb_q);
    wire w_irq_en = hit_irq_en_q;
    wire [31:0] n_irq_en = merge({30'd0, irq_en_q}, wr_data_q, wr_strb_q);
    wire w_irq_status = hit_irq_status_q;
    wire [31:0] n_irq_status = merge(32'd0, wr_data_q, wr_strb_q);
    wire w_mpdtc_ctrl = hit_mpdtc_ctrl_q;
    wire [31:0] n_mpdtc_ctrl = merge({29'd0, mpdtc_ctrl_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_start = hit_mpdtc_start_q;
    wire [31:0] n_mpdtc_start = merge(mpdtc_start_q, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_id = hit_mpdtc_in_id_q;
    wire [31:0] n_mpdtc_in_id = merge({7'd0, mpdtc_in_id_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_iq = hit_mpdtc_in_iq_q;
    wire [31:0] n_mpdtc_in_iq = merge({7'd0, mpdtc_in_iq_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_cos0 = hit_mpdtc_in_cos0_q;
    wire [31:0] n_mpdtc_in_cos0 = merge({14'd0, mpdtc_in_cos0_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_sin0 = hit_mpdtc_in_sin0_q;
    wire [31:0] n_mpdtc_in_sin0 = merge({14'd0, mpdtc_in_sin0_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_cos1 = hit_mpdtc_in_cos1_q;
    wire [31:0] n_mpdtc_in_cos1 = merge({14'd0, mpdtc_in_cos1_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_sin1 = hit_mpdtc_in_sin1_q;
    wire [31:0] n_mpdtc_in_sin1 = merge({14'd0, mpdtc_in_sin1_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_cos2 = hit_mpdtc_in_cos2_q;
    wire [31:0] n_mpdtc_in_cos2 = merge({14'd0, mpdtc_in_cos2_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_sin2 = hit_mpdtc_in_sin2_q;
    wire [31:0] n_mpdtc_in_sin2 = merge({14'd0, mpdtc_in_sin2_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_w_ts = hit_mpdtc_in_w_ts_q;
    wire [31:0] n_mpdtc_in_w_ts = merge({14'd0, mpdtc_in_w_ts_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_in_t_ref = hit_mpdtc_in_t_ref_q;
    wire [31:0] n_mpdtc_in_t_ref = merge({14'd0, mpdtc_in_t_ref_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_a = hit_mpdtc_p_a_q;
    wire [31:0] n_mpdtc_p_a = merge({14'd0, mpdtc_p_a_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_lambda = hit_mpdtc_p_lambda_q;
    wire [31:0] n_mpdtc_p_lambda = merge({14'd0, mpdtc_p_lambda_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_u0 = hit_mpdtc_p_u0_q;
    wire [31:0] n_mpdtc_p_u0 = merge({7'd0, mpdtc_p_u0_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_u0_half = hit_mpdtc_p_u0_half_q;
    wire [31:0] n_mpdtc_p_u0_half = merge({7'd0, mpdtc_p_u0_half_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_u0_h = hit_mpdtc_p_u0_h_q;
    wire [31:0] n_mpdtc_p_u0_h = merge({7'd0, mpdtc_p_u0_h_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_psi_l = hit_mpdtc_p_psi_l_q;
    wire [31:0] n_mpdtc_p_psi_l = merge({7'd0, mpdtc_p_psi_l_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_kinv_t = hit_mpdtc_p_kinv_t_q;
    wire [31:0] n_mpdtc_p_kinv_t = merge({7'd0, mpdtc_p_kinv_t_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_tol = hit_mpdtc_p_tol_q;
    wire [31:0] n_mpdtc_p_tol = merge({8'd0, mpdtc_p_tol_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_k_int = hit_mpdtc_p_k_int_q;
    wire [31:0] n_mpdtc_p_k_int = merge({14'd0, mpdtc_p_k_int_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_int_lim = hit_mpdtc_p_int_lim_q;
    wire [31:0] n_mpdtc_p_int_lim = merge({8'd0, mpdtc_p_int_lim_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_int_cond = hit_mpdtc_p_int_cond_q;
    wire [31:0] n_mpdtc_p_int_cond = merge({31'd0, mpdtc_p_int_cond_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_kp_o = hit_mpdtc_p_kp_o_q;
    wire [31:0] n_mpdtc_p_kp_o = merge({14'd0, mpdtc_p_kp_o_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_ki_o = hit_mpdtc_p_ki_o_q;
    wire [31:0] n_mpdtc_p_ki_o = merge({14'd0, mpdtc_p_ki_o_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_eta_lim = hit_mpdtc_p_eta_lim_q;
    wire [31:0] n_mpdtc_p_eta_lim = merge({8'd0, mpdtc_p_eta_lim_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_w2_0 = hit_mpdtc_p_w2_0_q;
    wire [31:0] n_mpdtc_p_w2_0 = merge({14'd0, mpdtc_p_w2_0_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_w2_1 = hit_mpdtc_p_w2_1_q;
    wire [31:0] n_mpdtc_p_w2_1 = merge({14'd0, mpdtc_p_w2_1_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_w2_2 = hit_mpdtc_p_w2_2_q;
    wire [31:0] n_mpdtc_p_w2_2 = merge({14'd0, mpdtc_p_w2_2_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_p_w2_3 = hit_mpdtc_p_w2_3_q;
    wire [31:0] n_mpdtc_p_w2_3 = merge({14'd0, mpdtc_p_w2_3_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_align_vec = hit_mpdtc_align_vec_q;
    wire [31:0] n_mpdtc_align_vec = merge({29'd0, mpdtc_align_vec_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_align_period = hit_mpdtc_align_period_q;
    wire [31:0] n_mpdtc_align_period = clamp(merge({16'd0, mpdtc_align_period_q}, wr_data_q, wr_strb_q), 32'h00000002, 32'h0000ffff);
    wire w_mpdtc_align_on = hit_mpdtc_align_on_q;
    wire [31:0] n_mpdtc_align_on = clamp(merge({16'd0, mpdtc_align_on_q}, wr_data_q, wr_strb_q), 32'h00000000, 32'h00007fff);
    wire w_mpdtc_align_time = hit_mpdtc_align_time_q;
    wire [31:0] n_mpdtc_align_time = clamp(merge(mpdtc_align_time_q, wr_data_q, wr_strb_q), 32'h00000001, 32'hffffffff);
    wire w_mpdtc_fe_ang_scale = hit_mpdtc_fe_ang_scale_q;
    wire [31:0] n_mpdtc_fe_ang_scale = merge(mpdtc_fe_ang_scale_q, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_spd_scale = hit_mpdtc_fe_spd_scale_q;
    wire [31:0] n_mpdtc_fe_spd_scale = merge(mpdtc_fe_spd_scale_q, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_age0 = hit_mpdtc_fe_age0_q;
    wire [31:0] n_mpdtc_fe_age0 = merge({14'd0, mpdtc_fe_age0_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_age1 = hit_mpdtc_fe_age1_q;
    wire [31:0] n_mpdtc_fe_age1 = merge({14'd0, mpdtc_fe_age1_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_age2 = hit_mpdtc_fe_age2_q;
    wire [31:0] n_mpdtc_fe_age2 = merge({14'd0, mpdtc_fe_age2_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_off_a = hit_mpdtc_fe_off_a_q;
    wire [31:0] n_mpdtc_fe_off_a = merge({16'd0, mpdtc_fe_off_a_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_off_b = hit_mpdtc_fe_off_b_q;
    wire [31:0] n_mpdtc_fe_off_b = merge({16'd0, mpdtc_fe_off_b_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_off_c = hit_mpdtc_fe_off_c_q;
    wire [31:0] n_mpdtc_fe_off_c = merge({16'd0, mpdtc_fe_off_c_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_gain_a = hit_mpdtc_fe_gain_a_q;
    wire [31:0] n_mpdtc_fe_gain_a = merge({14'd0, mpdtc_fe_gain_a_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_gain_b = hit_mpdtc_fe_gain_b_q;
    wire [31:0] n_mpdtc_fe_gain_b = merge({14'd0, mpdtc_fe_gain_b_q}, wr_data_q, wr_strb_q);
    wire w_mpdtc_fe_gain_c = hit_mpdtc_fe_gain_c_q;
    wire [31:0] n_mpdtc_fe_gain_c = merge({14'd0, mpdtc_fe_gain_c_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_start = hit_mpdcc_start_q;
    wire [31:0] n_mpdcc_start = merge({31'd0, mpdcc_start_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_n_use = hit_mpdcc_n_use_q;
    wire [31:0] n_mpdcc_n_use = clamp(merge({29'd0, mpdcc_n_use_q}, wr_data_q, wr_strb_q), 32'h00000001, 32'h00000006);
    wire w_mpdcc_s_prev = hit_mpdcc_s_prev_q;
    wire [31:0] n_mpdcc_s_prev = merge({23'd0, mpdcc_s_prev_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_i_a = hit_mpdcc_i_a_q;
    wire [31:0] n_mpdcc_i_a = merge({16'd0, mpdcc_i_a_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_i_b = hit_mpdcc_i_b_q;
    wire [31:0] n_mpdcc_i_b = merge({16'd0, mpdcc_i_b_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_psi_a = hit_mpdcc_psi_a_q;
    wire [31:0] n_mpdcc_psi_a = merge({16'd0, mpdcc_psi_a_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_psi_b = hit_mpdcc_psi_b_q;
    wire [31:0] n_mpdcc_psi_b = merge({16'd0, mpdcc_psi_b_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_v_n = hit_mpdcc_v_n_q;
    wire [31:0] n_mpdcc_v_n = merge({16'd0, mpdcc_v_n_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_v_ph_a = hit_mpdcc_v_ph_a_q;
    wire [31:0] n_mpdcc_v_ph_a = merge({16'd0, mpdcc_v_ph_a_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_v_ph_b = hit_mpdcc_v_ph_b_q;
    wire [31:0] n_mpdcc_v_ph_b = merge({16'd0, mpdcc_v_ph_b_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_v_ph_c = hit_mpdcc_v_ph_c_q;
    wire [31:0] n_mpdcc_v_ph_c = merge({16'd0, mpdcc_v_ph_c_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_iref_a = hit_mpdcc_iref_a_q;
    wire [31:0] n_mpdcc_iref_a = merge({16'd0, mpdcc_iref_a_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_iref_b = hit_mpdcc_iref_b_q;
    wire [31:0] n_mpdcc_iref_b = merge({16'd0, mpdcc_iref_b_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_omega_r = hit_mpdcc_omega_r_q;
    wire [31:0] n_mpdcc_omega_r = merge({16'd0, mpdcc_omega_r_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_omega_s = hit_mpdcc_omega_s_q;
    wire [31:0] n_mpdcc_omega_s = merge({16'd0, mpdcc_omega_s_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_tau = hit_mpdcc_c_tau_q;
    wire [31:0] n_mpdcc_c_tau = merge({16'd0, mpdcc_c_tau_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_r = hit_mpdcc_c_r_q;
    wire [31:0] n_mpdcc_c_r = merge({16'd0, mpdcc_c_r_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_w = hit_mpdcc_c_w_q;
    wire [31:0] n_mpdcc_c_w = merge({16'd0, mpdcc_c_w_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_p = hit_mpdcc_c_p_q;
    wire [31:0] n_mpdcc_c_p = merge({16'd0, mpdcc_c_p_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_s = hit_mpdcc_c_s_q;
    wire [31:0] n_mpdcc_c_s = merge({16'd0, mpdcc_c_s_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_3 = hit_mpdcc_c_3_q;
    wire [31:0] n_mpdcc_c_3 = merge({16'd0, mpdcc_c_3_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_d = hit_mpdcc_c_d_q;
    wire [31:0] n_mpdcc_c_d = merge({16'd0, mpdcc_c_d_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_n = hit_mpdcc_c_n_q;
    wire [31:0] n_mpdcc_c_n = merge({16'd0, mpdcc_c_n_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_ph = hit_mpdcc_c_ph_q;
    wire [31:0] n_mpdcc_c_ph = merge({16'd0, mpdcc_c_ph_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_s3h = hit_mpdcc_s3h_q;
    wire [31:0] n_mpdcc_s3h = merge({16'd0, mpdcc_s3h_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_v_ph_ref = hit_mpdcc_v_ph_ref_q;
    wire [31:0] n_mpdcc_v_ph_ref = merge({16'd0, mpdcc_v_ph_ref_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_tau1 = hit_mpdcc_c_tau1_q;
    wire [31:0] n_mpdcc_c_tau1 = merge({16'd0, mpdcc_c_tau1_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_r1 = hit_mpdcc_c_r1_q;
    wire [31:0] n_mpdcc_c_r1 = merge({16'd0, mpdcc_c_r1_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_w1 = hit_mpdcc_c_w1_q;
    wire [31:0] n_mpdcc_c_w1 = merge({16'd0, mpdcc_c_w1_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_c_s1 = hit_mpdcc_c_s1_q;
    wire [31:0] n_mpdcc_c_s1 = merge({16'd0, mpdcc_c_s1_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_vdc_half = hit_mpdcc_vdc_half_q;
    wire [31:0] n_mpdcc_vdc_half = merge({16'd0, mpdcc_vdc_half_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_g3 = hit_mpdcc_g3_q;
    wire [31:0] n_mpdcc_g3 = merge({16'd0, mpdcc_g3_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_gd = hit_mpdcc_gd_q;
    wire [31:0] n_mpdcc_gd = merge({16'd0, mpdcc_gd_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_g3_1 = hit_mpdcc_g3_1_q;
    wire [31:0] n_mpdcc_g3_1 = merge({16'd0, mpdcc_g3_1_q}, wr_data_q, wr_strb_q);
    wire w_mpdcc_bnd_ia = hit_mpdcc_bnd_ia_q;
    wire [31:0] n_mpdcc_bnd_ia = merge({16'd0, mpdcc_bnd_ia_q}, wr_data_q, wr_strb_q);
    wire bad_mpdcc_bnd_ia = n_mpdcc_bnd_ia > 32'h00007fff;
    wire w_mpdcc_bnd_ib = hit_mpdcc_bnd_ib_q;
    wire [31:0] n_mpdcc_bnd_ib = merge({16'd0, mpdcc_bnd_ib_q}, wr_data_q, wr_strb_q);
    wire bad_mpdcc_bnd_ib = n_mpdcc_bnd_ib > 32'h00007fff;
    wire w_mpdcc_bnd_ic = hit_mpdcc_bnd_ic_q;
    wire [31:0] n_mpdcc_bnd_ic = merge({16'd0, mpdcc_bnd_ic_q}, wr_data_q, wr_strb_q);
    wire bad_mpdcc_bnd_ic = n_mpdcc_bnd_ic > 32'h00007fff;
    wire w_mpdcc_bnd_vn = hit_mpdcc_bnd_vn_q;
    wire [31:0] n_mpdcc_bnd_vn = merge({16'd0, mpdcc_bnd_vn_q}, wr_data_q, wr_strb_q);
    wire bad_mpdcc_bnd_vn = n_mpdcc_bnd_vn > 32'h00007fff;
    wire w_mpdcc_bnd_vpa = hit_mpdcc_bnd_vpa_q;
    wire [31:0] n_mpdcc_bnd_vpa = merge({16'd0, mpdcc_bnd_vpa_q}, wr_data_q, wr_strb_q);
    wire bad_mpdcc_bnd_vpa = n_mpdcc_bnd_vpa > 32'h00007fff;
    wire w_mpdcc_bnd_vpb = hit_mpdcc_bnd_vpb_q;
    wire [31:0] n_mpdcc_bnd_vpb = merge({16'd0, mpdcc_bnd_vpb_q}, wr_data_q, wr_strb_q);
    wire bad_mpdcc_bnd_vpb = n_mpdcc_bnd_vpb > 32'h00007fff;
    wire w_mpdcc_bnd_vpc = hit_mpdcc_bnd_vpc_q;
    wire [31:0] n_mpdcc_bnd_vpc = merge({16'd0, mpdcc_bnd_vpc_q}, wr_data_q, wr_strb_q);
    wire bad_mpdcc_bnd_vpc = n_mpdcc_bnd_vpc > 32'h00007fff;
    wire w_mpdcc_lambda_n = hit_mpdcc_lambda_n_q;
    wire [31:0] n_mpdcc_lambda_n = merge({16'd0, mpdcc_lambda_n_q}, wr_data_q, wr_strb_q);
    wire w_gate_ctrl = hit_gate_ctrl_q;
    wire [31:0] n_gate_ctrl = merge({31'd0, gate_ctrl_q}, wr_data_q, wr_strb_q);
    wire w_dead_time = hit_dead_time_q;
    wire [31:0] n_dead_time = clamp(merge({22'd0, dead_time_q}, wr_data_q, wr_strb_q), 32'h00000000, 32'h000003ff);
    wire w_pwm_period = hit_pwm_period_q;
    wire [31:0] n_pwm_period = clamp(merge({16'd0, pwm_period_q}, wr_data_q, wr_strb_q), 32'h00000002, 32'h0000ffff);
    wire w_duty_a = hit_duty_a_q;
    wire [31:0] n_duty_a = merge({16'd0, duty_a_q}, wr_data_q, wr_strb_q);
    wire w_duty_b = hit_duty_b_q;
    wire [31:0] n_duty_b = merge({16'd0, duty_b_q}, wr_data_q, wr_strb_q);
    wire w_duty_c = hit_duty_c_q;
    wire [31:0] n_duty_c = merge({16'd0, duty_c_q}, wr_data_q, wr_strb_q);
    wire w_sw_state = hit_sw_state_q;
    wire [31:0] n_sw_state = merge({29'd0, sw_state_q}, wr_data_q, wr_strb_q);
    wire w_adc_ctrl = hit_adc_ctrl_q;
    wire [31:0] n_adc_ctrl = merge({31'd0, adc_ctrl_q}, wr_data_q, wr_strb_q);
    wire w_adc_period = hit_adc_period_q;
    wire [31:0] n_adc_period = clamp(merge({16'd0, adc_period_q}, wr_data_q, wr_strb_q), 32'h00000010, 32'h0000ffff);
    wire w_adc_avg_log2 = hit_adc_avg_log2_q;
    wire [31:0] n_adc_avg_log2 = merge({30'd0, adc_avg_log2_q}, wr_data_q, wr_strb_q);
    wire bad_adc_avg_log2 = n_adc_avg_log2 > 32'h00000002;
    wire w_enc_cpr = hit_enc_cpr_q;
    wire [31:0] n_enc_cpr = clamp(merge({16'd0, enc_cpr_q}, wr_data_q, wr_strb_q), 32'h00000004, 32'h0000ffff);
    wire w_enc_window = hit_enc_window_q;
    wire [31:0] n_enc_window = clamp(merge({8'd0, enc_window_q}, wr_data_q, wr_strb_q), 32'h00000064, 32'h00ffffff);
    wire w_fault_status = hit_fault_status_q;
    wire [31:0] n_fault_status = merge(32'd0, wr_data_q, wr_strb_q);
    wire w_oc_limit = hit_oc_limit_q;
    wire [31:0] n_oc_limit = clamp(merge({21'd0, oc_limit_q}, wr_data_q, wr_strb_q), 32'h00000000, 32'h000007ff);
    wire w_wdg_timeout = hit_wdg_timeout_q;
    wire [31:0] n_wdg_timeout = clamp(merge(wdg_timeout_q, wr_data_q, wr_strb_q), 32'h000003e8, 32'hffffffff);
    wire w_cap_source = hit_cap_source_q;
    wire [31:0] n_cap_source = merge({30'd0, cap_source_q}, wr_data_q, wr_strb_q);
    wire w_cap_pre = hit_cap_pre_q;
    wire [31:0] n_cap_pre = clamp(merge({22'd0, cap_pre_q}, wr_data_q, wr_strb_q), 32'h00000000, 32'h000003ff);
    wire w_cap_decim = hit_cap_decim_q;
    wire [31:0] n_cap_decim = merge({24'd0, cap_decim_q}, wr_data_q, wr_strb_q);
    wire w_cap_step = hit_cap_step_q;
    wire [31:0] n_cap_step = merge({16'd0, cap_step_q}, wr_data_q, wr_strb_q);
    wire w_cap_thr_ch = hit_cap_thr_ch_q;
    wire [31:0] n_cap_thr_ch = merge({29'd0, cap_thr_ch_q}, wr_data_q, wr_strb_q);
    wire bad_cap_thr_ch = n_cap_thr_ch > 32'h00000004;
    wire w_cap_thr_level = hit_cap_thr_level_q;
    wire [31:0] n_cap_thr_level = merge({16'd0, cap_thr_level_q}, wr_data_q, wr_strb_q);
    wire w_cap_thr_edge = hit_cap_thr_edge_q;
    wire [31:0] n_cap_thr_edge = merge({31'd0, cap_thr_edge_q}, wr_data_q, wr_strb_q);
    wire w_cap_sel = hit_cap_sel_q;
    wire [31:0] n_cap_sel = merge({29'd0, cap_sel_q}, wr_data_q, wr_strb_q);
    wire bad_cap_sel = n_cap_sel > 32'h00000004;
    wire w_cap_arm = hit_cap_arm_q;
    wire [31:0] n_cap_arm = merge({31'd0, cap_arm_q}, wr_data_q, wr_strb_q);
    wire w_cap_trig = hit_cap_trig_q;
    wire [31:0] n_cap_trig = merge({31'd0, cap_trig_q}, wr_data_q, wr_strb_q);
    wire w_cap_in_id = hit_cap_in_id_q;
    wire [31:0] n_cap_in_id = merge({16'd0, cap_in_id_q}, wr_data_q, wr_strb_q);
    wire w_cap_in_iq = hit_cap_in_iq_q;
    wire [31:0] n_cap_in_iq = merge({16'd0, cap_in_iq_q}, wr_data_q, wr_strb_q);
    wire w_cap_in_torque = hit_cap_in_torque_q;
    wire [31:0] n_cap_in_torque = merge({16'd0, cap_in_torque_q}, wr_data_q, wr_strb_q);
    wire w_cap_in_tref = hit_cap_in_tref_q;
    wire [31:0] n_cap_in_tref = merge({16'd0, cap_in_tref_q}, wr_data_q, wr_strb_q);
    wire w_cap_rd_index = hit_cap_rd_index_q;
    wire [31:0] n_cap_rd_index = clamp(merge({22'd0, cap_rd_index_q}, wr_data_q, wr_strb_q), 32'h00000000, 32'h000003ff);
    wire w_cap_in_pos = hit_cap_in_pos_q;
    wire [31:0] n_cap_in_pos = merge(cap_in_pos_q, wr_data_q, wr_strb_q);
    wire w_cap_in_vel = hit_cap_in_vel_q;
    wire [31:0] n_cap_in_vel = merge(cap_in_vel_q, wr_data_q, wr_strb_q);
    wire w_cap_in_ferr = hit_cap_in_ferr_q;
    wire [31:0] n_cap_in_ferr = merge({16'd0, cap_in_ferr_q}, wr_data_q, wr_strb_q);
    wire w_any_ok = w_ctrl | w_err | w_heartbeat | w_scratch | w_irq_en
        | w_irq_status | w_mpdtc_ctrl | w_mpdtc_start | w_mpdtc_in_id | w_mpdtc_in_iq
        | w_mpdtc_in_cos0 | w_mpdtc_in_sin0 | w_mpdtc_in_cos1 | w_mpdtc_in_sin1 | w_mpdtc_in_cos2
        | w_mpdtc_in_sin2 | w_mpdtc_in_w_ts | w_mpdtc_in_t_ref | w_mpdtc_p_a | w_mpdtc_p_lambda
        | w_mpdtc_p_u0 | w_mpdtc_p_u0_half | w_mpdtc_p_u0_h | w_mpdtc_p_psi_l | w_mpdtc_p_kinv_t
        | w_mpdtc_p_tol | w_mpdtc_p_k_int | w_mpdtc_p_int_lim | w_mpdtc_p_int_cond | w_mpdtc_p_kp_o
        | w_mpdtc_p_ki_o | w_mpdtc_p_eta_lim | w_mpdtc_p_w2_0 | w_mpdtc_p_w2_1 | w_mpdtc_p_w2_2
        | w_mpdtc_p_w2_3 | w_mpdtc_align_vec | w_mpdtc_align_period | w_mpdtc_align_on | w_mpdtc_align_time
        | w_mpdtc_fe_ang_scale | w_mpdtc_fe_spd_scale | w_mpdtc_fe_age0 | w_mpdtc_fe_age1 | w_mpdtc_fe_age2
        | w_mpdtc_fe_off_a | w_mpdtc_fe_off_b | w_mpdtc_fe_off_c | w_mpdtc_fe_gain_a | w_mpdtc_fe_gain_b
        | w_mpdtc_fe_gain_c | w_mpdcc_start | w_mpdcc_n_use | w_mpdcc_s_prev | w_mpdcc_i_a
        | w_mpdcc_i_b | w_mpdcc_psi_a | w_mpdcc_psi_b | w_mpdcc_v_n | w_mpdcc_v_ph_a
        | w_mpdcc_v_ph_b | w_mpdcc_v_ph_c | w_mpdcc_iref_a | w_mpdcc_iref_b | w_mpdcc_omega_r
        | w_mpdcc_omega_s | w_mpdcc_c_tau | w_mpdcc_c_r | w_mpdcc_c_w | w_mpdcc_c_p
        | w_mpdcc_c_s | w_mpdcc_c_3 | w_mpdcc_c_d | w_mpdcc_c_n | w_mpdcc_c_ph
        | w_mpdcc_s3h | w_mpdcc_v_ph_ref | w_mpdcc_c_tau1 | w_mpdcc_c_r1 | w_mpdcc_c_w1
        | w_mpdcc_c_s1 | w_mpdcc_vdc_half | w_mpdcc_g3 | w_mpdcc_gd | w_mpdcc_g3_1
        | w_mpdcc_bnd_ia | w_mpdcc_bnd_ib | w_mpdcc_bnd_ic | w_mpdcc_bnd_vn | w_mpdcc_bnd_vpa
        | w_mpdcc_bnd_vpb | w_mpdcc_bnd_vpc | w_mpdcc_lambda_n | w_gate_ctrl | w_dead_time
        | w_pwm_period | w_duty_a | w_duty_b | w_duty_c | w_sw_state
        | w_adc_ctrl | w_adc_period | w_adc_avg_log2 | w_enc_cpr | w_enc_window
        | w_fault_status | w_oc_limit | w_wdg_timeout | w_cap_source | w_cap_pre
        | w_cap_decim | w_cap_step | w_cap_thr_ch | w_cap_thr_level | w_cap_thr_edge
        | w_cap_sel | w_cap_arm | w_cap_trig | w_cap_in_id | w_cap_in_iq
        | w_cap_in_torque | w_cap_in_tref | w_cap_rd_index | w_cap_in_pos | w_cap_in_vel
        | w_cap_in_ferr;
    // Access errors of this cycle (set ERR).
    wire bad_value = (w_ctrl && bad_ctrl) || (w_mpdcc_bnd_ia && bad_mpdcc_bnd_ia) || (w_mpdcc_bnd_ib && bad_mpdcc_bnd_ib) || (w_mpdcc_bnd_ic && bad_mpdcc_bnd_ic) || (w_mpdcc_bnd_vn && bad_mpdcc_bnd_vn) || (w_mpdcc_bnd_vpa && bad_mpdcc_bnd_vpa) || (w_mpdcc_bnd_vpb && bad_mpdcc_bnd_vpb) || (w_mpdcc_bnd_vpc && bad_mpdcc_bnd_vpc) || (w_adc_avg_log2 && bad_adc_avg_log2) || (w_cap_thr_ch && bad_cap_thr_ch) || (w_cap_sel && bad_cap_sel);
    wire bad_addr = (wr_q && !w_any_ok) || (rd_i && rd_err_o);

    assign wr_err_o = wr_q && !w_any_ok;

    always @(posedge clk_i) begin
        if (rst_i) begin
            ctrl_q <= 2'h0;
            err_q <= 2'h0;
            heartbeat_q <= 32'h0;
            scratch_q <= 32'h0;
            irq_en_q <= 2'h0;
            mpdtc_ctrl_q <= 3'h3;
            mpdtc_start_q <= 32'h0;
            mpdtc_in_id_q <= 25'h0;
            mpdtc_in_iq_q <= 25'h0;
            mpdtc_in_cos0_q <= 18'h0;
            mpdtc_in_sin0_q <= 18'h0;
            mpdtc_in_cos1_q <= 18'h0;
            mpdtc_in_sin1_q <= 18'h0;
            mpdtc_in_cos2_q <= 18'h0;
            mpdtc_in_sin2_q <= 18'h0;
            mpdtc_in_w_ts_q <= 18'h0;
            mpdtc_in_t_ref_q <= 18'h0;
            mpdtc_p_a_q <= 18'h0;
            mpdtc_p_lambda_q <= 18'h0;
            mpdtc_p_u0_q <= 25'h0;
            mpdtc_p_u0_half_q <= 25'h0;
            mpdtc_p_u0_h_q <= 25'h0;
            mpdtc_p_psi_l_q <= 25'h0;
            mpdtc_p_kinv_t_q <= 25'h0;
            mpdtc_p_tol_q <= 24'h0;
            mpdtc_p_k_int_q <= 18'h0;
            mpdtc_p_int_lim_q <= 24'h0;
            mpdtc_p_int_cond_q <= 1'h0;
            mpdtc_p_kp_o_q <= 18'h0;
            mpdtc_p_ki_o_q <= 18'h0;
            mpdtc_p_eta_lim_q <= 24'h0;
            mpdtc_p_w2_0_q <= 18'h0;
            mpdtc_p_w2_1_q <= 18'h0;
            mpdtc_p_w2_2_q <= 18'h0;
            mpdtc_p_w2_3_q <= 18'h0;
            mpdtc_align_vec_q <= 3'h4;
            mpdtc_align_period_q <= 16'h1388;
            mpdtc_align_on_q <= 16'hfa;
            mpdtc_align_time_q <= 32'h2faf080;
            mpdtc_fe_ang_scale_q <= 32'h700000;
            mpdtc_fe_spd_scale_q <= 32'h1c06e1a;
            mpdtc_fe_age0_q <= 18'h3e000;
            mpdtc_fe_age1_q <= 18'he000;
            mpdtc_fe_age2_q <= 18'h1e000;
            mpdtc_fe_off_a_q <= 16'h0;
            mpdtc_fe_off_b_q <= 16'h0;
            mpdtc_fe_off_c_q <= 16'h0;
            mpdtc_fe_gain_a_q <= 18'h0;
            mpdtc_fe_gain_b_q <= 18'h0;
            mpdtc_fe_gain_c_q <= 18'h0;
            mpdcc_start_q <= 1'h0;
            mpdcc_n_use_q <= 3'h1;
            mpdcc_s_prev_q <= 9'h0;
            mpdcc_i_a_q <= 16'h0;
            mpdcc_i_b_q <= 16'h0;
            mpdcc_psi_a_q <= 16'h0;
            mpdcc_psi_b_q <= 16'h0;
            mpdcc_v_n_q <= 16'h0;
            mpdcc_v_ph_a_q <= 16'h0;
            mpdcc_v_ph_b_q <= 16'h0;
            mpdcc_v_ph_c_q <= 16'h0;
            mpdcc_iref_a_q <= 16'h0;
            mpdcc_iref_b_q <= 16'h0;
            mpdcc_omega_r_q <= 16'h0;
            mpdcc_omega_s_q <= 16'h0;
            mpdcc_c_tau_q <= 16'h0;
            mpdcc_c_r_q <= 16'h0;
            mpdcc_c_w_q <= 16'h0;
            mpdcc_c_p_q <= 16'h0;
            mpdcc_c_s_q <= 16'h0;
            mpdcc_c_3_q <= 16'h0;
            mpdcc_c_d_q <= 16'h0;
            mpdcc_c_n_q <= 16'h0;
            mpdcc_c_ph_q <= 16'h0;
            mpdcc_s3h_q <= 16'h0;
            mpdcc_v_ph_ref_q <= 16'h0;
            mpdcc_c_tau1_q <= 16'h0;
            mpdcc_c_r1_q <= 16'h0;
            mpdcc_c_w1_q <= 16'h0;
            mpdcc_c_s1_q <= 16'h0;
            mpdcc_vdc_half_q <= 16'h0;
            mpdcc_g3_q <= 16'h0;
            mpdcc_gd_q <= 16'h0;
            mpdcc_g3_1_q <= 16'h0;
            mpdcc_bnd_ia_q <= 16'h0;
            mpdcc_bnd_ib_q <= 16'h0;
            mpdcc_bnd_ic_q <= 16'h0;
            mpdcc_bnd_vn_q <= 16'h0;
            mpdcc_bnd_vpa_q <= 16'h0;
            mpdcc_bnd_vpb_q <= 16'h0;
            mpdcc_bnd_vpc_q <= 16'h0;
            mpdcc_lambda_n_q <= 16'h0;
            gate_ctrl_q <= 1'h0;
            dead_time_q <= 10'h32;
            pwm_period_q <= 16'h9c4;
            duty_a_q <= 16'h4e2;
            duty_b_q <= 16'h4e2;
            duty_c_q <= 16'h4e2;
            sw_state_q <= 3'h0;
            adc_ctrl_q <= 1'h1;
            adc_period_q <= 16'h187;
            adc_avg_log2_q <= 2'h2;
            enc_cpr_q <= 16'h1000;
            enc_window_q <= 24'h186a0;
            oc_limit_q <= 11'h708;
            wdg_timeout_q <= 32'h989680;
            cap_source_q <= 2'h0;
            cap_pre_q <= 10'h80;
            cap_decim_q <= 8'h0;
            cap_step_q <= 16'h1f4;
            cap_thr_ch_q <= 3'h2;
            cap_thr_level_q <= 16'h0;
            cap_thr_edge_q <= 1'h0;
            cap_sel_q <= 3'h0;
            cap_arm_q <= 1'h0;
            cap_trig_q <= 1'h0;
            cap_in_id_q <= 16'h0;
            cap_in_iq_q <= 16'h0;
            cap_in_torque_q <= 16'h0;
            cap_in_tref_q <= 16'h0;
            cap_rd_index_q <= 10'h0;
            cap_in_pos_q <= 32'h0;
            cap_in_vel_q <= 32'h0;
            cap_in_ferr_q <= 16'h0;
        end else begin
            if (w_ctrl && !bad_ctrl) ctrl_q <= n_ctrl[1:0];
            // A flag set in this cycle wins over its clear.
            err_q <= (err_q & ~(w_err ? n_err[1:0] : 2'd0)) | {bad_addr, bad_value};
            if (w_heartbeat) heartbeat_q <= n_heartbeat[31:0];
            if (w_scratch) scratch_q <= n_scratch[31:0];
            if (w_irq_en) irq_en_q <= n_irq_en[1:0];
            if (w_mpdtc_ctrl) mpdtc_ctrl_q <= n_mpdtc_ctrl[2:0];
            if (w_mpdtc_start) mpdtc_start_q <= n_mpdtc_start[31:0];
            if (w_mpdtc_in_id) mpdtc_in_id_q <= n_mpdtc_in_id[24:0];
            if (w_mpdtc_in_iq) mpdtc_in_iq_q <= n_mpdtc_in_iq[24:0];
            if (w_mpdtc_in_cos0) mpdtc_in_cos0_q <= n_mpdtc_in_cos0[17:0];
            if (w_mpdtc_in_sin0) mpdtc_in_sin0_q <= n_mpdtc_in_sin0[17:0];
            if (w_mpdtc_in_cos1) mpdtc_in_cos1_q <= n_mpdtc_in_cos1[17:0];
            if (w_mpdtc_in_sin1) mpdtc_in_sin1_q <= n_mpdtc_in_sin1[17:0];
            if (w_mpdtc_in_cos2) mpdtc_in_cos2_q <= n_mpdtc_in_cos2[17:0];
            if (w_mpdtc_in_sin2) mpdtc_in_sin2_q <= n_mpdtc_in_sin2[17:0];
            if (w_mpdtc_in_w_ts) mpdtc_in_w_ts_q <= n_mpdtc_in_w_ts[17:0];
            if (w_mpdtc_in_t_ref) mpdtc_in_t_ref_q <= n_mpdtc_in_t_ref[17:0];
            if (w_mpdtc_p_a) mpdtc_p_a_q <= n_mpdtc_p_a[17:0];
            if (w_mpdtc_p_lambda) mpdtc_p_lambda_q <= n_mpdtc_p_lambda[17:0];
            if (w_mpdtc_p_u0) mpdtc_p_u0_q <= n_mpdtc_p_u0[24:0];
            if (w_mpdtc_p_u0_half) mpdtc_p_u0_half_q <= n_mpdtc_p_u0_half[24:0];
            if (w_mpdtc_p_u0_h) mpdtc_p_u0_h_q <= n_mpdtc_p_u0_h[24:0];
            if (w_mpdtc_p_psi_l) mpdtc_p_psi_l_q <= n_mpdtc_p_psi_l[24:0];
            if (w_mpdtc_p_kinv_t) mpdtc_p_kinv_t_q <= n_mpdtc_p_kinv_t[24:0];
            if (w_mpdtc_p_tol) mpdtc_p_tol_q <= n_mpdtc_p_tol[23:0];
            if (w_mpdtc_p_k_int) mpdtc_p_k_int_q <= n_mpdtc_p_k_int[17:0];
            if (w_mpdtc_p_int_lim) mpdtc_p_int_lim_q <= n_mpdtc_p_int_lim[23:0];
            if (w_mpdtc_p_int_cond) mpdtc_p_int_cond_q <= n_mpdtc_p_int_cond[0:0];
            if (w_mpdtc_p_kp_o) mpdtc_p_kp_o_q <= n_mpdtc_p_kp_o[17:0];
            if (w_mpdtc_p_ki_o) mpdtc_p_ki_o_q <= n_mpdtc_p_ki_o[17:0];
            if (w_mpdtc_p_eta_lim) mpdtc_p_eta_lim_q <= n_mpdtc_p_eta_lim[23:0];
            if (w_mpdtc_p_w2_0) mpdtc_p_w2_0_q <= n_mpdtc_p_w2_0[17:0];
            if (w_mpdtc_p_w2_1) mpdtc_p_w2_1_q <= n_mpdtc_p_w2_1[17:0];
            if (w_mpdtc_p_w2_2) mpdtc_p_w2_2_q <= n_mpdtc_p_w2_2[17:0];
            if (w_mpdtc_p_w2_3) mpdtc_p_w2_3_q <= n_mpdtc_p_w2_3[17:0];
            if (w_mpdtc_align_vec) mpdtc_align_vec_q <= n_mpdtc_align_vec[2:0];
            if (w_mpdtc_align_period) mpdtc_align_period_q <= n_mpdtc_align_period[15:0];
            if (w_mpdtc_align_on) mpdtc_align_on_q <= n_mpdtc_align_on[15:0];
            if (w_mpdtc_align_time) mpdtc_align_time_q <= n_mpdtc_align_time[31:0];
            if (w_mpdtc_fe_ang_scale) mpdtc_fe_ang_scale_q <= n_mpdtc_fe_ang_scale[31:0];
            if (w_mpdtc_fe_spd_scale) mpdtc_fe_spd_scale_q <= n_mpdtc_fe_spd_scale[31:0];
            if (w_mpdtc_fe_age0) mpdtc_fe_age0_q <= n_mpdtc_fe_age0[17:0];
            if (w_mpdtc_fe_age1) mpdtc_fe_age1_q <= n_mpdtc_fe_age1[17:0];
            if (w_mpdtc_fe_age2) mpdtc_fe_age2_q <= n_mpdtc_fe_age2[17:0];
            if (w_mpdtc_fe_off_a) mpdtc_fe_off_a_q <= n_mpdtc_fe_off_a[15:0];
            if (w_mpdtc_fe_off_b) mpdtc_fe_off_b_q <= n_mpdtc_fe_off_b[15:0];
            if (w_mpdtc_fe_off_c) mpdtc_fe_off_c_q <= n_mpdtc_fe_off_c[15:0];
            if (w_mpdtc_fe_gain_a) mpdtc_fe_gain_a_q <= n_mpdtc_fe_gain_a[17:0];
            if (w_mpdtc_fe_gain_b) mpdtc_fe_gain_b_q <= n_mpdtc_fe_gain_b[17:0];
            if (w_mpdtc_fe_gain_c) mpdtc_fe_gain_c_q <= n_mpdtc_fe_gain_c[17:0];
            if (w_mpdcc_start) mpdcc_start_q <= n_mpdcc_start[0:0];
            if (w_mpdcc_n_use) mpdcc_n_use_q <= n_mpdcc_n_use[2:0];
            if (w_mpdcc_s_prev) mpdcc_s_prev_q <= n_mpdcc_s_prev[8:0];
            if (w_mpdcc_i_a) mpdcc_i_a_q <= n_mpdcc_i_a[15:0];
            if (w_mpdcc_i_b) mpdcc_i_b_q <= n_mpdcc_i_b[15:0];
            if (w_mpdcc_psi_a) mpdcc_psi_a_q <= n_mpdcc_psi_a[15:0];
            if (w_mpdcc_psi_b) mpdcc_psi_b_q <= n_mpdcc_psi_b[15:0];
            if (w_mpdcc_v_n) mpdcc_v_n_q <= n_mpdcc_v_n[15:0];
            if (w_mpdcc_v_ph_a) mpdcc_v_ph_a_q <= n_mpdcc_v_ph_a[15:0];
            if (w_mpdcc_v_ph_b) mpdcc_v_ph_b_q <= n_mpdcc_v_ph_b[15:0];
            if (w_mpdcc_v_ph_c) mpdcc_v_ph_c_q <= n_mpdcc_v_ph_c[15:0];
            if (w_mpdcc_iref_a) mpdcc_iref_a_q <= n_mpdcc_iref_a[15:0];
            if (w_mpdcc_iref_b) mpdcc_iref_b_q <= n_mpdcc_iref_b[15:0];
            if (w_mpdcc_omega_r) mpdcc_omega_r_q <= n_mpdcc_omega_r[15:0];
            if (w_mpdcc_omega_s) mpdcc_omega_s_q <= n_mpdcc_omega_s[15:0];
            if (w_mpdcc_c_tau) mpdcc_c_tau_q <= n_mpdcc_c_tau[15:0];
            if (w_mpdcc_c_r) mpdcc_c_r_q <= n_mpdcc_c_r[15:0];
            if (w_mpdcc_c_w) mpdcc_c_w_q <= n_mpdcc_c_w[15:0];
            if (w_mpdcc_c_p) mpdcc_c_p_q <= n_mpdcc_c_p[15:0];
            if (w_mpdcc_c_s) mpdcc_c_s_q <= n_mpdcc_c_s[15:0];
            if (w_mpdcc_c_3) mpdcc_c_3_q <= n_mpdcc_c_3[15:0];
            if (w_mpdcc_c_d) mpdcc_c_d_q <= n_mpdcc_c_d[15:0];
            if (w_mpdcc_c_n) mpdcc_c_n_q <= n_mpdcc_c_n[15:0];
            if (w_mpdcc_c_ph) mpdcc_c_ph_q <= n_mpdcc_c_ph[15:0];
            if (w_mpdcc_s3h) mpdcc_s3h_q <= n_mpdcc_s3h[15:0];
            if (w_mpdcc_v_ph_ref) mpdcc_v_ph_ref_q <= n_mpdcc_v_ph_ref[15:0];
            if (w_mpdcc_c_tau1) mpdcc_c_tau1_q <= n_mpdcc_c_tau1[15:0];
            if (w_mpdcc_c_r1) mpdcc_c_r1_q <= n_mpdcc_c_r1[15:0];
            if (w_mpdcc_c_w1) mpdcc_c_w1_q <= n_mpdcc_c_w1[15:0];
            if (w_mpdcc_c_s1) mpdcc_c_s1_q <= n_mpdcc_c_s1[15:0];
            if (w_mpdcc_vdc_half) mpdcc_vdc_half_q <= n_mpdcc_vdc_half[15:0];
            if (w_mpdcc_g3) mpdcc_g3_q <= n_mpdcc_g3[15:0];
            if (w_mpdcc_gd) mpdcc_gd_q <= n_mpdcc_gd[15:0];
            if (w_mpdcc_g3_1) mpdcc_g3_1_q <= n_mpdcc_g3_1[15:0];
            if (w_mpdcc_bnd_ia && !bad_mpdcc_bnd_ia) mpdcc_bnd_ia_q <= n_mpdcc_bnd_ia[15:0];
            if (w_mpdcc_bnd_ib && !bad_mpdcc_bnd_ib) mpdcc_bnd_ib_q <= n_mpdcc_bnd_ib[15:0];
            if (w_mpdcc_bnd_ic && !bad_mpdcc_bnd_ic) mpdcc_bnd_ic_q <= n_mpdcc_bnd_ic[15:0];
            if (w_mpdcc_bnd_vn && !bad_mpdcc_bnd_vn) mpdcc_bnd_vn_q <= n_mpdcc_bnd_vn[15:0];
            if (w_mpdcc_bnd_vpa && !bad_mpdcc_bnd_vpa) mpdcc_bnd_vpa_q <= n_mpdcc_bnd_vpa[15:0];
            if (w_mpdcc_bnd_vpb && !bad_mpdcc_bnd_vpb) mpdcc_bnd_vpb_q <= n_mpdcc_bnd_vpb[15:0];
            if (w_mpdcc_bnd_vpc && !bad_mpdcc_bnd_vpc) mpdcc_bnd_vpc_q <= n_mpdcc_bnd_vpc[15:0];
            if (w_mpdcc_lambda_n) mpdcc_lambda_n_q <= n_mpdcc_lambda_n[15:0];
            if (gate_ctrl_hw_clr_i) gate_ctrl_q <= 1'd0;
            else if (w_gate_ctrl) gate_ctrl_q <= n_gate_ctrl[0:0];
            if (w_dead_time) dead_time_q <= n_dead_time[9:0];
            if (w_pwm_period) pwm_period_q <= n_pwm_period[15:0];
            if (w_duty_a) duty_a_q <= n_duty_a[15:0];
            if (w_duty_b) duty_b_q <= n_duty_b[15:0];
            if (w_duty_c) duty_c_q <= n_duty_c[15:0];
            if (w_sw_state) sw_state_q <= n_sw_state[2:0];
            if (w_adc_ctrl) adc_ctrl_q <= n_adc_ctrl[0:0];
            if (w_adc_period) adc_period_q <= n_adc_period[15:0];
            if (w_adc_avg_log2 && !bad_adc_avg_log2) adc_avg_log2_q <= n_adc_avg_log2[1:0];
            if (w_enc_cpr) enc_cpr_q <= n_enc_cpr[15:0];
            if (w_enc_window) enc_window_q <= n_enc_window[23:0];
            if (w_oc_limit) oc_limit_q <= n_oc_limit[10:0];
            if (w_wdg_timeout) wdg_timeout_q <= n_wdg_timeout[31:0];
            if (w_cap_source) cap_source_q <= n_cap_source[1:0];
            if (w_cap_pre) cap_pre_q <= n_cap_pre[9:0];
            if (w_cap_decim) cap_decim_q <= n_cap_decim[7:0];
            if (w_cap_step) cap_step_q <= n_cap_step[15:0];
            if (w_cap_thr_ch && !bad_cap_thr_ch) cap_thr_ch_q <= n_cap_thr_ch[2:0];
            if (w_cap_thr_level) cap_thr_level_q <= n_cap_thr_level[15:0];
            if (w_cap_thr_edge) cap_thr_edge_q <= n_cap_thr_edge[0:0];
            if (w_cap_sel && !bad_cap_sel) cap_sel_q <= n_cap_sel[2:0];
            if (w_cap_arm) cap_arm_q <= n_cap_arm[0:0];
            if (w_cap_trig) cap_trig_q <= n_cap_trig[0:0];
            if (w_cap_in_id) cap_in_id_q <= n_cap_in_id[15:0];
            if (w_cap_in_iq) cap_in_iq_q <= n_cap_in_iq[15:0];
            if (w_cap_in_torque) cap_in_torque_q <= n_cap_in_torque[15:0];
            if (w_cap_in_tref) cap_in_tref_q <= n_cap_in_tref[15:0];
            if (w_cap_rd_index) cap_rd_index_q <= n_cap_rd_index[9:0];
            if (w_cap_in_pos) cap_in_pos_q <= n_cap_in_pos[31:0];
            if (w_cap_in_vel) cap_in_vel_q <= n_cap_in_vel[31:0];
            if (w_cap_in_ferr) cap_in_ferr_q <= n_cap_in_ferr[15:0];
        end
    end

    // Read mux, two stages (one clock each at 100 MHz, docs/rtl.md): at
    // the read strobe each page's registers are multiplexed into that page's
    // word (the other pages' words are 0); the next cycle rd_data_o is the
    // addressed page's word. rd_err_o is combinational (ERR.BAD_ADDR is set
    // at the strobe's edge).
    reg [2:0] rd_page_q;
    reg [31:0] rd_top_q;
    reg [31:0] rd_mpdtc_q;
    reg [31:0] rd_mpdcc_q;
    reg [31:0] rd_pwm_q;
    reg [31:0] rd_adc_q;
    reg [31:0] rd_enc_q;
    reg [31:0] rd_fault_q;
    reg [31:0] rd_capture_q;
    always @(posedge clk_i) begin
        if (rst_i) begin
            rd_page_q <= 3'd0;
            rd_top_q <= 32'd0;
            rd_mpdtc_q <= 32'd0;
            rd_mpdcc_q <= 32'd0;
            rd_pwm_q <= 32'd0;
            rd_adc_q <= 32'd0;
            rd_enc_q <= 32'd0;
            rd_fault_q <= 32'd0;
            rd_capture_q <= 32'd0;
        end else if (rd_i) begin
            rd_page_q <= rd_addr_i[14:12];
            rd_top_q <= 32'd0;
            rd_mpdtc_q <= 32'd0;
            rd_mpdcc_q <= 32'd0;
            rd_pwm_q <= 32'd0;
            rd_adc_q <= 32'd0;
            rd_enc_q <= 32'd0;
            rd_fault_q <= 32'd0;
            rd_capture_q <= 32'd0;
            case (rd_addr_i)
                15'h0000: rd_top_q <= 32'h50534452;  // ID
                15'h0004: rd_top_q <= 32'h00010004;  // VERSION
                15'h0008: rd_top_q <= {30'd0, ctrl_q};  // CTRL
                15'h000c: rd_top_q <= {28'd0, status_fault_i, status_gates_active_i, status_mode_i};  // STATUS
                15'h0010: rd_top_q <= {30'd0, err_q};  // ERR
                15'h0014: rd_top_q <= heartbeat_q;  // HEARTBEAT
                15'h0018: rd_top_q <= scratch_q;  // SCRATCH
                15'h0040: rd_top_q <= {30'd0, irq_en_q};  // IRQ_EN
                15'h0044: rd_top_q <= {29'd0, irq_status_missed_i, irq_status_fault_i, irq_status_boundary_i};  // IRQ_STATUS
                15'h0048: rd_top_q <= {16'd0, boundary_age_i};  // BOUNDARY_AGE
                15'h1000: rd_mpdtc_q <= {29'd0, mpdtc_ctrl_q};  // MPDTC_CTRL
                15'h1004: rd_mpdtc_q <= mpdtc_start_q;  // MPDTC_START
                15'h1008: rd_mpdtc_q <= {mpdtc_status_done_count_i, 12'd0, mpdtc_status_s_next_i, mpdtc_status_busy_i};  // MPDTC_STATUS
                15'h100c: rd_mpdtc_q <= 32'h00000027;  // MPDTC_LATENCY
                15'h1010: rd_mpdtc_q <= {7'd0, mpdtc_in_id_q};  // MPDTC_IN_ID
                15'h1014: rd_mpdtc_q <= {7'd0, mpdtc_in_iq_q};  // MPDTC_IN_IQ
                15'h1018: rd_mpdtc_q <= {14'd0, mpdtc_in_cos0_q};  // MPDTC_IN_COS0
                15'h101c: rd_mpdtc_q <= {14'd0, mpdtc_in_sin0_q};  // MPDTC_IN_SIN0
                15'h1020: rd_mpdtc_q <= {14'd0, mpdtc_in_cos1_q};  // MPDTC_IN_COS1
                15'h1024: rd_mpdtc_q <= {14'd0, mpdtc_in_sin1_q};  // MPDTC_IN_SIN1
                15'h1028: rd_mpdtc_q <= {14'd0, mpdtc_in_cos2_q};  // MPDTC_IN_COS2
                15'h102c: rd_mpdtc_q <= {14'd0, mpdtc_in_sin2_q};  // MPDTC_IN_SIN2
                15'h1030: rd_mpdtc_q <= {14'd0, mpdtc_in_w_ts_q};  // MPDTC_IN_W_TS
                15'h1034: rd_mpdtc_q <= {14'd0, mpdtc_in_t_ref_q};  // MPDTC_IN_T_REF
                15'h1040: rd_mpdtc_q <= {14'd0, mpdtc_p_a_q};  // MPDTC_P_A
                15'h1044: rd_mpdtc_q <= {14'd0, mpdtc_p_lambda_q};  // MPDTC_P_LAMBDA
                15'h1048: rd_mpdtc_q <= {7'd0, mpdtc_p_u0_q};  // MPDTC_P_U0
                15'h104c: rd_mpdtc_q <= {7'd0, mpdtc_p_u0_half_q};  // MPDTC_P_U0_HALF
                15'h1050: rd_mpdtc_q <= {7'd0, mpdtc_p_u0_h_q};  // MPDTC_P_U0_H
                15'h1054: rd_mpdtc_q <= {7'd0, mpdtc_p_psi_l_q};  // MPDTC_P_PSI_L
                15'h1058: rd_mpdtc_q <= {7'd0, mpdtc_p_kinv_t_q};  // MPDTC_P_KINV_T
                15'h105c: rd_mpdtc_q <= {8'd0, mpdtc_p_tol_q};  // MPDTC_P_TOL
                15'h1060: rd_mpdtc_q <= {14'd0, mpdtc_p_k_int_q};  // MPDTC_P_K_INT
                15'h1064: rd_mpdtc_q <= {8'd0, mpdtc_p_int_lim_q};  // MPDTC_P_INT_LIM
                15'h1068: rd_mpdtc_q <= {31'd0, mpdtc_p_int_cond_q};  // MPDTC_P_INT_COND
                15'h106c: rd_mpdtc_q <= {14'd0, mpdtc_p_kp_o_q};  // MPDTC_P_KP_O
                15'h1070: rd_mpdtc_q <= {14'd0, mpdtc_p_ki_o_q};  // MPDTC_P_KI_O
                15'h1074: rd_mpdtc_q <= {8'd0, mpdtc_p_eta_lim_q};  // MPDTC_P_ETA_LIM
                15'h1078: rd_mpdtc_q <= {14'd0, mpdtc_p_w2_0_q};  // MPDTC_P_W2_0
                15'h107c: rd_mpdtc_q <= {14'd0, mpdtc_p_w2_1_q};  // MPDTC_P_W2_1
                15'h1080: rd_mpdtc_q <= {14'd0, mpdtc_p_w2_2_q};  // MPDTC_P_W2_2
                15'h1084: rd_mpdtc_q <= {14'd0, mpdtc_p_w2_3_q};  // MPDTC_P_W2_3
                15'h1090: rd_mpdtc_q <= {7'd0, mpdtc_iq_ref_i};  // MPDTC_IQ_REF
                15'h10a0: rd_mpdtc_q <= {mpdtc_seq_status_periods_i, mpdtc_seq_status_overruns_i, 3'd0, mpdtc_seq_status_aligned_i, mpdtc_seq_status_sampled_i, mpdtc_seq_status_state_i};  // MPDTC_SEQ_STATUS
                15'h10a4: rd_mpdtc_q <= {29'd0, mpdtc_align_vec_q};  // MPDTC_ALIGN_VEC
                15'h10a8: rd_mpdtc_q <= {16'd0, mpdtc_align_period_q};  // MPDTC_ALIGN_PERIOD
                15'h10ac: rd_mpdtc_q <= {16'd0, mpdtc_align_on_q};  // MPDTC_ALIGN_ON
                15'h10b0: rd_mpdtc_q <= mpdtc_align_time_q;  // MPDTC_ALIGN_TIME
                15'h10b4: rd_mpdtc_q <= {16'd0, mpdtc_align_pos_i};  // MPDTC_ALIGN_POS
                15'h10b8: rd_mpdtc_q <= mpdtc_fe_ang_scale_q;  // MPDTC_FE_ANG_SCALE
                15'h10bc: rd_mpdtc_q <= mpdtc_fe_spd_scale_q;  // MPDTC_FE_SPD_SCALE
                15'h10c0: rd_mpdtc_q <= {14'd0, mpdtc_fe_age0_q};  // MPDTC_FE_AGE0
                15'h10c4: rd_mpdtc_q <= {14'd0, mpdtc_fe_age1_q};  // MPDTC_FE_AGE1
                15'h10c8: rd_mpdtc_q <= {14'd0, mpdtc_fe_age2_q};  // MPDTC_FE_AGE2
                15'h10cc: rd_mpdtc_q <= {16'd0, mpdtc_fe_off_a_q};  // MPDTC_FE_OFF_A
                15'h10d0: rd_mpdtc_q <= {16'd0, mpdtc_fe_off_b_q};  // MPDTC_FE_OFF_B
                15'h10d4: rd_mpdtc_q <= {16'd0, mpdtc_fe_off_c_q};  // MPDTC_FE_OFF_C
                15'h10d8: rd_mpdtc_q <= {14'd0, mpdtc_fe_gain_a_q};  // MPDTC_FE_GAIN_A
                15'h10dc: rd_mpdtc_q <= {14'd0, mpdtc_fe_gain_b_q};  // MPDTC_FE_GAIN_B
                15'h10e0: rd_mpdtc_q <= {14'd0, mpdtc_fe_gain_c_q};  // MPDTC_FE_GAIN_C
                15'h10e4: rd_mpdtc_q <= {7'd0, mpdtc_fe_id_i};  // MPDTC_FE_ID
                15'h10e8: rd_mpdtc_q <= {7'd0, mpdtc_fe_iq_i};  // MPDTC_FE_IQ
                15'h2000: rd_mpdcc_q <= {31'd0, mpdcc_start_q};  // MPDCC_START
                15'h2004: rd_mpdcc_q <= {mpdcc_status_count_i, 14'd0, mpdcc_status_done_i, mpdcc_status_busy_i};  // MPDCC_STATUS
                15'h2008: rd_mpdcc_q <= {29'd0, mpdcc_n_use_q};  // MPDCC_N_USE
                15'h200c: rd_mpdcc_q <= {16'd0, mpdcc_config_nodes_i, mpdcc_config_m_bits_i, mpdcc_config_lambda_i, mpdcc_config_explorers_i};  // MPDCC_CONFIG
                15'h2010: rd_mpdcc_q <= {23'd0, mpdcc_s_prev_q};  // MPDCC_S_PREV
                15'h2014: rd_mpdcc_q <= {16'd0, mpdcc_i_a_q};  // MPDCC_I_A
                15'h2018: rd_mpdcc_q <= {16'd0, mpdcc_i_b_q};  // MPDCC_I_B
                15'h201c: rd_mpdcc_q <= {16'd0, mpdcc_psi_a_q};  // MPDCC_PSI_A
                15'h2020: rd_mpdcc_q <= {16'd0, mpdcc_psi_b_q};  // MPDCC_PSI_B
                15'h2024: rd_mpdcc_q <= {16'd0, mpdcc_v_n_q};  // MPDCC_V_N
                15'h2028: rd_mpdcc_q <= {16'd0, mpdcc_v_ph_a_q};  // MPDCC_V_PH_A
                15'h202c: rd_mpdcc_q <= {16'd0, mpdcc_v_ph_b_q};  // MPDCC_V_PH_B
                15'h2030: rd_mpdcc_q <= {16'd0, mpdcc_v_ph_c_q};  // MPDCC_V_PH_C
                15'h2034: rd_mpdcc_q <= {16'd0, mpdcc_iref_a_q};  // MPDCC_IREF_A
                15'h2038: rd_mpdcc_q <= {16'd0, mpdcc_iref_b_q};  // MPDCC_IREF_B
                15'h203c: rd_mpdcc_q <= {16'd0, mpdcc_omega_r_q};  // MPDCC_OMEGA_R
                15'h2040: rd_mpdcc_q <= {16'd0, mpdcc_omega_s_q};  // MPDCC_OMEGA_S
                15'h2080: rd_mpdcc_q <= {16'd0, mpdcc_c_tau_q};  // MPDCC_C_TAU
                15'h2084: rd_mpdcc_q <= {16'd0, mpdcc_c_r_q};  // MPDCC_C_R
                15'h2088: rd_mpdcc_q <= {16'd0, mpdcc_c_w_q};  // MPDCC_C_W
                15'h208c: rd_mpdcc_q <= {16'd0, mpdcc_c_p_q};  // MPDCC_C_P
                15'h2090: rd_mpdcc_q <= {16'd0, mpdcc_c_s_q};  // MPDCC_C_S
                15'h2094: rd_mpdcc_q <= {16'd0, mpdcc_c_3_q};  // MPDCC_C_3
                15'h2098: rd_mpdcc_q <= {16'd0, mpdcc_c_d_q};  // MPDCC_C_D
                15'h209c: rd_mpdcc_q <= {16'd0, mpdcc_c_n_q};  // MPDCC_C_N
                15'h20a0: rd_mpdcc_q <= {16'd0, mpdcc_c_ph_q};  // MPDCC_C_PH
                15'h20a4: rd_mpdcc_q <= {16'd0, mpdcc_s3h_q};  // MPDCC_S3H
                15'h20a8: rd_mpdcc_q <= {16'd0, mpdcc_v_ph_ref_q};  // MPDCC_V_PH_REF
                15'h20ac: rd_mpdcc_q <= {16'd0, mpdcc_c_tau1_q};  // MPDCC_C_TAU1
                15'h20b0: rd_mpdcc_q <= {16'd0, mpdcc_c_r1_q};  // MPDCC_C_R1
                15'h20b4: rd_mpdcc_q <= {16'd0, mpdcc_c_w1_q};  // MPDCC_C_W1
                15'h20b8: rd_mpdcc_q <= {16'd0, mpdcc_c_s1_q};  // MPDCC_C_S1
                15'h20bc: rd_mpdcc_q <= {16'd0, mpdcc_vdc_half_q};  // MPDCC_VDC_HALF
                15'h20c0: rd_mpdcc_q <= {16'd0, mpdcc_g3_q};  // MPDCC_G3
                15'h20c4: rd_mpdcc_q <= {16'd0, mpdcc_gd_q};  // MPDCC_GD
                15'h20c8: rd_mpdcc_q <= {16'd0, mpdcc_g3_1_q};  // MPDCC_G3_1
                15'h20cc: rd_mpdcc_q <= {16'd0, mpdcc_bnd_ia_q};  // MPDCC_BND_IA
                15'h20d0: rd_mpdcc_q <= {16'd0, mpdcc_bnd_ib_q};  // MPDCC_BND_IB
                15'h20d4: rd_mpdcc_q <= {16'd0, mpdcc_bnd_ic_q};  // MPDCC_BND_IC
                15'h20d8: rd_mpdcc_q <= {16'd0, mpdcc_bnd_vn_q};  // MPDCC_BND_VN
                15'h20dc: rd_mpdcc_q <= {16'd0, mpdcc_bnd_vpa_q};  // MPDCC_BND_VPA
                15'h20e0: rd_mpdcc_q <= {16'd0, mpdcc_bnd_vpb_q};  // MPDCC_BND_VPB
                15'h20e4: rd_mpdcc_q <= {16'd0, mpdcc_bnd_vpc_q};  // MPDCC_BND_VPC
                15'h20e8: rd_mpdcc_q <= {16'd0, mpdcc_lambda_n_q};  // MPDCC_LAMBDA_N
                15'h2100: rd_mpdcc_q <= {8'd0, mpdcc_decision_l_star_i, 2'd0, mpdcc_decision_kind_i, 3'd0, mpdcc_decision_s_c_i, mpdcc_decision_s_b_i, mpdcc_decision_s_a_i};  // MPDCC_DECISION
                15'h2104: rd_mpdcc_q <= mpdcc_cost_i;  // MPDCC_COST
                15'h2108: rd_mpdcc_q <= mpdcc_j_dl_i;  // MPDCC_J_DL
                15'h210c: rd_mpdcc_q <= {8'd0, mpdcc_cycles_candidates_i, mpdcc_cycles_cycles_i};  // MPDCC_CYCLES
                15'h2110: rd_mpdcc_q <= {16'd0, mpdcc_deadlocks_i};  // MPDCC_DEADLOCKS
                15'h3000: rd_pwm_q <= {31'd0, gate_ctrl_q};  // GATE_CTRL
                15'h3004: rd_pwm_q <= {22'd0, dead_time_q};  // DEAD_TIME
                15'h3008: rd_pwm_q <= {16'd0, pwm_period_q};  // PWM_PERIOD
                15'h300c: rd_pwm_q <= {16'd0, duty_a_q};  // DUTY_A
                15'h3010: rd_pwm_q <= {16'd0, duty_b_q};  // DUTY_B
                15'h3014: rd_pwm_q <= {16'd0, duty_c_q};  // DUTY_C
                15'h3018: rd_pwm_q <= {29'd0, sw_state_q};  // SW_STATE
                15'h301c: rd_pwm_q <= {23'd0, gate_status_state_i, gate_status_lo_i, gate_status_hi_i};  // GATE_STATUS
                15'h3020: rd_pwm_q <= {15'd0, pwm_count_down_i, pwm_count_count_i};  // PWM_COUNT
                15'h4000: rd_adc_q <= {31'd0, adc_ctrl_q};  // ADC_CTRL
                15'h4004: rd_adc_q <= {16'd0, adc_period_q};  // ADC_PERIOD
                15'h4008: rd_adc_q <= {16'd0, adc_ia_i};  // ADC_IA
                15'h400c: rd_adc_q <= {16'd0, adc_ib_i};  // ADC_IB
                15'h4010: rd_adc_q <= {16'd0, adc_ic_i};  // ADC_IC
                15'h4014: rd_adc_q <= adc_count_i;  // ADC_COUNT
                15'h4018: rd_adc_q <= {30'd0, adc_avg_log2_q};  // ADC_AVG_LOG2
                15'h5000: rd_enc_q <= {16'd0, enc_cpr_q};  // ENC_CPR
                15'h5004: rd_enc_q <= {16'd0, enc_pos_i};  // ENC_POS
                15'h5008: rd_enc_q <= {16'd0, enc_speed_i};  // ENC_SPEED
                15'h500c: rd_enc_q <= {8'd0, enc_window_q};  // ENC_WINDOW
                15'h5010: rd_enc_q <= {16'd0, enc_index_i};  // ENC_INDEX
                15'h5014: rd_enc_q <= {16'd0, enc_pos_sample_i};  // ENC_POS_SAMPLE
                15'h6000: rd_fault_q <= {27'd0, fault_status_adc_stuck_i, fault_status_encoder_loss_i, fault_status_watchdog_i, fault_status_external_i, fault_status_overcurrent_i};  // FAULT_STATUS
                15'h6004: rd_fault_q <= {27'd0, fault_raw_i};  // FAULT_RAW
                15'h6008: rd_fault_q <= {21'd0, oc_limit_q};  // OC_LIMIT
                15'h600c: rd_fault_q <= wdg_timeout_q;  // WDG_TIMEOUT
                15'h7000: rd_capture_q <= {30'd0, cap_source_q};  // CAP_SOURCE
                15'h7004: rd_capture_q <= {22'd0, cap_pre_q};  // CAP_PRE
                15'h7008: rd_capture_q <= {24'd0, cap_decim_q};  // CAP_DECIM
                15'h700c: rd_capture_q <= {16'd0, cap_step_q};  // CAP_STEP
                15'h7010: rd_capture_q <= {29'd0, cap_thr_ch_q};  // CAP_THR_CH
                15'h7014: rd_capture_q <= {16'd0, cap_thr_level_q};  // CAP_THR_LEVEL
                15'h7018: rd_capture_q <= {31'd0, cap_thr_edge_q};  // CAP_THR_EDGE
                15'h701c: rd_capture_q <= {29'd0, cap_sel_q};  // CAP_SEL
                15'h7020: rd_capture_q <= {31'd0, cap_arm_q};  // CAP_ARM
                15'h7024: rd_capture_q <= {31'd0, cap_trig_q};  // CAP_TRIG
                15'h7028: rd_capture_q <= {5'd0, cap_status_count_i, 1'd0, cap_status_trig_index_i, 2'd0, cap_status_state_i};  // CAP_STATUS
                15'h7030: rd_capture_q <= {16'd0, cap_in_id_q};  // CAP_IN_ID
                15'h7034: rd_capture_q <= {16'd0, cap_in_iq_q};  // CAP_IN_IQ
                15'h7038: rd_capture_q <= {16'd0, cap_in_torque_q};  // CAP_IN_TORQUE
                15'h703c: rd_capture_q <= {16'd0, cap_in_tref_q};  // CAP_IN_TREF
                15'h7040: rd_capture_q <= {22'd0, cap_rd_index_q};  // CAP_RD_INDEX
                15'h7044: rd_capture_q <= {cap_data0_i_q_i, cap_data0_i_d_i};  // CAP_DATA0
                15'h7048: rd_capture_q <= {cap_data1_tref_i, cap_data1_torque_i};  // CAP_DATA1
                15'h704c: rd_capture_q <= {cap_data2_sel_i, 13'd0, cap_data2_sw_i};  // CAP_DATA2
                15'h7050: rd_capture_q <= 32'h00000400;  // CAP_DEPTH
                15'h7054: rd_capture_q <= cap_in_pos_q;  // CAP_IN_POS
                15'h7058: rd_capture_q <= cap_in_vel_q;  // CAP_IN_VEL
                15'h705c: rd_capture_q <= {16'd0, cap_in_ferr_q};  // CAP_IN_FERR
                15'h7060: rd_capture_q <= cap_data3_i;  // CAP_DATA3
                15'h7064: rd_capture_q <= cap_data4_i;  // CAP_DATA4
                15'h7068: rd_capture_q <= {16'd0, cap_data5_i};  // CAP_DATA5
                default: ;
            endcase
        end
    end
    always @(*) begin
        case (rd_page_q)
            3'd0: rd_data_o = rd_top_q;
            3'd1: rd_data_o = rd_mpdtc_q;
            3'd2: rd_data_o = rd_mpdcc_q;
            3'd3: rd_data_o = rd_pwm_q;
            3'd4: rd_data_o = rd_adc_q;
            3'd5: rd_data_o = rd_enc_q;
            3'd6: rd_data_o = rd_fault_q;
            3'd7: rd_data_o = rd_capture_q;
            default: rd_data_o = 32'd0;
        endcase
    end
    always @(*) begin
        case (rd_addr_i)
            15'h0000, 15'h0004, 15'h0008, 15'h000c, 15'h0010, 15'h0014: rd_err_o = 1'b0;
            15'h0018, 15'h0040, 15'h0044, 15'h0048, 15'h1000, 15'h1004: rd_err_o = 1'b0;
            15'h1008, 15'h100c, 15'h1010, 15'h1014, 15'h1018, 15'h101c: rd_err_o = 1'b0;
            15'h1020, 15'h1024, 15'h1028, 15'h102c, 15'h1030, 15'h1034: rd_err_o = 1'b0;
            15'h1040, 15'h1044, 15'h1048, 15'h104c, 15'h1050, 15'h1054: rd_err_o = 1'b0;
            15'h1058, 15'h105c, 15'h1060, 15'h1064, 15'h1068, 15'h106c: rd_err_o = 1'b0;
            15'h1070, 15'h1074, 15'h1078, 15'h107c, 15'h1080, 15'h1084: rd_err_o = 1'b0;
            15'h1090, 15'h10a0, 15'h10a4, 15'h10a8, 15'h10ac, 15'h10b0: rd_err_o = 1'b0;
            15'h10b4, 15'h10b8, 15'h10bc, 15'h10c0, 15'h10c4, 15'h10c8: rd_err_o = 1'b0;
            15'h10cc, 15'h10d0, 15'h10d4, 15'h10d8, 15'h10dc, 15'h10e0: rd_err_o = 1'b0;
            15'h10e4, 15'h10e8, 15'h2000, 15'h2004, 15'h2008, 15'h200c: rd_err_o = 1'b0;
            15'h2010, 15'h2014, 15'h2018, 15'h201c, 15'h2020, 15'h2024: rd_err_o = 1'b0;
            15'h2028, 15'h202c, 15'h2030, 15'h2034, 15'h2038, 15'h203c: rd_err_o = 1'b0;
            15'h2040, 15'h2080, 15'h2084, 15'h2088, 15'h208c, 15'h2090: rd_err_o = 1'b0;
            15'h2094, 15'h2098, 15'h209c, 15'h20a0, 15'h20a4, 15'h20a8: rd_err_o = 1'b0;
            15'h20ac, 15'h20b0, 15'h20b4, 15'h20b8, 15'h20bc, 15'h20c0: rd_err_o = 1'b0;
            15'h20c4, 15'h20c8, 15'h20cc, 15'h20d0, 15'h20d4, 15'h20d8: rd_err_o = 1'b0;
            15'h20dc, 15'h20e0, 15'h20e4, 15'h20e8, 15'h2100, 15'h2104: rd_err_o = 1'b0;
            15'h2108, 15'h210c, 15'h2110, 15'h3000, 15'h3004, 15'h3008: rd_err_o = 1'b0;
            15'h300c, 15'h3010, 15'h3014, 15'h3018, 15'h301c, 15'h3020: rd_err_o = 1'b0;
            15'h4000, 15'h4004, 15'h4008, 15'h400c, 15'h4010, 15'h4014: rd_err_o = 1'b0;
            15'h4018, 15'h5000, 15'h5004, 15'h5008, 15'h500c, 15'h5010: rd_err_o = 1'b0;
            15'h5014, 15'h6000, 15'h6004, 15'h6008, 15'h600c, 15'h7000: rd_err_o = 1'b0;
            15'h7004, 15'h7008, 15'h700c, 15'h7010, 15'h7014, 15'h7018: rd_err_o = 1'b0;
            15'h701c, 15'h7020, 15'h7024, 15'h7028, 15'h7030, 15'h7034: rd_err_o = 1'b0;
            15'h7038, 15'h703c, 15'h7040, 15'h7044, 15'h7048, 15'h704c: rd_err_o = 1'b0;
            15'h7050, 15'h7054, 15'h7058, 15'h705c, 15'h7060, 15'h7064: rd_err_o = 1'b0;
            15'h7068: rd_err_o = 1'b0;
            default: rd_err_o = rd_i;
        endcase
    end

    // Fields to the cores.
    assign ctrl_mode_o = ctrl_q;
    assign heartbeat_we_o = w_heartbeat;
    assign scratch_o = scratch_q;
    assign irq_en_boundary_o = irq_en_q[0];
    assign irq_en_fault_o = irq_en_q[1];
    assign irq_status_boundary_clr_o = w_irq_status ? n_irq_status[0] : 1'd0;
    assign irq_status_fault_clr_o = w_irq_status ? n_irq_status[1] : 1'd0;
    assign irq_status_missed_clr_o = w_irq_status ? n_irq_status[2] : 1'd0;
    assign mpdtc_ctrl_manual_o = mpdtc_ctrl_q[0];
    assign mpdtc_ctrl_state_clr_o = mpdtc_ctrl_q[1];
    assign mpdtc_ctrl_auto_o = mpdtc_ctrl_q[2];
    assign mpdtc_start_we_o = w_mpdtc_start;
    assign mpdtc_in_id_o = mpdtc_in_id_q;
    assign mpdtc_in_iq_o = mpdtc_in_iq_q;
    assign mpdtc_in_cos0_o = mpdtc_in_cos0_q;
    assign mpdtc_in_sin0_o = mpdtc_in_sin0_q;
    assign mpdtc_in_cos1_o = mpdtc_in_cos1_q;
    assign mpdtc_in_sin1_o = mpdtc_in_sin1_q;
    assign mpdtc_in_cos2_o = mpdtc_in_cos2_q;
    assign mpdtc_in_sin2_o = mpdtc_in_sin2_q;
    assign mpdtc_in_w_ts_o = mpdtc_in_w_ts_q;
    assign mpdtc_in_t_ref_o = mpdtc_in_t_ref_q;
    assign mpdtc_p_a_o = mpdtc_p_a_q;
    assign mpdtc_p_lambda_o = mpdtc_p_lambda_q;
    assign mpdtc_p_u0_o = mpdtc_p_u0_q;
    assign mpdtc_p_u0_half_o = mpdtc_p_u0_half_q;
    assign mpdtc_p_u0_h_o = mpdtc_p_u0_h_q;
    assign mpdtc_p_psi_l_o = mpdtc_p_psi_l_q;
    assign mpdtc_p_kinv_t_o = mpdtc_p_kinv_t_q;
    assign mpdtc_p_tol_o = mpdtc_p_tol_q;
    assign mpdtc_p_k_int_o = mpdtc_p_k_int_q;
    assign mpdtc_p_int_lim_o = mpdtc_p_int_lim_q;
    assign mpdtc_p_int_cond_o = mpdtc_p_int_cond_q;
    assign mpdtc_p_kp_o_o = mpdtc_p_kp_o_q;
    assign mpdtc_p_ki_o_o = mpdtc_p_ki_o_q;
    assign mpdtc_p_eta_lim_o = mpdtc_p_eta_lim_q;
    assign mpdtc_p_w2_0_o = mpdtc_p_w2_0_q;
    assign mpdtc_p_w2_1_o = mpdtc_p_w2_1_q;
    assign mpdtc_p_w2_2_o = mpdtc_p_w2_2_q;
    assign mpdtc_p_w2_3_o = mpdtc_p_w2_3_q;
    assign mpdtc_align_vec_o = mpdtc_align_vec_q;
    assign mpdtc_align_period_o = mpdtc_align_period_q;
    assign mpdtc_align_on_o = mpdtc_align_on_q;
    assign mpdtc_align_time_o = mpdtc_align_time_q;
    assign mpdtc_fe_ang_scale_o = mpdtc_fe_ang_scale_q;
    assign mpdtc_fe_spd_scale_o = mpdtc_fe_spd_scale_q;
    assign mpdtc_fe_age0_o = mpdtc_fe_age0_q;
    assign mpdtc_fe_age1_o = mpdtc_fe_age1_q;
    assign mpdtc_fe_age2_o = mpdtc_fe_age2_q;
    assign mpdtc_fe_off_a_o = mpdtc_fe_off_a_q;
    assign mpdtc_fe_off_b_o = mpdtc_fe_off_b_q;
    assign mpdtc_fe_off_c_o = mpdtc_fe_off_c_q;
    assign mpdtc_fe_gain_a_o = mpdtc_fe_gain_a_q;
    assign mpdtc_fe_gain_b_o = mpdtc_fe_gain_b_q;
    assign mpdtc_fe_gain_c_o = mpdtc_fe_gain_c_q;
    assign mpdcc_start_we_o = w_mpdcc_start;
    assign mpdcc_n_use_o = mpdcc_n_use_q;
    assign mpdcc_s_prev_a_o = mpdcc_s_prev_q[2:0];
    assign mpdcc_s_prev_b_o = mpdcc_s_prev_q[5:3];
    assign mpdcc_s_prev_c_o = mpdcc_s_prev_q[8:6];
    assign mpdcc_i_a_o = mpdcc_i_a_q;
    assign mpdcc_i_b_o = mpdcc_i_b_q;
    assign mpdcc_psi_a_o = mpdcc_psi_a_q;
    assign mpdcc_psi_b_o = mpdcc_psi_b_q;
    assign mpdcc_v_n_o = mpdcc_v_n_q;
    assign mpdcc_v_ph_a_o = mpdcc_v_ph_a_q;
    assign mpdcc_v_ph_b_o = mpdcc_v_ph_b_q;
    assign mpdcc_v_ph_c_o = mpdcc_v_ph_c_q;
    assign mpdcc_iref_a_o = mpdcc_iref_a_q;
    assign mpdcc_iref_b_o = mpdcc_iref_b_q;
    assign mpdcc_omega_r_o = mpdcc_omega_r_q;
    assign mpdcc_omega_s_o = mpdcc_omega_s_q;
    assign mpdcc_c_tau_o = mpdcc_c_tau_q;
    assign mpdcc_c_r_o = mpdcc_c_r_q;
    assign mpdcc_c_w_o = mpdcc_c_w_q;
    assign mpdcc_c_p_o = mpdcc_c_p_q;
    assign mpdcc_c_s_o = mpdcc_c_s_q;
    assign mpdcc_c_3_o = mpdcc_c_3_q;
    assign mpdcc_c_d_o = mpdcc_c_d_q;
    assign mpdcc_c_n_o = mpdcc_c_n_q;
    assign mpdcc_c_ph_o = mpdcc_c_ph_q;
    assign mpdcc_s3h_o = mpdcc_s3h_q;
    assign mpdcc_v_ph_ref_o = mpdcc_v_ph_ref_q;
    assign mpdcc_c_tau1_o = mpdcc_c_tau1_q;
    assign mpdcc_c_r1_o = mpdcc_c_r1_q;
    assign mpdcc_c_w1_o = mpdcc_c_w1_q;
    assign mpdcc_c_s1_o = mpdcc_c_s1_q;
    assign mpdcc_vdc_half_o = mpdcc_vdc_half_q;
    assign mpdcc_g3_o = mpdcc_g3_q;
    assign mpdcc_gd_o = mpdcc_gd_q;
    assign mpdcc_g3_1_o = mpdcc_g3_1_q;
    assign mpdcc_bnd_ia_o = mpdcc_bnd_ia_q;
    assign mpdcc_bnd_ib_o = mpdcc_bnd_ib_q;
    assign mpdcc_bnd_ic_o = mpdcc_bnd_ic_q;
    assign mpdcc_bnd_vn_o = mpdcc_bnd_vn_q;
    assign mpdcc_bnd_vpa_o = mpdcc_bnd_vpa_q;
    assign mpdcc_bnd_vpb_o = mpdcc_bnd_vpb_q;
    assign mpdcc_bnd_vpc_o = mpdcc_bnd_vpc_q;
    assign mpdcc_lambda_n_o = mpdcc_lambda_n_q;
    assign gate_ctrl_gate_en_o = gate_ctrl_q;
    assign dead_time_o = dead_time_q;
    assign pwm_period_o = pwm_period_q;
    assign duty_a_o = duty_a_q;
    assign duty_b_o = duty_b_q;
    assign duty_c_o = duty_c_q;
    assign sw_state_o = sw_state_q;
    assign adc_ctrl_enable_o = adc_ctrl_q;
    assign adc_period_o = adc_period_q;
    assign adc_avg_log2_o = adc_avg_log2_q;
    assign enc_cpr_o = enc_cpr_q;
    assign enc_window_o = enc_window_q;
    assign fault_status_overcurrent_clr_o = w_fault_status ? n_fault_status[0] : 1'd0;
    assign fault_status_external_clr_o = w_fault_status ? n_fault_status[1] : 1'd0;
    assign fault_status_watchdog_clr_o = w_fault_status ? n_fault_status[2] : 1'd0;
    assign fault_status_encoder_loss_clr_o = w_fault_status ? n_fault_status[3] : 1'd0;
    assign fault_status_adc_stuck_clr_o = w_fault_status ? n_fault_status[4] : 1'd0;
    assign oc_limit_o = oc_limit_q;
    assign wdg_timeout_o = wdg_timeout_q;
    assign cap_source_o = cap_source_q;
    assign cap_pre_o = cap_pre_q;
    assign cap_decim_o = cap_decim_q;
    assign cap_step_o = cap_step_q;
    assign cap_thr_ch_o = cap_thr_ch_q;
    assign cap_thr_level_o = cap_thr_level_q;
    assign cap_thr_edge_o = cap_thr_edge_q;
    assign cap_sel_o = cap_sel_q;
    assign cap_arm_we_o = w_cap_arm;
    assign cap_trig_we_o = w_cap_trig;
    assign cap_in_id_o = cap_in_id_q;
    assign cap_in_iq_o = cap_in_iq_q;
    assign cap_in_torque_o = cap_in_torque_q;
    assign cap_in_tref_o = cap_in_tref_q;
    assign cap_rd_index_o = cap_rd_index_q;
    assign cap_in_pos_o = cap_in_pos_q;
    assign cap_in_vel_o = cap_in_vel_q;
    assign cap_in_ferr_o = cap_in_ferr_q;

`ifdef FORMAL
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;
    always @(*) begin
        if (!f_past_valid) assume (rst_i);
    end
    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            // CTRL: changed only by a write.
            if ($past(!w_ctrl)) assert (ctrl_q == $past(ctrl_q));
            // CTRL: a rejected value is never stored.
            assert ({30'd0, ctrl_q} <= 32'h00000002);
            // ERR.BAD_VALUE is set by its event.
            if ($past(bad_value)) assert (err_q[0]);
            // ERR.BAD_ADDR is set by its event.
            if ($past(bad_addr)) assert (err_q[1]);
            // Only a write clears ERR bits.
            if ($past(!w_err)) assert ((err_q & $past(err_q)) == $past(err_q));
            // HEARTBEAT: changed only by a write.
            if ($past(!w_heartbeat)) assert (heartbeat_q == $past(heartbeat_q));
            // SCRATCH: changed only by a write.
            if ($past(!w_scratch)) assert (scratch_q == $past(scratch_q));
            // IRQ_EN: changed only by a write.
            if ($past(!w_irq_en)) assert (irq_en_q == $past(irq_en_q));
            // MPDTC_CTRL: changed only by a write.
            if ($past(!w_mpdtc_ctrl)) assert (mpdtc_ctrl_q == $past(mpdtc_ctrl_q));
            // MPDTC_START: changed only by a write.
            if ($past(!w_mpdtc_start)) assert (mpdtc_start_q == $past(mpdtc_start_q));
            // MPDTC_IN_ID: changed only by a write.
            if ($past(!w_mpdtc_in_id)) assert (mpdtc_in_id_q == $past(mpdtc_in_id_q));
            // MPDTC_IN_IQ: changed only by a write.
            if ($past(!w_mpdtc_in_iq)) assert (mpdtc_in_iq_q == $past(mpdtc_in_iq_q));
            // MPDTC_IN_COS0: changed only by a write.
            if ($past(!w_mpdtc_in_cos0)) assert (mpdtc_in_cos0_q == $past(mpdtc_in_cos0_q));
            // MPDTC_IN_SIN0: changed only by a write.
            if ($past(!w_mpdtc_in_sin0)) assert (mpdtc_in_sin0_q == $past(mpdtc_in_sin0_q));
            // MPDTC_IN_COS1: changed only by a write.
            if ($past(!w_mpdtc_in_cos1)) assert (mpdtc_in_cos1_q == $past(mpdtc_in_cos1_q));
            // MPDTC_IN_SIN1: changed only by a write.
            if ($past(!w_mpdtc_in_sin1)) assert (mpdtc_in_sin1_q == $past(mpdtc_in_sin1_q));
            // MPDTC_IN_COS2: changed only by a write.
            if ($past(!w_mpdtc_in_cos2)) assert (mpdtc_in_cos2_q == $past(mpdtc_in_cos2_q));
            // MPDTC_IN_SIN2: changed only by a write.
            if ($past(!w_mpdtc_in_sin2)) assert (mpdtc_in_sin2_q == $past(mpdtc_in_sin2_q));
            // MPDTC_IN_W_TS: changed only by a write.
            if ($past(!w_mpdtc_in_w_ts)) assert (mpdtc_in_w_ts_q == $past(mpdtc_in_w_ts_q));
            // MPDTC_IN_T_REF: changed only by a write.
            if ($past(!w_mpdtc_in_t_ref)) assert (mpdtc_in_t_ref_q == $past(mpdtc_in_t_ref_q));
            // MPDTC_P_A: changed only by a write.
            if ($past(!w_mpdtc_p_a)) assert (mpdtc_p_a_q == $past(mpdtc_p_a_q));
            // MPDTC_P_LAMBDA: changed only by a write.
            if ($past(!w_mpdtc_p_lambda)) assert (mpdtc_p_lambda_q == $past(mpdtc_p_lambda_q));
            // MPDTC_P_U0: changed only by a write.
            if ($past(!w_mpdtc_p_u0)) assert (mpdtc_p_u0_q == $past(mpdtc_p_u0_q));
            // MPDTC_P_U0_HALF: changed only by a write.
            if ($past(!w_mpdtc_p_u0_half)) assert (mpdtc_p_u0_half_q == $past(mpdtc_p_u0_half_q));
            // MPDTC_P_U0_H: changed only by a write.
            if ($past(!w_mpdtc_p_u0_h)) assert (mpdtc_p_u0_h_q == $past(mpdtc_p_u0_h_q));
            // MPDTC_P_PSI_L: changed only by a write.
            if ($past(!w_mpdtc_p_psi_l)) assert (mpdtc_p_psi_l_q == $past(mpdtc_p_psi_l_q));
            // MPDTC_P_KINV_T: changed only by a write.
            if ($past(!w_mpdtc_p_kinv_t)) assert (mpdtc_p_kinv_t_q == $past(mpdtc_p_kinv_t_q));
            // MPDTC_P_TOL: changed only by a write.
            if ($past(!w_mpdtc_p_tol)) assert (mpdtc_p_tol_q == $past(mpdtc_p_tol_q));
            // MPDTC_P_K_INT: changed only by a write.
            if ($past(!w_mpdtc_p_k_int)) assert (mpdtc_p_k_int_q == $past(mpdtc_p_k_int_q));
            // MPDTC_P_INT_LIM: changed only by a write.
            if ($past(!w_mpdtc_p_int_lim)) assert (mpdtc_p_int_lim_q == $past(mpdtc_p_int_lim_q));
            // MPDTC_P_INT_COND: changed only by a write.
            if ($past(!w_mpdtc_p_int_cond)) assert (mpdtc_p_int_cond_q == $past(mpdtc_p_int_cond_q));
            // MPDTC_P_KP_O: changed only by a write.
            if ($past(!w_mpdtc_p_kp_o)) assert (mpdtc_p_kp_o_q == $past(mpdtc_p_kp_o_q));
            // MPDTC_P_KI_O: changed only by a write.
            if ($past(!w_mpdtc_p_ki_o)) assert (mpdtc_p_ki_o_q == $past(mpdtc_p_ki_o_q));
            // MPDTC_P_ETA_LIM: changed only by a write.
            if ($past(!w_mpdtc_p_eta_lim)) assert (mpdtc_p_eta_lim_q == $past(mpdtc_p_eta_lim_q));
            // MPDTC_P_W2_0: changed only by a write.
            if ($past(!w_mpdtc_p_w2_0)) assert (mpdtc_p_w2_0_q == $past(mpdtc_p_w2_0_q));
            // MPDTC_P_W2_1: changed only by a write.
            if ($past(!w_mpdtc_p_w2_1)) assert (mpdtc_p_w2_1_q == $past(mpdtc_p_w2_1_q));
            // MPDTC_P_W2_2: changed only by a write.
            if ($past(!w_mpdtc_p_w2_2)) assert (mpdtc_p_w2_2_q == $past(mpdtc_p_w2_2_q));
            // MPDTC_P_W2_3: changed only by a write.
            if ($past(!w_mpdtc_p_w2_3)) assert (mpdtc_p_w2_3_q == $past(mpdtc_p_w2_3_q));
            // MPDTC_ALIGN_VEC: changed only by a write.
            if ($past(!w_mpdtc_align_vec)) assert (mpdtc_align_vec_q == $past(mpdtc_align_vec_q));
            // MPDTC_ALIGN_PERIOD: changed only by a write.
            if ($past(!w_mpdtc_align_period)) assert (mpdtc_align_period_q == $past(mpdtc_align_period_q));
            // MPDTC_ALIGN_PERIOD: always inside its clamp range.
            assert ({16'd0, mpdtc_align_period_q} >= 32'h00000002);
            // MPDTC_ALIGN_ON: changed only by a write.
            if ($past(!w_mpdtc_align_on)) assert (mpdtc_align_on_q == $past(mpdtc_align_on_q));
            // MPDTC_ALIGN_ON: always inside its clamp range.
            assert ({16'd0, mpdtc_align_on_q} <= 32'h00007fff);
            // MPDTC_ALIGN_TIME: changed only by a write.
            if ($past(!w_mpdtc_align_time)) assert (mpdtc_align_time_q == $past(mpdtc_align_time_q));
            // MPDTC_ALIGN_TIME: always inside its clamp range.
            assert (mpdtc_align_time_q >= 32'h00000001);
            // MPDTC_FE_ANG_SCALE: changed only by a write.
            if ($past(!w_mpdtc_fe_ang_scale)) assert (mpdtc_fe_ang_scale_q == $past(mpdtc_fe_ang_scale_q));
            // MPDTC_FE_SPD_SCALE: changed only by a write.
            if ($past(!w_mpdtc_fe_spd_scale)) assert (mpdtc_fe_spd_scale_q == $past(mpdtc_fe_spd_scale_q));
            // MPDTC_FE_AGE0: changed only by a write.
            if ($past(!w_mpdtc_fe_age0)) assert (mpdtc_fe_age0_q == $past(mpdtc_fe_age0_q));
            // MPDTC_FE_AGE1: changed only by a write.
            if ($past(!w_mpdtc_fe_age1)) assert (mpdtc_fe_age1_q == $past(mpdtc_fe_age1_q));
            // MPDTC_FE_AGE2: changed only by a write.
            if ($past(!w_mpdtc_fe_age2)) assert (mpdtc_fe_age2_q == $past(mpdtc_fe_age2_q));
            // MPDTC_FE_OFF_A: changed only by a write.
            if ($past(!w_mpdtc_fe_off_a)) assert (mpdtc_fe_off_a_q == $past(mpdtc_fe_off_a_q));
            // MPDTC_FE_OFF_B: changed only by a write.
            if ($past(!w_mpdtc_fe_off_b)) assert (mpdtc_fe_off_b_q == $past(mpdtc_fe_off_b_q));
            // MPDTC_FE_OFF_C: changed only by a write.
            if ($past(!w_mpdtc_fe_off_c)) assert (mpdtc_fe_off_c_q == $past(mpdtc_fe_off_c_q));
            // MPDTC_FE_GAIN_A: changed only by a write.
            if ($past(!w_mpdtc_fe_gain_a)) assert (mpdtc_fe_gain_a_q == $past(mpdtc_fe_gain_a_q));
            // MPDTC_FE_GAIN_B: changed only by a write.
            if ($past(!w_mpdtc_fe_gain_b)) assert (mpdtc_fe_gain_b_q == $past(mpdtc_fe_gain_b_q));
            // MPDTC_FE_GAIN_C: changed only by a write.
            if ($past(!w_mpdtc_fe_gain_c)) assert (mpdtc_fe_gain_c_q == $past(mpdtc_fe_gain_c_q));
            // MPDCC_START: changed only by a write.
            if ($past(!w_mpdcc_start)) assert (mpdcc_start_q == $past(mpdcc_start_q));
            // MPDCC_N_USE: changed only by a write.
            if ($past(!w_mpdcc_n_use)) assert (mpdcc_n_use_q == $past(mpdcc_n_use_q));
            // MPDCC_N_USE: always inside its clamp range.
            assert ({29'd0, mpdcc_n_use_q} >= 32'h00000001 && {29'd0, mpdcc_n_use_q} <= 32'h00000006);
            // MPDCC_S_PREV: changed only by a write.
            if ($past(!w_mpdcc_s_prev)) assert (mpdcc_s_prev_q == $past(mpdcc_s_prev_q));
            // MPDCC_I_A: changed only by a write.
            if ($past(!w_mpdcc_i_a)) assert (mpdcc_i_a_q == $past(mpdcc_i_a_q));
            // MPDCC_I_B: changed only by a write.
            if ($past(!w_mpdcc_i_b)) assert (mpdcc_i_b_q == $past(mpdcc_i_b_q));
            // MPDCC_PSI_A: changed only by a write.
            if ($past(!w_mpdcc_psi_a)) assert (mpdcc_psi_a_q == $past(mpdcc_psi_a_q));
            // MPDCC_PSI_B: changed only by a write.
            if ($past(!w_mpdcc_psi_b)) assert (mpdcc_psi_b_q == $past(mpdcc_psi_b_q));
            // MPDCC_V_N: changed only by a write.
            if ($past(!w_mpdcc_v_n)) assert (mpdcc_v_n_q == $past(mpdcc_v_n_q));
            // MPDCC_V_PH_A: changed only by a write.
            if ($past(!w_mpdcc_v_ph_a)) assert (mpdcc_v_ph_a_q == $past(mpdcc_v_ph_a_q));
            // MPDCC_V_PH_B: changed only by a write.
            if ($past(!w_mpdcc_v_ph_b)) assert (mpdcc_v_ph_b_q == $past(mpdcc_v_ph_b_q));
            // MPDCC_V_PH_C: changed only by a write.
            if ($past(!w_mpdcc_v_ph_c)) assert (mpdcc_v_ph_c_q == $past(mpdcc_v_ph_c_q));
            // MPDCC_IREF_A: changed only by a write.
            if ($past(!w_mpdcc_iref_a)) assert (mpdcc_iref_a_q == $past(mpdcc_iref_a_q));
            // MPDCC_IREF_B: changed only by a write.
            if ($past(!w_mpdcc_iref_b)) assert (mpdcc_iref_b_q == $past(mpdcc_iref_b_q));
            // MPDCC_OMEGA_R: changed only by a write.
            if ($past(!w_mpdcc_omega_r)) assert (mpdcc_omega_r_q == $past(mpdcc_omega_r_q));
            // MPDCC_OMEGA_S: changed only by a write.
            if ($past(!w_mpdcc_omega_s)) assert (mpdcc_omega_s_q == $past(mpdcc_omega_s_q));
            // MPDCC_C_TAU: changed only by a write.
            if ($past(!w_mpdcc_c_tau)) assert (mpdcc_c_tau_q == $past(mpdcc_c_tau_q));
            // MPDCC_C_R: changed only by a write.
            if ($past(!w_mpdcc_c_r)) assert (mpdcc_c_r_q == $past(mpdcc_c_r_q));
            // MPDCC_C_W: changed only by a write.
            if ($past(!w_mpdcc_c_w)) assert (mpdcc_c_w_q == $past(mpdcc_c_w_q));
            // MPDCC_C_P: changed only by a write.
            if ($past(!w_mpdcc_c_p)) assert (mpdcc_c_p_q == $past(mpdcc_c_p_q));
            // MPDCC_C_S: changed only by a write.
            if ($past(!w_mpdcc_c_s)) assert (mpdcc_c_s_q == $past(mpdcc_c_s_q));
            // MPDCC_C_3: changed only by a write.
            if ($past(!w_mpdcc_c_3)) assert (mpdcc_c_3_q == $past(mpdcc_c_3_q));
            // MPDCC_C_D: changed only by a write.
            if ($past(!w_mpdcc_c_d)) assert (mpdcc_c_d_q == $past(mpdcc_c_d_q));
            // MPDCC_C_N: changed only by a write.
            if ($past(!w_mpdcc_c_n)) assert (mpdcc_c_n_q == $past(mpdcc_c_n_q));
            // MPDCC_C_PH: changed only by a write.
            if ($past(!w_mpdcc_c_ph)) assert (mpdcc_c_ph_q == $past(mpdcc_c_ph_q));
            // MPDCC_S3H: changed only by a write.
            if ($past(!w_mpdcc_s3h)) assert (mpdcc_s3h_q == $past(mpdcc_s3h_q));
            // MPDCC_V_PH_REF: changed only by a write.
            if ($past(!w_mpdcc_v_ph_ref)) assert (mpdcc_v_ph_ref_q == $past(mpdcc_v_ph_ref_q));
            // MPDCC_C_TAU1: changed only by a write.
            if ($past(!w_mpdcc_c_tau1)) assert (mpdcc_c_tau1_q == $past(mpdcc_c_tau1_q));
            // MPDCC_C_R1: changed only by a write.
            if ($past(!w_mpdcc_c_r1)) assert (mpdcc_c_r1_q == $past(mpdcc_c_r1_q));
            // MPDCC_C_W1: changed only by a write.
            if ($past(!w_mpdcc_c_w1)) assert (mpdcc_c_w1_q == $past(mpdcc_c_w1_q));
            // MPDCC_C_S1: changed only by a write.
            if ($past(!w_mpdcc_c_s1)) assert (mpdcc_c_s1_q == $past(mpdcc_c_s1_q));
            // MPDCC_VDC_HALF: changed only by a write.
            if ($past(!w_mpdcc_vdc_half)) assert (mpdcc_vdc_half_q == $past(mpdcc_vdc_half_q));
            // MPDCC_G3: changed only by a write.
            if ($past(!w_mpdcc_g3)) assert (mpdcc_g3_q == $past(mpdcc_g3_q));
            // MPDCC_GD: changed only by a write.
            if ($past(!w_mpdcc_gd)) assert (mpdcc_gd_q == $past(mpdcc_gd_q));
            // MPDCC_G3_1: changed only by a write.
            if ($past(!w_mpdcc_g3_1)) assert (mpdcc_g3_1_q == $past(mpdcc_g3_1_q));
            // MPDCC_BND_IA: changed only by a write.
            if ($past(!w_mpdcc_bnd_ia)) assert (mpdcc_bnd_ia_q == $past(mpdcc_bnd_ia_q));
            // MPDCC_BND_IA: a rejected value is never stored.
            assert ({16'd0, mpdcc_bnd_ia_q} <= 32'h00007fff);
            // MPDCC_BND_IB: changed only by a write.
            if ($past(!w_mpdcc_bnd_ib)) assert (mpdcc_bnd_ib_q == $past(mpdcc_bnd_ib_q));
            // MPDCC_BND_IB: a rejected value is never stored.
            assert ({16'd0, mpdcc_bnd_ib_q} <= 32'h00007fff);
            // MPDCC_BND_IC: changed only by a write.
            if ($past(!w_mpdcc_bnd_ic)) assert (mpdcc_bnd_ic_q == $past(mpdcc_bnd_ic_q));
            // MPDCC_BND_IC: a rejected value is never stored.
            assert ({16'd0, mpdcc_bnd_ic_q} <= 32'h00007fff);
            // MPDCC_BND_VN: changed only by a write.
            if ($past(!w_mpdcc_bnd_vn)) assert (mpdcc_bnd_vn_q == $past(mpdcc_bnd_vn_q));
            // MPDCC_BND_VN: a rejected value is never stored.
            assert ({16'd0, mpdcc_bnd_vn_q} <= 32'h00007fff);
            // MPDCC_BND_VPA: changed only by a write.
            if ($past(!w_mpdcc_bnd_vpa)) assert (mpdcc_bnd_vpa_q == $past(mpdcc_bnd_vpa_q));
            // MPDCC_BND_VPA: a rejected value is never stored.
            assert ({16'd0, mpdcc_bnd_vpa_q} <= 32'h00007fff);
            // MPDCC_BND_VPB: changed only by a write.
            if ($past(!w_mpdcc_bnd_vpb)) assert (mpdcc_bnd_vpb_q == $past(mpdcc_bnd_vpb_q));
            // MPDCC_BND_VPB: a rejected value is never stored.
            assert ({16'd0, mpdcc_bnd_vpb_q} <= 32'h00007fff);
            // MPDCC_BND_VPC: changed only by a write.
            if ($past(!w_mpdcc_bnd_vpc)) assert (mpdcc_bnd_vpc_q == $past(mpdcc_bnd_vpc_q));
            // MPDCC_BND_VPC: a rejected value is never stored.
            assert ({16'd0, mpdcc_bnd_vpc_q} <= 32'h00007fff);
            // MPDCC_LAMBDA_N: changed only by a write.
            if ($past(!w_mpdcc_lambda_n)) assert (mpdcc_lambda_n_q == $past(mpdcc_lambda_n_q));
            // GATE_CTRL: held at 0 by the hardware, else changed only by a write.
            if ($past(gate_ctrl_hw_clr_i)) assert (gate_ctrl_q == 1'd0);
            if ($past(!gate_ctrl_hw_clr_i && !w_gate_ctrl)) assert (gate_ctrl_q == $past(gate_ctrl_q));
            // DEAD_TIME: changed only by a write.
            if ($past(!w_dead_time)) assert (dead_time_q == $past(dead_time_q));
            // PWM_PERIOD: changed only by a write.
            if ($past(!w_pwm_period)) assert (pwm_period_q == $past(pwm_period_q));
            // PWM_PERIOD: always inside its clamp range.
            assert ({16'd0, pwm_period_q} >= 32'h00000002);
            // DUTY_A: changed only by a write.
            if ($past(!w_duty_a)) assert (duty_a_q == $past(duty_a_q));
            // DUTY_B: changed only by a write.
            if ($past(!w_duty_b)) assert (duty_b_q == $past(duty_b_q));
            // DUTY_C: changed only by a write.
            if ($past(!w_duty_c)) assert (duty_c_q == $past(duty_c_q));
            // SW_STATE: changed only by a write.
            if ($past(!w_sw_state)) assert (sw_state_q == $past(sw_state_q));
            // ADC_CTRL: changed only by a write.
            if ($past(!w_adc_ctrl)) assert (adc_ctrl_q == $past(adc_ctrl_q));
            // ADC_PERIOD: changed only by a write.
            if ($past(!w_adc_period)) assert (adc_period_q == $past(adc_period_q));
            // ADC_PERIOD: always inside its clamp range.
            assert ({16'd0, adc_period_q} >= 32'h00000010);
            // ADC_AVG_LOG2: changed only by a write.
            if ($past(!w_adc_avg_log2)) assert (adc_avg_log2_q == $past(adc_avg_log2_q));
            // ADC_AVG_LOG2: a rejected value is never stored.
            assert ({30'd0, adc_avg_log2_q} <= 32'h00000002);
            // ENC_CPR: changed only by a write.
            if ($past(!w_enc_cpr)) assert (enc_cpr_q == $past(enc_cpr_q));
            // ENC_CPR: always inside its clamp range.
            assert ({16'd0, enc_cpr_q} >= 32'h00000004);
            // ENC_WINDOW: changed only by a write.
            if ($past(!w_enc_window)) assert (enc_window_q == $past(enc_window_q));
            // ENC_WINDOW: always inside its clamp range.
            assert ({8'd0, enc_window_q} >= 32'h00000064);
            // OC_LIMIT: changed only by a write.
            if ($past(!w_oc_limit)) assert (oc_limit_q == $past(oc_limit_q));
            // WDG_TIMEOUT: changed only by a write.
            if ($past(!w_wdg_timeout)) assert (wdg_timeout_q == $past(wdg_timeout_q));
            // WDG_TIMEOUT: always inside its clamp range.
            assert (wdg_timeout_q >= 32'h000003e8);
            // CAP_SOURCE: changed only by a write.
            if ($past(!w_cap_source)) assert (cap_source_q == $past(cap_source_q));
            // CAP_PRE: changed only by a write.
            if ($past(!w_cap_pre)) assert (cap_pre_q == $past(cap_pre_q));
            // CAP_DECIM: changed only by a write.
            if ($past(!w_cap_decim)) assert (cap_decim_q == $past(cap_decim_q));
            // CAP_STEP: changed only by a write.
            if ($past(!w_cap_step)) assert (cap_step_q == $past(cap_step_q));
            // CAP_THR_CH: changed only by a write.
            if ($past(!w_cap_thr_ch)) assert (cap_thr_ch_q == $past(cap_thr_ch_q));
            // CAP_THR_CH: a rejected value is never stored.
            assert ({29'd0, cap_thr_ch_q} <= 32'h00000004);
            // CAP_THR_LEVEL: changed only by a write.
            if ($past(!w_cap_thr_level)) assert (cap_thr_level_q == $past(cap_thr_level_q));
            // CAP_THR_EDGE: changed only by a write.
            if ($past(!w_cap_thr_edge)) assert (cap_thr_edge_q == $past(cap_thr_edge_q));
            // CAP_SEL: changed only by a write.
            if ($past(!w_cap_sel)) assert (cap_sel_q == $past(cap_sel_q));
            // CAP_SEL: a rejected value is never stored.
            assert ({29'd0, cap_sel_q} <= 32'h00000004);
            // CAP_ARM: changed only by a write.
            if ($past(!w_cap_arm)) assert (cap_arm_q == $past(cap_arm_q));
            // CAP_TRIG: changed only by a write.
            if ($past(!w_cap_trig)) assert (cap_trig_q == $past(cap_trig_q));
            // CAP_IN_ID: changed only by a write.
            if ($past(!w_cap_in_id)) assert (cap_in_id_q == $past(cap_in_id_q));
            // CAP_IN_IQ: changed only by a write.
            if ($past(!w_cap_in_iq)) assert (cap_in_iq_q == $past(cap_in_iq_q));
            // CAP_IN_TORQUE: changed only by a write.
            if ($past(!w_cap_in_torque)) assert (cap_in_torque_q == $past(cap_in_torque_q));
            // CAP_IN_TREF: changed only by a write.
            if ($past(!w_cap_in_tref)) assert (cap_in_tref_q == $past(cap_in_tref_q));
            // CAP_RD_INDEX: changed only by a write.
            if ($past(!w_cap_rd_index)) assert (cap_rd_index_q == $past(cap_rd_index_q));
            // CAP_IN_POS: changed only by a write.
            if ($past(!w_cap_in_pos)) assert (cap_in_pos_q == $past(cap_in_pos_q));
            // CAP_IN_VEL: changed only by a write.
            if ($past(!w_cap_in_vel)) assert (cap_in_vel_q == $past(cap_in_vel_q));
            // CAP_IN_FERR: changed only by a write.
            if ($past(!w_cap_in_ferr)) assert (cap_in_ferr_q == $past(cap_in_ferr_q));
        end
    end
`endif
endmodule

`default_nettype wire
