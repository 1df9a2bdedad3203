// Random-vector comparison of the synthesised dsp_cascade (module
// dsp_cascade, from the netlist) with the same RTL renamed dsp_cascade_rtl
// (scripts/rtl-gatesim cascade): prints "mismatches M of N".
`timescale 1ns / 1ps
module dsp_cascade_tb;
    localparam integer N = 2000;
    reg clk = 1'b0;
    reg signed [17:0] a, c;
    reg signed [24:0] b, d;
    wire signed [47:0] gl, rtl;
    integer i, bad = 0, seed = 1;
    dsp_cascade     u_gl  (.clk_i(clk), .a_i(a), .b_i(b), .c_i(c), .d_i(d), .sum_o(gl));
    dsp_cascade_rtl u_rtl (.clk_i(clk), .a_i(a), .b_i(b), .c_i(c), .d_i(d), .sum_o(rtl));
    initial begin
        for (i = 0; i < N; i = i + 1) begin
            a = $random(seed); b = $random(seed); c = $random(seed); d = $random(seed);
            #1 clk = 1'b1; #1 clk = 1'b0;  // p1_q
            #1 clk = 1'b1; #1 clk = 1'b0;  // sum_o
            if (gl !== rtl) bad = bad + 1;
        end
        $display("mismatches %0d of %0d", bad, N);
        $finish;
    end
endmodule
