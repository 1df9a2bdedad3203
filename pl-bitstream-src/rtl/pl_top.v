// pl_top: the PL design behind the PS's AXI GP0 port.
//
//   AXI4-Lite slave (15-bit address = 8 pages of 4 KiB at 0x43C0_0000)
//     -> axil_slave -> pl_regs (register map: regmap.vh / docs/register-map.md)
//   adc_frontend  -> raw samples to fault_block, averages to registers
//   encoder_qei   <- sync2(A, B, Z)
//   fault_block   <- raw samples, sync2(external fault), heartbeat, watchdog
//   pwm_center    -> switching state in mode FOC-PWM
//   PWM.SW_STATE  -> switching state in mode MPDTC (stand-in for mpdtc_core)
//   gate_driver   <- selected state, DEAD_TIME, enable = GATE_EN && mode != off,
//                    fault = fault_block trip (all gates off at the next edge)
// Reset: s_axi_aresetn_i (active low, synchronous, from the PS reset block).
// Safety chain: a fault condition present in cycle t (over-current on a raw
// sample, synchronised external fault, watchdog expired) or any latched
// fault turns every gate off at the edge ending cycle t; the fault latches
// and also clears GATE_EN, so gates stay off until software clears
// FAULT_STATUS and sets GATE_EN again. The external pin adds the 2 cycles
// of its synchroniser.
`default_nettype none

module pl_top (
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
    // ADC (modelled parallel interface, see adc_frontend)
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
    output wire        adc_avg_valid_o
);
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

    wire        sel_pwm;
    wire        sel_state;
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
    wire [ 2:0] fault_clr;

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
    wire [ 2:0] fault_status;
    wire [ 2:0] fault_raw;
    wire        trip;
    wire        enc_a;
    wire        enc_b;
    wire        enc_z;
    wire        fault_ext_n;

    // Switching-state source by mode (decoded in pl_regs from CTRL.MODE).
    wire [ 2:0] state_sel = sel_pwm ? pwm_s : sel_state ? sw_state : 3'b000;
    wire drive_en = gate_en && (sel_pwm || sel_state);
    wire fault_any = |fault_status;

    pl_regs #(
        .AW(15)
    ) u_regs (
        .clk_i         (clk_i),
        .rst_i         (rst),
        .wr_i          (wr),
        .wr_addr_i     (wr_addr),
        .wr_data_i     (wr_data),
        .wr_strb_i     (wr_strb),
        .wr_err_o      (wr_err),
        .rd_i          (rd),
        .rd_addr_i     (rd_addr),
        .rd_data_o     (rd_data),
        .rd_err_o      (rd_err),
        .sel_pwm_o     (sel_pwm),
        .sel_state_o   (sel_state),
        .gate_en_o     (gate_en),
        .dead_time_o   (dead_time),
        .pwm_period_o  (pwm_period),
        .duty_a_o      (duty_a),
        .duty_b_o      (duty_b),
        .duty_c_o      (duty_c),
        .sw_state_o    (sw_state),
        .adc_en_o      (adc_en),
        .adc_period_o  (adc_period),
        .enc_cpr_o     (enc_cpr),
        .enc_window_o  (enc_window),
        .oc_limit_o    (oc_limit),
        .wdg_timeout_o (wdg_timeout),
        .heartbeat_o   (heartbeat),
        .fault_clr_o   (fault_clr),
        .gates_active_i(drive_en && !trip),
        .gate_hi_i     (gate_hi_o),
        .gate_lo_i     (gate_lo_o),
        .state_sel_i   (state_sel),
        .pwm_count_i   (pwm_count),
        .pwm_down_i    (pwm_down),
        .adc_ia_i      (avg_a),
        .adc_ib_i      (avg_b),
        .adc_ic_i      (avg_c),
        .adc_count_i   (avg_count),
        .enc_pos_i     (enc_pos),
        .enc_speed_i   (enc_speed),
        .enc_index_i   (enc_index),
        .fault_status_i(fault_status),
        .fault_raw_i   (fault_raw),
        .fault_any_i   (fault_any)
    );

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
        .pos_o      (enc_pos),
        .speed_o    (enc_speed),
        .index_cnt_o(enc_index)
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
        .en_i     (drive_en),
        .fault_i  (trip),
        .s_i      (state_sel),
        .dt_i     (dead_time),
        .gate_hi_o(gate_hi_o),
        .gate_lo_o(gate_lo_o)
    );

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
            if ($past(fault_any && fault_clr == 3'b000)) assert (fault_any);
            // Mode off or GATE_EN = 0 also turns every gate off.
            if ($past(!drive_en)) assert (gate_hi_o == 3'b000 && gate_lo_o == 3'b000);
            // No leg has both gates on.
            assert ((gate_hi_o & gate_lo_o) == 3'b000);
        end
    end
`endif
endmodule

`default_nettype wire
