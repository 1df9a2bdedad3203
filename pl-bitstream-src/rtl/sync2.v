// sync2: two-flip-flop synchroniser for an asynchronous input (encoder,
// external fault). Adds 2 clock cycles of latency. RESET_VAL is the output
// during and right after reset.
`default_nettype none

module sync2 #(
    parameter [0:0] RESET_VAL = 1'b0
) (
    input  wire clk_i,
    input  wire rst_i,
    input  wire d_i,
    output wire q_o
);
    (* ASYNC_REG = "TRUE" *) reg meta_q;
    (* ASYNC_REG = "TRUE" *) reg sync_q;
    always @(posedge clk_i) begin
        if (rst_i) begin
            meta_q <= RESET_VAL;
            sync_q <= RESET_VAL;
        end else begin
            meta_q <= d_i;
            sync_q <= meta_q;
        end
    end
    assign q_o = sync_q;
endmodule

`default_nettype wire
