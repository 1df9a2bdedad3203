// Exhaustive comparison of the CARRY4 of xc7_carry4.v with the one of
// Yosys's cells_sim.v, renamed CARRY4_yosys (scripts/rtl-gatesim cascade):
// all 1,024 values of CI, CYINIT, DI and S; prints "carry4 mismatches M of N".
`timescale 1ns / 1ps
module carry4_tb;
    localparam integer N = 1024;
    reg [9:0] v;
    wire [3:0] co, o, co_y, o_y;
    integer i, bad = 0;
    CARRY4 u_new (
        .CO(co), .O(o), .CI(v[0]), .CYINIT(v[1]), .DI(v[5:2]), .S(v[9:6])
    );
    CARRY4_yosys u_yosys (
        .CO(co_y), .O(o_y), .CI(v[0]), .CYINIT(v[1]), .DI(v[5:2]), .S(v[9:6])
    );
    initial begin
        for (i = 0; i < N; i = i + 1) begin
            v = i;
            #1 if (co !== co_y || o !== o_y) bad = bad + 1;
        end
        $display("carry4 mismatches %0d of %0d", bad, N);
        $finish;
    end
endmodule
