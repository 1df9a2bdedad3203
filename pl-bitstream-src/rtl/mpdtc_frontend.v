// mpdtc_frontend: the PL front end of the MPDTC core, bit for bit
// models::pmsm::frontend_fixed::frontend (formats, table and error bound
// there): encoder count -> electrical angle, speed -> angle step and w Ts,
// cos/sin at the Park angle and at the core's three instants (1024-entry
// sine table, generated sin_table.vh, with linear interpolation), ADC
// offset/gain, Clarke and Park -> i_d, i_q in the core's format (CUR).
//
// Timing: in_valid_i captures the inputs and registers; out_valid_o is high
// exactly LATENCY = 9 cycles later with every output valid; i_d_o and i_q_o
// (registers MPDTC_FE_ID/IQ of the PS) change only at that edge and hold
// the last result. Stages read the captured registers, so a new
// in_valid_i is taken at most every LATENCY cycles (one period in flight;
// the control period is far longer). At most one multiplier level and one
// adder between registers:
//   1  pos - align; speed x spd_scale; ADC - offset
//   2  count (+ cpr if negative); dphi = product >> 8; (ADC - off) x gain
//   3  phi = count x ang_scale (low 32 bits); (dphi >> 8) x age[j];
//      (dphi >> 8) x 2 pi 2^14; Clarke: b + c, b - c
//   4  the three instants' angles (phi + offset); Clarke: 2 a - (b + c)
//      (one adder per register: the three-operand sum with its
//      saturation was 8.0 ns estimated in pl_top); i_beta (x 1/sqrt 3);
//      that product + 2^21; table read 0: sin and cos at phi
//   5  value 0 = T[i] + round(D[i] f / 2^16) (T[i] << 16 in the addend);
//      table read 1 (instant 0); w Ts = sat18(that sum >> 22); i_alpha
//      (x 1/3; the Park products read it from cycle 6 on)
//   6  value 1; read 2          7  value 2; read 3
//   8  value 3; Park: i_d = R(c i_alpha + s i_beta), i_q = R(c i_beta - s i_alpha)
//      (products and sums in free-running registers from cycle 6 on, the
//      saturation at the edge that raises out_valid_o)
// One 1024-word table (one BRAM36, two read ports) serves all eight
// lookups; word i = {D[i] = T[i + 1] - T[i], T[i]}.
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
    localparam integer LATENCY = 9;
    localparam signed [47:0] MAX25 = 48'sd16777215;
    localparam signed [47:0] MIN25 = -48'sd16777216;
    localparam signed [47:0] MAX18 = 48'sd131071;
    localparam signed [47:0] MIN18 = -48'sd131072;
    localparam signed [17:0] TWO_PI_Q14 = 18'sd102944;
    localparam signed [17:0] ONE_THIRD = 18'sd21845;
    localparam signed [17:0] INV_SQRT3 = 18'sd37837;

    // Saturation to 25 / 18 bits. The range test looks at the bits above
    // the result's sign (x > MAX: positive with any of them set; x < MIN:
    // negative with any of them clear): LUTs only, no 48-bit comparison
    // chain after the adder that feeds it (one clock at 100 MHz, docs/rtl.md).
    function automatic signed [24:0] sat25(input signed [47:0] x);
        if (!x[47] && |x[46:24]) sat25 = MAX25[24:0];
        else if (x[47] && !(&x[46:24])) sat25 = MIN25[24:0];
        else sat25 = x[24:0];
    endfunction

    function automatic signed [17:0] sat18(input signed [47:0] x);
        if (!x[47] && |x[46:17]) sat18 = MAX18[17:0];
        else if (x[47] && !(&x[46:17])) sat18 = MIN18[17:0];
        else sat18 = x[17:0];
    endfunction

    // ------------------------------------------------------------ control
    reg [LATENCY-1:0] vld_q;
    always @(posedge clk_i) begin
        if (rst_i) vld_q <= {LATENCY{1'b0}};
        else vld_q <= {vld_q[LATENCY-2:0], in_valid_i};
    end
    assign out_valid_o = vld_q[LATENCY-1];

    // ------------------------------------------------------------ capture
    reg        [15:0] pos, cpr, align;
    reg signed [15:0] speed;
    reg signed [15:0] adc[0:2], off[0:2];
    reg signed [17:0] gain[0:2], age[0:2], tref;
    reg        [31:0] ang_scale, spd_scale;
    always @(posedge clk_i) begin
        if (in_valid_i) begin
            pos       <= pos_i;
            speed     <= speed_i;
            adc[0]    <= adc_a_i;
            adc[1]    <= adc_b_i;
            adc[2]    <= adc_c_i;
            tref      <= t_ref_i;
            cpr       <= cpr_i;
            align     <= align_pos_i;
            ang_scale <= ang_scale_i;
            spd_scale <= spd_scale_i;
            age[0]    <= age0_i;
            age[1]    <= age1_i;
            age[2]    <= age2_i;
            off[0]    <= off_a_i;
            off[1]    <= off_b_i;
            off[2]    <= off_c_i;
            gain[0]   <= gain_a_i;
            gain[1]   <= gain_b_i;
            gain[2]   <= gain_c_i;
        end
    end

    // ------------------------------------------------------------ stages 1-4
    reg signed [16:0] d1, adiff[0:2];
    reg signed [31:0] dphi;
    reg signed [17:0] cnt;
    reg signed [24:0] cur[0:2];
    reg        [31:0] phi, offs[0:2];
    reg signed [17:0] w_ts;
    reg signed [47:0] wtp, wtr;
    reg signed [24:0] csa, csb;
    reg signed [25:0] bc;  // b + c, exact
    reg        [31:0] ang[1:3];
    reg signed [24:0] i_al, i_be;
    reg signed [48:0] spdp;
    wire signed [23:0] dphi24 = dphi[31:8];
    // Products whose low or high bits are dropped on purpose: the angle
    // and its offsets are taken modulo one turn (low 32 bits), the step
    // is floor(product / 2^8).
    /* verilator lint_off UNUSEDSIGNAL */
    wire signed [50:0] pw = cnt * $signed({1'b0, ang_scale});
    wire signed [41:0] po[0:2];
    wire signed [48:0] spdp_w = spdp;
    /* verilator lint_on UNUSEDSIGNAL */
    // ADC - offset times gain at its exact width (17 x 18 bits: |p| <= 2^33,
    // + 8 still inside 35 bits), sign-extended explicitly: written as a
    // 48-bit product, the saturation tested all 24 bits above the result
    // behind the DSP48E1 (8.0 ns estimated in pl_top), now the 7 that can
    // differ from the sign.
    wire signed [34:0] gp[0:2];
    wire signed [34:0] gr[0:2];
    genvar gk;
    for (gk = 0; gk < 3; gk = gk + 1) begin : g_gain
        assign gp[gk] = adiff[gk] * gain[gk];
        assign gr[gk] = gp[gk] + 35'sd8;
    end
    assign po[0] = dphi24 * age[0];
    assign po[1] = dphi24 * age[1];
    assign po[2] = dphi24 * age[2];
    always @(posedge clk_i) begin : stages1_4
        integer k;
        // 1
        d1   <= $signed({1'b0, pos}) - $signed({1'b0, align});
        spdp <= speed * $signed({1'b0, spd_scale});
        for (k = 0; k < 3; k = k + 1) adiff[k] <= {adc[k][15], adc[k]} - {off[k][15], off[k]};
        // 2
        cnt  <= (d1 < 0) ? {d1[16], d1} + $signed({2'b00, cpr}) : {d1[16], d1};
        dphi <= spdp_w[39:8];
        for (k = 0; k < 3; k = k + 1) cur[k] <= sat25({{17{gr[k][34]}}, gr[k][34:4]});
        // 3
        phi  <= pw[31:0];
        for (k = 0; k < 3; k = k + 1) offs[k] <= po[k][39:8];
        wtp  <= dphi24 * TWO_PI_Q14;  // exact, 42 bits
        bc   <= {cur[1][24], cur[1]} + {cur[2][24], cur[2]};
        csb  <= sat25({{23{cur[1][24]}}, cur[1]} - {{23{cur[2][24]}}, cur[2]});
        // 4
        for (k = 0; k < 3; k = k + 1) ang[k+1] <= phi + offs[k];
        csa  <= sat25({{22{cur[0][24]}}, cur[0], 1'b0} - {{22{bc[25]}}, bc});
        i_be <= sat25((INV_SQRT3 * csb + 48'sd32768) >>> 16);
        wtr  <= wtp + 48'sd2097152;
        // 5
        w_ts <= sat18(wtr >>> 22);
        i_al <= sat25((ONE_THIRD * csa + 48'sd32768) >>> 16);
    end

    // ------------------------------------------------------------ stages 5-8
    // One shared table, read through two ports (sine and cosine of the same
    // angle) in four consecutive cycles: Park angle at stage 4 (phi is
    // ready after stage 3), then the three instants at stages 5..7. Each
    // word holds the entry and its step to the next, {T[i + 1] - T[i], T[i]}
    // (the step is at most 402, so 18 bits hold it exactly), so the
    // interpolation is one multiply-add after the read: the eight lookups
    // take one 1024 x 36 ROM (one BRAM36) and two multipliers.
    reg [35:0] sin_rom[0:1023];
    `include "sin_table.vh"

    // Read r (0 = Park, 1..3 = instants) is issued in the cycle vld_q[3 + r].
    // bits 5..0 of the angle are below the interpolation step
    /* verilator lint_off UNUSEDSIGNAL */
    wire [31:0] a = vld_q[3] ? phi : vld_q[4] ? ang[1] : vld_q[5] ? ang[2] : ang[3];
    /* verilator lint_on UNUSEDSIGNAL */
    wire [9:0] idx_s = a[31:22];
    wire [9:0] idx_c = {a[31:30] + 2'd1, a[29:22]};  // + 1/4 turn
    reg  [35:0] qs_q, qc_q;
    reg  [15:0] fr_q;
    always @(posedge clk_i) begin
        qs_q <= sin_rom[idx_s];
        qc_q <= sin_rom[idx_c];
        fr_q <= a[21:6];
    end

    // T[i] + round((T[i + 1] - T[i]) f / 2^16), one multiply-add per port.
    function automatic signed [17:0] interp(input [35:0] q, input [15:0] f);
        interp = sat18(($signed(q[35:18]) * $signed({1'b0, f})
                        + $signed({{14{q[17]}}, q[17:0], 16'h8000})) >>> 16);
    endfunction
    wire signed [17:0] vs = interp(qs_q, fr_q);
    wire signed [17:0] vc = interp(qc_q, fr_q);

    // v[2 m] = sin, v[2 m + 1] = cos of angle m, written one cycle after
    // read m; each holds until the next period's read.
    reg signed [17:0] v[0:7];
    always @(posedge clk_i) begin : store
        integer m;
        for (m = 0; m < 4; m = m + 1) begin
            if (vld_q[4+m]) begin
                v[2*m]   <= vs;
                v[2*m+1] <= vc;
            end
        end
    end

    // ------------------------------------------------------------ stage 8
    // Loaded only at the edge that raises out_valid_o: i_d_o and i_q_o are
    // the registers MPDTC_FE_ID/IQ, which must hold the last result (a
    // free-running stage would show mixes of the new currents and the old
    // angle in the cycles before, since i_alpha and the table values of a
    // new input arrive in different cycles).
    // The products and their sums in free-running registers: v[0], v[1]
    // and i_alpha, i_beta hold from the cycle vld_q[5] on, so the products
    // are settled in cycle vld_q[6] and the sums in cycle vld_q[7].
    reg signed [47:0] pk_q[0:3];  // c i_alpha, s i_beta, c i_beta, s i_alpha (exact)
    reg signed [47:0] pd_q, pq_q;
    always @(posedge clk_i) begin
        pk_q[0] <= v[1] * i_al;
        pk_q[1] <= v[0] * i_be;
        pk_q[2] <= v[1] * i_be;
        pk_q[3] <= v[0] * i_al;
        pd_q    <= pk_q[0] + pk_q[1] + 48'sd32768;
        pq_q    <= pk_q[2] - pk_q[3] + 48'sd32768;
    end
    reg signed [24:0] i_d, i_q;
    always @(posedge clk_i) begin
        if (vld_q[LATENCY-2]) begin
            i_d <= sat25(pd_q >>> 16);
            i_q <= sat25(pq_q >>> 16);
        end
    end

`ifdef FORMAL
    // Independent monitors; the all-zero power-up state is the reset state.
    reg        f_past_valid = 1'b0;
    reg [3:0]  f_norst_q = 4'd0;    // cycles since the last reset, up to 15
    reg [8:0]  f_iv_q = 9'd0;       // f_iv_q[k]: in_valid_i k + 1 cycles ago
    always @(posedge clk_i) begin
        f_past_valid <= 1'b1;
        f_norst_q    <= rst_i ? 4'd0 : (f_norst_q == 4'd15) ? 4'd15 : f_norst_q + 4'd1;
        f_iv_q       <= {f_iv_q[7:0], in_valid_i};
    end

    // Exactly one period's input in the read window (legal spacing).
    wire f_alone = (f_iv_q[6:3] == 4'b0001) || (f_iv_q[6:3] == 4'b0010)
                || (f_iv_q[6:3] == 4'b0100) || (f_iv_q[6:3] == 4'b1000);
    // The values in pairs (sin, cos of angle m).
    wire [35:0] f_v0 = {v[1], v[0]};
    wire [35:0] f_v1 = {v[3], v[2]};
    wire [35:0] f_v2 = {v[5], v[4]};
    wire [35:0] f_v3 = {v[7], v[6]};

    integer f_k;
    always @(*) begin
        // Fixed latency: out_valid_o exactly LATENCY cycles after an
        // in_valid_i with no reset in between; never without one, never
        // within LATENCY cycles of a reset.
        assert (out_valid_o == (f_norst_q >= 4'd9 && f_iv_q[8]));
        // The same for every stage of the valid pipeline (makes the
        // induction hold in one step).
        for (f_k = 0; f_k < LATENCY; f_k = f_k + 1)
            assert (vld_q[f_k] == (f_iv_q[f_k] && {28'd0, f_norst_q} > f_k));
        // The cosine reads a quarter turn (256 entries) after the sine.
        assert (idx_c == idx_s + 10'd256);
        // Read m takes the Park angle (m = 0) or instant m - 1, 4 + m cycles
        // after the input (whenever one period is in flight).
        if (f_alone && f_iv_q[3] && f_norst_q >= 4'd4) assert (a == phi);
        if (f_alone && f_iv_q[4] && f_norst_q >= 4'd5) assert (a == ang[1]);
        if (f_alone && f_iv_q[5] && f_norst_q >= 4'd6) assert (a == ang[2]);
        if (f_alone && f_iv_q[6] && f_norst_q >= 4'd7) assert (a == ang[3]);
    end

    always @(posedge clk_i) begin
        if (f_past_valid) begin
            // The currents change only together with out_valid_o (they
            // hold the last result in between), or after a reset.
            if (i_d != $past(i_d) || i_q != $past(i_q)) assert (out_valid_o || $past(rst_i));
            // Value m changes only in the cycle after its read, 6 + m
            // cycles after the input: the outputs hold until the next one.
            if (f_v0 != $past(f_v0))
                assert (f_iv_q[5] && $past(f_norst_q) >= 4'd5);
            if (f_v1 != $past(f_v1))
                assert (f_iv_q[6] && $past(f_norst_q) >= 4'd6);
            if (f_v2 != $past(f_v2))
                assert (f_iv_q[7] && $past(f_norst_q) >= 4'd7);
            if (f_v3 != $past(f_v3))
                assert (f_iv_q[8] && $past(f_norst_q) >= 4'd8);
        end
    end
`endif

    assign i_d_o     = i_d;
    assign i_q_o     = i_q;
    assign cos0_o    = v[3];
    assign sin0_o    = v[2];
    assign cos1_o    = v[5];
    assign sin1_o    = v[4];
    assign cos2_o    = v[7];
    assign sin2_o    = v[6];
    assign w_ts_o    = w_ts;
    assign t_ref_o   = tref;
    assign phi_o     = phi;
    assign dphi_o    = dphi;
    assign i_alpha_o = i_al;
    assign i_beta_o  = i_be;
endmodule

`default_nettype wire
