// Simulation model of the xc7 carry chain element CARRY4 for the
// gate-level checks (scripts/rtl-gatesim), in place of the one in Yosys's
// share/xilinx/cells_sim.v. The behaviour is the same (UG474, 7 Series
// FPGAs CLB: four MUXCY stages, carry k+1 = S[k] ? carry k : DI[k], and
// four XORCY, O[k] = S[k] ^ carry k; the chain's input is CI or CYINIT,
// whichever is used, the other tied to 0 as Yosys maps it). The Yosys
// model computes CO[k] from CO[k-1] of the same output vector, a
// combinational loop to Verilator: it gives every CARRY4 instance change
// triggers, evaluated until the loop settles on each clock edge (most of
// the simulation time of the mpdcc_core netlist, 2,936 CARRY4). Here the
// carries are separate wires, so the chain is ordered statically.
`default_nettype none

// the primitive's name, which the netlist instantiates
/* verilator lint_off DECLFILENAME */
module CARRY4 (
    (* abc9_carry *)
    output wire [3:0] CO,
    output wire [3:0] O,
    (* abc9_carry *)
    input wire CI,
    input wire CYINIT,
    input wire [3:0] DI,
    input wire [3:0] S
);
    wire c0 = CI | CYINIT;
    wire c1 = S[0] ? c0 : DI[0];
    wire c2 = S[1] ? c1 : DI[1];
    wire c3 = S[2] ? c2 : DI[2];
    wire c4 = S[3] ? c3 : DI[3];
    assign CO = {c4, c3, c2, c1};
    assign O = S ^ {c3, c2, c1, c0};
endmodule
/* verilator lint_on DECLFILENAME */

`default_nettype wire
