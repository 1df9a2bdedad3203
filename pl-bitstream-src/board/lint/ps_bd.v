// ps_bd (lint stand-in): the port list of the block design that
// scripts/vivado/bitstream.tcl builds, so that Verilator can lint
// board_top without Vivado. The names follow Vivado's rule for block-design
// ports (<interface port>_<signal>); scripts/board-check compares this list
// with the ports the Tcl creates. No logic: outputs are tied off.
`default_nettype none

module ps_bd (
    inout  wire [14:0] DDR_addr,
    inout  wire [ 2:0] DDR_ba,
    inout  wire        DDR_cas_n,
    inout  wire        DDR_ck_n,
    inout  wire        DDR_ck_p,
    inout  wire        DDR_cke,
    inout  wire        DDR_cs_n,
    inout  wire [ 3:0] DDR_dm,
    inout  wire [31:0] DDR_dq,
    inout  wire [ 3:0] DDR_dqs_n,
    inout  wire [ 3:0] DDR_dqs_p,
    inout  wire        DDR_odt,
    inout  wire        DDR_ras_n,
    inout  wire        DDR_reset_n,
    inout  wire        DDR_we_n,
    inout  wire        FIXED_IO_ddr_vrn,
    inout  wire        FIXED_IO_ddr_vrp,
    inout  wire [53:0] FIXED_IO_mio,
    inout  wire        FIXED_IO_ps_clk,
    inout  wire        FIXED_IO_ps_porb,
    inout  wire        FIXED_IO_ps_srstb,
    output wire [31:0] M_AXI_PL_araddr,
    output wire [ 2:0] M_AXI_PL_arprot,
    input  wire        M_AXI_PL_arready,
    output wire        M_AXI_PL_arvalid,
    output wire [31:0] M_AXI_PL_awaddr,
    output wire [ 2:0] M_AXI_PL_awprot,
    input  wire        M_AXI_PL_awready,
    output wire        M_AXI_PL_awvalid,
    output wire        M_AXI_PL_bready,
    input  wire [ 1:0] M_AXI_PL_bresp,
    input  wire        M_AXI_PL_bvalid,
    input  wire [31:0] M_AXI_PL_rdata,
    output wire        M_AXI_PL_rready,
    input  wire [ 1:0] M_AXI_PL_rresp,
    input  wire        M_AXI_PL_rvalid,
    output wire [31:0] M_AXI_PL_wdata,
    input  wire        M_AXI_PL_wready,
    output wire [ 3:0] M_AXI_PL_wstrb,
    output wire        M_AXI_PL_wvalid,
    output wire        fclk0,
    output wire        aresetn,
    input  wire        irq_f2p,
    input  wire [31:0] emio_gpio_i
);
    assign M_AXI_PL_araddr  = 32'd0;
    assign M_AXI_PL_arprot  = 3'd0;
    assign M_AXI_PL_arvalid = 1'b0;
    assign M_AXI_PL_awaddr  = 32'd0;
    assign M_AXI_PL_awprot  = 3'd0;
    assign M_AXI_PL_awvalid = 1'b0;
    assign M_AXI_PL_bready  = 1'b0;
    assign M_AXI_PL_rready  = 1'b0;
    assign M_AXI_PL_wdata   = 32'd0;
    assign M_AXI_PL_wstrb   = 4'd0;
    assign M_AXI_PL_wvalid  = 1'b0;
    assign fclk0            = 1'b0;
    assign aresetn          = 1'b0;
endmodule

`default_nettype wire
