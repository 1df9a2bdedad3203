// mpdtc_core: the fixed-point MPDTC of drive::pmsm::mpdtc_fixed::decide,
// bit for bit (formats and arithmetic rules: docs/mpdtc-fixed.md).
//
// Formats: CUR sQ8.16 (25 bits), COEF sQ1.16 (18), TRQ sQ3.14 (18),
// KINV sQ8.16 (25), WGT sQ3.14 (18), COST = MAG x WGT (43 bits, kept 48).
//
// Timing: in_valid_i (with in_ready_o high) captures the inputs and the
// parameters; out_valid_o is high exactly LATENCY = 20 cycles later, with
// s_next_o and the debug outputs valid in that cycle; the state registers
// (S[k], S[k-1], eta, x, i_hat, nu, iq_ref_prev) take their next values at
// the same edge that raises out_valid_o. Initiation interval = 20 cycles:
// decision k+1 needs S[k+1] and the observer state of decision k, so one
// decision is in flight at a time (in_ready_o low while busy). Latency and
// II do not depend on the data. At a 1 us control period (100 cycles at
// 100 MHz) the core is busy 20 % of the time.
//
// Pipeline (stage n = register loaded at the n-th edge after capture). Each
// stage has at most one multiplier and one adder level between registers;
// where a stage needs a second operation it is done on parallel adders and a
// mux, or on a constant folded into the low zero bits of an operand (the
// rounding constant 2^15 under y << 16):
//   1  basis products round(u0 x cos) ...; a i_m, a i_hat; -(w Ts) psi/L; T* / k_T
//   2  legs a (negated), b; w Ts x i_m cascade
//   3  leg c (sum and negated sum in parallel); projection of legs a + b
//   4  projections (+ leg c) for S[k-1], S[k] and the 8 candidates
//   5  y0 = u + eta_prev
//   6  full = sat(round(a i_m + w Ts i_x + y0))
//   7  full - i_m
//   8  i0 = i_m + sat(round(lambda (full - i_m))) (two post-adders in parallel)
//   9  e = i0 - i_hat, iq*_prev - i0_q; a i0 products
//  10  kp e, ki e, K Ts (..) (multiply, round, saturate); w Ts i0 cascade
//  11  eta, nu, x: add + clamp (x only if the last decision hit the band,
//      when int_cond is set)
//  12  y1 = u1 + eta, y2[s] = u2[s] + eta, iq* = T*/k_T + x
//  13  i1, i_hat[k+1]; candidate offsets y2[s] << 16 (+ round, - w Ts psi/L)
//  14  a i1, w Ts i1 products
//  15  i2[s] for the 8 candidates (ternary add, round, saturate)
//  16  |iq* - i2q[s]| (clipped), CSQ operands (round >> 8)
//  17  squares i2 x CSQ; in-band flags; transition counts
//  18  |I|^2 = sat(round((sq_d + sq_q) >> 13)), J^2 = |I|^2 x WGT[n]
//  19  8-way lexicographic minimum (band, J^2 or error, n, index) -> S[k+1]
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
    input  wire signed [24:0] p_u0_i,
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
    localparam integer LATENCY = 20;
    localparam signed [47:0] MAX25 = 48'sd16777215;
    localparam signed [47:0] MIN25 = -48'sd16777216;
    localparam signed [47:0] MAX18 = 48'sd131071;
    localparam signed [47:0] MIN18 = -48'sd131072;
    localparam signed [47:0] RND16 = 48'sd32768;

    // ------------------------------------------------------------ helpers
    function automatic signed [24:0] sat25(input signed [47:0] x);
        if (x > MAX25) sat25 = MAX25[24:0];
        else if (x < MIN25) sat25 = MIN25[24:0];
        else sat25 = x[24:0];
    endfunction

    function automatic signed [17:0] sat18(input signed [47:0] x);
        if (x > MAX18) sat18 = MAX18[17:0];
        else if (x < MIN18) sat18 = MIN18[17:0];
        else sat18 = x[17:0];
    endfunction

    // sat25(round-half-up(x / 2^16))
    function automatic signed [24:0] rsat16(input signed [47:0] x);
        reg signed [47:0] t;
        begin
            t = (x + RND16) >>> 16;
            rsat16 = sat25(t);
        end
    endfunction

    function automatic signed [47:0] ext25(input signed [24:0] x);
        ext25 = {{23{x[24]}}, x};
    endfunction

    // (y << 16) + 2^15: a CUR addend under a MAC with the rounding constant
    // in its 16 zero low bits.
    function automatic signed [47:0] yr16(input signed [24:0] y);
        yr16 = {{7{y[24]}}, y, 16'h8000};
    endfunction

    function automatic signed [47:0] ext18(input signed [17:0] x);
        ext18 = {{30{x[17]}}, x};
    endfunction

    // 18 x 25-bit signed product at its exact width (43 bits): the operands
    // are sign-extended to 43 bits by the context, so the result is exact.
    function automatic signed [42:0] mul43(input signed [17:0] c, input signed [24:0] x);
        mul43 = c * x;
    endfunction

    // COEF x CUR, exact, sign-extended to 48 bits explicitly (so that no
    // tool sees undriven upper product bits).
    function automatic signed [47:0] mul(input signed [17:0] c, input signed [24:0] x);
        reg signed [42:0] p;
        begin
            p   = mul43(c, x);
            mul = {{5{p[42]}}, p};
        end
    endfunction

    // clamp(x, lim) for lim >= 0 (x wide).
    function automatic signed [24:0] clamp(input signed [47:0] x, input signed [24:0] lim);
        if (x > ext25(lim)) clamp = lim;
        else if (x < -ext25(lim)) clamp = -lim;
        else clamp = x[24:0];
    endfunction

    // Leg c = sat25(-sat25(a + b)), from t = a + b and nt = -a - b.
    function automatic signed [24:0] leg_c(input signed [47:0] t, input signed [47:0] nt);
        if (t > MAX25) leg_c = -MAX25[24:0];
        else if (t <= MIN25) leg_c = MAX25[24:0];
        else leg_c = nt[24:0];
    endfunction

    // ------------------------------------------------------------ control
    reg  [LATENCY-1:0] vld_q;  // vld_q[n]: stage n+1 holds the decision
    reg                busy_q;
    wire               start = in_valid_i && !busy_q;
    wire               done = vld_q[LATENCY-2];  // stage 19 loads at this edge

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
    reg signed [24:0] pu0, pu0half, pu0h, ppsi, pkinv, ptol, pintlim, petalim;
    reg signed [17:0] pw2[0:3];
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
            pu0 <= p_u0_i;
            pu0half <= p_u0_half_i;
            pu0h <= p_u0_h_i;
            ppsi <= p_psi_l_i;
            pkinv <= p_kinv_t_i;
            ptol <= p_tol_i;
            pintlim <= p_int_lim_i;
            pintcond <= p_int_cond_i;
            petalim <= p_eta_lim_i;
            pw2[0] <= p_w2_i[17:0];
            pw2[1] <= p_w2_i[35:18];
            pw2[2] <= p_w2_i[53:36];
            pw2[3] <= p_w2_i[71:54];
        end
    end

    // ------------------------------------------------------------ stage 1
    // Basis products per angle k: u0 c, u0 s, u0h s, u0/2 c, u0/2 s, u0h c.
    reg signed [24:0] m_u0c[0:2], m_u0s[0:2], m_hs[0:2], m_halfc[0:2], m_halfs[0:2], m_hc[0:2];
    reg signed [47:0] f_pd, f_pq, h_pd, h_pq, ppsi_g;
    reg signed [24:0] iq_orig;
    reg signed [24:0] im_d_pmax, im_d_pmin, im_q_pmax, im_q_pmin;
    wire signed [17:0] cs_c[0:2];
    wire signed [17:0] cs_s[0:2];
    assign cs_c[0] = c0;
    assign cs_c[1] = c1;
    assign cs_c[2] = c2;
    assign cs_s[0] = s0;
    assign cs_s[1] = s1;
    assign cs_s[2] = s2;
    always @(posedge clk_i) begin : stage1
        integer k;
        for (k = 0; k < 3; k = k + 1) begin
            m_u0c[k]   <= rsat16(mul(cs_c[k], pu0));
            m_u0s[k]   <= rsat16(mul(cs_s[k], pu0));
            m_hs[k]    <= rsat16(mul(cs_s[k], pu0h));
            m_halfc[k] <= rsat16(mul(cs_c[k], pu0half));
            m_halfs[k] <= rsat16(mul(cs_s[k], pu0half));
            m_hc[k]    <= rsat16(mul(cs_c[k], pu0h));
        end
        f_pd <= mul(pa, im_d);
        f_pq <= mul(pa, im_q);
        h_pd <= mul(pa, ih_d_q);
        h_pq <= mul(pa, ih_q_q);
        ppsi_g <= -mul(g, ppsi);
        // T* (14 frac) x 1/k_T (16 frac) -> CUR: round half up >> 14.
        iq_orig <= sat25((mul(tref, pkinv) + 48'sd8192) >>> 14);
        // For stage 8: i_m + the two saturation values of the lambda term.
        im_d_pmax <= sat25(ext25(im_d) + MAX25);
        im_d_pmin <= sat25(ext25(im_d) + MIN25);
        im_q_pmax <= sat25(ext25(im_q) + MAX25);
        im_q_pmin <= sat25(ext25(im_q) + MIN25);
    end

    // ------------------------------------------------------------ stage 2
    reg signed [25:0] la_d[0:2], la_q[0:2], nla_d[0:2];  // leg a, -leg a (d)
    reg signed [24:0] lb_d[0:2], lb_q[0:2];
    reg signed [47:0] f_ad, f_aq;
    always @(posedge clk_i) begin : stage2
        integer k;
        for (k = 0; k < 3; k = k + 1) begin
            la_d[k]  <= {m_u0c[k][24], m_u0c[k]};
            nla_d[k] <= -{m_u0c[k][24], m_u0c[k]};
            la_q[k]  <= -{m_u0s[k][24], m_u0s[k]};  // may be +2^24: 26 bits
            lb_d[k]  <= sat25(ext25(m_hs[k]) - ext25(m_halfc[k]));
            lb_q[k]  <= sat25(ext25(m_halfs[k]) + ext25(m_hc[k]));
        end
        f_ad <= f_pd + mul(g, im_q);
        f_aq <= f_pq - mul(g, im_d);
    end

    // ------------------------------------------------------------ stage 3
    reg signed [24:0] lc_d[0:2], lc_q[0:2];
    reg signed [24:0] ra_d[0:2], ra_q[0:2];  // sat25(leg a)
    reg signed [24:0] rab_d[0:2], rab_q[0:2];  // sat25(sat25(a) + b)
    reg signed [47:0] f_aq2;
    function automatic signed [47:0] ext26(input signed [25:0] x);
        ext26 = {{22{x[25]}}, x};
    endfunction
    always @(posedge clk_i) begin : stage3
        integer k;
        for (k = 0; k < 3; k = k + 1) begin
            lc_d[k]  <= leg_c(ext26(la_d[k]) + ext25(lb_d[k]), ext26(nla_d[k]) - ext25(lb_d[k]));
            lc_q[k]  <= leg_c(ext26(la_q[k]) + ext25(lb_q[k]), ext25(m_u0s[k]) - ext25(lb_q[k]));
            ra_d[k]  <= sat25(ext26(la_d[k]));
            ra_q[k]  <= sat25(ext26(la_q[k]));
            rab_d[k] <= sat25(ext25(sat25(ext26(la_d[k]))) + ext25(lb_d[k]));
            rab_q[k] <= sat25(ext25(sat25(ext26(la_q[k]))) + ext25(lb_q[k]));
        end
        f_aq2 <= f_aq + ppsi_g;
    end

    // ------------------------------------------------------------ stage 4
    // proj(b, s) = sat(sat(sat(a') + b') + c'): legs a, b (stage 3), then c.
    function automatic signed [24:0] proj_ab(input [1:0] ab, input signed [24:0] ra,
                                             input signed [24:0] lb, input signed [24:0] rab);
        case (ab)
            2'b00: proj_ab = 25'sd0;
            2'b01: proj_ab = lb;
            2'b10: proj_ab = ra;
            default: proj_ab = rab;
        endcase
    endfunction
    reg signed [24:0] u0_d, u0_q, u1_d, u1_q;
    reg signed [24:0] u2_d[0:7], u2_q[0:7];
    always @(posedge clk_i) begin : stage4
        integer s;
        u0_d <= sat25(ext25(proj_ab(sp_q[2:1], ra_d[0], lb_d[0], rab_d[0]))
                      + (sp_q[0] ? ext25(lc_d[0]) : 48'sd0));
        u0_q <= sat25(ext25(proj_ab(sp_q[2:1], ra_q[0], lb_q[0], rab_q[0]))
                      + (sp_q[0] ? ext25(lc_q[0]) : 48'sd0));
        u1_d <= sat25(ext25(proj_ab(sa_q[2:1], ra_d[1], lb_d[1], rab_d[1]))
                      + (sa_q[0] ? ext25(lc_d[1]) : 48'sd0));
        u1_q <= sat25(ext25(proj_ab(sa_q[2:1], ra_q[1], lb_q[1], rab_q[1]))
                      + (sa_q[0] ? ext25(lc_q[1]) : 48'sd0));
        for (s = 0; s < 8; s = s + 1) begin
            u2_d[s] <= sat25(ext25(proj_ab(s[2:1], ra_d[2], lb_d[2], rab_d[2]))
                             + (s[0] ? ext25(lc_d[2]) : 48'sd0));
            u2_q[s] <= sat25(ext25(proj_ab(s[2:1], ra_q[2], lb_q[2], rab_q[2]))
                             + (s[0] ? ext25(lc_q[2]) : 48'sd0));
        end
    end

    // ------------------------------------------------------------ stages 5-8
    reg signed [24:0] y0_d, y0_q, full_d, full_q, df_d, df_q, i0_d, i0_q;
    // lambda (full - i_m): rounded alone (to detect saturation) and with
    // i_m added under the rounding constant, in parallel.
    wire signed [47:0] lam_d = mul(plam, df_d);
    wire signed [47:0] lam_q = mul(plam, df_q);
    wire signed [47:0] lr_d = (lam_d + RND16) >>> 16;
    wire signed [47:0] lr_q = (lam_q + RND16) >>> 16;
    wire signed [47:0] lri_d = (lam_d + yr16(im_d)) >>> 16;
    wire signed [47:0] lri_q = (lam_q + yr16(im_q)) >>> 16;
    always @(posedge clk_i) begin
        y0_d   <= sat25(ext25(u0_d) + ext25(etap_d_q));
        y0_q   <= sat25(ext25(u0_q) + ext25(etap_q_q));
        full_d <= sat25((f_ad + yr16(y0_d)) >>> 16);
        full_q <= sat25((f_aq2 + yr16(y0_q)) >>> 16);
        df_d   <= sat25(ext25(full_d) - ext25(im_d));
        df_q   <= sat25(ext25(full_q) - ext25(im_q));
        i0_d   <= (lr_d > MAX25) ? im_d_pmax : (lr_d < MIN25) ? im_d_pmin : sat25(lri_d);
        i0_q   <= (lr_q > MAX25) ? im_q_pmax : (lr_q < MIN25) ? im_q_pmin : sat25(lri_q);
    end

    // ------------------------------------------------------------ stages 9-11
    reg signed [24:0] e_d, e_q, di, km_d, km_q, ki_d, ki_q, kx;
    reg signed [24:0] eta_d, eta_q, nu_n_d, nu_n_q, x_n;
    reg signed [47:0] g_pd, g_pq, g_ad, g_aq, g_aq2, h_ad, h_aq, h_aq2;
    always @(posedge clk_i) begin
        // 9
        e_d  <= sat25(ext25(i0_d) - ext25(ih_d_q));
        e_q  <= sat25(ext25(i0_q) - ext25(ih_q_q));
        di   <= sat25(ext25(iqrp_q) - ext25(i0_q));
        g_pd <= mul(pa, i0_d);
        g_pq <= mul(pa, i0_q);
        h_ad <= h_pd + mul(g, i0_q);
        h_aq <= h_pq - mul(g, i0_d);
        // 10
        km_d  <= rsat16(mul(pkp, e_d));
        km_q  <= rsat16(mul(pkp, e_q));
        ki_d  <= rsat16(mul(pki, e_d));
        ki_q  <= rsat16(mul(pki, e_q));
        kx    <= rsat16(mul(pkint, di));
        g_ad  <= g_pd + mul(g, i0_q);
        g_aq  <= g_pq - mul(g, i0_d);
        h_aq2 <= h_aq + ppsi_g;
        // 11 (clamp(sat25(a + b), lim) = clamp(a + b, lim) for 0 <= lim <= MAX)
        eta_d  <= clamp(ext25(km_d) + ext25(nu_d_q), petalim);
        eta_q  <= clamp(ext25(km_q) + ext25(nu_q_q), petalim);
        nu_n_d <= clamp(ext25(nu_d_q) + ext25(ki_d), petalim);
        nu_n_q <= clamp(ext25(nu_q_q) + ext25(ki_q), petalim);
        // Eq. (13), conditional on the previous band hit if enabled.
        x_n    <= (band_q || !pintcond) ? clamp(ext25(x_q) + ext25(kx), pintlim) : x_q;
        g_aq2  <= g_aq + ppsi_g;
    end

    // ------------------------------------------------------------ stages 12-13
    reg signed [24:0] y1_d, y1_q, iq_ref, y2_d[0:7], y2_q[0:7];
    reg signed [24:0] i1_d, i1_q, ihn_d, ihn_q;
    reg signed [47:0] yo_d[0:7], yo_q[0:7];
    always @(posedge clk_i) begin : stages12_13
        integer s;
        // 12
        y1_d   <= sat25(ext25(u1_d) + ext25(eta_d));
        y1_q   <= sat25(ext25(u1_q) + ext25(eta_q));
        iq_ref <= sat25(ext25(iq_orig) + ext25(x_n));
        for (s = 0; s < 8; s = s + 1) begin
            y2_d[s] <= sat25(ext25(u2_d[s]) + ext25(eta_d));
            y2_q[s] <= sat25(ext25(u2_q[s]) + ext25(eta_q));
        end
        // 13
        i1_d  <= sat25((g_ad + yr16(y1_d)) >>> 16);
        i1_q  <= sat25((g_aq2 + yr16(y1_q)) >>> 16);
        ihn_d <= sat25((h_ad + yr16(y1_d)) >>> 16);
        ihn_q <= sat25((h_aq2 + yr16(y1_q)) >>> 16);
        for (s = 0; s < 8; s = s + 1) begin
            yo_d[s] <= yr16(y2_d[s]);
            yo_q[s] <= yr16(y2_q[s]) + ppsi_g;
        end
    end

    // ------------------------------------------------------------ stages 14-19
    reg signed [47:0] k_pd, k_pq, k_wq, k_wd;
    reg signed [24:0] i2_d[0:7], i2_q[0:7], err[0:7];
    reg signed [17:0] dc[0:7], qc[0:7];
    reg signed [47:0] sq_d[0:7], sq_q[0:7];
    reg               inband[0:7];
    reg        [ 1:0] ntr[0:7];
    reg signed [47:0] cost2[0:7];
    reg               inband2[0:7];
    reg        [ 1:0] ntr2[0:7];
    reg signed [24:0] err2[0:7];
    reg        [ 2:0] s_next;

    function automatic [1:0] popcount3(input [2:0] v);
        popcount3 = {1'b0, v[0]} + {1'b0, v[1]} + {1'b0, v[2]};
    endfunction

    // |t| clipped to MAX25 (= min(|sat25(t)|, MAX25), see the model's err).
    function automatic signed [24:0] abs_clip(input signed [47:0] t);
        reg signed [47:0] a;
        begin
            a = (t < 0) ? -t : t;
            abs_clip = (a > MAX25) ? MAX25[24:0] : a[24:0];
        end
    endfunction

    // Selection key: {out of band, value (offset binary), n}; the first
    // candidate with the least key wins (the model's strict < scan).
    function automatic [50:0] key(input ob, input signed [47:0] val, input [1:0] n);
        key = {ob, ~val[47], val[46:0], n};
    endfunction

    reg [50:0] keys[0:7];
    reg win;
    reg [2:0] best;
    always @(*) begin : select8
        integer s, j;
        for (s = 0; s < 8; s = s + 1) begin
            keys[s] = key(!inband2[s], inband2[s] ? cost2[s] : ext25(err2[s]), ntr2[s]);
        end
        best = 3'd0;
        for (s = 7; s >= 0; s = s - 1) begin
            win = 1'b1;
            for (j = 0; j < 8; j = j + 1) begin
                if (j < s && !(keys[s] < keys[j])) win = 1'b0;
                if (j > s && keys[j] < keys[s]) win = 1'b0;
            end
            if (win) best = s[2:0];
        end
    end

    always @(posedge clk_i) begin : stages14_19
        integer s;
        // 14
        k_pd <= mul(pa, i1_d);
        k_pq <= mul(pa, i1_q);
        k_wq <= mul(g, i1_q);
        k_wd <= mul(g, i1_d);
        for (s = 0; s < 8; s = s + 1) begin
            // 15
            i2_d[s] <= sat25((k_pd + k_wq + yo_d[s]) >>> 16);
            i2_q[s] <= sat25((k_pq - k_wd + yo_q[s]) >>> 16);
            // 16
            err[s] <= abs_clip(ext25(iq_ref) - ext25(i2_q[s]));
            dc[s]  <= sat18((ext25(i2_d[s]) + 48'sd128) >>> 8);
            qc[s]  <= sat18((ext25(i2_q[s]) + 48'sd128) >>> 8);
            // 17
            sq_d[s]   <= mul(dc[s], i2_d[s]);
            sq_q[s]   <= mul(qc[s], i2_q[s]);
            inband[s] <= ext25(err[s]) <= ext25(ptol);
            ntr[s]    <= popcount3(s[2:0] ^ sa_q);
            err2[s]   <= err[s];
            // 18
            cost2[s]   <= mul(pw2[ntr[s]], sat25((sq_d[s] + sq_q[s] + 48'sd4096) >>> 13));
            inband2[s] <= inband[s];
            ntr2[s]    <= ntr[s];
        end
        // 19
        s_next <= best;
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
            band_q <= inband2[0] | inband2[1] | inband2[2] | inband2[3]
                    | inband2[4] | inband2[5] | inband2[6] | inband2[7];
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
            assign err_o[25*gi+:25]   = err2[gi];
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
