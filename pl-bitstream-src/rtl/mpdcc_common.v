// mpdcc_common: the MPDCC scheduler's common terms (paper 001, Sec. V-A,
// eq. 14), drive::mpdcc::fpga::common_terms of the frozen core bit for bit:
// output errors at k, the switch-independent error changes at the nodes
// k + 8, 16, 32, 64 and over one step, and the capacitor-current products.
// A straight pipeline, fixed latency LATENCY = 16 cycles; the outputs follow
// the inputs (held stable by the caller) with that delay.
//
// Formats (docs/mpdcc-fpga.md): i_ab, i_ref_ab, v_n, v_ph, omega_r, omega_s,
// v_ph_ref Q2.13; psi_ab and the L-step coefficients Q1.14; the one-step
// coefficients c_tau1, c_r1, c_w1, c_s1 f17; wide sums exact (f28 L-step,
// f31 one step); mul(a, b) = sat16(rnd(a b, s)), rnd = round half up
// ((x >>> s) + x[s-1]), as drive::mpdcc::fixed::mul.
//
// Stages (at most one multiplier or one adder between registers; a
// saturation is a compare and mux on a registered sum):
//   1  products of the inputs; e_ab = i* - i; -v_n; v_ph_ref - v_ph; x_a/2
//   2  rounding of kw, w2, ks, s2, kw1, ks1, s3h i_b; nat = -2 c_tau i + c_r psi
//   3  kp, tr, ts, k2, kw psi, ks i*, kw1 psi, ks1 i*, s3h e_b (products);
//      i_b,c = -i_a/2 +- s3h i_b
//   4  rounding; nat += kw J psi; ref = ks J i* (x 2); e_b/2 ...
//   5  kw tr, ks ts, kp psi, k2 i* (products); rate = ref - nat; round nat;
//      e_b,c; P_n = c_n i, P_ph = c_ph i
//   6  kw3, ks3; cor = kp psi + 2 k2 i*; c_d nat (product)
//   7  ks3 i*, kw3 psi (products); dmp - cor
//   8  cub_a; cub_b (1/2)
//   9  cub_b (2/2); rnd(cor << 3, 6)
//  10  m rate + m^2 (dmp - cor); rnd(cub << 3, 9); rate1 - rnd(cor..)
//  11  + m^3 cub; + rnd(cub..)
//  12  rnd to Q2.13 (node: 15, one step: 18)
//  13  sat16; s3h x_b (products); x_a / 2
//  14  rnd(s3h x_b, 14)
//  15  -x_a/2 +- r
//  16  sat16
`default_nettype none

module mpdcc_common (
    input  wire               clk_i,
    input  wire               rst_i,
    // state registers (raw)
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
    // design constants
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
    // common terms
    output wire        [111:0] e0_o,      // 7 x Q2.13
    output wire        [191:0] dn_o,      // [(3 m + ph) 16 +: 16]
    output wire        [47:0]  dn1_o,
    output wire        [95:0]  pn_o,      // 3 x f27
    output wire        [95:0]  pph_o
);
    localparam integer W = 48;

    function automatic signed [W-1:0] rnd(input signed [W-1:0] x, input integer s);
        rnd = (x >>> s) + $signed({{(W - 1) {1'b0}}, x[s-1]});
    endfunction
    function automatic signed [W-1:0] sat(input signed [W-1:0] x);
        if (x > 48'sd32767) sat = 48'sd32767;
        else if (x < -48'sd32768) sat = -48'sd32768;
        else sat = x;
    endfunction
    function automatic signed [W-1:0] sx(input signed [15:0] x);
        sx = {{(W - 16) {x[15]}}, x};
    endfunction
    function automatic signed [W-1:0] pr(input signed [W-1:0] a, input signed [W-1:0] b);
        // 16 x 16 (both operands hold 16-bit values)
        pr = $signed(a[15:0]) * $signed(b[15:0]);
    endfunction

    // ------------------------------------------------------- stage 1
    wire signed [W-1:0] ia = sx(i_a_i), ib = sx(i_b_i), pa = sx(psi_a_i), pb = sx(psi_b_i);
    wire signed [W-1:0] ra = sx(ir_a_i), rb = sx(ir_b_i), wr = sx(omega_r_i), ws = sx(omega_s_i);
    wire signed [W-1:0] s1_pkw, s1_pw2, s1_pks, s1_ps2, s1_pkw1, s1_pks1;
    wire signed [W-1:0] s1_ta, s1_tb, s1_ra, s1_rb, s1_t1a, s1_t1b, s1_r1a, s1_r1b;
    wire signed [W-1:0] s1_ea, s1_eb, s1_en, s1_psi, s1_hi;
    wire signed [W-1:0] s1_eph [0:2];
    mpdcc_pipe #(.W(W)) u1a (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_w_i), wr)), .q_o(s1_pkw));
    mpdcc_pipe #(.W(W)) u1b (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(wr, wr)), .q_o(s1_pw2));
    mpdcc_pipe #(.W(W)) u1c (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_s_i), ws)), .q_o(s1_pks));
    mpdcc_pipe #(.W(W)) u1d (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(ws, ws)), .q_o(s1_ps2));
    mpdcc_pipe #(.W(W)) u1e (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_w1_i), wr)), .q_o(s1_pkw1));
    mpdcc_pipe #(.W(W)) u1f (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_s1_i), ws)), .q_o(s1_pks1));
    mpdcc_pipe #(.W(W)) u1g (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_tau_i), ia)), .q_o(s1_ta));
    mpdcc_pipe #(.W(W)) u1h (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_tau_i), ib)), .q_o(s1_tb));
    mpdcc_pipe #(.W(W)) u1i (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_r_i), pa)), .q_o(s1_ra));
    mpdcc_pipe #(.W(W)) u1j (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_r_i), pb)), .q_o(s1_rb));
    mpdcc_pipe #(.W(W)) u1k (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_tau1_i), ia)), .q_o(s1_t1a));
    mpdcc_pipe #(.W(W)) u1l (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_tau1_i), ib)), .q_o(s1_t1b));
    mpdcc_pipe #(.W(W)) u1m (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_r1_i), pa)), .q_o(s1_r1a));
    mpdcc_pipe #(.W(W)) u1n (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_r1_i), pb)), .q_o(s1_r1b));
    mpdcc_pipe #(.W(W)) u1o (.clk_i(clk_i), .rst_i(rst_i), .d_i(ra - ia), .q_o(s1_ea));
    mpdcc_pipe #(.W(W)) u1p (.clk_i(clk_i), .rst_i(rst_i), .d_i(rb - ib), .q_o(s1_eb));
    mpdcc_pipe #(.W(W)) u1q (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - sx(v_n_i)), .q_o(s1_en));
    mpdcc_pipe #(.W(W)) u1r (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(s3h_i), ib)), .q_o(s1_psi));
    mpdcc_pipe #(.W(W)) u1s (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(ia, 1)), .q_o(s1_hi));
    genvar g;
    generate
        for (g = 0; g < 3; g = g + 1) begin : g_eph
            mpdcc_pipe #(.W(W)) u (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(sx(v_ph_ref_i) - sx(v_ph_i[16*g +: 16])), .q_o(s1_eph[g]));
        end
    endgenerate

    // ------------------------------------------------------- stage 2
    wire signed [W-1:0] s2_kw, s2_w2, s2_ks, s2_s2, s2_kw1, s2_ks1, s2_ri, s2_hi;
    wire signed [W-1:0] s2_na, s2_nb, s2_n1a, s2_n1b, s2_ea, s2_eb;
    mpdcc_pipe #(.W(W)) u2a (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s1_pkw, 13))), .q_o(s2_kw));
    mpdcc_pipe #(.W(W)) u2b (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s1_pw2, 13))), .q_o(s2_w2));
    mpdcc_pipe #(.W(W)) u2c (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s1_pks, 13))), .q_o(s2_ks));
    mpdcc_pipe #(.W(W)) u2d (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s1_ps2, 13))), .q_o(s2_s2));
    mpdcc_pipe #(.W(W)) u2e (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s1_pkw1, 13))), .q_o(s2_kw1));
    mpdcc_pipe #(.W(W)) u2f (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s1_pks1, 13))), .q_o(s2_ks1));
    mpdcc_pipe #(.W(W)) u2g (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s1_psi, 14))), .q_o(s2_ri));
    mpdcc_pipe #(.W(W)) u2h (.clk_i(clk_i), .rst_i(rst_i), .d_i(s1_hi), .q_o(s2_hi));
    mpdcc_pipe #(.W(W)) u2i (.clk_i(clk_i), .rst_i(rst_i), .d_i(s1_ra - (s1_ta <<< 1)), .q_o(s2_na));
    mpdcc_pipe #(.W(W)) u2j (.clk_i(clk_i), .rst_i(rst_i), .d_i(s1_rb - (s1_tb <<< 1)), .q_o(s2_nb));
    mpdcc_pipe #(.W(W)) u2k (.clk_i(clk_i), .rst_i(rst_i), .d_i(s1_r1a - (s1_t1a <<< 1)), .q_o(s2_n1a));
    mpdcc_pipe #(.W(W)) u2l (.clk_i(clk_i), .rst_i(rst_i), .d_i(s1_r1b - (s1_t1b <<< 1)), .q_o(s2_n1b));
    mpdcc_pipe #(.W(W)) u2m (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s1_ea)), .q_o(s2_ea));
    mpdcc_pipe #(.W(W)) u2n (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s1_eb)), .q_o(s2_eb));
    // e0 of v_n and v_ph: saturate, then delay to the output stage
    wire signed [W-1:0] e0_vn, e0_ph [0:2];
    mpdcc_pipe #(.W(W), .N(15)) u2o (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s1_en)), .q_o(e0_vn));
    generate
        for (g = 0; g < 3; g = g + 1) begin : g_e0ph
            mpdcc_pipe #(.W(W), .N(15)) u (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s1_eph[g])), .q_o(e0_ph[g]));
        end
    endgenerate

    // ------------------------------------------------------- stage 3
    wire signed [W-1:0] s3_pkp, s3_ptr, s3_pts, s3_pk2, s3_kwpb, s3_kwpa, s3_ksrb, s3_ksra;
    wire signed [W-1:0] s3_k1pb, s3_k1pa, s3_s1rb, s3_s1ra, s3_pse, s3_he, s3_ib, s3_ic;
    wire signed [W-1:0] s3_kw, s3_ks, s3_na, s3_nb, s3_n1a, s3_n1b, s3_ea;
    mpdcc_pipe #(.W(W)) u3a (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_p_i), s2_w2)), .q_o(s3_pkp));
    mpdcc_pipe #(.W(W)) u3b (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_3_i), s2_w2)), .q_o(s3_ptr));
    mpdcc_pipe #(.W(W)) u3c (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_3_i), s2_s2)), .q_o(s3_pts));
    mpdcc_pipe #(.W(W)) u3d (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_ks, s2_ks)), .q_o(s3_pk2));
    mpdcc_pipe #(.W(W)) u3e (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_kw, pb)), .q_o(s3_kwpb));
    mpdcc_pipe #(.W(W)) u3f (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_kw, pa)), .q_o(s3_kwpa));
    mpdcc_pipe #(.W(W)) u3g (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_ks, rb)), .q_o(s3_ksrb));
    mpdcc_pipe #(.W(W)) u3h (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_ks, ra)), .q_o(s3_ksra));
    mpdcc_pipe #(.W(W)) u3i (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_kw1, pb)), .q_o(s3_k1pb));
    mpdcc_pipe #(.W(W)) u3j (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_kw1, pa)), .q_o(s3_k1pa));
    mpdcc_pipe #(.W(W)) u3k (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_ks1, rb)), .q_o(s3_s1rb));
    mpdcc_pipe #(.W(W)) u3l (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s2_ks1, ra)), .q_o(s3_s1ra));
    mpdcc_pipe #(.W(W)) u3m (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(s3h_i), s2_eb)), .q_o(s3_pse));
    mpdcc_pipe #(.W(W)) u3n (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(s2_ea, 1)), .q_o(s3_he));
    mpdcc_pipe #(.W(W)) u3o (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_ri - s2_hi), .q_o(s3_ib));
    mpdcc_pipe #(.W(W)) u3p (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - s2_hi - s2_ri), .q_o(s3_ic));
    mpdcc_pipe #(.W(W)) u3q (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_kw), .q_o(s3_kw));
    mpdcc_pipe #(.W(W)) u3r (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_ks), .q_o(s3_ks));
    mpdcc_pipe #(.W(W)) u3s (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_na), .q_o(s3_na));
    mpdcc_pipe #(.W(W)) u3t (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_nb), .q_o(s3_nb));
    mpdcc_pipe #(.W(W)) u3u (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_n1a), .q_o(s3_n1a));
    mpdcc_pipe #(.W(W)) u3v (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_n1b), .q_o(s3_n1b));
    mpdcc_pipe #(.W(W)) u3w (.clk_i(clk_i), .rst_i(rst_i), .d_i(s2_ea), .q_o(s3_ea));

    // ------------------------------------------------------- stage 4
    wire signed [W-1:0] s4_kp, s4_tr, s4_ts, s4_k2, s4_na, s4_nb, s4_ra, s4_rb;
    wire signed [W-1:0] s4_n1a, s4_n1b, s4_r1a, s4_r1b, s4_re, s4_he, s4_kw, s4_ks, s4_ea;
    wire signed [W-1:0] i_abc [0:2];
    mpdcc_pipe #(.W(W)) u4a (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s3_pkp, 13))), .q_o(s4_kp));
    mpdcc_pipe #(.W(W)) u4b (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s3_ptr, 13))), .q_o(s4_tr));
    mpdcc_pipe #(.W(W)) u4c (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s3_pts, 13))), .q_o(s4_ts));
    mpdcc_pipe #(.W(W)) u4d (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s3_pk2, 15))), .q_o(s4_k2));
    mpdcc_pipe #(.W(W)) u4e (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_na + s3_kwpb), .q_o(s4_na));
    mpdcc_pipe #(.W(W)) u4f (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_nb - s3_kwpa), .q_o(s4_nb));
    mpdcc_pipe #(.W(W)) u4g (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - (s3_ksrb <<< 1)), .q_o(s4_ra));
    mpdcc_pipe #(.W(W)) u4h (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_ksra <<< 1), .q_o(s4_rb));
    mpdcc_pipe #(.W(W)) u4i (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_n1a + s3_k1pb), .q_o(s4_n1a));
    mpdcc_pipe #(.W(W)) u4j (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_n1b - s3_k1pa), .q_o(s4_n1b));
    mpdcc_pipe #(.W(W)) u4k (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - (s3_s1rb <<< 1)), .q_o(s4_r1a));
    mpdcc_pipe #(.W(W)) u4l (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_s1ra <<< 1), .q_o(s4_r1b));
    mpdcc_pipe #(.W(W)) u4m (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s3_pse, 14))), .q_o(s4_re));
    mpdcc_pipe #(.W(W)) u4n (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_he), .q_o(s4_he));
    mpdcc_pipe #(.W(W)) u4o (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_kw), .q_o(s4_kw));
    mpdcc_pipe #(.W(W)) u4p (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_ks), .q_o(s4_ks));
    mpdcc_pipe #(.W(W)) u4q (.clk_i(clk_i), .rst_i(rst_i), .d_i(s3_ea), .q_o(s4_ea));
    // i_abc = inv_clarke_q(i_ab): [i_a, sat(-h + r), sat(-h - r)]
    mpdcc_pipe #(.W(W)) u4r (.clk_i(clk_i), .rst_i(rst_i), .d_i(ia), .q_o(i_abc[0]));
    mpdcc_pipe #(.W(W)) u4s (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s3_ib)), .q_o(i_abc[1]));
    mpdcc_pipe #(.W(W)) u4t (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s3_ic)), .q_o(i_abc[2]));

    // ------------------------------------------------------- stage 5
    wire signed [W-1:0] s5_pkw3, s5_pks3, s5_kppa, s5_kppb, s5_k2ra, s5_k2rb;
    wire signed [W-1:0] s5_rta, s5_rtb, s5_r1a, s5_r1b, s5_nqa, s5_nqb, s5_eb, s5_ec, s5_ea;
    mpdcc_pipe #(.W(W)) u5a (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s4_kw, s4_tr)), .q_o(s5_pkw3));
    mpdcc_pipe #(.W(W)) u5b (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s4_ks, s4_ts)), .q_o(s5_pks3));
    mpdcc_pipe #(.W(W)) u5c (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s4_kp, pa)), .q_o(s5_kppa));
    mpdcc_pipe #(.W(W)) u5d (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s4_kp, pb)), .q_o(s5_kppb));
    mpdcc_pipe #(.W(W)) u5e (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s4_k2, ra)), .q_o(s5_k2ra));
    mpdcc_pipe #(.W(W)) u5f (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s4_k2, rb)), .q_o(s5_k2rb));
    mpdcc_pipe #(.W(W)) u5g (.clk_i(clk_i), .rst_i(rst_i), .d_i(s4_ra - s4_na), .q_o(s5_rta));
    mpdcc_pipe #(.W(W)) u5h (.clk_i(clk_i), .rst_i(rst_i), .d_i(s4_rb - s4_nb), .q_o(s5_rtb));
    mpdcc_pipe #(.W(W)) u5i (.clk_i(clk_i), .rst_i(rst_i), .d_i(s4_r1a - s4_n1a), .q_o(s5_r1a));
    mpdcc_pipe #(.W(W)) u5j (.clk_i(clk_i), .rst_i(rst_i), .d_i(s4_r1b - s4_n1b), .q_o(s5_r1b));
    mpdcc_pipe #(.W(W)) u5k (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s4_na, 15))), .q_o(s5_nqa));
    mpdcc_pipe #(.W(W)) u5l (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s4_nb, 15))), .q_o(s5_nqb));
    mpdcc_pipe #(.W(W)) u5m (.clk_i(clk_i), .rst_i(rst_i), .d_i(s4_re - s4_he), .q_o(s5_eb));
    mpdcc_pipe #(.W(W)) u5n (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - s4_he - s4_re), .q_o(s5_ec));
    mpdcc_pipe #(.W(W)) u5o (.clk_i(clk_i), .rst_i(rst_i), .d_i(s4_ea), .q_o(s5_ea));
    // P_n, P_ph (f27), delayed to the output stage
    generate
        for (g = 0; g < 3; g = g + 1) begin : g_p
            wire signed [W-1:0] pn5, pph5;
            mpdcc_pipe #(.W(W)) un (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_n_i), i_abc[g])), .q_o(pn5));
            mpdcc_pipe #(.W(W)) up (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_ph_i), i_abc[g])), .q_o(pph5));
            wire signed [W-1:0] pn16, pph16;
            mpdcc_pipe #(.W(W), .N(11)) dn (.clk_i(clk_i), .rst_i(rst_i), .d_i(pn5), .q_o(pn16));
            mpdcc_pipe #(.W(W), .N(11)) dp (.clk_i(clk_i), .rst_i(rst_i), .d_i(pph5), .q_o(pph16));
            assign pn_o[32*g +: 32] = pn16[31:0];
            assign pph_o[32*g +: 32] = pph16[31:0];
        end
    endgenerate
    // e0 of the currents: e_abc = inv_clarke_q(e_ab), delayed to stage 16
    wire signed [W-1:0] e0_i3 [0:2];
    mpdcc_pipe #(.W(W), .N(11)) u5p (.clk_i(clk_i), .rst_i(rst_i), .d_i(s5_ea), .q_o(e0_i3[0]));
    mpdcc_pipe #(.W(W), .N(11)) u5q (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s5_eb)), .q_o(e0_i3[1]));
    mpdcc_pipe #(.W(W), .N(11)) u5r (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(s5_ec)), .q_o(e0_i3[2]));

    // ------------------------------------------------------- stage 6
    wire signed [W-1:0] s6_kw3, s6_ks3, s6_cora, s6_corb, s6_pda, s6_pdb;
    wire signed [W-1:0] s6_rta, s6_rtb, s6_r1a, s6_r1b;
    mpdcc_pipe #(.W(W)) u6a (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s5_pkw3, 14))), .q_o(s6_kw3));
    mpdcc_pipe #(.W(W)) u6b (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(s5_pks3, 14))), .q_o(s6_ks3));
    mpdcc_pipe #(.W(W)) u6c (.clk_i(clk_i), .rst_i(rst_i), .d_i(s5_kppa + (s5_k2ra <<< 1)), .q_o(s6_cora));
    mpdcc_pipe #(.W(W)) u6d (.clk_i(clk_i), .rst_i(rst_i), .d_i(s5_kppb + (s5_k2rb <<< 1)), .q_o(s6_corb));
    mpdcc_pipe #(.W(W)) u6e (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_d_i), s5_nqa)), .q_o(s6_pda));
    mpdcc_pipe #(.W(W)) u6f (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(c_d_i), s5_nqb)), .q_o(s6_pdb));
    mpdcc_pipe #(.W(W)) u6g (.clk_i(clk_i), .rst_i(rst_i), .d_i(s5_rta), .q_o(s6_rta));
    mpdcc_pipe #(.W(W)) u6h (.clk_i(clk_i), .rst_i(rst_i), .d_i(s5_rtb), .q_o(s6_rtb));
    mpdcc_pipe #(.W(W)) u6i (.clk_i(clk_i), .rst_i(rst_i), .d_i(s5_r1a), .q_o(s6_r1a));
    mpdcc_pipe #(.W(W)) u6j (.clk_i(clk_i), .rst_i(rst_i), .d_i(s5_r1b), .q_o(s6_r1b));

    // ------------------------------------------------------- stage 7
    wire signed [W-1:0] s7_ka, s7_wa, s7_kb, s7_wb, s7_dca, s7_dcb, s7_cora, s7_corb;
    mpdcc_pipe #(.W(W)) u7a (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s6_ks3, rb)), .q_o(s7_ka));
    mpdcc_pipe #(.W(W)) u7b (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s6_kw3, pb)), .q_o(s7_wa));
    mpdcc_pipe #(.W(W)) u7c (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s6_ks3, ra)), .q_o(s7_kb));
    mpdcc_pipe #(.W(W)) u7d (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(s6_kw3, pa)), .q_o(s7_wb));
    mpdcc_pipe #(.W(W)) u7e (.clk_i(clk_i), .rst_i(rst_i), .d_i((s6_pda <<< 1) - s6_cora), .q_o(s7_dca));
    mpdcc_pipe #(.W(W)) u7f (.clk_i(clk_i), .rst_i(rst_i), .d_i((s6_pdb <<< 1) - s6_corb), .q_o(s7_dcb));
    mpdcc_pipe #(.W(W)) u7g (.clk_i(clk_i), .rst_i(rst_i), .d_i(s6_cora), .q_o(s7_cora));
    mpdcc_pipe #(.W(W)) u7h (.clk_i(clk_i), .rst_i(rst_i), .d_i(s6_corb), .q_o(s7_corb));
    wire signed [W-1:0] rt9a, rt9b, r19a, r19b;
    mpdcc_pipe #(.W(W), .N(3)) u7i (.clk_i(clk_i), .rst_i(rst_i), .d_i(s6_rta), .q_o(rt9a));
    mpdcc_pipe #(.W(W), .N(3)) u7j (.clk_i(clk_i), .rst_i(rst_i), .d_i(s6_rtb), .q_o(rt9b));
    mpdcc_pipe #(.W(W), .N(3)) u7k (.clk_i(clk_i), .rst_i(rst_i), .d_i(s6_r1a), .q_o(r19a));
    mpdcc_pipe #(.W(W), .N(3)) u7l (.clk_i(clk_i), .rst_i(rst_i), .d_i(s6_r1b), .q_o(r19b));

    // ------------------------------------------------------- stages 8-9
    // cub_a = 2 ks3 i*_b + kw3 psi_b; cub_b = -(2 ks3 i*_a + kw3 psi_a)
    wire signed [W-1:0] s8_cua, s8_tb, s9_cua, s9_cub, s9_dca, s9_dcb, s9_c1a, s9_c1b;
    wire signed [W-1:0] s8_dca, s8_dcb, s8_cora, s8_corb;
    mpdcc_pipe #(.W(W)) u8a (.clk_i(clk_i), .rst_i(rst_i), .d_i((s7_ka <<< 1) + s7_wa), .q_o(s8_cua));
    mpdcc_pipe #(.W(W)) u8b (.clk_i(clk_i), .rst_i(rst_i), .d_i((s7_kb <<< 1) + s7_wb), .q_o(s8_tb));
    mpdcc_pipe #(.W(W)) u8c (.clk_i(clk_i), .rst_i(rst_i), .d_i(s7_dca), .q_o(s8_dca));
    mpdcc_pipe #(.W(W)) u8d (.clk_i(clk_i), .rst_i(rst_i), .d_i(s7_dcb), .q_o(s8_dcb));
    mpdcc_pipe #(.W(W)) u8e (.clk_i(clk_i), .rst_i(rst_i), .d_i(s7_cora), .q_o(s8_cora));
    mpdcc_pipe #(.W(W)) u8f (.clk_i(clk_i), .rst_i(rst_i), .d_i(s7_corb), .q_o(s8_corb));
    mpdcc_pipe #(.W(W)) u9a (.clk_i(clk_i), .rst_i(rst_i), .d_i(s8_cua), .q_o(s9_cua));
    mpdcc_pipe #(.W(W)) u9b (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - s8_tb), .q_o(s9_cub));
    mpdcc_pipe #(.W(W)) u9c (.clk_i(clk_i), .rst_i(rst_i), .d_i(s8_dca), .q_o(s9_dca));
    mpdcc_pipe #(.W(W)) u9d (.clk_i(clk_i), .rst_i(rst_i), .d_i(s8_dcb), .q_o(s9_dcb));
    mpdcc_pipe #(.W(W)) u9e (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(s8_cora <<< 3, 6)), .q_o(s9_c1a));
    mpdcc_pipe #(.W(W)) u9f (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(s8_corb <<< 3, 6)), .q_o(s9_c1b));

    // ----------------------------------------------- stages 10-12: x_a, x_b
    // x[m][0..1] for the nodes m = 0..3, x[4] for the one step (Q2.13)
    wire signed [W-1:0] x12 [0:4][0:1];
    wire signed [W-1:0] rt9 [0:1], dc9 [0:1], cu9 [0:1], c19 [0:1], r19 [0:1];
    assign rt9[0] = rt9a; assign rt9[1] = rt9b;
    assign dc9[0] = s9_dca; assign dc9[1] = s9_dcb;
    assign cu9[0] = s9_cua; assign cu9[1] = s9_cub;
    assign c19[0] = s9_c1a; assign c19[1] = s9_c1b;
    assign r19[0] = r19a; assign r19[1] = r19b;
    generate
        for (g = 0; g < 2; g = g + 1) begin : g_ab
            genvar m;
            for (m = 0; m < 4; m = m + 1) begin : g_node
                wire signed [W-1:0] t10, cu10, t11;
                mpdcc_pipe #(.W(W)) ua (.clk_i(clk_i), .rst_i(rst_i),
                    .d_i((rt9[g] <<< m) + (dc9[g] <<< (2 * m))), .q_o(t10));
                mpdcc_pipe #(.W(W)) ub (.clk_i(clk_i), .rst_i(rst_i), .d_i(cu9[g] <<< (3 * m)), .q_o(cu10));
                mpdcc_pipe #(.W(W)) uc (.clk_i(clk_i), .rst_i(rst_i), .d_i(t10 + cu10), .q_o(t11));
                mpdcc_pipe #(.W(W)) ud (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(t11, 15)), .q_o(x12[m][g]));
            end
            wire signed [W-1:0] d10, cu10, d11;
            mpdcc_pipe #(.W(W)) ue (.clk_i(clk_i), .rst_i(rst_i), .d_i(r19[g] - c19[g]), .q_o(d10));
            mpdcc_pipe #(.W(W)) uf (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(cu9[g] <<< 3, 9)), .q_o(cu10));
            mpdcc_pipe #(.W(W)) ug (.clk_i(clk_i), .rst_i(rst_i), .d_i(d10 + cu10), .q_o(d11));
            mpdcc_pipe #(.W(W)) uh (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(d11, 18)), .q_o(x12[4][g]));
        end
    endgenerate

    // ---------------------------------- stages 13-16: inverse Clarke, output
    generate
        for (g = 0; g < 5; g = g + 1) begin : g_ic
            wire signed [W-1:0] xa13, xb13, xa14, h14, p14, xa15, h15, r15, b16, c16, xa16;
            mpdcc_pipe #(.W(W)) ua (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(x12[g][0])), .q_o(xa13));
            mpdcc_pipe #(.W(W)) ub (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(x12[g][1])), .q_o(xb13));
            mpdcc_pipe #(.W(W)) uc (.clk_i(clk_i), .rst_i(rst_i), .d_i(pr(sx(s3h_i), xb13)), .q_o(p14));
            mpdcc_pipe #(.W(W)) ud (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(xa13, 1)), .q_o(h14));
            mpdcc_pipe #(.W(W)) ue (.clk_i(clk_i), .rst_i(rst_i), .d_i(xa13), .q_o(xa14));
            mpdcc_pipe #(.W(W)) uf (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat(rnd(p14, 14))), .q_o(r15));
            mpdcc_pipe #(.W(W)) ug (.clk_i(clk_i), .rst_i(rst_i), .d_i(h14), .q_o(h15));
            mpdcc_pipe #(.W(W)) uh (.clk_i(clk_i), .rst_i(rst_i), .d_i(xa14), .q_o(xa15));
            mpdcc_pipe #(.W(W)) ui (.clk_i(clk_i), .rst_i(rst_i), .d_i(r15 - h15), .q_o(b16));
            mpdcc_pipe #(.W(W)) uj (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - h15 - r15), .q_o(c16));
            mpdcc_pipe #(.W(W)) uk (.clk_i(clk_i), .rst_i(rst_i), .d_i(xa15), .q_o(xa16));
            wire signed [W-1:0] ob = sat(b16), oc = sat(c16);
            if (g < 4) begin : g_dn
                assign dn_o[16*(3*g+0) +: 16] = xa16[15:0];
                assign dn_o[16*(3*g+1) +: 16] = ob[15:0];
                assign dn_o[16*(3*g+2) +: 16] = oc[15:0];
            end else begin : g_d1
                assign dn1_o[15:0]  = xa16[15:0];
                assign dn1_o[31:16] = ob[15:0];
                assign dn1_o[47:32] = oc[15:0];
            end
        end
    endgenerate
    assign e0_o[15:0]    = e0_i3[0][15:0];
    assign e0_o[31:16]   = e0_i3[1][15:0];
    assign e0_o[47:32]   = e0_i3[2][15:0];
    assign e0_o[63:48]   = e0_vn[15:0];
    assign e0_o[79:64]   = e0_ph[0][15:0];
    assign e0_o[95:80]   = e0_ph[1][15:0];
    assign e0_o[111:96]  = e0_ph[2][15:0];
endmodule

`default_nettype wire
