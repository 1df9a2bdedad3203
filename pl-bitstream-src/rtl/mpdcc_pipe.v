// mpdcc_pipe: N pipeline registers of W bits (a delay line that keeps a
// value beside the datapath of the MPDCC explorer).
// N = 1: one register with a synchronous reset to 0 (the reset rule).
// N >= 2: a delay line without reset, a documented exception to the
// synchronous-reset rule: a reset on every stage keeps Xilinx tools from
// mapping the line to shift-register LUTs (SRL16E/SRLC32E have no reset),
// so each bit would cost N flip-flops instead of one LUT (measured on one
// explorer: 26,498 FF with the reset, 15,853 without; Yosys maps lines of
// N >= 3 to SRLs, N = 2 stays two flip-flops per bit). Safe because every
// value on such a line travels beside a valid bit whose own pipeline (N = 1
// stages) is reset: after a reset the line's contents are never read as a
// result (the explorer's hand-shake, proved in scripts/rtl-formal).
`default_nettype none

module mpdcc_pipe #(
    parameter integer W = 1,
    parameter integer N = 1  // >= 1
) (
    input  wire         clk_i,
    input  wire         rst_i,
    input  wire [W-1:0] d_i,
    output wire [W-1:0] q_o
);
    reg [W-1:0] r_q [0:N-1];
    generate
        if (N == 1) begin : g_reg
            always @(posedge clk_i) begin
                if (rst_i) r_q[0] <= {W{1'b0}};
                else r_q[0] <= d_i;
            end
        end else begin : g_srl
            // no reset: maps to SRLs (see above)
            integer k;
            always @(posedge clk_i) begin
                r_q[0] <= d_i;
                for (k = 1; k < N; k = k + 1) r_q[k] <= r_q[k-1];
            end
        end
    endgenerate
    assign q_o = r_q[N-1];
endmodule

`default_nettype wire
