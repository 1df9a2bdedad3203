// Formal stand-in for mpdcc_explorer in the mpdcc_core proof: every output
// is an unconstrained value in every cycle ((* anyseq *)). mpdcc_core's
// FORMAL block assumes the explorer's hand-shake contract on out_valid_o
// (a candidate comes back exactly F_LAT = 41 clocks after it was issued,
// nothing else comes back, a reset clears what is in flight), which the
// real explorer proves in its own FORMAL block; the results (code, L*, J,
// J_dl) stay free, so the scheduler's properties hold for ANY explorer
// arithmetic and the SAT problem stays small. Same ports as
// rtl/mpdcc_explorer.v; used only by scripts/rtl-formal.
`default_nettype none

module mpdcc_explorer (
    input  wire               clk_i,
    input  wire               rst_i,
    input  wire               in_valid_i,
    input  wire        [8:0]  s_i,
    input  wire        [8:0]  s_prev_i,
    input  wire        [111:0] e0_i,
    input  wire        [191:0] dn_i,
    input  wire        [47:0] dn1_i,
    input  wire        [95:0] pn_i,
    input  wire        [95:0] pph_i,
    input  wire signed [15:0] v_n_i,
    input  wire        [47:0] v_ph_i,
    input  wire signed [15:0] vdc_half_i,
    input  wire signed [15:0] g3_i,
    input  wire signed [15:0] gd_i,
    input  wire signed [15:0] g3_1_i,
    input  wire        [111:0] bnd_i,
    input  wire        [15:0] lambda_n_i,
    output wire               out_valid_o,
    output wire        [8:0]  s_o,
    output wire        [7:0]  l_star_o,
    output wire        [31:0] cost_o,
    output wire signed [31:0] j_dl_o,
    output wire        [3:0]  fs_o,
    output wire        [111:0] d0_o
);
    (* anyseq *) reg               out_valid_f;
    (* anyseq *) reg        [8:0]  s_f;
    (* anyseq *) reg        [7:0]  l_star_f;
    (* anyseq *) reg        [31:0] cost_f;
    (* anyseq *) reg signed [31:0] j_dl_f;
    (* anyseq *) reg        [3:0]  fs_f;
    (* anyseq *) reg        [111:0] d0_f;
    assign out_valid_o = out_valid_f;
    assign s_o = s_f;
    assign l_star_o = l_star_f;
    assign cost_o = cost_f;
    assign j_dl_o = j_dl_f;
    assign fs_o = fs_f;
    assign d0_o = d0_f;
    wire unused = &{1'b0, clk_i, rst_i, in_valid_i, s_i, s_prev_i, e0_i, dn_i, dn1_i, pn_i, pph_i,
                    v_n_i, v_ph_i, vdc_half_i, g3_i, gd_i, g3_1_i, bnd_i, lambda_n_i};
endmodule

`default_nettype wire
