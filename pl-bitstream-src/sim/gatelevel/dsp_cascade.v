// The smallest design that shows the DSP48E1 cascade defect of Yosys 0.70's
// xilinx_dsp (scripts/rtl-gatesim cascade, docs/rtl.md "Gate level"): two
// signed 18 x 25 products, the first registered, summed at 48 bits. With
// the default synth_xilinx flow the first product's DSP48E1 feeds the
// second through PCOUT -> PCIN and the netlist ties sum_o[47:44] to 0 (the
// sum's sign extension is lost); with xilinx_dsp.multonly each product is
// one DSP48E1 and the register and adder are fabric.
`default_nettype none

module dsp_cascade (
    input  wire               clk_i,
    input  wire signed [17:0] a_i,
    input  wire signed [24:0] b_i,
    input  wire signed [17:0] c_i,
    input  wire signed [24:0] d_i,
    output reg  signed [47:0] sum_o
);
    wire signed [47:0] p1 = a_i * b_i;
    wire signed [47:0] p2 = c_i * d_i;
    reg signed [47:0] p1_q;
    always @(posedge clk_i) begin
        p1_q  <= p1;
        sum_o <= p1_q + p2;
    end
endmodule
