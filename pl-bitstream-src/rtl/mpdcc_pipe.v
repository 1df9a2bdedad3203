// mpdcc_pipe: N pipeline registers of W bits (a delay line that keeps a
// value beside the datapath of the MPDCC explorer), synchronous reset to 0.
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
    integer k;
    always @(posedge clk_i) begin
        if (rst_i) begin
            for (k = 0; k < N; k = k + 1) r_q[k] <= {W{1'b0}};
        end else begin
            r_q[0] <= d_i;
            for (k = 1; k < N; k = k + 1) r_q[k] <= r_q[k-1];
        end
    end
    assign q_o = r_q[N-1];
endmodule

`default_nettype wire
