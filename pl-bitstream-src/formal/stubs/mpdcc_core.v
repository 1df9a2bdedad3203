// Formal stand-in for mpdcc_core in the pl_top proof: every output is an
// unconstrained value in every cycle ((* anyseq *)), so the top-level gate
// and fault properties are proved for ANY behaviour of the MPDCC core (and
// the SAT problem stays small: no explorers). Same ports as
// rtl/mpdcc_core.v; used only by scripts/rtl-formal, never synthesised or
// simulated.
`default_nettype none

module mpdcc_core #(
    parameter integer N = 2
) (
    input  wire               clk_i,
    input  wire               rst_i,
    input  wire               start_i,
    output wire               busy_o,
    input  wire        [2:0]  n_use_i,
    input  wire        [8:0]  s_prev_i,
    input  wire signed [15:0] i_a_i,
    input  wire signed [15:0] i_b_i,
    input  wire signed [15:0] psi_a_i,
    input  wire signed [15:0] psi_b_i,
    input  wire signed [15:0] v_n_i,
    input  wire        [47:0] v_ph_i,
    input  wire signed [15:0] ir_a_i,
    input  wire signed [15:0] ir_b_i,
    input  wire signed [15:0] omega_r_i,
    input  wire signed [15:0] omega_s_i,
    input  wire signed [15:0] c_tau_i,
    input  wire signed [15:0] c_r_i,
    input  wire signed [15:0] c_w_i,
    input  wire signed [15:0] c_p_i,
    input  wire signed [15:0] c_s_i,
    input  wire signed [15:0] c_3_i,
    input  wire signed [15:0] c_d_i,
    input  wire signed [15:0] c_n_i,
    input  wire signed [15:0] c_ph_i,
    input  wire signed [15:0] s3h_i,
    input  wire signed [15:0] v_ph_ref_i,
    input  wire signed [15:0] c_tau1_i,
    input  wire signed [15:0] c_r1_i,
    input  wire signed [15:0] c_w1_i,
    input  wire signed [15:0] c_s1_i,
    input  wire signed [15:0] vdc_half_i,
    input  wire signed [15:0] g3_i,
    input  wire signed [15:0] gd_i,
    input  wire signed [15:0] g3_1_i,
    input  wire        [111:0] bnd_i,
    input  wire        [15:0] lambda_n_i,
    output wire               done_o,
    output wire        [8:0]  s_o,
    output wire        [1:0]  kind_o,
    output wire        [7:0]  l_star_o,
    output wire        [31:0] cost_o,
    output wire signed [31:0] j_dl_o,
    output wire        [7:0]  candidates_o,
    output wire        [15:0] cycles_o
);
    (* anyseq *) reg busy_o_f;
    assign busy_o = busy_o_f;
    (* anyseq *) reg done_o_f;
    assign done_o = done_o_f;
    (* anyseq *) reg [8:0] s_o_f;
    assign s_o = s_o_f;
    (* anyseq *) reg [1:0] kind_o_f;
    assign kind_o = kind_o_f;
    (* anyseq *) reg [7:0] l_star_o_f;
    assign l_star_o = l_star_o_f;
    (* anyseq *) reg [31:0] cost_o_f;
    assign cost_o = cost_o_f;
    (* anyseq *) reg signed [31:0] j_dl_o_f;
    assign j_dl_o = j_dl_o_f;
    (* anyseq *) reg [7:0] candidates_o_f;
    assign candidates_o = candidates_o_f;
    (* anyseq *) reg [15:0] cycles_o_f;
    assign cycles_o = cycles_o_f;
    wire unused = ^{clk_i, rst_i, start_i, n_use_i, s_prev_i, i_a_i, i_b_i, psi_a_i, psi_b_i,
        v_n_i, v_ph_i, ir_a_i, ir_b_i, omega_r_i, omega_s_i, c_tau_i, c_r_i, c_w_i, c_p_i,
        c_s_i, c_3_i, c_d_i, c_n_i, c_ph_i, s3h_i, v_ph_ref_i, c_tau1_i, c_r1_i, c_w1_i,
        c_s1_i, vdc_half_i, g3_i, gd_i, g3_1_i, bnd_i, lambda_n_i};
endmodule

`default_nettype wire
