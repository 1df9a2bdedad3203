// axil_bfm_top: pl_top with its AXI4-Lite port under the plain AXI signal
// names (s_axi_awaddr, ...) a bus-functional model looks for, and the
// other pins tied to a quiet board: no ADC data ready, encoder still,
// external fault input inactive (high). Test bench only (test_axil.py).
`default_nettype none

module axil_bfm_top (
    input  wire        clk,
    input  wire        rst_n,
    input  wire [14:0] s_axi_awaddr,
    input  wire [ 2:0] s_axi_awprot,
    input  wire        s_axi_awvalid,
    output wire        s_axi_awready,
    input  wire [31:0] s_axi_wdata,
    input  wire [ 3:0] s_axi_wstrb,
    input  wire        s_axi_wvalid,
    output wire        s_axi_wready,
    output wire [ 1:0] s_axi_bresp,
    output wire        s_axi_bvalid,
    input  wire        s_axi_bready,
    input  wire [14:0] s_axi_araddr,
    input  wire [ 2:0] s_axi_arprot,
    input  wire        s_axi_arvalid,
    output wire        s_axi_arready,
    output wire [31:0] s_axi_rdata,
    output wire [ 1:0] s_axi_rresp,
    output wire        s_axi_rvalid,
    input  wire        s_axi_rready,
    output wire        gate_en
);
    wire [2:0] gate_hi, gate_lo;
    wire adc_cnv, adc_avg_valid, irq;
    wire unused = ^{s_axi_awprot, s_axi_arprot, gate_hi, gate_lo, adc_cnv, adc_avg_valid, irq};

    pl_top u_top (
        .clk_i          (clk),
        .s_axi_aresetn_i(rst_n),
        .s_axi_awaddr_i (s_axi_awaddr),
        .s_axi_awvalid_i(s_axi_awvalid),
        .s_axi_awready_o(s_axi_awready),
        .s_axi_wdata_i  (s_axi_wdata),
        .s_axi_wstrb_i  (s_axi_wstrb),
        .s_axi_wvalid_i (s_axi_wvalid),
        .s_axi_wready_o (s_axi_wready),
        .s_axi_bresp_o  (s_axi_bresp),
        .s_axi_bvalid_o (s_axi_bvalid),
        .s_axi_bready_i (s_axi_bready),
        .s_axi_araddr_i (s_axi_araddr),
        .s_axi_arvalid_i(s_axi_arvalid),
        .s_axi_arready_o(s_axi_arready),
        .s_axi_rdata_o  (s_axi_rdata),
        .s_axi_rresp_o  (s_axi_rresp),
        .s_axi_rvalid_o (s_axi_rvalid),
        .s_axi_rready_i (s_axi_rready),
        .gate_hi_o      (gate_hi),
        .gate_lo_o      (gate_lo),
        .gate_en_o      (gate_en),
        .adc_cnv_o      (adc_cnv),
        .adc_drdy_i     (1'b0),
        .adc_data_i     (36'd0),
        .enc_a_i        (1'b0),
        .enc_b_i        (1'b0),
        .enc_z_i        (1'b0),
        .fault_ext_ni   (1'b1),
        .adc_avg_valid_o(adc_avg_valid),
        .irq_o          (irq)
    );
endmodule

`default_nettype wire
