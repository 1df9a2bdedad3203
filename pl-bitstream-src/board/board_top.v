// board_top: the top level of the bitstream (every xc7z020 board).
//
//   ps_bd    the block design of scripts/vivado/bitstream.tcl: PS7 (DDR,
//            UART0/1, FCLK0 = 100 MHz), GP0 master -> AXI protocol converter
//            (AXI3 -> AXI4-Lite) -> M_AXI_PL, assigned 0x43C0_0000 (32 KiB),
//            a proc_sys_reset giving aresetn (synchronous to fclk0), IRQ_F2P[0]
//   pl_top   the drive's PL (register map, gates, ADC, encoder, fault)
//   LEDs     led_o[0] blinks at 1 Hz (0.5 s on, 0.5 s off) while FCLK0 runs (needs no reset: it
//            shows the bitstream is loaded and clocked); led_o[1] the PL is
//            out of reset; led_o[2] some gate was on within the last 2^23
//            cycles (84 ms), so short PWM pulses stay visible; led_o[3] the
//            external fault input is asserted (low)
//   IRQ      pl_top's control interrupt irq_o (a level, high until the
//            firmware clears IRQ_STATUS) to IRQ_F2P[0] (GIC ID 61, level
//            high): the PL paces the control step
//   EMIO     the constant signature RM_ID_RESET ("PSDR", the register map's
//            ID) on the PS7's 32 EMIO GPIO inputs (GPIO 54..85, the GPIO
//            controller's bank 2): the firmware reads it in DATA_RO_2, a PS
//            register, and touches GP0 only when it is ours, so a foreign
//            design in the PL never sees a GP0 access (a constant needs no
//            clock or reset: readable as soon as the PL is configured)
// Ports other than ddr_*/fixed_io_* (placed by the PS7 itself) are the
// board's PL pins: boards/<board>.toml constrains each bit exactly once
// (checked by scripts/board-check against this port list).
`default_nettype none

module board_top (
    // PS DDR3 and fixed MIO (PS-dedicated pins)
    inout  wire [14:0] ddr_addr_io,
    inout  wire [ 2:0] ddr_ba_io,
    inout  wire        ddr_cas_n_io,
    inout  wire        ddr_ck_n_io,
    inout  wire        ddr_ck_p_io,
    inout  wire        ddr_cke_io,
    inout  wire        ddr_cs_n_io,
    inout  wire [ 3:0] ddr_dm_io,
    inout  wire [31:0] ddr_dq_io,
    inout  wire [ 3:0] ddr_dqs_n_io,
    inout  wire [ 3:0] ddr_dqs_p_io,
    inout  wire        ddr_odt_io,
    inout  wire        ddr_ras_n_io,
    inout  wire        ddr_reset_n_io,
    inout  wire        ddr_we_n_io,
    inout  wire        fixed_io_ddr_vrn_io,
    inout  wire        fixed_io_ddr_vrp_io,
    inout  wire [53:0] fixed_io_mio_io,
    inout  wire        fixed_io_ps_clk_io,
    inout  wire        fixed_io_ps_porb_io,
    inout  wire        fixed_io_ps_srstb_io,
    // inverter gates, bit 2 = leg a, 1 = switch on; gate-driver enable
    // (1 = drivers may switch: GATE_EN set and no trip)
    output wire [ 2:0] gate_hi_o,
    output wire [ 2:0] gate_lo_o,
    output wire        gate_en_o,
    // ADC (asynchronous converter interface of adc_frontend)
    output wire        adc_cnv_o,
    input  wire        adc_drdy_i,
    input  wire [35:0] adc_data_i,
    // encoder and external fault (asynchronous)
    input  wire        enc_a_i,
    input  wire        enc_b_i,
    input  wire        enc_z_i,
    input  wire        fault_ext_ni,
    // status LEDs
    output wire [ 3:0] led_o
);
    wire        clk;
    wire        aresetn;
    wire        irq;
    wire [31:0] awaddr, araddr;
    wire [ 2:0] awprot, arprot;
    wire        awvalid, awready, wvalid, wready, bvalid, bready;
    wire        arvalid, arready, rvalid, rready;
    wire [31:0] wdata, rdata;
    wire [ 3:0] wstrb;
    wire [ 1:0] bresp, rresp;

    // RM_ID_RESET: the same word as the ID register, one source of truth
    // (firmware/regmap, generated into regmap.vh).
    `include "regmap.vh"
    localparam [31:0] EMIO_SIGNATURE = RM_ID_RESET;

    ps_bd u_ps (
        .DDR_addr         (ddr_addr_io),
        .DDR_ba           (ddr_ba_io),
        .DDR_cas_n        (ddr_cas_n_io),
        .DDR_ck_n         (ddr_ck_n_io),
        .DDR_ck_p         (ddr_ck_p_io),
        .DDR_cke          (ddr_cke_io),
        .DDR_cs_n         (ddr_cs_n_io),
        .DDR_dm           (ddr_dm_io),
        .DDR_dq           (ddr_dq_io),
        .DDR_dqs_n        (ddr_dqs_n_io),
        .DDR_dqs_p        (ddr_dqs_p_io),
        .DDR_odt          (ddr_odt_io),
        .DDR_ras_n        (ddr_ras_n_io),
        .DDR_reset_n      (ddr_reset_n_io),
        .DDR_we_n         (ddr_we_n_io),
        .FIXED_IO_ddr_vrn (fixed_io_ddr_vrn_io),
        .FIXED_IO_ddr_vrp (fixed_io_ddr_vrp_io),
        .FIXED_IO_mio     (fixed_io_mio_io),
        .FIXED_IO_ps_clk  (fixed_io_ps_clk_io),
        .FIXED_IO_ps_porb (fixed_io_ps_porb_io),
        .FIXED_IO_ps_srstb(fixed_io_ps_srstb_io),
        .M_AXI_PL_araddr  (araddr),
        .M_AXI_PL_arprot  (arprot),
        .M_AXI_PL_arready (arready),
        .M_AXI_PL_arvalid (arvalid),
        .M_AXI_PL_awaddr  (awaddr),
        .M_AXI_PL_awprot  (awprot),
        .M_AXI_PL_awready (awready),
        .M_AXI_PL_awvalid (awvalid),
        .M_AXI_PL_bready  (bready),
        .M_AXI_PL_bresp   (bresp),
        .M_AXI_PL_bvalid  (bvalid),
        .M_AXI_PL_rdata   (rdata),
        .M_AXI_PL_rready  (rready),
        .M_AXI_PL_rresp   (rresp),
        .M_AXI_PL_rvalid  (rvalid),
        .M_AXI_PL_wdata   (wdata),
        .M_AXI_PL_wready  (wready),
        .M_AXI_PL_wstrb   (wstrb),
        .M_AXI_PL_wvalid  (wvalid),
        .fclk0            (clk),
        .aresetn          (aresetn),
        .irq_f2p          (irq),
        .emio_gpio_i      (EMIO_SIGNATURE)
    );

    // pl_top sees the low 15 address bits. With a single slave the protocol
    // converter does not decode: every GP0 address (0x4000_0000 ..
    // 0x7FFF_FFFF) reaches pl_top and aliases onto its 32 KiB map
    // (the assigned 32 KiB at 0x43C0_0000 is the one the firmware uses).
    pl_top u_pl (
        .clk_i          (clk),
        .s_axi_aresetn_i(aresetn),
        .s_axi_awaddr_i (awaddr[14:0]),
        .s_axi_awvalid_i(awvalid),
        .s_axi_awready_o(awready),
        .s_axi_wdata_i  (wdata),
        .s_axi_wstrb_i  (wstrb),
        .s_axi_wvalid_i (wvalid),
        .s_axi_wready_o (wready),
        .s_axi_bresp_o  (bresp),
        .s_axi_bvalid_o (bvalid),
        .s_axi_bready_i (bready),
        .s_axi_araddr_i (araddr[14:0]),
        .s_axi_arvalid_i(arvalid),
        .s_axi_arready_o(arready),
        .s_axi_rdata_o  (rdata),
        .s_axi_rresp_o  (rresp),
        .s_axi_rvalid_o (rvalid),
        .s_axi_rready_i (rready),
        .gate_hi_o      (gate_hi_o),
        .gate_lo_o      (gate_lo_o),
        .gate_en_o      (gate_en_o),
        .adc_cnv_o      (adc_cnv_o),
        .adc_drdy_i     (adc_drdy_i),
        .adc_data_i     (adc_data_i),
        .enc_a_i        (enc_a_i),
        .enc_b_i        (enc_b_i),
        .enc_z_i        (enc_z_i),
        .fault_ext_ni   (fault_ext_ni),
        .adc_avg_valid_o(),
        .irq_o          (irq)
    );

    wire rst = !aresetn;

    // 1 Hz blink: toggles every 25,000,000 cycles (0.5 s) of the 100 MHz
    // FCLK0, one period per second.
    reg [24:0] blink_cnt_q;
    reg        blink_q;
    always @(posedge clk) begin
        if (blink_cnt_q == 25'd24_999_999) begin
            blink_cnt_q <= 25'd0;
            blink_q     <= !blink_q;
        end else begin
            blink_cnt_q <= blink_cnt_q + 25'd1;
        end
    end

    reg [22:0] gate_seen_q;
    reg        run_q;
    always @(posedge clk) begin
        if (rst) begin
            gate_seen_q <= 23'd0;
            run_q       <= 1'b0;
        end else begin
            run_q <= 1'b1;
            if (|{gate_hi_o, gate_lo_o}) gate_seen_q <= {23{1'b1}};
            else if (gate_seen_q != 23'd0) gate_seen_q <= gate_seen_q - 23'd1;
        end
    end

    wire fault_pin_n;
    sync2 #(
        .RESET_VAL(1'b1)
    ) u_fault_led (
        .clk_i(clk),
        .rst_i(rst),
        .d_i  (fault_ext_ni),
        .q_o  (fault_pin_n)
    );

    assign led_o = {!fault_pin_n, gate_seen_q != 23'd0, run_q, blink_q};
endmodule

`default_nettype wire
