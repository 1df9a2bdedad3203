// axil_slave: AXI4-Lite slave protocol engine -> simple register bus.
//
// Write: AW and W are accepted independently (each has a one-entry holding
// register, so they may arrive in the same cycle, in either order, or back
// to back). A write is taken as soon as both an address and data are
// available, no write is in flight and the B channel is free (no response
// pending, or it is being accepted this cycle); it is issued on the
// register bus (wr_o, one cycle) from registers the next cycle; the
// register file decodes it in a registered stage and answers wr_err_i the
// cycle after wr_o, which is presented on B (OKAY, or SLVERR) the cycle
// after that. The register stages keep the AXI handshake logic and the
// address decode each within one clock at 100 MHz (docs/rtl.md). With
// BREADY held high this sustains one write per three clocks.
// Read: AR is accepted when no read is in the register file and no read
// response is pending or it is being accepted; the register bus read (rd_o)
// is issued in the same cycle with its error (rd_err_i, combinational); the
// register file answers the data (rd_data_i) the next cycle (its read mux is
// pipelined), registered onto R with the error: RVALID two cycles after the
// AR handshake, one read per two clocks with RREADY high. Reads have no side
// effects in this design.
// AWPROT/ARPROT are not used (no ports). Reset is synchronous, active high.
`default_nettype none

module axil_slave #(
    parameter integer AW = 15
) (
    input  wire          clk_i,
    input  wire          rst_i,
    // AXI4-Lite slave
    input  wire [AW-1:0] s_awaddr_i,
    input  wire          s_awvalid_i,
    output wire          s_awready_o,
    input  wire [  31:0] s_wdata_i,
    input  wire [   3:0] s_wstrb_i,
    input  wire          s_wvalid_i,
    output wire          s_wready_o,
    output wire [   1:0] s_bresp_o,
    output wire          s_bvalid_o,
    input  wire          s_bready_i,
    input  wire [AW-1:0] s_araddr_i,
    input  wire          s_arvalid_i,
    output wire          s_arready_o,
    output wire [  31:0] s_rdata_o,
    output wire [   1:0] s_rresp_o,
    output wire          s_rvalid_o,
    input  wire          s_rready_i,
    // register bus
    output wire          wr_o,
    output wire [AW-1:0] wr_addr_o,
    output wire [  31:0] wr_data_o,
    output wire [   3:0] wr_strb_o,
    input  wire          wr_err_i,
    output wire          rd_o,
    output wire [AW-1:0] rd_addr_o,
    input  wire [  31:0] rd_data_i,
    input  wire          rd_err_i
);
    localparam [1:0] RESP_OKAY = 2'b00;
    localparam [1:0] RESP_SLVERR = 2'b10;

    reg          aw_held_q;
    reg [AW-1:0] awaddr_q;
    reg          w_held_q;
    reg [  31:0] wdata_q;
    reg [   3:0] wstrb_q;
    reg          bvalid_q;
    reg [   1:0] bresp_q;
    reg          rvalid_q;
    reg [  31:0] rdata_q;
    reg [   1:0] rresp_q;
    reg          wr_q;
    reg          wr_ack_q;
    reg [AW-1:0] wr_addr_q;
    reg [  31:0] wr_data_q;
    reg [   3:0] wr_strb_q;
    reg          rd_pend_q;
    reg          rd_err_q;

    wire aw_avail = aw_held_q || s_awvalid_i;
    wire w_avail = w_held_q || s_wvalid_i;
    wire b_free = !wr_q && !wr_ack_q && (!bvalid_q || s_bready_i);
    // a write taken this cycle (on the register bus the next)
    wire wr = !rst_i && aw_avail && w_avail && b_free;
    wire aw_hs = s_awvalid_i && !aw_held_q;
    wire w_hs = s_wvalid_i && !w_held_q;
    wire rd = !rst_i && s_arvalid_i && !rd_pend_q && (!rvalid_q || s_rready_i);

    always @(posedge clk_i) begin
        if (rst_i) begin
            aw_held_q <= 1'b0;
            w_held_q  <= 1'b0;
            bvalid_q  <= 1'b0;
            bresp_q   <= RESP_OKAY;
            rvalid_q  <= 1'b0;
            rresp_q   <= RESP_OKAY;
            wr_q      <= 1'b0;
            wr_ack_q  <= 1'b0;
            rd_pend_q <= 1'b0;
            rd_err_q  <= 1'b0;
        end else begin
            if (wr) aw_held_q <= 1'b0;
            else if (aw_hs) aw_held_q <= 1'b1;
            if (wr) w_held_q <= 1'b0;
            else if (w_hs) w_held_q <= 1'b1;
            wr_q <= wr;
            wr_ack_q <= wr_q;
            if (wr_ack_q) begin
                bvalid_q <= 1'b1;
                bresp_q  <= wr_err_i ? RESP_SLVERR : RESP_OKAY;
            end else if (s_bready_i) begin
                bvalid_q <= 1'b0;
            end
            rd_pend_q <= rd;
            if (rd) rd_err_q <= rd_err_i;
            if (rd_pend_q) begin
                rvalid_q <= 1'b1;
                rresp_q  <= rd_err_q ? RESP_SLVERR : RESP_OKAY;
            end else if (s_rready_i) begin
                rvalid_q <= 1'b0;
            end
        end
    end

    // Payload registers: no reset (datapath).
    always @(posedge clk_i) begin
        if (aw_hs && !wr) awaddr_q <= s_awaddr_i;
        if (w_hs && !wr) begin
            wdata_q <= s_wdata_i;
            wstrb_q <= s_wstrb_i;
        end
        if (wr) begin
            wr_addr_q <= aw_held_q ? awaddr_q : s_awaddr_i;
            wr_data_q <= w_held_q ? wdata_q : s_wdata_i;
            wr_strb_q <= w_held_q ? wstrb_q : s_wstrb_i;
        end
        if (rd_pend_q) rdata_q <= rd_data_i;
    end

    assign s_awready_o = !aw_held_q;
    assign s_wready_o  = !w_held_q;
    assign s_bvalid_o  = bvalid_q;
    assign s_bresp_o   = bresp_q;
    assign s_arready_o = !rd_pend_q && (!rvalid_q || s_rready_i);
    assign s_rvalid_o  = rvalid_q;
    assign s_rdata_o   = rdata_q;
    assign s_rresp_o   = rresp_q;

    assign wr_o        = wr_q;
    assign wr_addr_o   = wr_addr_q;
    assign wr_data_o   = wr_data_q;
    assign wr_strb_o   = wr_strb_q;
    assign rd_o        = rd;
    assign rd_addr_o   = s_araddr_i;

`ifdef FORMAL
    // AXI4-Lite handshake properties (slave side), assuming a legal master.
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;

    // Transactions accepted and not yet answered.
    reg [1:0] f_aw_out_q = 2'd0;
    reg [1:0] f_w_out_q = 2'd0;
    reg [1:0] f_ar_out_q = 2'd0;
    wire f_aw_hs = s_awvalid_i && s_awready_o;
    wire f_w_hs = s_wvalid_i && s_wready_o;
    wire f_b_hs = s_bvalid_o && s_bready_i;
    wire f_ar_hs = s_arvalid_i && s_arready_o;
    wire f_r_hs = s_rvalid_o && s_rready_i;
    always @(posedge clk_i) begin
        if (rst_i) begin
            f_aw_out_q <= 2'd0;
            f_w_out_q  <= 2'd0;
            f_ar_out_q <= 2'd0;
        end else begin
            f_aw_out_q <= f_aw_out_q + {1'b0, f_aw_hs} - {1'b0, f_b_hs};
            f_w_out_q  <= f_w_out_q + {1'b0, f_w_hs} - {1'b0, f_b_hs};
            f_ar_out_q <= f_ar_out_q + {1'b0, f_ar_hs} - {1'b0, f_r_hs};
        end
    end

    always @(*) begin
        // Start from reset; the master keeps VALIDs low during reset.
        if (!f_past_valid) assume (rst_i);
        if (rst_i) assume (!s_awvalid_i && !s_wvalid_i && !s_arvalid_i);
        // Every B answers one AW and one W; every R answers one AR; at
        // most one address and one data are held while a B waits.
        // (a write on the register bus counts until its B is taken).
        assert (f_aw_out_q == {1'b0, aw_held_q} + {1'b0, wr_q} + {1'b0, wr_ack_q} + {1'b0, bvalid_q});
        assert (f_w_out_q == {1'b0, w_held_q} + {1'b0, wr_q} + {1'b0, wr_ack_q} + {1'b0, bvalid_q});
        assert (f_ar_out_q == {1'b0, rd_pend_q} + {1'b0, rvalid_q});
        // At most one write and one read in flight.
        assert (!(wr_q && bvalid_q) && !(wr_ack_q && bvalid_q) && !(wr_q && wr_ack_q));
        assert (!(rd_pend_q && rvalid_q));
        // A write is taken with exactly one address and one data.
        if (wr) assert (aw_avail && w_avail && b_free);
    end

    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            // Master: a VALID stays up with a stable payload until READY.
            if ($past(s_awvalid_i && !s_awready_o)) begin
                assume (s_awvalid_i);
                assume (s_awaddr_i == $past(s_awaddr_i));
            end
            if ($past(s_wvalid_i && !s_wready_o)) begin
                assume (s_wvalid_i);
                assume (s_wdata_i == $past(s_wdata_i));
                assume (s_wstrb_i == $past(s_wstrb_i));
            end
            if ($past(s_arvalid_i && !s_arready_o)) begin
                assume (s_arvalid_i);
                assume (s_araddr_i == $past(s_araddr_i));
            end
        end
        if (f_past_valid) begin
            // Slave: no response out of reset.
            if ($past(rst_i)) assert (!s_bvalid_o && !s_rvalid_o);
            // Slave: a response stays up and stable until it is taken.
            if (!$past(rst_i) && $past(s_bvalid_o && !s_bready_i)) begin
                assert (s_bvalid_o);
                assert (s_bresp_o == $past(s_bresp_o));
            end
            if (!$past(rst_i) && $past(s_rvalid_o && !s_rready_i)) begin
                assert (s_rvalid_o);
                assert (s_rdata_o == $past(s_rdata_o));
                assert (s_rresp_o == $past(s_rresp_o));
            end
            // The held address/data are the ones handshaken.
            if (!$past(rst_i) && $past(f_aw_hs && !wr)) assert (awaddr_q == $past(s_awaddr_i));
            if (!$past(rst_i) && $past(f_w_hs && !wr)) assert (wdata_q == $past(s_wdata_i));
            // A response only follows a bus access (write or read).
            if (s_bvalid_o && !$past(s_bvalid_o)) assert ($past(wr_ack_q));
            if (wr_ack_q) assert ($past(wr_o));
            if (s_rvalid_o && !$past(s_rvalid_o)) assert ($past(rd_pend_q));
            if (rd_pend_q) assert ($past(rd_o));
            // The register-bus write is the one taken the cycle before.
            if (!$past(rst_i) && $past(wr)) begin
                assert (wr_o);
                assert (wr_addr_o == $past(aw_held_q ? awaddr_q : s_awaddr_i));
                assert (wr_data_o == $past(w_held_q ? wdata_q : s_wdata_i));
            end
        end
    end
`endif
endmodule

`default_nettype wire
