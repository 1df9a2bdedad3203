// Formal stand-in for mpdtc_frontend in the pl_top proof: every output is
// an unconstrained value in every cycle ((* anyseq *)), so the top-level
// gate and fault properties are proved for ANY behaviour of the front end
// (and the SAT problem stays small). Same ports as rtl/mpdtc_frontend.v;
// used only by scripts/rtl-formal (not in mpdtc_frontend's own proof),
// never synthesised or simulated.
`default_nettype none

module mpdtc_frontend (
    input  wire               clk_i,
    input  wire               rst_i,
    input  wire               in_valid_i,
    // inputs of the period
    input  wire        [15:0] pos_i,        // ENC_POS
    input  wire signed [15:0] speed_i,      // ENC_SPEED, counts per window
    input  wire signed [15:0] adc_a_i,      // averaged ADC results
    input  wire signed [15:0] adc_b_i,
    input  wire signed [15:0] adc_c_i,
    input  wire signed [17:0] t_ref_i,      // TRQ, passed through
    // registers
    input  wire        [15:0] cpr_i,
    input  wire        [15:0] align_pos_i,
    input  wire        [31:0] ang_scale_i,
    input  wire        [31:0] spd_scale_i,
    input  wire signed [17:0] age0_i,       // COEF, periods after the sample
    input  wire signed [17:0] age1_i,
    input  wire signed [17:0] age2_i,
    input  wire signed [15:0] off_a_i,
    input  wire signed [15:0] off_b_i,
    input  wire signed [15:0] off_c_i,
    input  wire signed [17:0] gain_a_i,     // 2^-20 A per count
    input  wire signed [17:0] gain_b_i,
    input  wire signed [17:0] gain_c_i,
    // results (the mpdtc_core inputs) and intermediate values
    output wire               out_valid_o,
    output wire signed [24:0] i_d_o,
    output wire signed [24:0] i_q_o,
    output wire signed [17:0] cos0_o,
    output wire signed [17:0] sin0_o,
    output wire signed [17:0] cos1_o,
    output wire signed [17:0] sin1_o,
    output wire signed [17:0] cos2_o,
    output wire signed [17:0] sin2_o,
    output wire signed [17:0] w_ts_o,
    output wire signed [17:0] t_ref_o,
    output wire        [31:0] phi_o,
    output wire signed [31:0] dphi_o,
    output wire signed [24:0] i_alpha_o,
    output wire signed [24:0] i_beta_o
);
    (* anyseq *) reg out_valid_o_f;
    assign out_valid_o = out_valid_o_f;
    (* anyseq *) reg signed [24:0] i_d_o_f;
    assign i_d_o = i_d_o_f;
    (* anyseq *) reg signed [24:0] i_q_o_f;
    assign i_q_o = i_q_o_f;
    (* anyseq *) reg signed [17:0] cos0_o_f;
    assign cos0_o = cos0_o_f;
    (* anyseq *) reg signed [17:0] sin0_o_f;
    assign sin0_o = sin0_o_f;
    (* anyseq *) reg signed [17:0] cos1_o_f;
    assign cos1_o = cos1_o_f;
    (* anyseq *) reg signed [17:0] sin1_o_f;
    assign sin1_o = sin1_o_f;
    (* anyseq *) reg signed [17:0] cos2_o_f;
    assign cos2_o = cos2_o_f;
    (* anyseq *) reg signed [17:0] sin2_o_f;
    assign sin2_o = sin2_o_f;
    (* anyseq *) reg signed [17:0] w_ts_o_f;
    assign w_ts_o = w_ts_o_f;
    (* anyseq *) reg signed [17:0] t_ref_o_f;
    assign t_ref_o = t_ref_o_f;
    (* anyseq *) reg [31:0] phi_o_f;
    assign phi_o = phi_o_f;
    (* anyseq *) reg signed [31:0] dphi_o_f;
    assign dphi_o = dphi_o_f;
    (* anyseq *) reg signed [24:0] i_alpha_o_f;
    assign i_alpha_o = i_alpha_o_f;
    (* anyseq *) reg signed [24:0] i_beta_o_f;
    assign i_beta_o = i_beta_o_f;
    wire unused = &{1'b0, clk_i, rst_i, in_valid_i, pos_i, speed_i, adc_a_i, adc_b_i, adc_c_i,
                    t_ref_i, cpr_i, align_pos_i, ang_scale_i, spd_scale_i, age0_i, age1_i, age2_i,
                    off_a_i, off_b_i, off_c_i, gain_a_i, gain_b_i, gain_c_i};
endmodule

`default_nettype wire
