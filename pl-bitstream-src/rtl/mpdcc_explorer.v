// mpdcc_explorer: one MPDCC explorer unit (models::mpdcc::fpga::explore of
// the frozen core, Structure::CORE), pipelined: one candidate every II
// clocks, fixed latency LAT = 41 + max(II - 3, 0) cycles.
//
// II = 1: seven search lanes, one per output, one candidate per clock.
// II = 2..7: ceil(7 / II) lanes shared by the seven outputs: the node
// changes of a candidate are held at stage 15 and lane i searches outputs
// i, i + L, i + 2 L, ... on successive clocks (L lanes); a running minimum
// per lane collects its l_j, and the lanes' minima meet where L* is formed
// (one comparison per clock in each). The caller gives an explorer at most one candidate
// every II clocks (mpdcc_core's scheduler does). Stage numbers below are
// those of II = 1; with II > 3 everything from stage 30 on is II - 3
// stages later.
//
// Per candidate s (three 3-bit positions) it predicts the seven output
// errors at the nodes k + 8, 16, 32, 64 (node changes, eq. 18b with the
// capacitor drift, the damped voltage term), the one-step change (lazy-check
// arithmetic: feasibility at k + 1 and J_dl of eq. 15), runs the seven
// search lanes (mpdcc_lane, Algorithm 2) and forms
//   L*   = min_j l_j, 0 when infeasible at k + 1 or outside at k, else >= 1
//   J    = f_s recip[L*] + round(lambda_n v_n(k + L*)^2)   (UQ15.17;
//          0xFFFFFFFF = +inf for L* = 0; saturates at 0xFFFFFFFE)
//   J_dl = max_j (|e_j(k+1)| - bnd_j)                       (Q2.13)
// The common terms of the decision (e0, dn, dn1, P_n, P_ph, v_n, v_ph, s(k-1))
// and the design constants are inputs that stay constant while the
// decision's candidates are in flight (registers of the scheduler).
//
// Formats (docs/mpdcc-fpga.md): e0, dn, dn1, v_n, v_ph, vdc_half Q2.13;
// g3, gd Q1.14; g3_1 f17; P_n, P_ph f27 (32 bits); bnd Q2.13 >= 0;
// lambda_n UQ8.8; node changes Q4.13 in 18 bits, saturated at
// +-(2^17 - 1); wide sums exact; every rounding is round half up,
// rshift_round(x, s) = (x >>> s) + x[s-1], as in models::fixedpoint.
//
// Stages (n = register loaded at the n-th edge after in_valid_i); at most
// one multiplier or one adder between registers:
//   1  positions; v0 = X +- Y (one add/sub, no position uses a rail and the
//      neutral point); np_a P_n,a + np_b P_n,b; -ph_current P_ph; f_s
//   2  inv_n (+ np_c P_n,c); -inv_ph; v0_a + v0_b; 3 v0
//   3  t = n inv_n + ph inv_ph; sum v0; inverter rows rounded
//   4  dv = -t; u0 = 3 v0 - sum; inverter rows clamped
//   5  vh = rnd(dv, 15), v1r = rnd(dv, 18); g3 u0, gd u0 (phases a, b)
//   6  vh_a - vh_b, vh_a - vh_c, vh_b - vh_c; v1 = v0 + v1r; sums of a, b
//   7  uh_a, uh_b; v1 differences; g3 u0_c = -(sum)
//   8  g3 uh (a, b); u1_a, u1_b
//   9  g3_1 u1 (a, b); -gd u0_c - g3 uh_a
//  10  Q = g3 uh - gd u0 (Q_c: - g3 uh_b); sum of g3_1 u1
//  11  g_m = m g3 u0 + m^2 Q (shifts, m = 1, 2, 4, 8); g3_1 u1_c = -(sum)
//  12  rnd(g_m, 14); rnd(g3_1 u1, 17)
//  13  dn_m - rnd(g_m, 14); sat16
//  14  node changes clamped; dn1 - ...
//  15  one-step changes saturated
//  15..26  the seven lanes (mpdcc_lane); beside them e1 = e0 + d1 (16),
//      |e1|, |e1| - bnd, a 3-level max tree (J_dl, 21), |e0| <= bnd
//      (inside at k)
//  27..29  3-level min tree of l_j
//  30  L*
//  31  recip ROM; piece of L*, L* - start, slope of v_n on it
//  32  (L* - start) slope; f_s recip (shift and add, 1/2)
//  33  rnd(., ls); f_s recip (2/2)   34  + n_(i-1)   35  + e0_vn   36  sat16
//  37  square   38  x lambda_n   39  rnd(., 17)   40  + J_sw   41  J
`default_nettype none

module mpdcc_explorer #(
    parameter integer II = 1  // clocks per candidate (1..7)
) (
    input  wire               clk_i,
    input  wire               rst_i,
    // one candidate per clock
    input  wire               in_valid_i,
    input  wire        [8:0]  s_i,        // {s_c, s_b, s_a}
    // common terms of the decision (constant while candidates are in flight)
    input  wire        [8:0]  s_prev_i,   // {c, b, a}
    input  wire        [111:0] e0_i,      // 7 x Q2.13: i_abc, v_n, v_ph,abc
    input  wire        [191:0] dn_i,      // 4 nodes x 3 phases x Q2.13, [(3 m + ph) 16 +: 16]
    input  wire        [47:0] dn1_i,      // 3 x Q2.13
    input  wire        [95:0] pn_i,       // 3 x f27 (32 bits)
    input  wire        [95:0] pph_i,      // 3 x f27
    input  wire signed [15:0] v_n_i,
    input  wire        [47:0] v_ph_i,     // 3 x Q2.13
    // design constants
    input  wire signed [15:0] vdc_half_i,
    input  wire signed [15:0] g3_i,
    input  wire signed [15:0] gd_i,
    input  wire signed [15:0] g3_1_i,
    input  wire        [111:0] bnd_i,     // 7 x Q2.13 (>= 0)
    input  wire        [15:0] lambda_n_i,
    // result
    output wire               out_valid_o,
    output wire        [8:0]  s_o,
    output wire        [7:0]  l_star_o,
    output wire        [31:0] cost_o,
    output wire signed [31:0] j_dl_o,
    output wire        [3:0]  fs_o,
    output wire        [111:0] d0_o       // 7 x Q2.13: node k + 8, saturated
);
    localparam integer W = 48;
    localparam signed [W-1:0] NODE_MAX = 48'sd131071;
    // stages the shared lanes add (II > 3: the running minimum ends later
    // than the II = 1 min tree)
    localparam integer EXTRA = (II > 3) ? II - 3 : 0;
    localparam integer LAT = 41 + EXTRA;
    // search lanes
    localparam integer NL = (7 + II - 1) / II;
    // J_dl words (Q2.13 differences, |e1| - bnd: |value| < 2^17)
    localparam integer JW = 20;

    // ---------------------------------------------------------------- valid
    wire [LAT:0] v;
    assign v[0] = in_valid_i;
    genvar gi;
    generate
        for (gi = 0; gi < LAT; gi = gi + 1) begin : g_v
            mpdcc_pipe #(.W(1), .N(1)) u_v (.clk_i(clk_i), .rst_i(rst_i), .d_i(v[gi]), .q_o(v[gi+1]));
        end
    endgenerate
    assign out_valid_o = v[LAT];

    // ------------------------------------------------------------- helpers
    function automatic signed [W-1:0] rnd(input signed [W-1:0] x, input integer s);
        rnd = (x >>> s) + $signed({{(W - 1) {1'b0}}, x[s-1]});
    endfunction
    function automatic signed [15:0] sat16(input signed [W-1:0] x);
        if (x > 48'sd32767) sat16 = 16'sh7FFF;
        else if (x < -48'sd32768) sat16 = 16'sh8000;
        else sat16 = x[15:0];
    endfunction
    function automatic signed [17:0] clamp18(input signed [W-1:0] x);
        if (x > NODE_MAX) clamp18 = 18'sd131071;
        else if (x < -NODE_MAX) clamp18 = -18'sd131071;
        else clamp18 = x[17:0];
    endfunction
    function automatic signed [W-1:0] sx16(input [15:0] x);
        sx16 = {{(W - 16) {x[15]}}, x};
    endfunction
    function automatic signed [W-1:0] sx32(input [31:0] x);
        sx32 = {{(W - 32) {x[31]}}, x};
    endfunction
    function automatic [7:0] umin(input [7:0] a, input [7:0] b);
        umin = (b < a) ? b : a;
    endfunction

    // ---------------------------------------------------- stage 1: positions
    // ANPC position table (models::mpdcc::anpc::TABLE): v0 = X +- Y with
    // X in {0, v_n, vdc/2, v_ph} and Y in {0, vdc/2, v_ph}; np = n_coef;
    // ph_current in {-1, 0, 1}.
    wire signed [W-1:0] v0_d [0:2];
    wire signed [W-1:0] invp_d [0:2];
    wire        [2:0]   ncoef_d;
    wire signed [1:0]   phc_d [0:2];
    wire        [2:0]   pt [0:2];
    generate
        for (gi = 0; gi < 3; gi = gi + 1) begin : g_pos
            wire [2:0] sp = s_i[3*gi +: 3];
            // 16-bit operands: the sum and difference are exact in 17 bits,
            // -P_ph in 33 (a short carry chain; the registers hold only
            // those bits and are sign-extended to W where read)
            wire signed [16:0] vph = {v_ph_i[16*gi+15], v_ph_i[16*gi +: 16]};
            wire signed [16:0] vdc = {vdc_half_i[15], vdc_half_i};
            wire signed [16:0] vn = {v_n_i[15], v_n_i};
            wire signed [32:0] pph = {pph_i[32*gi+31], pph_i[32*gi +: 32]};
            // The seven positions from the held inputs, every one in
            // parallel: the candidate only selects one (a LUT multiplexer),
            // so no carry chain follows the candidate's decode (8.04 ns
            // when the candidate chose the operands of one add/sub).
            wire signed [16:0] p0 = 17'sd0 - vdc, p1 = vph - vdc, p2 = vn - vph;
            wire signed [16:0] p5 = vn + vph, p6 = vdc - vph;
            reg signed [16:0] pos;
            reg signed [1:0] phc, phcur;
            reg n;
            always @(*) begin
                case (sp)
                    3'd0: begin pos = p0;  n = 1'b0; phc = 2'sd0;  phcur = 2'sd0;  end
                    3'd1: begin pos = p1;  n = 1'b0; phc = 2'sd1;  phcur = -2'sd1; end
                    3'd2: begin pos = p2;  n = 1'b1; phc = -2'sd1; phcur = 2'sd1;  end
                    3'd3: begin pos = vn;  n = 1'b1; phc = 2'sd0;  phcur = 2'sd0;  end
                    3'd4: begin pos = vn;  n = 1'b1; phc = 2'sd0;  phcur = 2'sd0;  end
                    3'd5: begin pos = p5;  n = 1'b1; phc = 2'sd1;  phcur = -2'sd1; end
                    3'd6: begin pos = p6;  n = 1'b0; phc = -2'sd1; phcur = 2'sd1;  end
                    default: begin pos = vdc; n = 1'b0; phc = 2'sd0; phcur = 2'sd0; end
                endcase
            end
            // -ph_current P_ph: 0 - P_ph, +P_ph or 0 (one add/sub).
            wire signed [32:0] ip = (phcur == 2'sd1) ? (33'sd0 - pph) : (phcur == -2'sd1) ? pph : 33'sd0;
            wire [2:0] dd = s_prev_i[3*gi +: 3] ^ sp;
            assign pt[gi] = {1'b0, dd[2], 1'b0} + {2'b0, dd[1]} + {2'b0, dd[0]};
            wire signed [16:0] v0n;
            wire signed [32:0] ipn;
            mpdcc_pipe #(.W(17), .N(1)) u_v0 (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(pos), .q_o(v0n));
            mpdcc_pipe #(.W(33), .N(1)) u_ip (.clk_i(clk_i), .rst_i(rst_i), .d_i(ip), .q_o(ipn));
            assign v0_d[gi] = {{(W - 17) {v0n[16]}}, v0n};
            assign invp_d[gi] = {{(W - 33) {ipn[32]}}, ipn};
            mpdcc_pipe #(.W(1), .N(1)) u_n (.clk_i(clk_i), .rst_i(rst_i), .d_i(n), .q_o(ncoef_d[gi]));
            mpdcc_pipe #(.W(2), .N(1)) u_phc (.clk_i(clk_i), .rst_i(rst_i), .d_i(phc), .q_o(phc_d[gi]));
        end
    endgenerate
    wire signed [W-1:0] pn2 = sx32(pn_i[95:64]);
    wire [3:0] fs1 = {1'b0, pt[0]} + {1'b0, pt[1]} + {1'b0, pt[2]};
    // two 32-bit terms: exact in 33 bits
    wire signed [32:0] pn0n = {pn_i[31], pn_i[31:0]};
    wire signed [32:0] pn1n = {pn_i[63], pn_i[63:32]};
    wire signed [32:0] ia01n;
    mpdcc_pipe #(.W(33), .N(1)) u_ia01 (.clk_i(clk_i), .rst_i(rst_i),
        .d_i((g_pos[0].n ? pn0n : 33'sd0) + (g_pos[1].n ? pn1n : 33'sd0)), .q_o(ia01n));
    wire signed [W-1:0] ia01_q = {{(W - 33) {ia01n[32]}}, ia01n};
    wire [8:0] s_out;
    mpdcc_pipe #(.W(9), .N(LAT)) u_s (.clk_i(clk_i), .rst_i(rst_i), .d_i(s_i), .q_o(s_out));
    wire [3:0] fs1_q;
    mpdcc_pipe #(.W(4), .N(1)) u_fs1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(fs1), .q_o(fs1_q));

    // --------------------------------------------------------------- stage 2
    wire signed [W-1:0] inv0_2;
    mpdcc_pipe #(.W(W), .N(1)) u_inv0 (.clk_i(clk_i), .rst_i(rst_i),
        .d_i(ia01_q + (ncoef_d[2] ? pn2 : 0)), .q_o(inv0_2));
    wire signed [W-1:0] s01_2;
    mpdcc_pipe #(.W(W), .N(1)) u_s01 (.clk_i(clk_i), .rst_i(rst_i), .d_i(v0_d[0] + v0_d[1]), .q_o(s01_2));
    wire signed [W-1:0] v0c_2;  // v0 of phase c at stage 2 (the sum)
    mpdcc_pipe #(.W(W), .N(1)) u_v0c (.clk_i(clk_i), .rst_i(rst_i), .d_i(v0_d[2]), .q_o(v0c_2));
    wire signed [W-1:0] v0x3_2 [0:2];
    wire signed [W-1:0] invp_2 [0:2];
    wire signed [W-1:0] ninvp_2 [0:2];
    wire        [2:0]   ncoef_2;
    wire signed [1:0]   phc_2 [0:2];
    generate
        for (gi = 0; gi < 3; gi = gi + 1) begin : g_s2
            mpdcc_pipe #(.W(W), .N(1)) u_b (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(v0_d[gi] + (v0_d[gi] <<< 1)), .q_o(v0x3_2[gi]));
            mpdcc_pipe #(.W(W), .N(1)) u_c (.clk_i(clk_i), .rst_i(rst_i), .d_i(invp_d[gi]), .q_o(invp_2[gi]));
            mpdcc_pipe #(.W(W), .N(1)) u_d (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - invp_d[gi]), .q_o(ninvp_2[gi]));
            mpdcc_pipe #(.W(1), .N(1)) u_e (.clk_i(clk_i), .rst_i(rst_i), .d_i(ncoef_d[gi]), .q_o(ncoef_2[gi]));
            mpdcc_pipe #(.W(2), .N(1)) u_f (.clk_i(clk_i), .rst_i(rst_i), .d_i(phc_d[gi]), .q_o(phc_2[gi]));
        end
    endgenerate
    wire [3:0] fs_out;
    mpdcc_pipe #(.W(4), .N(LAT - 1)) u_fs (.clk_i(clk_i), .rst_i(rst_i), .d_i(fs1_q), .q_o(fs_out));

    // --------------------------------------------------------------- stage 3
    // t = n inv_n + ph_coef inv_ph (dv = -t); inverter rows of the nodes and
    // of the one step: inv (f27) to Q4.13 (rnd 14 - i) and to Q2.13 (rnd 17).
    wire signed [W-1:0] s0_3;
    mpdcc_pipe #(.W(W), .N(1)) u_s0 (.clk_i(clk_i), .rst_i(rst_i), .d_i(s01_2 + v0c_2), .q_o(s0_3));
    wire signed [W-1:0] t_3 [0:2];
    wire signed [W-1:0] v0x3_3 [0:2];
    // inverter rows: j = 0 (v_n), 1..3 (v_ph); value inv_j
    wire signed [W-1:0] invj_2 [0:3];
    assign invj_2[0] = inv0_2;
    assign invj_2[1] = invp_2[0];
    assign invj_2[2] = invp_2[1];
    assign invj_2[3] = invp_2[2];
    wire signed [W-1:0] invr_3 [0:3][0:4];  // [j][node 0..3, one step 4]
    generate
        for (gi = 0; gi < 3; gi = gi + 1) begin : g_s3
            wire signed [W-1:0] a = ncoef_2[gi] ? inv0_2 : 0;
            wire signed [W-1:0] b = (phc_2[gi] == 2'sd1) ? invp_2[gi] :
                                    (phc_2[gi] == -2'sd1) ? ninvp_2[gi] : 0;
            mpdcc_pipe #(.W(W), .N(1)) u_t (.clk_i(clk_i), .rst_i(rst_i), .d_i(a + b), .q_o(t_3[gi]));
            mpdcc_pipe #(.W(W), .N(1)) u_x (.clk_i(clk_i), .rst_i(rst_i), .d_i(v0x3_2[gi]), .q_o(v0x3_3[gi]));
        end
        for (gi = 0; gi < 4; gi = gi + 1) begin : g_inv
            genvar m;
            for (m = 0; m < 4; m = m + 1) begin : g_node
                mpdcc_pipe #(.W(W), .N(1)) u_r (.clk_i(clk_i), .rst_i(rst_i),
                    .d_i(rnd(invj_2[gi], 14 - m)), .q_o(invr_3[gi][m]));
            end
            mpdcc_pipe #(.W(W), .N(1)) u_r1 (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(rnd(invj_2[gi], 17)), .q_o(invr_3[gi][4]));
        end
    endgenerate

    // --------------------------------------------------------------- stage 4
    wire signed [W-1:0] dv_4 [0:2];
    wire signed [W-1:0] u0_4 [0:2];
    // inverter rows, clamped / saturated, delayed to stage 14
    wire [17:0] invn_14 [0:3][0:3];
    wire [15:0] inv1_15 [0:3];
    generate
        for (gi = 0; gi < 3; gi = gi + 1) begin : g_s4
            mpdcc_pipe #(.W(W), .N(1)) u_dv (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - t_3[gi]), .q_o(dv_4[gi]));
            mpdcc_pipe #(.W(W), .N(1)) u_u0 (.clk_i(clk_i), .rst_i(rst_i), .d_i(v0x3_3[gi] - s0_3), .q_o(u0_4[gi]));
        end
        for (gi = 0; gi < 4; gi = gi + 1) begin : g_invc
            genvar m;
            for (m = 0; m < 4; m = m + 1) begin : g_node
                mpdcc_pipe #(.W(18), .N(11)) u_c (.clk_i(clk_i), .rst_i(rst_i),
                    .d_i(clamp18(invr_3[gi][m])), .q_o(invn_14[gi][m]));
            end
            mpdcc_pipe #(.W(16), .N(12)) u_c1 (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(sat16(invr_3[gi][4])), .q_o(inv1_15[gi]));
        end
    endgenerate

    // --------------------------------------------------------------- stage 5
    // u0, uh and u1 sum to zero over the phases (3 x - sum x), so the
    // products of phase c are minus the sum of those of a and b (exact:
    // the 25-bit operands never wrap, |u| < 2^21): two multipliers per
    // product row instead of three.
    wire signed [W-1:0] vh_5 [0:2];
    wire signed [W-1:0] v1r_5 [0:2];
    wire signed [W-1:0] p0_5 [0:1];
    wire signed [W-1:0] r_5 [0:1];
    wire signed [W-1:0] v0_5 [0:2];
    generate
        for (gi = 0; gi < 3; gi = gi + 1) begin : g_s5
            mpdcc_pipe #(.W(W), .N(1)) u_a (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(dv_4[gi], 15)), .q_o(vh_5[gi]));
            mpdcc_pipe #(.W(W), .N(1)) u_b (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(dv_4[gi], 18)), .q_o(v1r_5[gi]));
            // v0 from stage 1 to 5 in a delay line (an SRL: no reset, see
            // mpdcc_pipe), 17 bits
            wire signed [16:0] v0n_5;
            mpdcc_pipe #(.W(17), .N(4)) u_e (.clk_i(clk_i), .rst_i(rst_i), .d_i(v0_d[gi][16:0]), .q_o(v0n_5));
            assign v0_5[gi] = {{(W - 17) {v0n_5[16]}}, v0n_5};
        end
        for (gi = 0; gi < 2; gi = gi + 1) begin : g_s5m
            wire signed [24:0] u0n = u0_4[gi][24:0];
            wire signed [40:0] p0 = g3_i * u0n;
            wire signed [40:0] r = gd_i * u0n;
            mpdcc_pipe #(.W(W), .N(1)) u_c (.clk_i(clk_i), .rst_i(rst_i),
                .d_i({{(W - 41) {p0[40]}}, p0}), .q_o(p0_5[gi]));
            mpdcc_pipe #(.W(W), .N(1)) u_d (.clk_i(clk_i), .rst_i(rst_i),
                .d_i({{(W - 41) {r[40]}}, r}), .q_o(r_5[gi]));
        end
    endgenerate

    // ----------------------------------------------------------- stages 6-8
    // uh_a = (vh_a - vh_b) + (vh_a - vh_c), uh_b = (vh_b - vh_c) - (vh_a -
    // vh_b) (= 3 vh - sum vh), two adders deep; likewise u1 one stage later.
    wire signed [W-1:0] xh_6, yh_6, zh_6, ps_6;
    mpdcc_pipe #(.W(W), .N(1)) u_xh (.clk_i(clk_i), .rst_i(rst_i), .d_i(vh_5[0] - vh_5[1]), .q_o(xh_6));
    mpdcc_pipe #(.W(W), .N(1)) u_yh (.clk_i(clk_i), .rst_i(rst_i), .d_i(vh_5[0] - vh_5[2]), .q_o(yh_6));
    mpdcc_pipe #(.W(W), .N(1)) u_zh (.clk_i(clk_i), .rst_i(rst_i), .d_i(vh_5[1] - vh_5[2]), .q_o(zh_6));
    mpdcc_pipe #(.W(W), .N(1)) u_ps (.clk_i(clk_i), .rst_i(rst_i), .d_i(p0_5[0] + p0_5[1]), .q_o(ps_6));
    // -gd u0_c = gd u0_a + gd u0_b
    // (from stage 6 to 8 in one delay line: lines of 3 or more map to SRLs,
    // shorter ones stay flip-flops)
    mpdcc_pipe #(.W(W), .N(3)) u_nrc (.clk_i(clk_i), .rst_i(rst_i), .d_i(r_5[0] + r_5[1]), .q_o(nrc_8));
    wire signed [W-1:0] v1_6 [0:2];
    generate
        for (gi = 0; gi < 3; gi = gi + 1) begin : g_s6
            mpdcc_pipe #(.W(W), .N(1)) u_c (.clk_i(clk_i), .rst_i(rst_i), .d_i(v0_5[gi] + v1r_5[gi]), .q_o(v1_6[gi]));
        end
    endgenerate
    wire signed [W-1:0] uh_7 [0:1];
    wire signed [W-1:0] p0c_7, x1_7, y1_7, z1_7;
    mpdcc_pipe #(.W(W), .N(1)) u_uha (.clk_i(clk_i), .rst_i(rst_i), .d_i(xh_6 + yh_6), .q_o(uh_7[0]));
    mpdcc_pipe #(.W(W), .N(1)) u_uhb (.clk_i(clk_i), .rst_i(rst_i), .d_i(zh_6 - xh_6), .q_o(uh_7[1]));
    mpdcc_pipe #(.W(W), .N(1)) u_p0c (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - ps_6), .q_o(p0c_7));
    mpdcc_pipe #(.W(W), .N(1)) u_x1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(v1_6[0] - v1_6[1]), .q_o(x1_7));
    mpdcc_pipe #(.W(W), .N(1)) u_y1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(v1_6[0] - v1_6[2]), .q_o(y1_7));
    mpdcc_pipe #(.W(W), .N(1)) u_z1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(v1_6[1] - v1_6[2]), .q_o(z1_7));
    wire signed [W-1:0] r_9 [0:1];
    wire signed [W-1:0] p0_10 [0:2];
    wire signed [W-1:0] g_8 [0:1];
    wire signed [W-1:0] u1_8 [0:1];
    wire signed [W-1:0] nrc_8;
    generate
        for (gi = 0; gi < 2; gi = gi + 1) begin : g_s8
            wire signed [24:0] uhn = uh_7[gi][24:0];
            wire signed [40:0] gg = g3_i * uhn;
            mpdcc_pipe #(.W(W), .N(1)) u_g (.clk_i(clk_i), .rst_i(rst_i),
                .d_i({{(W - 41) {gg[40]}}, gg}), .q_o(g_8[gi]));
            mpdcc_pipe #(.W(W), .N(5)) u_p (.clk_i(clk_i), .rst_i(rst_i), .d_i(p0_5[gi]), .q_o(p0_10[gi]));
            mpdcc_pipe #(.W(W), .N(4)) u_r (.clk_i(clk_i), .rst_i(rst_i), .d_i(r_5[gi]), .q_o(r_9[gi]));
        end
    endgenerate
    mpdcc_pipe #(.W(W), .N(3)) u_p0c8 (.clk_i(clk_i), .rst_i(rst_i), .d_i(p0c_7), .q_o(p0_10[2]));
    mpdcc_pipe #(.W(W), .N(1)) u_u1a (.clk_i(clk_i), .rst_i(rst_i), .d_i(x1_7 + y1_7), .q_o(u1_8[0]));
    mpdcc_pipe #(.W(W), .N(1)) u_u1b (.clk_i(clk_i), .rst_i(rst_i), .d_i(z1_7 - x1_7), .q_o(u1_8[1]));

    // ---------------------------------------------------------- stages 9-15
    // Q = g3 uh - gd u0 (stage 10); Q_c = -gd u0_c - g3 uh_a - g3 uh_b.
    // The one-step changes d1 = dn1 - sat16(rnd(g3_1 u1, 17)) take one
    // stage more (stage 15): they only feed J_dl, which waits for L*.
    wire signed [W-1:0] g_9 [0:1];
    wire signed [W-1:0] tc_9;
    wire signed [W-1:0] q_10 [0:2];
    wire signed [W-1:0] g1_9 [0:1];
    wire signed [W-1:0] g1_11 [0:2];
    wire signed [W-1:0] g1s_10;
    mpdcc_pipe #(.W(W), .N(1)) u_tc (.clk_i(clk_i), .rst_i(rst_i), .d_i(nrc_8 - g_8[0]), .q_o(tc_9));
    mpdcc_pipe #(.W(W), .N(1)) u_qc (.clk_i(clk_i), .rst_i(rst_i), .d_i(tc_9 - g_9[1]), .q_o(q_10[2]));
    generate
        for (gi = 0; gi < 2; gi = gi + 1) begin : g_s9
            mpdcc_pipe #(.W(W), .N(1)) u_g (.clk_i(clk_i), .rst_i(rst_i), .d_i(g_8[gi]), .q_o(g_9[gi]));
            mpdcc_pipe #(.W(W), .N(1)) u_q (.clk_i(clk_i), .rst_i(rst_i), .d_i(g_9[gi] - r_9[gi]), .q_o(q_10[gi]));
            wire signed [24:0] u1n = u1_8[gi][24:0];
            wire signed [40:0] g1 = g3_1_i * u1n;
            mpdcc_pipe #(.W(W), .N(1)) u_g1 (.clk_i(clk_i), .rst_i(rst_i),
                .d_i({{(W - 41) {g1[40]}}, g1}), .q_o(g1_9[gi]));
            mpdcc_pipe #(.W(W), .N(2)) u_g1d (.clk_i(clk_i), .rst_i(rst_i), .d_i(g1_9[gi]), .q_o(g1_11[gi]));
        end
    endgenerate
    mpdcc_pipe #(.W(W), .N(1)) u_g1s (.clk_i(clk_i), .rst_i(rst_i), .d_i(g1_9[0] + g1_9[1]), .q_o(g1s_10));
    mpdcc_pipe #(.W(W), .N(1)) u_g1c (.clk_i(clk_i), .rst_i(rst_i), .d_i(0 - g1s_10), .q_o(g1_11[2]));
    wire [17:0] nodes_14 [0:3][0:6];  // [node][output]
    wire [15:0] d1_15 [0:6];
    generate
        for (gi = 0; gi < 3; gi = gi + 1) begin : g_s10
            // stage 12
            wire signed [W-1:0] r1_12;
            mpdcc_pipe #(.W(W), .N(1)) u_r1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(g1_11[gi], 17)), .q_o(r1_12));
            // stage 13
            wire signed [W-1:0] r1s_13;
            mpdcc_pipe #(.W(W), .N(1)) u_r1s (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(sx16(sat16(r1_12))), .q_o(r1s_13));
            // stage 14
            wire signed [W-1:0] d1c_14;
            mpdcc_pipe #(.W(W), .N(1)) u_d1c (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(sx16(dn1_i[16*gi +: 16]) - r1s_13), .q_o(d1c_14));
            // stage 15
            mpdcc_pipe #(.W(16), .N(1)) u_d1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat16(d1c_14)), .q_o(d1_15[gi]));
            genvar m;
            for (m = 0; m < 4; m = m + 1) begin : g_node
                wire signed [W-1:0] g_11, rg_12, nd_13;
                mpdcc_pipe #(.W(W), .N(1)) u_g (.clk_i(clk_i), .rst_i(rst_i),
                    .d_i((p0_10[gi] <<< m) + (q_10[gi] <<< (2 * m))), .q_o(g_11));
                // rnd(g, 14) of a W-bit g: |.| < 2^33 + 1, 35 bits; the
                // difference with a 16-bit dn: 36 bits (registers only as
                // wide, sign-extended where read)
                wire signed [34:0] rgn_12;
                wire signed [35:0] ndn_13;
                /* verilator lint_off UNUSEDSIGNAL */
                wire signed [W-1:0] rg_d = rnd(g_11, 14);
                mpdcc_pipe #(.W(35), .N(1)) u_rg (.clk_i(clk_i), .rst_i(rst_i), .d_i(rg_d[34:0]), .q_o(rgn_12));
                assign rg_12 = {{(W - 35) {rgn_12[34]}}, rgn_12};
                wire signed [W-1:0] nd_d = sx16(dn_i[16*(3*m+gi) +: 16]) - rg_12;
                /* verilator lint_on UNUSEDSIGNAL */
                mpdcc_pipe #(.W(36), .N(1)) u_nd (.clk_i(clk_i), .rst_i(rst_i), .d_i(nd_d[35:0]), .q_o(ndn_13));
                assign nd_13 = {{(W - 36) {ndn_13[35]}}, ndn_13};
                mpdcc_pipe #(.W(18), .N(1)) u_c (.clk_i(clk_i), .rst_i(rst_i),
                    .d_i(clamp18(nd_13)), .q_o(nodes_14[m][gi]));
            end
        end
        for (gi = 0; gi < 4; gi = gi + 1) begin : g_invn
            genvar m;
            for (m = 0; m < 4; m = m + 1) begin : g_node
                assign nodes_14[m][3 + gi] = invn_14[gi][m];
            end
            assign d1_15[3 + gi] = inv1_15[gi];
        end
    endgenerate

    // ------------------------------------------------ stages 15-26: lanes
    wire [7:0] lmin_29;
    generate
        if (II == 1) begin : g_lanes
            wire [7:0] lj_26 [0:6];
            wire [6:0] lv;
            for (gi = 0; gi < 7; gi = gi + 1) begin : g_lane
                mpdcc_lane u_lane (
                    .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(v[14]),
                    .e0_i(e0_i[16*gi +: 16]),
                    .n0_i(nodes_14[0][gi]), .n1_i(nodes_14[1][gi]),
                    .n2_i(nodes_14[2][gi]), .n3_i(nodes_14[3][gi]),
                    .bnd_i(bnd_i[16*gi +: 15]),
                    .out_valid_o(lv[gi]), .lj_o(lj_26[gi]));
            end
            // stages 27-29: min l_j
            wire [7:0] n27 [0:3];
            wire [7:0] n28 [0:1];
            mpdcc_pipe #(.W(8), .N(1)) u_n0 (.clk_i(clk_i), .rst_i(rst_i), .d_i(umin(lj_26[0], lj_26[1])), .q_o(n27[0]));
            mpdcc_pipe #(.W(8), .N(1)) u_n1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(umin(lj_26[2], lj_26[3])), .q_o(n27[1]));
            mpdcc_pipe #(.W(8), .N(1)) u_n2 (.clk_i(clk_i), .rst_i(rst_i), .d_i(umin(lj_26[4], lj_26[5])), .q_o(n27[2]));
            mpdcc_pipe #(.W(8), .N(1)) u_n3 (.clk_i(clk_i), .rst_i(rst_i), .d_i(lj_26[6]), .q_o(n27[3]));
            mpdcc_pipe #(.W(8), .N(1)) u_n4 (.clk_i(clk_i), .rst_i(rst_i), .d_i(umin(n27[0], n27[1])), .q_o(n28[0]));
            mpdcc_pipe #(.W(8), .N(1)) u_n5 (.clk_i(clk_i), .rst_i(rst_i), .d_i(umin(n27[2], n27[3])), .q_o(n28[1]));
            mpdcc_pipe #(.W(8), .N(1)) u_n6 (.clk_i(clk_i), .rst_i(rst_i), .d_i(umin(n28[0], n28[1])), .q_o(lmin_29));
        end else begin : g_shared
            // The node changes of output j: {n3..n0}, from stage 14 on: held
            // for the clocks t = 1, 2 after stage 14 (FF), in a delay line
            // of t clocks for t >= 3 (an SRL); e0 and bnd are inputs held
            // through the decision, read directly.
            localparam integer CW = 4 * 18;
            wire [7*CW-1:0] col;
            for (gi = 0; gi < 7; gi = gi + 1) begin : g_col
                assign col[CW*gi +: CW] = {nodes_14[3][gi], nodes_14[2][gi], nodes_14[1][gi], nodes_14[0][gi]};
            end
            // the node changes of output j at the clock t = j / NL that reads it
            wire [7*CW-1:0] late;
            for (gi = 0; gi < 7; gi = gi + 1) begin : g_late
                if (gi / NL >= 3) begin : g_srl
                    mpdcc_pipe #(.W(CW), .N(gi / NL)) u_d (.clk_i(clk_i), .rst_i(rst_i),
                        .d_i(col[CW*gi +: CW]), .q_o(late[CW*gi +: CW]));
                end else if (gi / NL >= 1) begin : g_hold
                    reg [CW-1:0] hold_q;
                    always @(posedge clk_i) begin
                        if (rst_i) hold_q <= {CW{1'b0}};
                        else if (v[14]) hold_q <= col[CW*gi +: CW];
                    end
                    assign late[CW*gi +: CW] = hold_q;
                end else begin : g_now
                    assign late[CW*gi +: CW] = col[CW*gi +: CW];
                end
            end
            // lane i at the clock t after stage 14 (v[14 + t]): output i + NL t
            wire [7:0] lj [0:NL-1];
            wire [NL-1:0] lv;
            wire lane_in = |v[14 +: II];
            for (gi = 0; gi < NL; gi = gi + 1) begin : g_lane
                reg [CW-1:0] c;
                reg [3:0] o;  // the output
                integer t;
                /* verilator lint_off UNUSEDSIGNAL */
                integer oj;
                /* verilator lint_on UNUSEDSIGNAL */
                always @(*) begin
                    c = col[CW*gi +: CW];
                    oj = gi;
                    o = oj[3:0];
                    for (t = 1; t < II; t = t + 1)
                        // (the index is kept in range where the output does not exist)
                        if (v[14+t] && gi + NL * t < 7) begin
                            c = late[CW*((gi+NL*t) % 7) +: CW];
                            oj = (gi + NL * t) % 7;
                            o = oj[3:0];
                        end
                end
                mpdcc_lane u_lane (
                    .clk_i(clk_i), .rst_i(rst_i), .in_valid_i(lane_in),
                    .e0_i(e0_i[16*o +: 16]),
                    .n0_i(c[0 +: 18]), .n1_i(c[18 +: 18]),
                    .n2_i(c[36 +: 18]), .n3_i(c[54 +: 18]),
                    .bnd_i(bnd_i[16*o +: 15]),
                    .out_valid_o(lv[gi]), .lj_o(lj[gi]));
            end
            // Running minimum over the II clocks, one per lane: lane q
            // folds its l_j of clock t (v[26 + t]) when its output exists
            // (q + NL t < 7); the lanes' minima meet only where L* reads
            // them. (One comparison per clock: a minimum over the lanes
            // before the running one put two in series, 9.43 ns est.)
            wire [NL*8-1:0] acc_w;
            for (gi = 0; gi < NL; gi = gi + 1) begin : g_acc
                reg use_l;
                integer t;
                always @(*) begin
                    use_l = 1'b0;
                    for (t = 0; t < II; t = t + 1)
                        if (gi + NL * t < 7) use_l = use_l | v[26+t];
                end
                reg [7:0] acc_q;
                always @(posedge clk_i) begin
                    if (rst_i) acc_q <= 8'd0;
                    else if (v[26]) acc_q <= lj[gi];
                    else if (use_l) acc_q <= umin(acc_q, lj[gi]);
                end
                assign acc_w[8*gi +: 8] = acc_q;
            end
            reg [7:0] lmin_w;
            integer q;
            always @(*) begin
                lmin_w = acc_w[7:0];
                for (q = 1; q < NL; q = q + 1) lmin_w = umin(lmin_w, acc_w[8*q +: 8]);
            end
            // the minimum is complete at stage 26 + II; L* reads it at 29 + EXTRA
            if (3 + EXTRA - II > 0) begin : g_pad
                mpdcc_pipe #(.W(8), .N(3 + EXTRA - II)) u_pad (.clk_i(clk_i), .rst_i(rst_i),
                    .d_i(lmin_w), .q_o(lmin_29));
            end else begin : g_nopad
                assign lmin_29 = lmin_w;
            end
        end
    endgenerate

    // J_dl and inside-at-k beside the lanes (stages 16-21, 15-17), JW-bit
    // words: |e1| < 2^16 + 2^15, bnd in 16 bits, so |e1| - bnd and |e0|
    // are exact in JW = 20 bits.
    function automatic signed [JW-1:0] jx16(input [15:0] x);
        jx16 = {{(JW - 16) {x[15]}}, x};
    endfunction
    wire signed [JW-1:0] x_18 [0:6];
    wire [6:0] ok_16;
    generate
        for (gi = 0; gi < 7; gi = gi + 1) begin : g_jdl
            wire signed [JW-1:0] e0w = jx16(e0_i[16*gi +: 16]);
            wire signed [JW-1:0] bw = jx16(bnd_i[16*gi +: 16]);
            wire signed [JW-1:0] e1_16, a_17;
            mpdcc_pipe #(.W(JW), .N(1)) u_e1 (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(e0w + jx16(d1_15[gi])), .q_o(e1_16));
            mpdcc_pipe #(.W(JW), .N(1)) u_a (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(e1_16[JW-1] ? {JW{1'b0}} - e1_16 : e1_16), .q_o(a_17));
            mpdcc_pipe #(.W(JW), .N(1)) u_x (.clk_i(clk_i), .rst_i(rst_i), .d_i(a_17 - bw), .q_o(x_18[gi]));
            // |e0| <= bnd as -bnd <= e0 <= bnd: two sums in parallel, no
            // |e0| register (e0 and bnd are held through the decision)
            wire signed [JW-1:0] lo_w = e0w + bw;
            wire signed [JW-1:0] hi_w = bw - e0w;
            mpdcc_pipe #(.W(1), .N(1)) u_ok (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(!lo_w[JW-1] && !hi_w[JW-1]), .q_o(ok_16[gi]));
        end
    endgenerate
    function automatic signed [JW-1:0] smax(input signed [JW-1:0] a, input signed [JW-1:0] b);
        smax = (b > a) ? b : a;
    endfunction
    wire signed [JW-1:0] m19 [0:3];
    wire signed [JW-1:0] m20 [0:1];
    wire signed [JW-1:0] jdl_21;
    mpdcc_pipe #(.W(JW), .N(1)) u_m0 (.clk_i(clk_i), .rst_i(rst_i), .d_i(smax(x_18[0], x_18[1])), .q_o(m19[0]));
    mpdcc_pipe #(.W(JW), .N(1)) u_m1 (.clk_i(clk_i), .rst_i(rst_i), .d_i(smax(x_18[2], x_18[3])), .q_o(m19[1]));
    mpdcc_pipe #(.W(JW), .N(1)) u_m2 (.clk_i(clk_i), .rst_i(rst_i), .d_i(smax(x_18[4], x_18[5])), .q_o(m19[2]));
    mpdcc_pipe #(.W(JW), .N(1)) u_m3 (.clk_i(clk_i), .rst_i(rst_i), .d_i(x_18[6]), .q_o(m19[3]));
    mpdcc_pipe #(.W(JW), .N(1)) u_m4 (.clk_i(clk_i), .rst_i(rst_i), .d_i(smax(m19[0], m19[1])), .q_o(m20[0]));
    mpdcc_pipe #(.W(JW), .N(1)) u_m5 (.clk_i(clk_i), .rst_i(rst_i), .d_i(smax(m19[2], m19[3])), .q_o(m20[1]));
    mpdcc_pipe #(.W(JW), .N(1)) u_m6 (.clk_i(clk_i), .rst_i(rst_i), .d_i(smax(m20[0], m20[1])), .q_o(jdl_21));
    wire inside_17;
    mpdcc_pipe #(.W(1), .N(1)) u_in (.clk_i(clk_i), .rst_i(rst_i), .d_i(&ok_16), .q_o(inside_17));
    wire signed [JW-1:0] jdl_29;
    wire inside_29;
    mpdcc_pipe #(.W(JW), .N(8 + EXTRA)) u_jdld (.clk_i(clk_i), .rst_i(rst_i), .d_i(jdl_21), .q_o(jdl_29));
    mpdcc_pipe #(.W(1), .N(12 + EXTRA)) u_ind (.clk_i(clk_i), .rst_i(rst_i), .d_i(inside_17), .q_o(inside_29));

    // ------------------------------------------------------- stage 30: L*
    wire [7:0] ls_30;
    wire [7:0] ls_d = (jdl_29 > 0 || !inside_29) ? 8'd0 : (lmin_29 == 8'd0) ? 8'd1 : lmin_29;
    mpdcc_pipe #(.W(8), .N(1)) u_ls (.clk_i(clk_i), .rst_i(rst_i), .d_i(ls_d), .q_o(ls_30));
    wire signed [JW-1:0] jdl_30;
    mpdcc_pipe #(.W(JW), .N(1)) u_jdl30 (.clk_i(clk_i), .rst_i(rst_i), .d_i(jdl_29), .q_o(jdl_30));

    // ----------------------------------------------- stages 31-41: cost
    // v_n node changes, delayed from stage 14 to 30
    wire signed [17:0] vn_30 [0:3];
    generate
        for (gi = 0; gi < 4; gi = gi + 1) begin : g_vn
            mpdcc_pipe #(.W(18), .N(16 + EXTRA)) u_d (.clk_i(clk_i), .rst_i(rst_i), .d_i(nodes_14[gi][3]), .q_o(vn_30[gi]));
        end
    endgenerate
    // reciprocal ROM: round(2^17 / l), l = 1..128 (entry 0 unused)
    reg [17:0] recip_rom [0:255];
    integer ri;
    reg [31:0] rtmp;
    initial begin
        recip_rom[0] = 18'd0;
        for (ri = 1; ri < 256; ri = ri + 1) begin
            rtmp = (32'd131072 + ri / 2) / ri;
            recip_rom[ri] = rtmp[17:0];
        end
    end
    reg [17:0] recip_31;
    always @(posedge clk_i) begin
        if (rst_i) recip_31 <= 18'd0;
        else recip_31 <= recip_rom[ls_30];
    end
    // piece of L*: 0 for l <= 8 (from 0, shift 3), 1: (8, 16] (from n0,
    // shift 3), 2: (16, 32] (from n1, shift 4), 3: above (from n2, shift 5)
    wire [1:0] pc = (ls_30 <= 8'd8) ? 2'd0 : (ls_30 <= 8'd16) ? 2'd1 : (ls_30 <= 8'd32) ? 2'd2 : 2'd3;
    wire [7:0] start = (pc == 2'd0) ? 8'd0 : (pc == 2'd1) ? 8'd8 : (pc == 2'd2) ? 8'd16 : 8'd32;
    wire signed [W-1:0] vw [0:3];
    assign vw[0] = {{(W - 18) {vn_30[0][17]}}, vn_30[0]};
    assign vw[1] = {{(W - 18) {vn_30[1][17]}}, vn_30[1]};
    assign vw[2] = {{(W - 18) {vn_30[2][17]}}, vn_30[2]};
    assign vw[3] = {{(W - 18) {vn_30[3][17]}}, vn_30[3]};
    wire signed [W-1:0] nlo = (pc == 2'd0) ? 0 : (pc == 2'd1) ? vw[0] : (pc == 2'd2) ? vw[1] : vw[2];
    wire signed [W-1:0] nhi = (pc == 2'd0) ? vw[0] : (pc == 2'd1) ? vw[1] : (pc == 2'd2) ? vw[2] : vw[3];
    wire [7:0] dl_31;
    wire signed [W-1:0] slope_31, nlo_31;
    wire [1:0] pc_31;
    wire [7:0] ls_31;
    mpdcc_pipe #(.W(8), .N(1)) u_dl (.clk_i(clk_i), .rst_i(rst_i), .d_i(ls_30 - start), .q_o(dl_31));
    mpdcc_pipe #(.W(W), .N(1)) u_sl (.clk_i(clk_i), .rst_i(rst_i), .d_i(nhi - nlo), .q_o(slope_31));
    mpdcc_pipe #(.W(W), .N(1)) u_nl (.clk_i(clk_i), .rst_i(rst_i), .d_i(nlo), .q_o(nlo_31));
    mpdcc_pipe #(.W(2), .N(1)) u_pc (.clk_i(clk_i), .rst_i(rst_i), .d_i(pc), .q_o(pc_31));
    mpdcc_pipe #(.W(8), .N(1)) u_ls31 (.clk_i(clk_i), .rst_i(rst_i), .d_i(ls_30), .q_o(ls_31));
    wire [3:0] fs_31;
    mpdcc_pipe #(.W(4), .N(30 + EXTRA)) u_fs31 (.clk_i(clk_i), .rst_i(rst_i), .d_i(fs1_q), .q_o(fs_31));
    // 32: products
    wire signed [8:0]  dl_s = {1'b0, dl_31};
    wire signed [18:0] slope_s = slope_31[18:0];
    wire signed [27:0] prod = dl_s * slope_s;
    wire signed [W-1:0] prod_32, nlo_32;
    wire [1:0] pc_32;
    mpdcc_pipe #(.W(W), .N(1)) u_pr (.clk_i(clk_i), .rst_i(rst_i),
        .d_i({{(W - 28) {prod[27]}}, prod}), .q_o(prod_32));
    // f_s recip[L*] by shift and add (f_s <= 12, four bits): two partial
    // sums here, their sum at stage 33, no multiplier
    wire [21:0] rw = {4'd0, recip_31};
    wire [21:0] jsw_lo_32, jsw_hi_32;
    mpdcc_pipe #(.W(22), .N(1)) u_jswl (.clk_i(clk_i), .rst_i(rst_i),
        .d_i((fs_31[0] ? rw : 22'd0) + (fs_31[1] ? rw << 1 : 22'd0)), .q_o(jsw_lo_32));
    mpdcc_pipe #(.W(22), .N(1)) u_jswh (.clk_i(clk_i), .rst_i(rst_i),
        .d_i((fs_31[2] ? rw << 2 : 22'd0) + (fs_31[3] ? rw << 3 : 22'd0)), .q_o(jsw_hi_32));
    mpdcc_pipe #(.W(W), .N(1)) u_nl2 (.clk_i(clk_i), .rst_i(rst_i), .d_i(nlo_31), .q_o(nlo_32));
    mpdcc_pipe #(.W(2), .N(1)) u_pc2 (.clk_i(clk_i), .rst_i(rst_i), .d_i(pc_31), .q_o(pc_32));
    // 33: rnd(prod, ls), ls = 3, 3, 4, 5
    wire signed [W-1:0] rr = (pc_32 == 2'd2) ? rnd(prod_32, 4) : (pc_32 == 2'd3) ? rnd(prod_32, 5) : rnd(prod_32, 3);
    wire signed [W-1:0] rr_33, nlo_33;
    mpdcc_pipe #(.W(W), .N(1)) u_rr (.clk_i(clk_i), .rst_i(rst_i), .d_i(rr), .q_o(rr_33));
    mpdcc_pipe #(.W(W), .N(1)) u_nl3 (.clk_i(clk_i), .rst_i(rst_i), .d_i(nlo_32), .q_o(nlo_33));
    // 34: v_n change; 35: + e0_vn; 36: sat16
    wire signed [W-1:0] ch_34, ev_35;
    mpdcc_pipe #(.W(W), .N(1)) u_ch (.clk_i(clk_i), .rst_i(rst_i), .d_i(nlo_33 + rr_33), .q_o(ch_34));
    mpdcc_pipe #(.W(W), .N(1)) u_ev (.clk_i(clk_i), .rst_i(rst_i), .d_i(sx16(e0_i[63:48]) + ch_34), .q_o(ev_35));
    wire signed [15:0] evn_36;
    mpdcc_pipe #(.W(16), .N(1)) u_evn (.clk_i(clk_i), .rst_i(rst_i), .d_i(sat16(ev_35)), .q_o(evn_36));
    // 37: square (f26); 38: x lambda_n; 39: rnd 17; 40: + J_sw; 41: J
    wire [31:0] sq_37;
    wire signed [31:0] sq_s = evn_36 * evn_36;
    mpdcc_pipe #(.W(32), .N(1)) u_sq (.clk_i(clk_i), .rst_i(rst_i), .d_i(sq_s), .q_o(sq_37));
    wire [W-1:0] jl_38, jl_39;
    mpdcc_pipe #(.W(W), .N(1)) u_jl (.clk_i(clk_i), .rst_i(rst_i),
        .d_i({16'd0, sq_37} * {32'd0, lambda_n_i}), .q_o(jl_38));
    mpdcc_pipe #(.W(W), .N(1)) u_jl2 (.clk_i(clk_i), .rst_i(rst_i), .d_i(rnd(jl_38, 17)), .q_o(jl_39));
    wire [21:0] jsw_39;
    wire [21:0] jsw_33;
    mpdcc_pipe #(.W(22), .N(1)) u_jsw (.clk_i(clk_i), .rst_i(rst_i), .d_i(jsw_lo_32 + jsw_hi_32), .q_o(jsw_33));
    mpdcc_pipe #(.W(22), .N(6)) u_jswd (.clk_i(clk_i), .rst_i(rst_i), .d_i(jsw_33), .q_o(jsw_39));
    wire [W-1:0] tot_40;
    mpdcc_pipe #(.W(W), .N(1)) u_tot (.clk_i(clk_i), .rst_i(rst_i), .d_i(jl_39 + {26'd0, jsw_39}), .q_o(tot_40));
    wire [7:0] ls_40;
    mpdcc_pipe #(.W(8), .N(9)) u_ls40 (.clk_i(clk_i), .rst_i(rst_i), .d_i(ls_31), .q_o(ls_40));
    wire [31:0] cost_d = (ls_40 == 8'd0) ? 32'hFFFF_FFFF :
                         (tot_40 > 48'h0000_FFFF_FFFE) ? 32'hFFFF_FFFE : tot_40[31:0];
    mpdcc_pipe #(.W(32), .N(1)) u_cost (.clk_i(clk_i), .rst_i(rst_i), .d_i(cost_d), .q_o(cost_o));
    mpdcc_pipe #(.W(8), .N(1)) u_lso (.clk_i(clk_i), .rst_i(rst_i), .d_i(ls_40), .q_o(l_star_o));
    wire signed [JW-1:0] jdl_41;
    mpdcc_pipe #(.W(JW), .N(11)) u_jdlo (.clk_i(clk_i), .rst_i(rst_i), .d_i(jdl_30), .q_o(jdl_41));
    assign j_dl_o = {{(32 - JW) {jdl_41[JW-1]}}, jdl_41};
    assign s_o = s_out;
    assign fs_o = fs_out;
    // deltas: node k + 8 saturated to 16 bits, delayed from 14 to 41
    generate
        for (gi = 0; gi < 7; gi = gi + 1) begin : g_d0
            mpdcc_pipe #(.W(16), .N(27 + EXTRA)) u_d (.clk_i(clk_i), .rst_i(rst_i),
                .d_i(sat16({{(W - 18) {nodes_14[0][gi][17]}}, nodes_14[0][gi]})), .q_o(d0_o[16*gi +: 16]));
        end
    endgenerate

`ifdef FORMAL
    // Hand-shake contract of an explorer, the one mpdcc_core's proof assumes
    // of each of its explorers (F_LAT there): a candidate taken at a clock
    // comes out exactly LAT clocks later, once; nothing comes out that was
    // not taken; a reset clears every candidate in flight. The datapath
    // plays no part: scripts/rtl-formal proves this with the explorer's
    // result outputs cut off, so the arithmetic is pruned. (The candidate's
    // code travels beside it in u_s, an mpdcc_pipe of the same LAT; it is
    // checked by the bit-exact runs, not here: a 41-deep induction.)
    // Shadow of the last LAT valid bits (stage j = j clocks ago), cleared
    // by a reset as the pipeline registers are.
    reg [LAT:1] f_v = {LAT{1'b0}};
    always @(posedge clk_i) begin
        if (rst_i) f_v <= {LAT{1'b0}};
        else f_v <= {f_v[LAT-1:1], in_valid_i};
    end
    always @(*) begin
        // mpdcc_core's proof assumes this latency: change both together.
        assert (LAT == 41 + ((II > 3) ? II - 3 : 0));
        assert (out_valid_o == f_v[LAT]);
    end
    // Stage by stage, so that the proof is inductive in one step.
    generate
        for (gi = 1; gi <= LAT; gi = gi + 1) begin : g_fv
            always @(*) assert (v[gi] == f_v[gi]);
        end
    endgenerate
`endif
endmodule

`default_nettype wire
