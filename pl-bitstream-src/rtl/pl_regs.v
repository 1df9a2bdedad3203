// pl_regs: the PL register file behind axil_slave, decoded from regmap.vh
// (generated from firmware/drive/src/regmap.rs, the one source of truth).
//
// Register-bus side (from axil_slave): wr_i/rd_i are one-cycle strobes;
// wr_err_o/rd_err_o/rd_data_o are combinational. Write rules (as the
// table's Register::apply_write): byte strobes merge into the current value,
// then the 32-bit word is masked to the width (all valid), clamped as a whole
// (RM_*_MIN/MAX) or rejected (CTRL: > RM_CTRL_MAX keeps the old value and
// sets ERR.BAD_VALUE). Unmapped offsets and writes to RO registers give
// SLVERR and set ERR.BAD_ADDR. W1C bits (ERR here, FAULT_STATUS in
// fault_block via fault_clr_o) clear on a written 1.
// GATE_EN is held at 0 while a fault is latched (fault_any_i).
`default_nettype none

module pl_regs #(
    parameter integer AW = 15
) (
    input  wire          clk_i,
    input  wire          rst_i,
    // register bus
    input  wire          wr_i,
    input  wire [AW-1:0] wr_addr_i,
    input  wire [  31:0] wr_data_i,
    input  wire [   3:0] wr_strb_i,
    output reg           wr_err_o,
    input  wire          rd_i,
    input  wire [AW-1:0] rd_addr_i,
    output reg  [  31:0] rd_data_o,
    output reg           rd_err_o,
    // control outputs
    output wire          sel_pwm_o,    // CTRL.MODE = FOC-PWM
    output wire          sel_state_o,  // CTRL.MODE = MPDTC
    output wire          gate_en_o,
    output wire [   9:0] dead_time_o,
    output wire [  15:0] pwm_period_o,
    output wire [  15:0] duty_a_o,
    output wire [  15:0] duty_b_o,
    output wire [  15:0] duty_c_o,
    output wire [   2:0] sw_state_o,
    output wire          adc_en_o,
    output wire [  15:0] adc_period_o,
    output wire [  15:0] enc_cpr_o,
    output wire [  23:0] enc_window_o,
    output wire [  10:0] oc_limit_o,
    output wire [  31:0] wdg_timeout_o,
    output wire          heartbeat_o,
    output wire [   2:0] fault_clr_o,
    // MPDTC block: control, start strobe, inputs and parameters (raw
    // register bits, two's complement where the table says so)
    output wire          mpdtc_manual_o,
    output wire          mpdtc_clr_o,
    output wire          mpdtc_start_o,
    output wire [  24:0] mp_id_o,
    output wire [  24:0] mp_iq_o,
    output wire [  17:0] mp_cos0_o,
    output wire [  17:0] mp_sin0_o,
    output wire [  17:0] mp_cos1_o,
    output wire [  17:0] mp_sin1_o,
    output wire [  17:0] mp_cos2_o,
    output wire [  17:0] mp_sin2_o,
    output wire [  17:0] mp_w_ts_o,
    output wire [  17:0] mp_t_ref_o,
    output wire [  17:0] mp_a_o,
    output wire [  17:0] mp_lambda_o,
    output wire [  24:0] mp_u0_o,
    output wire [  24:0] mp_u0_half_o,
    output wire [  24:0] mp_u0_h_o,
    output wire [  24:0] mp_psi_l_o,
    output wire [  24:0] mp_kinv_t_o,
    output wire [  24:0] mp_tol_o,
    output wire [  17:0] mp_k_int_o,
    output wire [  24:0] mp_int_lim_o,
    output wire          mp_int_cond_o,
    output wire [  17:0] mp_kp_o_o,
    output wire [  17:0] mp_ki_o_o,
    output wire [  24:0] mp_eta_lim_o,
    output wire [  71:0] mp_w2_o,
    // control sequence (mpdtc_seq): alignment settings
    output wire [   2:0] align_vec_o,
    output wire [  15:0] align_period_o,
    output wire [  15:0] align_on_o,
    output wire [  31:0] align_time_o,
    // status inputs
    input  wire          gates_active_i,
    input  wire [   2:0] gate_hi_i,
    input  wire [   2:0] gate_lo_i,
    input  wire [   2:0] state_sel_i,
    input  wire [  15:0] pwm_count_i,
    input  wire          pwm_down_i,
    input  wire [  15:0] adc_ia_i,
    input  wire [  15:0] adc_ib_i,
    input  wire [  15:0] adc_ic_i,
    input  wire [  31:0] adc_count_i,
    input  wire [  15:0] enc_pos_i,
    input  wire [  15:0] enc_speed_i,
    input  wire [  15:0] enc_index_i,
    input  wire [   2:0] fault_status_i,
    input  wire [   2:0] fault_raw_i,
    input  wire          fault_any_i,
    input  wire          mpdtc_busy_i,
    input  wire [   2:0] mpdtc_s_next_i,
    input  wire [  15:0] mpdtc_done_cnt_i,
    input  wire [  24:0] mpdtc_iq_ref_i,
    input  wire [  31:0] seq_status_i,
    input  wire [  15:0] align_pos_i
);
`include "regmap.vh"

    // Byte-strobe merge of a write over the current (zero-extended) value.
    function automatic [31:0] merge(input [31:0] old, input [31:0] data, input [3:0] strb);
        integer i;
        begin
            for (i = 0; i < 4; i = i + 1) begin
                merge[8*i+:8] = strb[i] ? data[8*i+:8] : old[8*i+:8];
            end
        end
    endfunction

    function automatic [31:0] clamp(input [31:0] v, input [31:0] lo, input [31:0] hi);
        begin
            if (v < lo) clamp = lo;
            else if (v > hi) clamp = hi;
            else clamp = v;
        end
    endfunction

    reg [ 1:0] ctrl_q;
    reg [ 1:0] err_q;
    reg [31:0] heartbeat_q;
    reg [31:0] scratch_q;
    reg        gate_en_q;
    reg [ 9:0] dead_time_q;
    reg [15:0] pwm_period_q;
    reg [15:0] duty_a_q;
    reg [15:0] duty_b_q;
    reg [15:0] duty_c_q;
    reg [ 2:0] sw_state_q;
    reg        adc_en_q;
    reg [15:0] adc_period_q;
    reg [15:0] enc_cpr_q;
    reg [23:0] enc_window_q;
    reg [10:0] oc_limit_q;
    reg [31:0] wdg_timeout_q;
    reg [ 1:0] mpdtc_ctrl_q;
    reg [31:0] mpdtc_start_q;
    reg [ 2:0] align_vec_q;
    reg [15:0] align_period_q;
    reg [15:0] align_on_q;
    reg [31:0] align_time_q;
    // Plain RW words 4..33 of the MPDTC page (inputs, parameters).
    reg [31:0] mp_q[4:33];

    // Write decode: one-hot select of the addressed register.
    wire [AW-1:0] wa = wr_addr_i;
    wire w_ctrl = wr_i && wa == RM_CTRL_ADDR;
    wire w_err = wr_i && wa == RM_ERR_ADDR;
    wire w_heartbeat = wr_i && wa == RM_HEARTBEAT_ADDR;
    wire w_scratch = wr_i && wa == RM_SCRATCH_ADDR;
    wire w_gate_ctrl = wr_i && wa == RM_GATE_CTRL_ADDR;
    wire w_dead_time = wr_i && wa == RM_DEAD_TIME_ADDR;
    wire w_pwm_period = wr_i && wa == RM_PWM_PERIOD_ADDR;
    wire w_duty_a = wr_i && wa == RM_DUTY_A_ADDR;
    wire w_duty_b = wr_i && wa == RM_DUTY_B_ADDR;
    wire w_duty_c = wr_i && wa == RM_DUTY_C_ADDR;
    wire w_sw_state = wr_i && wa == RM_SW_STATE_ADDR;
    wire w_adc_ctrl = wr_i && wa == RM_ADC_CTRL_ADDR;
    wire w_adc_period = wr_i && wa == RM_ADC_PERIOD_ADDR;
    wire w_enc_cpr = wr_i && wa == RM_ENC_CPR_ADDR;
    wire w_enc_window = wr_i && wa == RM_ENC_WINDOW_ADDR;
    wire w_fault_status = wr_i && wa == RM_FAULT_STATUS_ADDR;
    wire w_oc_limit = wr_i && wa == RM_OC_LIMIT_ADDR;
    wire w_wdg_timeout = wr_i && wa == RM_WDG_TIMEOUT_ADDR;
    wire w_mpdtc_ctrl = wr_i && wa == RM_MPDTC_CTRL_ADDR;
    wire w_mpdtc_start = wr_i && wa == RM_MPDTC_START_ADDR;
    wire w_align_vec = wr_i && wa == RM_MPDTC_ALIGN_VEC_ADDR;
    wire w_align_period = wr_i && wa == RM_MPDTC_ALIGN_PERIOD_ADDR;
    wire w_align_on = wr_i && wa == RM_MPDTC_ALIGN_ON_ADDR;
    wire w_align_time = wr_i && wa == RM_MPDTC_ALIGN_TIME_ADDR;
    wire [31:0] mp_wmask = rm_mpdtc_plain_mask(wa[11:2]);
    wire w_mp = wr_i && wa[14:12] == RM_BLK_MPDTC && wa[1:0] == 2'b00 && mp_wmask != 32'd0;
    wire [31:0] ra_mask = rm_mpdtc_plain_mask(rd_addr_i[11:2]);
    wire r_mp = rd_addr_i[14:12] == RM_BLK_MPDTC && rd_addr_i[1:0] == 2'b00 && ra_mask != 32'd0;
    // Word index kept inside the storage range (only used when r_mp).
    wire [5:0] r_mp_idx = (rd_addr_i[7:2] >= 6'd4 && rd_addr_i[7:2] <= 6'd33) ? rd_addr_i[7:2] : 6'd4;
    wire w_any_ok = w_ctrl | w_err | w_heartbeat | w_scratch | w_gate_ctrl | w_dead_time
        | w_pwm_period | w_duty_a | w_duty_b | w_duty_c | w_sw_state | w_adc_ctrl
        | w_adc_period | w_enc_cpr | w_enc_window | w_fault_status | w_oc_limit
        | w_wdg_timeout | w_mpdtc_ctrl | w_mpdtc_start | w_mp
        | w_align_vec | w_align_period | w_align_on | w_align_time;

    // Merged write values (zero-extended current value underneath).
    wire [31:0] m_ctrl = merge({30'd0, ctrl_q}, wr_data_i, wr_strb_i);
    wire [31:0] m_err = merge(32'd0, wr_data_i, wr_strb_i);  // W1C: ones written
    wire ctrl_bad = m_ctrl > RM_CTRL_MAX;

    // Next values of the RW registers: byte merge, then mask (by the
    // assignment width) or clamp as the table says.
    wire [31:0] n_heartbeat = merge(heartbeat_q, wr_data_i, wr_strb_i);
    wire [31:0] n_scratch = merge(scratch_q, wr_data_i, wr_strb_i);
    wire [31:0] n_gate_ctrl = merge({31'd0, gate_en_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_dead_time = clamp(merge({22'd0, dead_time_q}, wr_data_i, wr_strb_i),
                                    RM_DEAD_TIME_MIN, RM_DEAD_TIME_MAX);
    wire [31:0] n_pwm_period = clamp(merge({16'd0, pwm_period_q}, wr_data_i, wr_strb_i),
                                     RM_PWM_PERIOD_MIN, RM_PWM_PERIOD_MAX);
    wire [31:0] n_duty_a = merge({16'd0, duty_a_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_duty_b = merge({16'd0, duty_b_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_duty_c = merge({16'd0, duty_c_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_sw_state = merge({29'd0, sw_state_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_adc_ctrl = merge({31'd0, adc_en_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_adc_period = clamp(merge({16'd0, adc_period_q}, wr_data_i, wr_strb_i),
                                     RM_ADC_PERIOD_MIN, RM_ADC_PERIOD_MAX);
    wire [31:0] n_enc_cpr = clamp(merge({16'd0, enc_cpr_q}, wr_data_i, wr_strb_i),
                                  RM_ENC_CPR_MIN, RM_ENC_CPR_MAX);
    wire [31:0] n_enc_window = clamp(merge({8'd0, enc_window_q}, wr_data_i, wr_strb_i),
                                     RM_ENC_WINDOW_MIN, RM_ENC_WINDOW_MAX);
    wire [31:0] n_oc_limit = clamp(merge({21'd0, oc_limit_q}, wr_data_i, wr_strb_i),
                                   RM_OC_LIMIT_MIN, RM_OC_LIMIT_MAX);
    wire [31:0] n_mpdtc_ctrl = merge({30'd0, mpdtc_ctrl_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_align_vec = merge({29'd0, align_vec_q}, wr_data_i, wr_strb_i);
    wire [31:0] n_align_period = clamp(merge({16'd0, align_period_q}, wr_data_i, wr_strb_i),
                                       RM_MPDTC_ALIGN_PERIOD_MIN, RM_MPDTC_ALIGN_PERIOD_MAX);
    wire [31:0] n_align_on = clamp(merge({16'd0, align_on_q}, wr_data_i, wr_strb_i),
                                   RM_MPDTC_ALIGN_ON_MIN, RM_MPDTC_ALIGN_ON_MAX);
    wire [31:0] n_align_time = clamp(merge(align_time_q, wr_data_i, wr_strb_i),
                                     RM_MPDTC_ALIGN_TIME_MIN, RM_MPDTC_ALIGN_TIME_MAX);
    wire [31:0] n_wdg_timeout = clamp(merge(wdg_timeout_q, wr_data_i, wr_strb_i),
                                      RM_WDG_TIMEOUT_MIN, RM_WDG_TIMEOUT_MAX);

    always @(*) begin
        wr_err_o = wr_i && !w_any_ok;
    end

    always @(posedge clk_i) begin
        if (rst_i) begin
            ctrl_q        <= RM_CTRL_RESET[1:0];
            err_q         <= RM_ERR_RESET[1:0];
            heartbeat_q   <= RM_HEARTBEAT_RESET;
            scratch_q     <= RM_SCRATCH_RESET;
            gate_en_q     <= RM_GATE_CTRL_RESET[0];
            dead_time_q   <= RM_DEAD_TIME_RESET[9:0];
            pwm_period_q  <= RM_PWM_PERIOD_RESET[15:0];
            duty_a_q      <= RM_DUTY_A_RESET[15:0];
            duty_b_q      <= RM_DUTY_B_RESET[15:0];
            duty_c_q      <= RM_DUTY_C_RESET[15:0];
            sw_state_q    <= RM_SW_STATE_RESET[2:0];
            adc_en_q      <= RM_ADC_CTRL_RESET[0];
            adc_period_q  <= RM_ADC_PERIOD_RESET[15:0];
            enc_cpr_q     <= RM_ENC_CPR_RESET[15:0];
            enc_window_q  <= RM_ENC_WINDOW_RESET[23:0];
            oc_limit_q    <= RM_OC_LIMIT_RESET[10:0];
            wdg_timeout_q <= RM_WDG_TIMEOUT_RESET;
            mpdtc_ctrl_q  <= RM_MPDTC_CTRL_RESET[1:0];
            mpdtc_start_q <= RM_MPDTC_START_RESET;
            align_vec_q   <= RM_MPDTC_ALIGN_VEC_RESET[2:0];
            align_period_q <= RM_MPDTC_ALIGN_PERIOD_RESET[15:0];
            align_on_q    <= RM_MPDTC_ALIGN_ON_RESET[15:0];
            align_time_q  <= RM_MPDTC_ALIGN_TIME_RESET;
        end else begin
            if (w_ctrl && !ctrl_bad) ctrl_q <= m_ctrl[1:0];
            // ERR: set wins over a simultaneous clear.
            err_q <= (err_q & ~(w_err ? m_err[1:0] : 2'b00))
                | {(wr_i && !w_any_ok) || (rd_i && rd_err_o), w_ctrl && ctrl_bad};
            if (w_heartbeat) heartbeat_q <= n_heartbeat;
            if (w_scratch) scratch_q <= n_scratch;
            if (fault_any_i) gate_en_q <= 1'b0;
            else if (w_gate_ctrl) gate_en_q <= n_gate_ctrl[0];
            if (w_dead_time) dead_time_q <= n_dead_time[9:0];
            if (w_pwm_period) pwm_period_q <= n_pwm_period[15:0];
            if (w_duty_a) duty_a_q <= n_duty_a[15:0];
            if (w_duty_b) duty_b_q <= n_duty_b[15:0];
            if (w_duty_c) duty_c_q <= n_duty_c[15:0];
            if (w_sw_state) sw_state_q <= n_sw_state[2:0];
            if (w_adc_ctrl) adc_en_q <= n_adc_ctrl[0];
            if (w_adc_period) adc_period_q <= n_adc_period[15:0];
            if (w_enc_cpr) enc_cpr_q <= n_enc_cpr[15:0];
            if (w_enc_window) enc_window_q <= n_enc_window[23:0];
            if (w_oc_limit) oc_limit_q <= n_oc_limit[10:0];
            if (w_wdg_timeout) wdg_timeout_q <= n_wdg_timeout;
            if (w_mpdtc_ctrl) mpdtc_ctrl_q <= n_mpdtc_ctrl[1:0];
            if (w_mpdtc_start) mpdtc_start_q <= merge(mpdtc_start_q, wr_data_i, wr_strb_i);
            if (w_align_vec) align_vec_q <= n_align_vec[2:0];
            if (w_align_period) align_period_q <= n_align_period[15:0];
            if (w_align_on) align_on_q <= n_align_on[15:0];
            if (w_align_time) align_time_q <= n_align_time;
        end
    end

    // Plain MPDTC words: reset 0 (table), byte strobes, masked to the width.
    integer wi;
    always @(posedge clk_i) begin
        for (wi = 4; wi <= 33; wi = wi + 1) begin
            if (rst_i) mp_q[wi] <= 32'd0;
            else if (w_mp && wa[7:2] == wi[5:0])
                mp_q[wi] <= merge(mp_q[wi], wr_data_i, wr_strb_i) & mp_wmask;
        end
    end

    // Read mux.
    always @(*) begin
        rd_data_o = 32'd0;
        rd_err_o  = 1'b0;
        case (rd_addr_i)
            RM_ID_ADDR: rd_data_o = RM_ID_RESET;
            RM_VERSION_ADDR: rd_data_o = RM_VERSION_RESET;
            RM_CTRL_ADDR: rd_data_o = {30'd0, ctrl_q};
            RM_STATUS_ADDR: rd_data_o = {28'd0, fault_any_i, gates_active_i, ctrl_q};
            RM_ERR_ADDR: rd_data_o = {30'd0, err_q};
            RM_HEARTBEAT_ADDR: rd_data_o = heartbeat_q;
            RM_SCRATCH_ADDR: rd_data_o = scratch_q;
            RM_GATE_CTRL_ADDR: rd_data_o = {31'd0, gate_en_q};
            RM_DEAD_TIME_ADDR: rd_data_o = {22'd0, dead_time_q};
            RM_PWM_PERIOD_ADDR: rd_data_o = {16'd0, pwm_period_q};
            RM_DUTY_A_ADDR: rd_data_o = {16'd0, duty_a_q};
            RM_DUTY_B_ADDR: rd_data_o = {16'd0, duty_b_q};
            RM_DUTY_C_ADDR: rd_data_o = {16'd0, duty_c_q};
            RM_SW_STATE_ADDR: rd_data_o = {29'd0, sw_state_q};
            RM_GATE_STATUS_ADDR: rd_data_o = {23'd0, state_sel_i, gate_lo_i, gate_hi_i};
            RM_PWM_COUNT_ADDR: rd_data_o = {15'd0, pwm_down_i, pwm_count_i};
            RM_ADC_CTRL_ADDR: rd_data_o = {31'd0, adc_en_q};
            RM_ADC_PERIOD_ADDR: rd_data_o = {16'd0, adc_period_q};
            RM_ADC_IA_ADDR: rd_data_o = {16'd0, adc_ia_i};
            RM_ADC_IB_ADDR: rd_data_o = {16'd0, adc_ib_i};
            RM_ADC_IC_ADDR: rd_data_o = {16'd0, adc_ic_i};
            RM_ADC_COUNT_ADDR: rd_data_o = adc_count_i;
            RM_ENC_CPR_ADDR: rd_data_o = {16'd0, enc_cpr_q};
            RM_ENC_POS_ADDR: rd_data_o = {16'd0, enc_pos_i};
            RM_ENC_SPEED_ADDR: rd_data_o = {16'd0, enc_speed_i};
            RM_ENC_WINDOW_ADDR: rd_data_o = {8'd0, enc_window_q};
            RM_ENC_INDEX_ADDR: rd_data_o = {16'd0, enc_index_i};
            RM_FAULT_STATUS_ADDR: rd_data_o = {29'd0, fault_status_i};
            RM_FAULT_RAW_ADDR: rd_data_o = {29'd0, fault_raw_i};
            RM_OC_LIMIT_ADDR: rd_data_o = {21'd0, oc_limit_q};
            RM_WDG_TIMEOUT_ADDR: rd_data_o = wdg_timeout_q;
            RM_MPDTC_CTRL_ADDR: rd_data_o = {30'd0, mpdtc_ctrl_q};
            RM_MPDTC_START_ADDR: rd_data_o = mpdtc_start_q;
            RM_MPDTC_STATUS_ADDR:
            rd_data_o = {mpdtc_done_cnt_i, 12'd0, mpdtc_s_next_i, mpdtc_busy_i};
            RM_MPDTC_LATENCY_ADDR: rd_data_o = RM_MPDTC_LATENCY_RESET;
            RM_MPDTC_IQ_REF_ADDR: rd_data_o = {7'd0, mpdtc_iq_ref_i};
            RM_MPDTC_SEQ_STATUS_ADDR: rd_data_o = seq_status_i;
            RM_MPDTC_ALIGN_VEC_ADDR: rd_data_o = {29'd0, align_vec_q};
            RM_MPDTC_ALIGN_PERIOD_ADDR: rd_data_o = {16'd0, align_period_q};
            RM_MPDTC_ALIGN_ON_ADDR: rd_data_o = {16'd0, align_on_q};
            RM_MPDTC_ALIGN_TIME_ADDR: rd_data_o = align_time_q;
            RM_MPDTC_ALIGN_POS_ADDR: rd_data_o = {16'd0, align_pos_i};
            default: begin
                if (r_mp) rd_data_o = mp_q[r_mp_idx] & ra_mask;
                else rd_err_o = rd_i;
            end
        endcase
    end

    assign sel_pwm_o     = {30'd0, ctrl_q} == RM_MODE_FOC_PWM;
    assign sel_state_o   = {30'd0, ctrl_q} == RM_MODE_MPDTC;
    assign gate_en_o     = gate_en_q;
    assign dead_time_o   = dead_time_q;
    assign pwm_period_o  = pwm_period_q;
    assign duty_a_o      = duty_a_q;
    assign duty_b_o      = duty_b_q;
    assign duty_c_o      = duty_c_q;
    assign sw_state_o    = sw_state_q;
    assign adc_en_o      = adc_en_q;
    assign adc_period_o  = adc_period_q;
    assign enc_cpr_o     = enc_cpr_q;
    assign enc_window_o  = enc_window_q;
    assign oc_limit_o    = oc_limit_q;
    assign wdg_timeout_o = wdg_timeout_q;
    assign heartbeat_o   = w_heartbeat;
    assign fault_clr_o   = w_fault_status ? m_err[2:0] : 3'b000;
    assign mpdtc_manual_o = mpdtc_ctrl_q[0];
    assign mpdtc_clr_o    = mpdtc_ctrl_q[1];
    assign mpdtc_start_o  = w_mpdtc_start;
    assign mp_id_o       = mp_q[RM_MPDTC_IN_ID_ADDR[7:2]][24:0];
    assign mp_iq_o       = mp_q[RM_MPDTC_IN_IQ_ADDR[7:2]][24:0];
    assign mp_cos0_o     = mp_q[RM_MPDTC_IN_COS0_ADDR[7:2]][17:0];
    assign mp_sin0_o     = mp_q[RM_MPDTC_IN_SIN0_ADDR[7:2]][17:0];
    assign mp_cos1_o     = mp_q[RM_MPDTC_IN_COS1_ADDR[7:2]][17:0];
    assign mp_sin1_o     = mp_q[RM_MPDTC_IN_SIN1_ADDR[7:2]][17:0];
    assign mp_cos2_o     = mp_q[RM_MPDTC_IN_COS2_ADDR[7:2]][17:0];
    assign mp_sin2_o     = mp_q[RM_MPDTC_IN_SIN2_ADDR[7:2]][17:0];
    assign mp_w_ts_o     = mp_q[RM_MPDTC_IN_W_TS_ADDR[7:2]][17:0];
    assign mp_t_ref_o    = mp_q[RM_MPDTC_IN_T_REF_ADDR[7:2]][17:0];
    assign mp_a_o        = mp_q[RM_MPDTC_P_A_ADDR[7:2]][17:0];
    assign mp_lambda_o   = mp_q[RM_MPDTC_P_LAMBDA_ADDR[7:2]][17:0];
    assign mp_u0_o       = mp_q[RM_MPDTC_P_U0_ADDR[7:2]][24:0];
    assign mp_u0_half_o  = mp_q[RM_MPDTC_P_U0_HALF_ADDR[7:2]][24:0];
    assign mp_u0_h_o     = mp_q[RM_MPDTC_P_U0_H_ADDR[7:2]][24:0];
    assign mp_psi_l_o    = mp_q[RM_MPDTC_P_PSI_L_ADDR[7:2]][24:0];
    assign mp_kinv_t_o   = mp_q[RM_MPDTC_P_KINV_T_ADDR[7:2]][24:0];
    assign mp_tol_o      = mp_q[RM_MPDTC_P_TOL_ADDR[7:2]][24:0];
    assign mp_k_int_o    = mp_q[RM_MPDTC_P_K_INT_ADDR[7:2]][17:0];
    assign mp_int_lim_o  = mp_q[RM_MPDTC_P_INT_LIM_ADDR[7:2]][24:0];
    assign mp_int_cond_o = mp_q[RM_MPDTC_P_INT_COND_ADDR[7:2]][0];
    assign mp_kp_o_o     = mp_q[RM_MPDTC_P_KP_O_ADDR[7:2]][17:0];
    assign mp_ki_o_o     = mp_q[RM_MPDTC_P_KI_O_ADDR[7:2]][17:0];
    assign mp_eta_lim_o  = mp_q[RM_MPDTC_P_ETA_LIM_ADDR[7:2]][24:0];
    assign align_vec_o    = align_vec_q;
    assign align_period_o = align_period_q;
    assign align_on_o     = align_on_q;
    assign align_time_o   = align_time_q;
    assign mp_w2_o = {
        mp_q[RM_MPDTC_P_W2_3_ADDR[7:2]][17:0],
        mp_q[RM_MPDTC_P_W2_2_ADDR[7:2]][17:0],
        mp_q[RM_MPDTC_P_W2_1_ADDR[7:2]][17:0],
        mp_q[RM_MPDTC_P_W2_0_ADDR[7:2]][17:0]
    };
endmodule

`default_nettype wire
