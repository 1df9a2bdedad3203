// Formal stand-in for mpdtc_core in the pl_top proof: every output is an
// unconstrained value in every cycle ((* anyseq *)), so the top-level gate
// and fault properties are proved for ANY behaviour of the MPDTC core (and
// the SAT problem stays small). Same ports as rtl/mpdtc_core.v; used only by
// scripts/rtl-formal, never synthesised or simulated.
`default_nettype none

module mpdtc_core (
    input  wire               clk_i,
    input  wire               rst_i,
    input  wire               in_valid_i,
    output wire               in_ready_o,
    input  wire signed [24:0] i_d_i,
    input  wire signed [24:0] i_q_i,
    input  wire signed [17:0] cos0_i,
    input  wire signed [17:0] sin0_i,
    input  wire signed [17:0] cos1_i,
    input  wire signed [17:0] sin1_i,
    input  wire signed [17:0] cos2_i,
    input  wire signed [17:0] sin2_i,
    input  wire signed [17:0] w_ts_i,
    input  wire signed [17:0] t_ref_i,
    input  wire signed [17:0] p_a_i,
    input  wire signed [17:0] p_lambda_i,
    input  wire signed [24:0] p_u0_i,
    input  wire signed [24:0] p_u0_half_i,
    input  wire signed [24:0] p_u0_h_i,
    input  wire signed [24:0] p_psi_l_i,
    input  wire signed [24:0] p_kinv_t_i,
    input  wire signed [24:0] p_tol_i,
    input  wire signed [17:0] p_k_int_i,
    input  wire signed [24:0] p_int_lim_i,
    input  wire               p_int_cond_i,
    input  wire signed [17:0] p_kp_o_i,
    input  wire signed [17:0] p_ki_o_i,
    input  wire signed [24:0] p_eta_lim_i,
    input  wire        [71:0] p_w2_i,
    input  wire               st_load_i,
    input  wire        [ 2:0] st_s_applied_i,
    input  wire        [ 2:0] st_s_prev_i,
    input  wire signed [24:0] st_eta_d_i,
    input  wire signed [24:0] st_eta_q_i,
    input  wire signed [24:0] st_x_i,
    input  wire               st_band_i,
    input  wire signed [24:0] st_iq_ref_prev_i,
    input  wire signed [24:0] st_i_hat_d_i,
    input  wire signed [24:0] st_i_hat_q_i,
    input  wire signed [24:0] st_nu_d_i,
    input  wire signed [24:0] st_nu_q_i,
    output wire               out_valid_o,
    output wire        [ 2:0] s_next_o,
    output wire signed [24:0] iq_ref_o,
    output wire signed [24:0] eta_d_o,
    output wire signed [24:0] eta_q_o,
    output wire signed [24:0] i1_d_o,
    output wire signed [24:0] i1_q_o,
    output wire       [199:0] i2_d_o,
    output wire       [199:0] i2_q_o,
    output wire       [199:0] err_o,
    output wire       [383:0] cost2_o,
    output wire        [ 2:0] st_s_applied_o,
    output wire        [ 2:0] st_s_prev_o,
    output wire signed [24:0] st_eta_d_o,
    output wire signed [24:0] st_eta_q_o,
    output wire signed [24:0] st_x_o,
    output wire               st_band_o,
    output wire signed [24:0] st_iq_ref_prev_o,
    output wire signed [24:0] st_i_hat_d_o,
    output wire signed [24:0] st_i_hat_q_o,
    output wire signed [24:0] st_nu_d_o,
    output wire signed [24:0] st_nu_q_o
);
    (* anyseq *) reg  in_ready_o_f;
    assign in_ready_o = in_ready_o_f;
    (* anyseq *) reg  out_valid_o_f;
    assign out_valid_o = out_valid_o_f;
    (* anyseq *) reg [ 2:0] s_next_o_f;
    assign s_next_o = s_next_o_f;
    (* anyseq *) reg signed [24:0] iq_ref_o_f;
    assign iq_ref_o = iq_ref_o_f;
    (* anyseq *) reg signed [24:0] eta_d_o_f;
    assign eta_d_o = eta_d_o_f;
    (* anyseq *) reg signed [24:0] eta_q_o_f;
    assign eta_q_o = eta_q_o_f;
    (* anyseq *) reg signed [24:0] i1_d_o_f;
    assign i1_d_o = i1_d_o_f;
    (* anyseq *) reg signed [24:0] i1_q_o_f;
    assign i1_q_o = i1_q_o_f;
    (* anyseq *) reg [199:0] i2_d_o_f;
    assign i2_d_o = i2_d_o_f;
    (* anyseq *) reg [199:0] i2_q_o_f;
    assign i2_q_o = i2_q_o_f;
    (* anyseq *) reg [199:0] err_o_f;
    assign err_o = err_o_f;
    (* anyseq *) reg [383:0] cost2_o_f;
    assign cost2_o = cost2_o_f;
    (* anyseq *) reg [ 2:0] st_s_applied_o_f;
    assign st_s_applied_o = st_s_applied_o_f;
    (* anyseq *) reg [ 2:0] st_s_prev_o_f;
    assign st_s_prev_o = st_s_prev_o_f;
    (* anyseq *) reg signed [24:0] st_eta_d_o_f;
    assign st_eta_d_o = st_eta_d_o_f;
    (* anyseq *) reg signed [24:0] st_eta_q_o_f;
    assign st_eta_q_o = st_eta_q_o_f;
    (* anyseq *) reg signed [24:0] st_x_o_f;
    assign st_x_o = st_x_o_f;
    (* anyseq *) reg  st_band_o_f;
    assign st_band_o = st_band_o_f;
    (* anyseq *) reg signed [24:0] st_iq_ref_prev_o_f;
    assign st_iq_ref_prev_o = st_iq_ref_prev_o_f;
    (* anyseq *) reg signed [24:0] st_i_hat_d_o_f;
    assign st_i_hat_d_o = st_i_hat_d_o_f;
    (* anyseq *) reg signed [24:0] st_i_hat_q_o_f;
    assign st_i_hat_q_o = st_i_hat_q_o_f;
    (* anyseq *) reg signed [24:0] st_nu_d_o_f;
    assign st_nu_d_o = st_nu_d_o_f;
    (* anyseq *) reg signed [24:0] st_nu_q_o_f;
    assign st_nu_q_o = st_nu_q_o_f;
    wire unused = &{1'b0, clk_i, rst_i, in_valid_i, i_d_i, i_q_i, cos0_i, sin0_i, cos1_i, sin1_i,
                    cos2_i, sin2_i, w_ts_i, t_ref_i, p_a_i, p_lambda_i, p_u0_i, p_u0_half_i,
                    p_u0_h_i, p_psi_l_i, p_kinv_t_i, p_tol_i, p_k_int_i, p_int_lim_i,
                    p_int_cond_i, p_kp_o_i, p_ki_o_i, p_eta_lim_i, p_w2_i, st_load_i,
                    st_s_applied_i, st_s_prev_i, st_eta_d_i, st_eta_q_i, st_x_i, st_band_i,
                    st_iq_ref_prev_i, st_i_hat_d_i, st_i_hat_q_i, st_nu_d_i, st_nu_q_i};
endmodule

`default_nettype wire
