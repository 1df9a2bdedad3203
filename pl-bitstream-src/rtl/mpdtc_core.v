// mpdtc_core: the fixed-point MPDTC of models::pmsm::mpdtc_fixed::decide,
// bit for bit (formats and arithmetic rules: docs/mpdtc-fixed.md).
//
// Formats: CUR sQ8.16 (25 bits), COEF sQ1.16 (18), TRQ sQ3.14 (18),
// KINV sQ8.16 (25), WGT sQ3.14 (18), COST = MAG x WGT (43 bits, kept 48).
//
// Timing: in_valid_i (with in_ready_o high) captures the inputs and the
// parameters; out_valid_o is high exactly LATENCY = 39 cycles later, with
// s_next_o and the debug outputs valid in that cycle (they hold until the
// next decision); the state registers (S[k], S[k-1], eta, x, i_hat, nu,
// iq_ref_prev) take their next values at the edge that raises out_valid_o.
// Initiation interval = 39 cycles: decision k+1 needs S[k+1] and the
// observer state of decision k, so one decision is in flight at a time
// (in_ready_o low while busy). Latency and II do not depend on the data.
// 39 cycles = 0.39 us at 100 MHz, against a control period of 1564 cycles.
//
// Multipliers: one decision in flight means a stage's multipliers idle in
// the other stages, so 16 shared 18 x 25 multipliers (operands chosen by
// the stage, one-hot ph) do all products of stages 1-8 (at most 16 per
// stage), plus 8 for the weights of stage 9: 24 DSP48E1.
//
// Pipeline: stage n owns a window of cycles (5, 5, 4, 4, 3, 4, 2, 3, 5, 3
// for stages 1..10: WIN) and its registers load only at the last edge of
// its window. Inside a window, free-running registers (suffix _r, _rr)
// split the arithmetic so that every register-to-register path has at
// most one multiplier, or one adder (two or three inputs), or a comparison
// and a mux, or a saturation (the delay budget of docs/rtl.md: 8 ns at
// 100 MHz): cycle 0 registers the multiplier operands, cycle 1 the
// products, the next cycles sums and terms, the last edge the saturation
// or clamp into the stage register. The arithmetic is that of the 10
// stages (R(x) = sat25((x + 2^15) >>> 16)):
//   1  full's MAC parts (a i_m + w i_m + eta<<16; the exact step of S[k-1]),
//      lambda i_m, T* / k_T, kp i_hat, ki i_hat
//   2  full; exact step of S[k] at angle 1; rounded legs at angle 2;
//      a i_hat; K Ts iq*_prev
//   3  i0 = R(lambda full + i_m<<16 - lambda i_m); candidate steps
//   4  eta, nu, x before their clamps (multiply + add + saturate); the
//      i1 and i_hat MACs without eta
//   5  clamps; i1, i_hat[k+1] = sat25(MAC>>16 + eta) for the three clamp
//      outcomes in parallel, then the mux (eta<<16 commutes with the
//      rounding)
//   6  a i1 + w i1 (+ back-EMF, rounding constant); y2[s] = step[s] + eta;
//      iq* = T*/k_T + x
//   7  i2[s] = sat25(MAC>>16 + y2[s]) for the 8 candidates
//   8  squares i2 x CSQ (CSQ = i2 >>> 8); |iq* - i2q[s]| (clipped)
//   9  |I|^2 = sat25(round((sq_d + sq_q) >> 13)), J^2 = |I|^2 x WGT[n]; band
//  10  8-way lexicographic minimum (band, J^2 or error, n, index) -> S[k+1]
// eta_lim and int_lim are meant to be >= 0 (the registers hold 24 bits, so
// the PL always passes a non-negative value); a negative limit is still
// defined, by the same comparator chain as the Rust model's clamp
// (x > lim ? lim : x < -lim ? -lim : x).
`default_nettype none

module mpdtc_core (
    input  wire               clk_i,
    input  wire               rst_i,
    // one decision
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
    // parameter registers (FixedParams), captured with the inputs
    input  wire signed [17:0] p_a_i,
    input  wire signed [17:0] p_lambda_i,
    // u0 is not used: the core forms U0 as 2 x u0_half (the register stays
    // in the map for the PS side).
    /* verilator lint_off UNUSEDSIGNAL */
    input  wire signed [24:0] p_u0_i,
    /* verilator lint_on UNUSEDSIGNAL */
    input  wire signed [24:0] p_u0_half_i,
    input  wire signed [24:0] p_u0_h_i,
    input  wire signed [24:0] p_psi_l_i,
    input  wire signed [24:0] p_kinv_t_i,
    input  wire signed [24:0] p_tol_i,
    input  wire signed [17:0] p_k_int_i,
    input  wire signed [24:0] p_int_lim_i,
    input  wire               p_int_cond_i,  // integrate only after a band hit
    input  wire signed [17:0] p_kp_o_i,
    input  wire signed [17:0] p_ki_o_i,
    input  wire signed [24:0] p_eta_lim_i,
    input  wire        [71:0] p_w2_i,        // 4 x WGT, n = 0 in [17:0]
    // state load (FixedState), when idle; reset loads all zero
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
    // results
    output wire               out_valid_o,
    output wire        [ 2:0] s_next_o,
    output wire signed [24:0] iq_ref_o,
    output wire signed [24:0] eta_d_o,
    output wire signed [24:0] eta_q_o,
    output wire signed [24:0] i1_d_o,
    output wire signed [24:0] i1_q_o,
    output wire       [199:0] i2_d_o,        // 8 x CUR, candidate s in [25 s +: 25]
    output wire       [199:0] i2_q_o,
    output wire       [199:0] err_o,
    output wire       [383:0] cost2_o,       // 8 x 48 bits, sign-extended
    // state registers (FixedState), for read-back and the next decision
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
    // Cycles of stage n + 1 in WIN[4n +: 4] (stage 1 in the low nibble):
    // the register levels each stage needs (pipeline comment above).
    localparam [39:0] WIN = {4'd3, 4'd5, 4'd3, 4'd2, 4'd4, 4'd3, 4'd4, 4'd4, 4'd5, 4'd5};
    // The first cycle (index into vld_q) of stage n + 1.
    function automatic integer wfirst(input integer n);
        integer k;
        begin
            wfirst = 0;
            for (k = 0; k < n; k = k + 1) wfirst = wfirst + {28'd0, WIN[4*k+:4]};
        end
    endfunction
    localparam integer LATENCY = wfirst(10) + 1;
    localparam signed [47:0] MAX25 = 48'sd16777215;
    localparam signed [47:0] MIN25 = -48'sd16777216;
    localparam signed [47:0] RND16 = 48'sd32768;

    // ------------------------------------------------------------ helpers
    function automatic signed [24:0] sat25(input signed [47:0] x);
        if (x > MAX25) sat25 = MAX25[24:0];
        else if (x < MIN25) sat25 = MIN25[24:0];
        else sat25 = x[24:0];
    endfunction

    function automatic signed [47:0] ext25(input signed [24:0] x);
        ext25 = {{23{x[24]}}, x};
    endfunction

    function automatic signed [47:0] ext27(input signed [26:0] x);
        ext27 = {{21{x[26]}}, x};
    endfunction

    function automatic signed [26:0] w27(input signed [24:0] x);
        w27 = {{2{x[24]}}, x};
    endfunction

    function automatic signed [47:0] ext43(input signed [42:0] x);
        ext43 = {{5{x[42]}}, x};
    endfunction

    // (y << 16) + 2^15: a CUR addend with the rounding constant in its 16
    // zero low bits.
    function automatic signed [47:0] yr16(input signed [24:0] y);
        yr16 = {{7{y[24]}}, y, 16'h8000};
    endfunction

    // alpha2 x (exact product) for alpha2 in -2..2 (state bits a, b, c:
    // alpha2 = 2a - b - c): a shift and a conditional negation.
    function automatic signed [47:0] alpha_term(input [2:0] st, input signed [42:0] x);
        case ({1'b0, st[2], 1'b0} - {2'b00, st[1]} - {2'b00, st[0]})
            3'sd2:   alpha_term = ext43(x) <<< 1;
            3'sd1:   alpha_term = ext43(x);
            -3'sd1:  alpha_term = -ext43(x);
            -3'sd2:  alpha_term = -(ext43(x) <<< 1);
            default: alpha_term = 48'sd0;
        endcase
    endfunction

    // beta x for beta = b - c in -1..1.
    function automatic signed [47:0] beta_term(input [1:0] bc, input signed [42:0] x);
        case (bc)
            2'b10:   beta_term = ext43(x);
            2'b01:   beta_term = -ext43(x);
            default: beta_term = 48'sd0;
        endcase
    endfunction

    // Candidate step (Sa - Sc) a + (Sb - Sc) b from the rounded legs; the
    // six non-zero values are precomputed (stage 3), this is a mux.
    function automatic signed [26:0] cand(input [2:0] s, input signed [24:0] a,
                                          input signed [24:0] b, input signed [26:0] ab,
                                          input signed [26:0] nab, input signed [26:0] na,
                                          input signed [26:0] nb);
        case (s)
            3'b100:  cand = w27(a);
            3'b010:  cand = w27(b);
            3'b001:  cand = nab;
            3'b110:  cand = ab;
            3'b101:  cand = nb;
            3'b011:  cand = na;
            default: cand = 27'sd0;
        endcase
    endfunction

    function automatic [1:0] popcount3(input [2:0] v);
        popcount3 = {1'b0, v[0]} + {1'b0, v[1]} + {1'b0, v[2]};
    endfunction

    // |t| clipped to MAX25, from t and -t computed in parallel.
    function automatic signed [24:0] abs_clip(input signed [47:0] t, input signed [47:0] nt);
        if (t < 0) abs_clip = (nt > MAX25) ? MAX25[24:0] : nt[24:0];
        else abs_clip = (t > MAX25) ? MAX25[24:0] : t[24:0];
    endfunction

    // Selection key: {out of band, value (offset binary), n}; the first
    // candidate with the least key wins (the model's strict < scan).
    function automatic [50:0] key(input ob, input signed [47:0] val, input [1:0] n);
        key = {ob, ~val[47], val[46:0], n};
    endfunction

    // ------------------------------------------------------------ control
    // vld_q[t]: the (t+1)-th cycle after the capture edge. Stage n owns the
    // cycles vld_q[wfirst(n-1) .. wfirst(n)-1] (ph[n-1]) and its registers
    // load at the last of them (ld[n-1]).
    reg  [LATENCY-1:0] vld_q;
    reg                busy_q;
    wire               start = in_valid_i && !busy_q;
    // stages 5, 7, 9, 10 use no shared multiplier: their ph bits are unused
    /* verilator lint_off UNUSEDSIGNAL */
    wire [9:0]         ph;
    /* verilator lint_on UNUSEDSIGNAL */
    wire [9:0]         ld;
    genvar gw;
    generate
        for (gw = 0; gw < 10; gw = gw + 1) begin : g_win
            localparam integer F = wfirst(gw), L = wfirst(gw + 1) - 1;
            assign ph[gw] = |vld_q[L:F];
            assign ld[gw] = vld_q[L];
        end
    endgenerate
    wire               done = ld[9];  // stage 10 loads at this edge

    always @(posedge clk_i) begin
        if (rst_i) begin
            vld_q  <= {LATENCY{1'b0}};
            busy_q <= 1'b0;
        end else begin
            vld_q <= {vld_q[LATENCY-2:0], start};
            if (start) busy_q <= 1'b1;
            else if (done) busy_q <= 1'b0;
        end
    end
    assign in_ready_o  = !busy_q;
    assign out_valid_o = vld_q[LATENCY-1];

    // ------------------------------------------------------------ state
    reg        [ 2:0] sa_q;  // S[k]
    reg        [ 2:0] sp_q;  // S[k-1]
    reg signed [24:0] etap_d_q, etap_q_q, x_q, iqrp_q, ih_d_q, ih_q_q, nu_d_q, nu_q_q;
    reg               band_q;  // the previous decision had a candidate in band

    // ------------------------------------------------------------ stage 0
    reg signed [24:0] im_d, im_q;
    reg signed [17:0] c0, s0, c1, s1, c2, s2, g, tref;
    reg signed [17:0] pa, plam, pkint, pkp, pki;
    reg               pintcond;
    reg signed [24:0] pu0half, pu0h, ppsi, pkinv, ptol, pintlim, petalim;
    reg        [71:0] pw2;
    always @(posedge clk_i) begin
        if (start) begin
            im_d <= i_d_i;
            im_q <= i_q_i;
            c0 <= cos0_i;
            s0 <= sin0_i;
            c1 <= cos1_i;
            s1 <= sin1_i;
            c2 <= cos2_i;
            s2 <= sin2_i;
            g <= w_ts_i;
            tref <= t_ref_i;
            pa <= p_a_i;
            plam <= p_lambda_i;
            pkint <= p_k_int_i;
            pkp <= p_kp_o_i;
            pki <= p_ki_o_i;
            pu0half <= p_u0_half_i;
            pu0h <= p_u0_h_i;
            ppsi <= p_psi_l_i;
            pkinv <= p_kinv_t_i;
            ptol <= p_tol_i;
            pintlim <= p_int_lim_i;
            pintcond <= p_int_cond_i;
            petalim <= p_eta_lim_i;
            pw2 <= p_w2_i;
        end
    end

    // ------------------------------------------------------------ stage registers
    // 1
    reg signed [47:0] fx_d, fx_q, kl_d, kl_q, kh_d, kh_q, kn_d, kn_q, ngpsi;
    reg signed [47:0] fy_d, fy_q;
    reg signed [24:0] iq_orig;
    // 2
    reg signed [24:0] full_d, full_q;
    reg signed [47:0] v1r_d, v1r_q, ah_d, ah_q, kx;
    reg signed [24:0] la_d, la_q, lb_d, lb_q;
    // 3
    reg signed [24:0] i0_d, i0_q;
    reg signed [47:0] ahv_d, ahv_q;
    reg signed [26:0] ab_d, ab_q, nab_d, nab_q, na_d, na_q, nb_d, nb_q;
    // 4
    reg signed [24:0] etar_d, etar_q, nur_d, nur_q, xr;
    reg signed [47:0] t_d, t_q, h_d, h_q;
    // 5
    reg signed [24:0] eta_d, eta_q, nu_n_d, nu_n_q, x_n, i1_d, i1_q, ihn_d, ihn_q;
    // 6
    reg signed [47:0] cb_d, cb_q;
    reg signed [26:0] y2_d[0:7], y2_q[0:7];
    reg signed [24:0] iq_ref;
    // 7
    reg signed [24:0] i2_d[0:7], i2_q[0:7];
    // 8
    reg signed [47:0] sq_d[0:7], sq_q[0:7];
    reg signed [24:0] err[0:7];
    // 9
    reg signed [47:0] cost2[0:7];
    reg               inband[0:7];
    // 10
    reg        [ 2:0] s_next;

    // ------------------------------------------------------------ shared multipliers
    // Operands of the 16 shared multipliers by stage (one-hot ph); the
    // products are exact (43 bits).
    reg [18*16-1:0] ma;
    reg [25*16-1:0] mb;
    always @(*) begin : pool_operands
        integer m;
        m  = 0;
        ma = {18 * 16{1'b0}};
        mb = {25 * 16{1'b0}};
        if (ph[0]) begin  // stage 1
            ma[18*0+:18] = pa;     mb[25*0+:25] = im_d;
            ma[18*1+:18] = g;      mb[25*1+:25] = im_q;
            ma[18*2+:18] = pa;     mb[25*2+:25] = im_q;
            ma[18*3+:18] = g;      mb[25*3+:25] = im_d;
            ma[18*4+:18] = c0;     mb[25*4+:25] = pu0half;
            ma[18*5+:18] = s0;     mb[25*5+:25] = pu0half;
            ma[18*6+:18] = c0;     mb[25*6+:25] = pu0h;
            ma[18*7+:18] = s0;     mb[25*7+:25] = pu0h;
            ma[18*8+:18] = g;      mb[25*8+:25] = ppsi;
            ma[18*9+:18] = plam;   mb[25*9+:25] = im_d;
            ma[18*10+:18] = plam;  mb[25*10+:25] = im_q;
            ma[18*11+:18] = tref;  mb[25*11+:25] = pkinv;
            ma[18*12+:18] = pkp;   mb[25*12+:25] = ih_d_q;
            ma[18*13+:18] = pkp;   mb[25*13+:25] = ih_q_q;
            ma[18*14+:18] = pki;   mb[25*14+:25] = ih_d_q;
            ma[18*15+:18] = pki;   mb[25*15+:25] = ih_q_q;
        end
        if (ph[1]) begin  // stage 2
            ma[18*0+:18] = c1;     mb[25*0+:25] = pu0half;
            ma[18*1+:18] = s1;     mb[25*1+:25] = pu0half;
            ma[18*2+:18] = c1;     mb[25*2+:25] = pu0h;
            ma[18*3+:18] = s1;     mb[25*3+:25] = pu0h;
            ma[18*4+:18] = c2;     mb[25*4+:25] = pu0half;
            ma[18*5+:18] = s2;     mb[25*5+:25] = pu0half;
            ma[18*6+:18] = c2;     mb[25*6+:25] = pu0h;
            ma[18*7+:18] = s2;     mb[25*7+:25] = pu0h;
            ma[18*8+:18] = pa;     mb[25*8+:25] = ih_d_q;
            ma[18*9+:18] = pa;     mb[25*9+:25] = ih_q_q;
            ma[18*10+:18] = pkint; mb[25*10+:25] = iqrp_q;
        end
        if (ph[2]) begin  // stage 3
            ma[18*0+:18] = plam;   mb[25*0+:25] = full_d;
            ma[18*1+:18] = plam;   mb[25*1+:25] = full_q;
        end
        if (ph[3]) begin  // stage 4
            ma[18*0+:18] = pkp;    mb[25*0+:25] = i0_d;
            ma[18*1+:18] = pkp;    mb[25*1+:25] = i0_q;
            ma[18*2+:18] = pki;    mb[25*2+:25] = i0_d;
            ma[18*3+:18] = pki;    mb[25*3+:25] = i0_q;
            ma[18*4+:18] = pkint;  mb[25*4+:25] = i0_q;
            ma[18*5+:18] = pa;     mb[25*5+:25] = i0_d;
            ma[18*6+:18] = g;      mb[25*6+:25] = i0_q;
            ma[18*7+:18] = pa;     mb[25*7+:25] = i0_q;
            ma[18*8+:18] = g;      mb[25*8+:25] = i0_d;
        end
        if (ph[5]) begin  // stage 6
            ma[18*0+:18] = pa;     mb[25*0+:25] = i1_d;
            ma[18*1+:18] = g;      mb[25*1+:25] = i1_q;
            ma[18*2+:18] = pa;     mb[25*2+:25] = i1_q;
            ma[18*3+:18] = g;      mb[25*3+:25] = i1_d;
        end
        if (ph[7]) begin  // stage 8: i2 x CSQ, CSQ = i2 >>> 8 (17 bits)
            for (m = 0; m < 8; m = m + 1) begin
                ma[18*m+:18]     = {i2_d[m][24], i2_d[m][24:8]};
                mb[25*m+:25]     = i2_d[m];
                ma[18*(m+8)+:18] = {i2_q[m][24], i2_q[m][24:8]};
                mb[25*(m+8)+:25] = i2_q[m];
            end
        end
    end
    // Operands registered (cycle 0 of the window), products registered
    // (cycle 1): the products of stage n are valid from cycle 2 of its
    // window on.
    reg signed [17:0] opa_q[0:15];
    reg signed [24:0] opb_q[0:15];
    reg signed [42:0] mp[0:15];
    always @(posedge clk_i) begin : pool_regs
        integer m;
        for (m = 0; m < 16; m = m + 1) begin
            opa_q[m] <= ma[18*m+:18];
            opb_q[m] <= mb[25*m+:25];
            mp[m]    <= opa_q[m] * opb_q[m];
        end
    end
    // Products as 48-bit values.
    wire signed [47:0] P0 = ext43(mp[0]), P1 = ext43(mp[1]), P2 = ext43(mp[2]), P3 = ext43(mp[3]);
    wire signed [47:0] P4 = ext43(mp[4]), P5 = ext43(mp[5]), P6 = ext43(mp[6]), P7 = ext43(mp[7]);
    wire signed [47:0] P8 = ext43(mp[8]), P9 = ext43(mp[9]), P10 = ext43(mp[10]);
    wire signed [47:0] P11 = ext43(mp[11]), P12 = ext43(mp[12]), P13 = ext43(mp[13]);
    wire signed [47:0] P14 = ext43(mp[14]), P15 = ext43(mp[15]);

    // ------------------------------------------------------------ stages 1-3
    // Free-running intermediate registers (names ending in _r): sums and
    // terms of the stage whose window it is, from inputs that hold through
    // the window, so each path has at most one adder (or a term mux and
    // its negation) between registers. The stage registers load only at
    // the window's last edge (ld), when every _r register is settled:
    // products are valid from cycle 2, _r registers fed by products from
    // cycle 3, the second level (_rr) from cycle 4 = W - 1.
    reg signed [47:0] s1x_d_r, s1x_q_r, a1d_r, b1d_r, a1q_r, b1q_r, f1q_rr, iqo_r;
    reg signed [47:0] sf_d_r, sf_q_r, a2d_r, b2d_r, a2q_r, b2q_r, v2d_rr, v2q_rr;
    reg signed [47:0] la2d_r, la2q_r, lb2d_r, lb2q_r, la2d_rr, la2q_rr, lb2d_rr, lb2q_rr;
    reg signed [47:0] i0d_r, i0q_r;
    always @(posedge clk_i) begin : pipe1_3
        // 1
        s1x_d_r <= P0 + P1;
        s1x_q_r <= P2 - P3;
        a1d_r   <= alpha_term(sp_q, mp[4]);
        b1d_r   <= beta_term(sp_q[1:0], mp[7]);
        a1q_r   <= alpha_term(sp_q, mp[5]);
        b1q_r   <= beta_term(sp_q[1:0], mp[6]);
        f1q_rr  <= b1q_r - a1q_r;
        iqo_r   <= P11 + 48'sd8192;
        // 2
        sf_d_r  <= fx_d + fy_d;
        sf_q_r  <= fx_q + fy_q;
        a2d_r   <= alpha_term(sa_q, mp[0]);
        b2d_r   <= beta_term(sa_q[1:0], mp[3]);
        a2q_r   <= alpha_term(sa_q, mp[1]);
        b2q_r   <= beta_term(sa_q[1:0], mp[2]);
        v2d_rr  <= a2d_r + b2d_r;
        v2q_rr  <= b2q_r - a2q_r;
        la2d_r  <= P4 + P4;
        la2q_r  <= P5 + P5;
        lb2d_r  <= P7 - P4;
        lb2q_r  <= P5 + P6;
        la2d_rr <= la2d_r + RND16;
        la2q_rr <= RND16 - la2q_r;
        lb2d_rr <= lb2d_r + RND16;
        lb2q_rr <= lb2q_r + RND16;
        // 3
        i0d_r   <= P0 + kl_d;
        i0q_r   <= P1 + kl_q;
    end

    always @(posedge clk_i) begin
        if (ld[0]) begin
            // full = R(a im + w J im + u(S[k-1]) + eta_prev<<16), in two parts
            fx_d  <= s1x_d_r + yr16(etap_d_q);
            fx_q  <= s1x_q_r + yr16(etap_q_q);
            fy_d  <= a1d_r + b1d_r;
            fy_q  <= f1q_rr - P8;
            ngpsi <= RND16 - P8;
            kl_d  <= yr16(im_d) - P9;
            kl_q  <= yr16(im_q) - P10;
            // T* (14 frac) x 1/k_T (16 frac) -> CUR: round half up >> 14.
            iq_orig <= sat25(iqo_r >>> 14);
            kh_d  <= yr16(nu_d_q) - P12;
            kh_q  <= yr16(nu_q_q) - P13;
            kn_d  <= yr16(nu_d_q) - P14;
            kn_q  <= yr16(nu_q_q) - P15;
        end
        if (ld[1]) begin
            full_d <= sat25(sf_d_r >>> 16);
            full_q <= sat25(sf_q_r >>> 16);
            // exact step of S[k] at angle 1 (+ rounding; q: - w Ts psi/L)
            v1r_d <= v2d_rr + RND16;
            v1r_q <= v2q_rr + ngpsi;
            // legs a, b at angle 2, rounded once
            la_d <= sat25(la2d_rr >>> 16);
            la_q <= sat25(la2q_rr >>> 16);
            lb_d <= sat25(lb2d_rr >>> 16);
            lb_q <= sat25(lb2q_rr >>> 16);
            ah_d <= P8;
            ah_q <= P9;
            kx   <= yr16(x_q) + P10;
        end
        if (ld[2]) begin
            i0_d  <= sat25(i0d_r >>> 16);
            i0_q  <= sat25(i0q_r >>> 16);
            ahv_d <= ah_d + v1r_d;
            ahv_q <= ah_q + v1r_q;
            ab_d  <= w27(la_d) + w27(lb_d);
            ab_q  <= w27(la_q) + w27(lb_q);
            nab_d <= -w27(la_d) - w27(lb_d);
            nab_q <= -w27(la_q) - w27(lb_q);
            na_d  <= -w27(la_d);
            na_q  <= -w27(la_q);
            nb_d  <= -w27(lb_d);
            nb_q  <= -w27(lb_q);
        end
    end

    // ------------------------------------------------------------ stages 4-5
    // i1 / i_hat: sat25(MAC >>> 16 + eta) for eta = clamp(eta_raw); the
    // three outcomes of the clamp (base + lim, base - lim, base + raw) are
    // summed in parallel, selected by the clamp's comparisons, then
    // saturated (eta<<16 commutes with the rounding).
    reg signed [47:0] etd_r, etq_r, nud_r, nuq_r, xr_r, t5d_r, t7q_r;
    reg signed [47:0] nel_r, nil_r;  // -lim, 48 bits
    reg               gted_r, lted_r, gteq_r, lteq_r, gtnd_r, ltnd_r, gtnq_r, ltnq_r, gtx_r, ltx_r;
    reg signed [47:0] hi_r[0:3], lo_r[0:3], mid_r[0:3], sel_rr[0:3];
    wire signed [47:0] mac5[0:3];
    assign mac5[0] = t_d;
    assign mac5[1] = t_q;
    assign mac5[2] = h_d;
    assign mac5[3] = h_q;
    always @(posedge clk_i) begin : pipe4_5
        integer k;
        reg signed [47:0] base;
        reg signed [24:0] raw;
        reg gt, lt;
        // 4
        etd_r  <= P0 + kh_d;
        etq_r  <= P1 + kh_q;
        nud_r  <= P2 + kn_d;
        nuq_r  <= P3 + kn_q;
        xr_r   <= kx - P4;
        t5d_r  <= P5 + P6;
        t7q_r  <= P7 - P8;
        // 5
        nel_r  <= -ext25(petalim);
        nil_r  <= -ext25(pintlim);
        gted_r <= ext25(etar_d) > ext25(petalim);
        lted_r <= ext25(etar_d) < nel_r;
        gteq_r <= ext25(etar_q) > ext25(petalim);
        lteq_r <= ext25(etar_q) < nel_r;
        gtnd_r <= ext25(nur_d) > ext25(petalim);
        ltnd_r <= ext25(nur_d) < nel_r;
        gtnq_r <= ext25(nur_q) > ext25(petalim);
        ltnq_r <= ext25(nur_q) < nel_r;
        gtx_r  <= ext25(xr) > ext25(pintlim);
        ltx_r  <= ext25(xr) < nil_r;
        for (k = 0; k < 4; k = k + 1) begin
            base     = mac5[k] >>> 16;
            raw      = k[0] ? etar_q : etar_d;
            gt       = k[0] ? gteq_r : gted_r;
            lt       = k[0] ? lteq_r : lted_r;
            hi_r[k]  <= base + ext25(petalim);
            lo_r[k]  <= base + nel_r;
            mid_r[k] <= base + ext25(raw);
            sel_rr[k] <= gt ? hi_r[k] : lt ? lo_r[k] : mid_r[k];
        end
    end

    always @(posedge clk_i) begin
        if (ld[3]) begin
            etar_d <= sat25(etd_r >>> 16);
            etar_q <= sat25(etq_r >>> 16);
            nur_d  <= sat25(nud_r >>> 16);
            nur_q  <= sat25(nuq_r >>> 16);
            xr     <= sat25(xr_r >>> 16);
            t_d    <= t5d_r + v1r_d;
            t_q    <= t7q_r + v1r_q;
            h_d    <= ahv_d + P6;
            h_q    <= ahv_q - P8;
        end
        if (ld[4]) begin
            // clamp(x, lim) = x > lim ? lim : x < -lim ? -lim : x
            eta_d  <= gted_r ? petalim : lted_r ? nel_r[24:0] : etar_d;
            eta_q  <= gteq_r ? petalim : lteq_r ? nel_r[24:0] : etar_q;
            nu_n_d <= gtnd_r ? petalim : ltnd_r ? nel_r[24:0] : nur_d;
            nu_n_q <= gtnq_r ? petalim : ltnq_r ? nel_r[24:0] : nur_q;
            // Eq. (13), conditional on the previous band hit if enabled.
            x_n    <= (band_q || !pintcond) ? (gtx_r ? pintlim : ltx_r ? nil_r[24:0] : xr) : x_q;
            i1_d   <= sat25(sel_rr[0]);
            i1_q   <= sat25(sel_rr[1]);
            ihn_d  <= sat25(sel_rr[2]);
            ihn_q  <= sat25(sel_rr[3]);
        end
    end

    // ------------------------------------------------------------ stages 6-10
    reg signed [47:0] cb_d_r, cb_q_r, iqr_r;
    reg signed [47:0] i2d_r[0:7], i2q_r[0:7], et_r[0:7], net_r[0:7];
    reg signed [47:0] ss_r[0:7], ss_rr[0:7];
    reg signed [24:0] wx_r[0:7];     // |I|^2 (CUR), the weight multiplier's operand
    reg signed [17:0] ww_r[0:7];     // WGT[n] of candidate s
    reg signed [42:0] wp_r[0:7];     // J^2 = |I|^2 x WGT[n], exact
    reg        [50:0] key_r[0:7];
    reg        [ 7:0] lt_r[0:7];     // lt_r[s][j]: key s < key j

    // Weight of candidate s: WGT[popcount(s ^ S[k])].
    function automatic signed [17:0] wgt(input [71:0] w, input [1:0] n);
        wgt = w[18*n+:18];
    endfunction

    always @(posedge clk_i) begin : pipe6_10
        integer s, j;
        // 6
        cb_d_r <= P0 + P1;
        cb_q_r <= P2 - P3;
        iqr_r  <= ext25(iq_orig) + ext25(x_n);
        for (s = 0; s < 8; s = s + 1) begin
            // 7
            i2d_r[s] <= (cb_d >>> 16) + ext27(y2_d[s]);
            i2q_r[s] <= (cb_q >>> 16) + ext27(y2_q[s]);
            // 8
            et_r[s]  <= ext25(iq_ref) - ext25(i2_q[s]);
            net_r[s] <= ext25(i2_q[s]) - ext25(iq_ref);
            // 9: sum, rounding constant, saturation, weight product
            ss_r[s]  <= sq_d[s] + sq_q[s];
            ss_rr[s] <= ss_r[s] + 48'sd4096;
            wx_r[s]  <= sat25(ss_rr[s] >>> 13);
            ww_r[s]  <= wgt(pw2, popcount3(s[2:0] ^ sa_q));
            wp_r[s]  <= ww_r[s] * wx_r[s];
            // 10: the selection keys, then their pairwise comparisons
            key_r[s] <= key(!inband[s], inband[s] ? cost2[s] : ext25(err[s]),
                            popcount3(s[2:0] ^ sa_q));
        end
        for (s = 0; s < 8; s = s + 1)
            for (j = 0; j < 8; j = j + 1) lt_r[s][j] <= key_r[s] < key_r[j];
    end

    // 8-way lexicographic minimum: the first candidate with the least key.
    reg [2:0] best;
    always @(*) begin : select8
        integer s, j;
        reg win;
        best = 3'd0;
        for (s = 7; s >= 0; s = s - 1) begin
            win = 1'b1;
            for (j = 0; j < 8; j = j + 1) begin
                if (j < s && !lt_r[s][j]) win = 1'b0;
                if (j > s && lt_r[j][s]) win = 1'b0;
            end
            if (win) best = s[2:0];
        end
    end

    always @(posedge clk_i) begin : stages6_10
        integer s;
        if (ld[5]) begin
            cb_d   <= cb_d_r + RND16;
            cb_q   <= cb_q_r + ngpsi;
            iq_ref <= sat25(iqr_r);
            for (s = 0; s < 8; s = s + 1) begin
                y2_d[s] <= cand(s[2:0], la_d, lb_d, ab_d, nab_d, na_d, nb_d) + w27(eta_d);
                y2_q[s] <= cand(s[2:0], la_q, lb_q, ab_q, nab_q, na_q, nb_q) + w27(eta_q);
            end
        end
        if (ld[6]) begin
            for (s = 0; s < 8; s = s + 1) begin
                i2_d[s] <= sat25(i2d_r[s]);
                i2_q[s] <= sat25(i2q_r[s]);
            end
        end
        if (ld[7]) begin
            for (s = 0; s < 8; s = s + 1) begin
                sq_d[s] <= ext43(mp[s]);
                sq_q[s] <= ext43(mp[s+8]);
                err[s]  <= abs_clip(et_r[s], net_r[s]);
            end
        end
        if (ld[8]) begin
            for (s = 0; s < 8; s = s + 1) begin
                cost2[s]  <= ext43(wp_r[s]);
                inband[s] <= ext25(err[s]) <= ext25(ptol);
            end
        end
        if (ld[9]) s_next <= best;
    end

    // ------------------------------------------------------------ state update
    always @(posedge clk_i) begin
        if (rst_i) begin
            sa_q <= 3'd0;
            sp_q <= 3'd0;
            etap_d_q <= 25'sd0;
            etap_q_q <= 25'sd0;
            x_q <= 25'sd0;
            band_q <= 1'b0;
            iqrp_q <= 25'sd0;
            ih_d_q <= 25'sd0;
            ih_q_q <= 25'sd0;
            nu_d_q <= 25'sd0;
            nu_q_q <= 25'sd0;
        end else if (done) begin
            sa_q <= best;
            sp_q <= sa_q;
            etap_d_q <= eta_d;
            etap_q_q <= eta_q;
            x_q <= x_n;
            band_q <= inband[0] | inband[1] | inband[2] | inband[3]
                    | inband[4] | inband[5] | inband[6] | inband[7];
            iqrp_q <= iq_orig;
            ih_d_q <= ihn_d;
            ih_q_q <= ihn_q;
            nu_d_q <= nu_n_d;
            nu_q_q <= nu_n_q;
        end else if (st_load_i && !busy_q) begin
            sa_q <= st_s_applied_i;
            sp_q <= st_s_prev_i;
            etap_d_q <= st_eta_d_i;
            etap_q_q <= st_eta_q_i;
            x_q <= st_x_i;
            band_q <= st_band_i;
            iqrp_q <= st_iq_ref_prev_i;
            ih_d_q <= st_i_hat_d_i;
            ih_q_q <= st_i_hat_q_i;
            nu_d_q <= st_nu_d_i;
            nu_q_q <= st_nu_q_i;
        end
    end

    // ------------------------------------------------------------ outputs
    genvar gi;
    generate
        for (gi = 0; gi < 8; gi = gi + 1) begin : g_out
            assign i2_d_o[25*gi+:25]  = i2_d[gi];
            assign i2_q_o[25*gi+:25]  = i2_q[gi];
            assign err_o[25*gi+:25]   = err[gi];
            assign cost2_o[48*gi+:48] = cost2[gi];
        end
    endgenerate
    assign s_next_o         = s_next;
    assign iq_ref_o         = iq_ref;
    assign eta_d_o          = eta_d;
    assign eta_q_o          = eta_q;
    assign i1_d_o           = i1_d;
    assign i1_q_o           = i1_q;
    assign st_s_applied_o   = sa_q;
    assign st_s_prev_o      = sp_q;
    assign st_eta_d_o       = etap_d_q;
    assign st_eta_q_o       = etap_q_q;
    assign st_x_o           = x_q;
    assign st_band_o        = band_q;
    assign st_iq_ref_prev_o = iqrp_q;
    assign st_i_hat_d_o     = ih_d_q;
    assign st_i_hat_q_o     = ih_q_q;
    assign st_nu_d_o        = nu_d_q;
    assign st_nu_q_o        = nu_q_q;
endmodule

`default_nettype wire
