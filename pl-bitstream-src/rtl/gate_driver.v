// gate_driver: gate signals of the 3-leg, 2-level inverter.
//
// Switching-state convention (ARCHITECTURE.md): bits SaSbSc, Sx = 1 = upper
// switch of leg x on, state index 4 Sa + 2 Sb + Sc. So s_i[2] is leg a,
// s_i[1] leg b, s_i[0] leg c, and the gate vectors use the same bit order.
//
//   dt_i     dead time in clock cycles, DT_W bits (default 10: 0..1023
//            cycles, 10 ns..10.23 us at 100 MHz); 0 is treated as 1.
//   en_i     1 = gates follow s_i; 0 = all six gates off.
//   fault_i  1 = all six gates off at the next clock edge.
//   rst_i    synchronous, active high.
// Each leg is a gate_leg (interlock, dead time, registered outputs).
`default_nettype none

module gate_driver #(
    parameter integer DT_W = 10
) (
    input  wire            clk_i,
    input  wire            rst_i,
    input  wire            en_i,
    input  wire            fault_i,
    input  wire [     2:0] s_i,
    input  wire [DT_W-1:0] dt_i,
    output wire [     2:0] gate_hi_o,
    output wire [     2:0] gate_lo_o
);
    genvar g;
    generate
        for (g = 0; g < 3; g = g + 1) begin : g_leg
            gate_leg #(
                .DT_W(DT_W)
            ) u_leg (
                .clk_i  (clk_i),
                .rst_i  (rst_i),
                .en_i   (en_i),
                .fault_i(fault_i),
                .s_i    (s_i[g]),
                .dt_i   (dt_i),
                .hi_o   (gate_hi_o[g]),
                .lo_o   (gate_lo_o[g])
            );
        end
    endgenerate
endmodule

`default_nettype wire
