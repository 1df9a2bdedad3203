// mpdcc_lane: the search lane of one output of an MPDCC explorer
// (models::mpdcc::fpga::lane for the frozen core, Structure::CORE), pipelined:
// one output per clock, fixed latency LATENCY = 12 cycles.
//
// Core constants: L = 8 (LAMBDA = 3), N_bar = 128, four interpolation nodes
// at k + 8, 16, 32, 64. The error of the output is piecewise linear through
// e0 (at k) and e0 + n_i (at node i); the pieces are [0, 8], [8, 16],
// [16, 32] and [32, 128] (the last one extended), each searched by an
// mpdcc_piece in parallel (the model searches them one after the other and
// stops at the first that is not capped: the same result, selected here).
//
// Formats: e0_i and bnd_i Q2.13 (bnd >= 0, 15 bits), n*_i Q4.13 node
// changes (18 bits, saturated at +-(2^17 - 1) by the explorer), piece
// values a = e0 + n_(i-1) and slopes d = n_i - n_(i-1) exact in 19 bits.
// lj_o in steps, 0..128.
//
// Stages: 1 piece inputs (one adder each); 2..11 mpdcc_piece (LATENCY 10);
// 12 first piece that is below or not capped, start + q (one adder).
`default_nettype none

module mpdcc_lane (
    input  wire               clk_i,
    input  wire               rst_i,
    input  wire               in_valid_i,
    input  wire signed [15:0] e0_i,
    input  wire signed [17:0] n0_i,
    input  wire signed [17:0] n1_i,
    input  wire signed [17:0] n2_i,
    input  wire signed [17:0] n3_i,
    input  wire        [14:0] bnd_i,
    output reg                out_valid_o,
    output reg         [7:0]  lj_o
);
    localparam integer NBAR = 128;

    // stage 1: piece inputs
    reg               v1_q;
    reg signed [18:0] a1_q [0:3];
    reg signed [18:0] d1_q [0:3];
    reg        [14:0] bnd1_q;
    wire signed [18:0] e0_w = {{3{e0_i[15]}}, e0_i};
    wire signed [18:0] n0_w = {n0_i[17], n0_i};
    wire signed [18:0] n1_w = {n1_i[17], n1_i};
    wire signed [18:0] n2_w = {n2_i[17], n2_i};
    wire signed [18:0] n3_w = {n3_i[17], n3_i};
    always @(posedge clk_i) begin
        if (rst_i) begin
            v1_q    <= 1'b0;
            a1_q[0] <= 19'sd0;
            a1_q[1] <= 19'sd0;
            a1_q[2] <= 19'sd0;
            a1_q[3] <= 19'sd0;
            d1_q[0] <= 19'sd0;
            d1_q[1] <= 19'sd0;
            d1_q[2] <= 19'sd0;
            d1_q[3] <= 19'sd0;
            bnd1_q  <= 15'd0;
        end else begin
            v1_q    <= in_valid_i;
            a1_q[0] <= e0_w;
            a1_q[1] <= e0_w + n0_w;
            a1_q[2] <= e0_w + n1_w;
            a1_q[3] <= e0_w + n2_w;
            d1_q[0] <= n0_w;
            d1_q[1] <= n1_w - n0_w;
            d1_q[2] <= n2_w - n1_w;
            d1_q[3] <= n3_w - n2_w;
            bnd1_q  <= bnd_i;
        end
    end

    // stages 2..11: the four pieces (length 8, 8, 16, 96 steps)
    wire [3:0] pv;
    wire [3:0] below;
    wire [3:0] capped;
    wire [7:0] q [0:3];
    mpdcc_piece #(.LS(3), .CAP(8), .QBITS(3), .QMAX(7)) u_p0 (
        .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(v1_q), .a_i(a1_q[0]), .d_i(d1_q[0]),
        .bnd_i(bnd1_q), .out_valid_o(pv[0]), .below_o(below[0]), .capped_o(capped[0]),
        .q_o(q[0]));
    mpdcc_piece #(.LS(3), .CAP(8), .QBITS(3), .QMAX(7)) u_p1 (
        .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(v1_q), .a_i(a1_q[1]), .d_i(d1_q[1]),
        .bnd_i(bnd1_q), .out_valid_o(pv[1]), .below_o(below[1]), .capped_o(capped[1]),
        .q_o(q[1]));
    mpdcc_piece #(.LS(4), .CAP(16), .QBITS(4), .QMAX(7)) u_p2 (
        .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(v1_q), .a_i(a1_q[2]), .d_i(d1_q[2]),
        .bnd_i(bnd1_q), .out_valid_o(pv[2]), .below_o(below[2]), .capped_o(capped[2]),
        .q_o(q[2]));
    mpdcc_piece #(.LS(5), .CAP(96), .QBITS(7), .QMAX(7)) u_p3 (
        .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(v1_q), .a_i(a1_q[3]), .d_i(d1_q[3]),
        .bnd_i(bnd1_q), .out_valid_o(pv[3]), .below_o(below[3]), .capped_o(capped[3]),
        .q_o(q[3]));

    // stage 12: the first piece the output leaves (below at its start, or
    // not capped), start of that piece + q; inside everywhere: N_bar.
    reg [7:0] lj_d;
    always @(*) begin
        if (below[0])       lj_d = 8'd0;
        else if (!capped[0]) lj_d = q[0];
        else if (below[1])  lj_d = 8'd8;
        else if (!capped[1]) lj_d = 8'd8 + q[1];
        else if (below[2])  lj_d = 8'd16;
        else if (!capped[2]) lj_d = 8'd16 + q[2];
        else if (below[3])  lj_d = 8'd32;
        else if (!capped[3]) lj_d = 8'd32 + q[3];
        else                lj_d = NBAR[7:0];
    end
    always @(posedge clk_i) begin
        if (rst_i) begin
            out_valid_o <= 1'b0;
            lj_o        <= 8'd0;
        end else begin
            out_valid_o <= &pv;  // the pieces run in lockstep
            lj_o        <= lj_d;
        end
    end
endmodule

`default_nettype wire
