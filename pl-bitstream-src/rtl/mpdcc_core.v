// mpdcc_core: the MPDCC core of paper 001 (Algorithm 1) with a central
// scheduler and N pipelined explorers, bit-exact with the decision of
// models::mpdcc::mpdcc_fixed (MpdccFixed::decide_raw, frozen core Structure::CORE).
//
// Inputs are the state registers (models::mpdcc::fpga::Inputs, already
// quantized) and the design constants (Coeffs), held stable from start_i to
// done_o. On start_i the scheduler starts the common terms (mpdcc_common,
// eq. 14, on MULS shared multipliers) and, once the terms the explorers read
// first are final (COMMON_LATENCY = mpdcc_common's ISSUE_DELAY = 20 cycles;
// the rest is final before it is read), enumerates S(s(k-1)): per phase the
// positions within one level of s(k-1), a contiguous code range [lo, hi]
// because the level is monotonic in the code; candidates in ascending code
// order (a outer, c inner), n_use_i (1..N) of them per issue clock,
// candidate i of an issue clock to explorer i; an issue clock every II
// clocks. Each explorer (mpdcc_explorer with the same II) takes one
// candidate every II clocks and returns it XLAT = 41 + max(II - 3, 0)
// cycles later, so the results of one issue clock arrive together and in
// enumeration order. II = 1 is the full-rate datapath (seven search lanes
// per explorer); II > 1 shares ceil(7 / II) lanes per explorer (less area,
// II times the issue time). A registered
// arg-min tree (ARGMIN_LEVELS = 3 levels, one comparison each) reduces them
// and the scheduler folds the tree's result into the decision's minimum
// (strict "<" with the earlier candidate on the left: the first of equal
// ones wins, as the model's select()):
//   best  = min J over L* > 0,  best_dl = min J_dl (eqs. 15-16)
// and takes the lazy check from the result of s(k-1) itself: "all seven
// |e(k+1)| <= bnd with s(k-1)" is exactly J_dl(s(k-1)) <= 0.
// Decision: kept (lazy check passes: s(k-1), no candidates), optimal (best),
// or deadlock (best_dl). done_o is high for one cycle with the decision;
// cycles_o counts the clock edges from the start_i cycle to the done_o cycle:
//   20 + II (G - 1) + 1 + XLAT + 3 + 1,  G = ceil(|S| / n_use)
//   (models::mpdcc::cycles::pipelined_core_cycles_ii; II = 1: 20 + G + 41 + 3 + 1)
// The search always runs (a kept decision takes as long): the lazy check
// costs no separate pass.
`default_nettype none

module mpdcc_core #(
    parameter integer N = 2,  // explorer units (1..6)
    parameter integer II = 1  // clocks per issue (1..7): 1 full rate, > 1 shared lanes
) (
    input  wire               clk_i,
    input  wire               rst_i,
    input  wire               start_i,
    output wire               busy_o,
    input  wire        [2:0]  n_use_i,    // explorers used, 1..N (clamped)
    input  wire        [8:0]  s_prev_i,   // {c, b, a}
    // state registers (raw, models::mpdcc::fpga::Inputs)
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
    // design constants (models::mpdcc::fpga::Coeffs)
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
    output reg                done_o,
    output reg         [8:0]  s_o,
    output reg         [1:0]  kind_o,      // 0 kept, 1 optimal, 2 deadlock
    output reg         [7:0]  l_star_o,    // horizon of an optimal decision, else 0
    output reg         [31:0] cost_o,      // J of the chosen candidate (kept: 0)
    output reg  signed [31:0] j_dl_o,      // J_dl of the chosen candidate (kept: 0)
    output reg         [7:0]  candidates_o,
    output reg         [15:0] cycles_o
);
    // mpdcc_common's shared multipliers; the candidates start this many
    // cycles after the start strobe's edge (mpdcc_common ISSUE_DELAY: the
    // common terms are final when the explorers read them)
    localparam integer MULS = 4;
    localparam integer COMMON_LATENCY = 20;
    // registered levels of the arg-min tree (up to 8 results per clock)
    localparam integer ARGMIN_LEVELS = 3;

    // ------------------------------------------------ admissible ranges
    function automatic [2:0] lo_of(input [2:0] f);
        case (f)
            3'd0, 3'd1, 3'd2: lo_of = 3'd0;
            3'd3, 3'd4:       lo_of = 3'd1;
            3'd5, 3'd6:       lo_of = 3'd3;
            default:          lo_of = 3'd5;
        endcase
    endfunction
    function automatic [2:0] hi_of(input [2:0] f);
        case (f)
            3'd0:             hi_of = 3'd2;
            3'd1, 3'd2:       hi_of = 3'd4;
            3'd3, 3'd4:       hi_of = 3'd6;
            default:          hi_of = 3'd7;
        endcase
    endfunction

    reg  [8:0] hi_q;         // {c, b, a}: the set's last candidate
    reg  [3:0] aend_q;       // hi_a + 1: a counter's a once past the set
    // Candidate counters, one per explorer, {a[3], c, b, a[2:0]}: counter
    // j holds the (issued + j)-th candidate of S; a (the outer digit) has
    // a fourth bit so that a counter past the set's last candidate reads
    // hi_a + 1 instead of wrapping. Each steps by n_use on its own, so no
    // path runs through another explorer's candidate (a chain of N
    // increments from one counter grows with N and missed 8 ns at N >= 2).
    // The step runs one position ahead: nxt_q[j] holds the candidate n_use
    // further, stepped from itself, and ctr_q[j] takes it. ctr_q drives its
    // explorer (81 LUT inputs at II = 1), so stepping it in place put that
    // fan-out on the step's path (8.09 ns at II = 1, N = 3); nxt_q drives
    // only the step and ctr_q. The start loads nxt_q with the set's j-th
    // candidate, and the last clock before the issue takes the first step.
    reg  [9:0] ctr_q [0:N-1];
    reg  [9:0] nxt_q [0:N-1];
    reg        gen_q;        // enumerating
    reg  [5:0] pre_q;        // cycles left until the common terms are valid
    reg        busy_q;
    reg  [2:0] nuse_q;
    reg  [15:0] cyc_q;
    reg  [7:0] issued_q, received_q;
    reg  [2:0] ph_q;         // clocks since the last issue clock (II > 1)
    // an issue clock: every clock at II = 1, every II-th clock otherwise
    wire slot = (II == 1) ? 1'b1 : (ph_q == 3'd0);
    assign busy_o = busy_q;

    // The k-th successor (k = 0..6) of a candidate in ascending code order
    // within the ranges (c inner, b, a outer) is a mixed-radix addition:
    // each range holds 3, 5 or 6 positions, so adding k <= 6 to c carries
    // at most 2 into b, and b carries at most 1 into a. Written as
    // arithmetic, its subtractions and comparisons became four carry chains
    // in series (11.7 ns at N = 2); here the digit steps are tables: built
    // at elaboration (indexed by s(k-1)'s digit, which gives the range, the
    // digit and the addend), from which the start loads the decision's own
    // small tables into registers (c plus n_use, b plus 1 and plus 2), so a
    // step is a register multiplexer and a select.
    // digit_rom entry {f, x, d} (byte f * 64 + x * 8 + d): {carry, x'} of
    // x + d in f's range: carry = (x - lo + d) / n in bits 4:3, x' = lo +
    // (x - lo + d) mod n in bits 2:0; entries of an x outside the range or
    // d > max_d are never read and hold 0.
    function automatic [8*512-1:0] digit_rom(input integer max_d);
        integer f, x, d, lo, hi, t;
        /* verilator lint_off UNUSEDSIGNAL */
        integer e;  // integer arithmetic; its low byte is the entry
        /* verilator lint_on UNUSEDSIGNAL */
        begin
            digit_rom = {8 * 512{1'b0}};
            for (f = 0; f < 8; f = f + 1) begin
                lo = {29'd0, lo_of(f[2:0])};
                hi = {29'd0, hi_of(f[2:0])};
                for (x = lo; x <= hi; x = x + 1)
                    for (d = 0; d <= max_d; d = d + 1) begin
                        t = x - lo + d;
                        e = ((t / (hi - lo + 1)) << 3) + lo + t % (hi - lo + 1);
                        digit_rom[8 * (64 * f + 8 * x + d) +: 8] = e[7:0];
                    end
            end
        end
    endfunction
    localparam [8*512-1:0] STEP_C = digit_rom(6);  // d = k
    localparam [8*512-1:0] STEP_B = digit_rom(2);  // d = the carry from c
    // The entries of a range's first position: byte f * 8 + d = digit_rom's
    // {f, lo(f), d} (the set's first candidate plus d, at the start).
    function automatic [8*64-1:0] first_rom(input [8*512-1:0] rom);
        integer f, d;
        begin
            first_rom = {8 * 64{1'b0}};
            for (f = 0; f < 8; f = f + 1)
                for (d = 0; d < 8; d = d + 1)
                    first_rom[8 * (8 * f + d) +: 8] = rom[8 * (64 * f + 8 * lo_of(f[2:0]) + d) +: 8];
        end
    endfunction
    localparam [8*64-1:0] FIRST_C = first_rom(STEP_C);
    localparam [8*64-1:0] FIRST_B = first_rom(STEP_B);
    // Entry idx of a table: a loop of comparisons, not an indexed part
    // select (that is a 4,096-bit shifter per look-up in a proof's SAT
    // problem, and a part select at a variable offset of the 4,096-bit
    // constant crashed the Verilated model). One function per table that
    // reads its constant directly: with the table as a 4,096-bit function
    // argument, the Verilated pl_top (Verilator 5.006) corrupted the state
    // of other blocks (the fault trip, the MPDTC closed loop). In synthesis
    // each output bit is a function of the index's variable bits (the
    // loads: s(k-1)'s digit and the addend, six bits, one LUT6).
    function automatic [4:0] rom_c_at(input [8:0] idx);
        integer e;
        begin
            rom_c_at = 5'd0;
            for (e = 0; e < 512; e = e + 1)
                if (idx == e[8:0]) rom_c_at = STEP_C[8 * e +: 5];
        end
    endfunction
    function automatic [4:0] rom_b_at(input [8:0] idx);
        integer e;
        begin
            rom_b_at = 5'd0;
            for (e = 0; e < 512; e = e + 1)
                if (idx == e[8:0]) rom_b_at = STEP_B[8 * e +: 5];
        end
    endfunction
    function automatic [4:0] first_at(input [8*64-1:0] rom, input [5:0] idx);
        integer e;
        begin
            first_at = 5'd0;
            for (e = 0; e < 64; e = e + 1)
                if (idx == e[5:0]) first_at = rom[8 * e +: 5];
        end
    endfunction
    // a + cy for the 4-bit a as logic (a carry chain of its own otherwise)
    function automatic [3:0] a_plus(input [3:0] a, input cy);
        a_plus = a ^ {cy & a[2] & a[1] & a[0], cy & a[1] & a[0], cy & a[0], cy};
    endfunction
    // the set's j-th candidate (j <= 6) from s(k-1): its first plus j
    function automatic [9:0] first_plus(input [8:0] sp, input [2:0] j);
        reg [4:0] ec;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [4:0] eb;  // b carries at most 1: bit 4 is 0
        /* verilator lint_on UNUSEDSIGNAL */
        reg [3:0] a;
        begin
            ec = first_at(FIRST_C, {sp[8:6], j});
            eb = first_at(FIRST_B, {sp[5:3], 1'b0, ec[4:3]});
            a = a_plus({1'b0, lo_of(sp[2:0])}, eb[3]);
            first_plus = {a[3], ec[2:0], eb[2:0], a[2:0]};
        end
    endfunction
    // this decision's digit tables, entry x (a nibble or a bit pair, so an
    // index is a shift, not a sum): tc_q c' and tcy_q the carry of c = x
    // plus n_use; tb1_q / tb2_q {carry, b'} of b = x plus 1 / plus 2
    reg  [31:0] tc_q;
    reg  [15:0] tcy_q;
    reg  [31:0] tb1_q, tb2_q;
    wire [2:0]  nuse_set = (n_use_i == 3'd0) ? 3'd1 : (n_use_i > N[2:0]) ? N[2:0] : n_use_i;
    // the tables a start loads, from s(k-1) and the clamped n_use
    wire [39:0] tc_ld;
    /* verilator lint_off UNUSEDSIGNAL */
    wire [39:0] tb1_ld, tb2_ld;  // b carries at most 1: bit 4 of an entry is 0
    /* verilator lint_on UNUSEDSIGNAL */
    genvar gx;
    generate
        for (gx = 0; gx < 8; gx = gx + 1) begin : g_tab
            localparam [2:0] X = gx;
            assign tc_ld[5 * gx +: 5] = rom_c_at({s_prev_i[8:6], X, nuse_set});
            assign tb1_ld[5 * gx +: 5] = rom_b_at({s_prev_i[5:3], X, 3'd1});
            assign tb2_ld[5 * gx +: 5] = rom_b_at({s_prev_i[5:3], X, 3'd2});
        end
    endgenerate

    // this clock's candidates: counter j is valid until it has passed the
    // set's last candidate (its a = hi_a + 1), up to n_use of them
    wire [8:0]  cand [0:N-1];
    wire [N-1:0] cv;
    wire [N-1:0] is_last;
    wire [9:0]  nxt_next [0:N-1];
    genvar gi;
    generate
        for (gi = 0; gi < N; gi = gi + 1) begin : g_cand
            assign cand[gi] = ctr_q[gi][8:0];
            assign cv[gi] = gen_q && slot && (gi < {29'd0, nuse_q})
                            && ({ctr_q[gi][9], ctr_q[gi][2:0]} != aend_q);
            // the last candidate of the set is issued this clock
            assign is_last[gi] = ({ctr_q[gi][9], ctr_q[gi][8:0]} == {1'b0, hi_q});
            // the look-ahead plus n_use, from the decision's tables
            wire [4:0] ec = {tcy_q[{nxt_q[gi][8:6], 1'b0} +: 2], tc_q[{nxt_q[gi][8:6], 2'd0} +: 3]};
            wire [3:0] eb = (ec[4:3] == 2'd0) ? {1'b0, nxt_q[gi][5:3]}
                          : (ec[4:3] == 2'd1) ? tb1_q[{nxt_q[gi][5:3], 2'd0} +: 4]
                          : tb2_q[{nxt_q[gi][5:3], 2'd0} +: 4];
            wire [3:0] an = a_plus({nxt_q[gi][9], nxt_q[gi][2:0]}, eb[3]);
            assign nxt_next[gi] = {an[3], ec[2:0], eb[2:0], an[2:0]};
        end
    endgenerate
    wire last_now = |(cv & is_last);
    reg [7:0] nissue;
    integer i;
    always @(*) begin
        nissue = 8'd0;
        for (i = 0; i < N; i = i + 1) nissue = nissue + {7'd0, cv[i]};
    end
    integer ki;

    // ---------------------------------------------------- common terms
    wire [111:0] e0_w;
    wire [191:0] dn_w;
    wire [47:0]  dn1_w;
    wire [95:0]  pn_w, pph_w;
    mpdcc_common #(.MULS(MULS), .EXPECT_ISSUE_DELAY(COMMON_LATENCY)) u_common (
        .clk_i(clk_i), .rst_i(rst_i), .start_i(start_i && !busy_q),
        .i_a_i(i_a_i), .i_b_i(i_b_i), .psi_a_i(psi_a_i), .psi_b_i(psi_b_i),
        .v_n_i(v_n_i), .v_ph_i(v_ph_i), .ir_a_i(ir_a_i), .ir_b_i(ir_b_i),
        .omega_r_i(omega_r_i), .omega_s_i(omega_s_i),
        .c_tau_i(c_tau_i), .c_r_i(c_r_i), .c_w_i(c_w_i), .c_p_i(c_p_i), .c_s_i(c_s_i),
        .c_3_i(c_3_i), .c_d_i(c_d_i), .c_n_i(c_n_i), .c_ph_i(c_ph_i), .s3h_i(s3h_i),
        .v_ph_ref_i(v_ph_ref_i), .c_tau1_i(c_tau1_i), .c_r1_i(c_r1_i), .c_w1_i(c_w1_i),
        .c_s1_i(c_s1_i),
        .e0_o(e0_w), .dn_o(dn_w), .dn1_o(dn1_w), .pn_o(pn_w), .pph_o(pph_w));

    // ------------------------------------------------------ explorers
    wire [N-1:0] rv;
    wire [8:0]  rs [0:N-1];
    wire [7:0]  rl [0:N-1];
    wire [31:0] rc [0:N-1];
    wire signed [31:0] rj [0:N-1];
    generate
        for (gi = 0; gi < N; gi = gi + 1) begin : g_exp
            /* verilator lint_off PINCONNECTEMPTY */
            mpdcc_explorer #(.II(II)) u_exp (
                .clk_i(clk_i), .rst_i(rst_i),
                .in_valid_i(cv[gi]), .s_i(cand[gi]),
                .s_prev_i(s_prev_i), .e0_i(e0_w), .dn_i(dn_w), .dn1_i(dn1_w),
                .pn_i(pn_w), .pph_i(pph_w), .v_n_i(v_n_i), .v_ph_i(v_ph_i),
                .vdc_half_i(vdc_half_i), .g3_i(g3_i), .gd_i(gd_i), .g3_1_i(g3_1_i),
                .bnd_i(bnd_i), .lambda_n_i(lambda_n_i),
                .out_valid_o(rv[gi]), .s_o(rs[gi]), .l_star_o(rl[gi]), .cost_o(rc[gi]),
                .j_dl_o(rj[gi]), .fs_o(), .d0_o());
            /* verilator lint_on PINCONNECTEMPTY */
        end
    endgenerate

    // ----------------------------------------------------------- arg-min
    // The results of one clock (at most N <= 8, candidate i of a clock
    // before i + 1 in enumeration order) are reduced by a registered binary
    // tree, ARGMIN_LEVELS levels of one comparison each, then folded into
    // the decision's running minimum; every comparison is strict "<" with
    // the earlier operand on the left, so the first of equal ones wins, as
    // a sequential scan and the model's select() do. A record:
    //   {n[3:0], lz, hd, ds, dc, dj, hb, bs, bl, bc, bj}
    //   hb/bs/bl/bc/bj  best optimal (L* > 0, min J); hd/ds/dc/dj  least
    //   J_dl (deadlock); lz  s(k-1) among them with J_dl <= 0; n  results.
    localparam integer RW = 4 + 1 + 1 + 9 + 32 + 32 + 1 + 9 + 8 + 32 + 32;
    localparam integer LEAVES = 1 << ARGMIN_LEVELS;
    // field offsets of a record (LSB first)
    localparam integer F_BJ = 0, F_BC = 32, F_BL = 64, F_BS = 72, F_HB = 81;
    localparam integer F_DJ = 82, F_DC = 114, F_DS = 146, F_HD = 155, F_LZ = 156, F_N = 157;
    function automatic [RW-1:0] comb(input [RW-1:0] l, input [RW-1:0] r);
        reg rb, rd;
        begin
            rb = r[F_HB] && (!l[F_HB] || r[F_BC +: 32] < l[F_BC +: 32]);
            rd = r[F_HD] && (!l[F_HD] || $signed(r[F_DJ +: 32]) < $signed(l[F_DJ +: 32]));
            comb[F_N +: 4] = l[F_N +: 4] + r[F_N +: 4];
            comb[F_LZ] = l[F_LZ] | r[F_LZ];
            comb[F_DJ +: 74] = rd ? r[F_DJ +: 74] : l[F_DJ +: 74];
            comb[F_BJ +: 82] = rb ? r[F_BJ +: 82] : l[F_BJ +: 82];
        end
    endfunction
    wire [RW*LEAVES-1:0] leaf;
    generate
        for (gi = 0; gi < LEAVES; gi = gi + 1) begin : g_leaf
            if (gi < N) begin : g_res
                assign leaf[RW*gi +: RW] = {
                    {3'd0, rv[gi]},
                    rv[gi] && rs[gi] == s_prev_i && rj[gi] <= 0,
                    rv[gi], rs[gi], rc[gi], rj[gi],
                    rv[gi] && rl[gi] != 8'd0, rs[gi], rl[gi], rc[gi], rj[gi]};
            end else begin : g_none
                assign leaf[RW*gi +: RW] = {RW{1'b0}};
            end
        end
    endgenerate
    // level v holds LEAVES >> v records
    wire [RW*LEAVES-1:0] lvl [0:ARGMIN_LEVELS];
    assign lvl[0] = leaf;
    generate
        genvar lv;
        for (lv = 0; lv < ARGMIN_LEVELS; lv = lv + 1) begin : g_lvl
            localparam integer K = LEAVES >> (lv + 1);
            reg [RW*K-1:0] r_q;
            integer x;
            always @(posedge clk_i) begin
                if (rst_i) r_q <= {(RW * K) {1'b0}};
                else begin
                    for (x = 0; x < K; x = x + 1)
                        r_q[RW*x +: RW] <= comb(lvl[lv][RW*(2*x) +: RW], lvl[lv][RW*(2*x+1) +: RW]);
                end
            end
            assign lvl[lv+1] = {{(RW * (LEAVES - K)) {1'b0}}, r_q};
        end
    endgenerate
    wire [RW-1:0] tree = lvl[ARGMIN_LEVELS][RW-1:0];

    reg        hb_q, hd_q, lazy_q;
    reg [8:0]  bs_q, ds_q;
    reg [7:0]  bl_q;
    reg [31:0] bc_q, dc_q;
    reg signed [31:0] bj_q, dj_q;
    wire [RW-1:0] acc = {4'd0, lazy_q, hd_q, ds_q, dc_q, dj_q, hb_q, bs_q, bl_q, bc_q, bj_q};
    wire [RW-1:0] fold = comb(acc, tree);
    wire        hb = fold[F_HB], hd = fold[F_HD], lz = fold[F_LZ];
    wire [8:0]  bs = fold[F_BS +: 9], ds = fold[F_DS +: 9];
    wire [7:0]  bl = fold[F_BL +: 8];
    wire [31:0] bc = fold[F_BC +: 32], dc = fold[F_DC +: 32];
    wire signed [31:0] bj = fold[F_BJ +: 32], dj = fold[F_DJ +: 32];
    wire [7:0]  nrecv = {4'd0, tree[F_N +: 4]};
    wire all_in = !gen_q && busy_q && (pre_q == 6'd0) && (received_q + nrecv == issued_q)
                  && (nrecv != 8'd0);
    always @(posedge clk_i) begin
        if (rst_i) begin
            hi_q <= 9'd0; aend_q <= 4'd0;
            tc_q <= 32'd0; tcy_q <= 16'd0; tb1_q <= 32'd0; tb2_q <= 32'd0;
            for (ki = 0; ki < N; ki = ki + 1) begin
                ctr_q[ki] <= 10'd0;
                nxt_q[ki] <= 10'd0;
            end
            gen_q <= 1'b0; busy_q <= 1'b0; nuse_q <= 3'd1; pre_q <= 6'd0;
            cyc_q <= 16'd0; issued_q <= 8'd0; received_q <= 8'd0; ph_q <= 3'd0;
            hb_q <= 1'b0; hd_q <= 1'b0; lazy_q <= 1'b0;
            bs_q <= 9'd0; ds_q <= 9'd0; bl_q <= 8'd0; bc_q <= 32'd0; dc_q <= 32'd0;
            bj_q <= 32'sd0; dj_q <= 32'sd0;
            done_o <= 1'b0; s_o <= 9'd0; kind_o <= 2'd0; l_star_o <= 8'd0;
            cost_o <= 32'd0; j_dl_o <= 32'sd0; candidates_o <= 8'd0; cycles_o <= 16'd0;
        end else begin
            done_o <= 1'b0;
            if (start_i && !busy_q) begin
                hi_q <= {hi_of(s_prev_i[8:6]), hi_of(s_prev_i[5:3]), hi_of(s_prev_i[2:0])};
                aend_q <= {1'b0, hi_of(s_prev_i[2:0])} + 4'd1;
                for (ki = 0; ki < N; ki = ki + 1)
                    nxt_q[ki] <= first_plus(s_prev_i, ki[2:0]);
                for (ki = 0; ki < 8; ki = ki + 1) begin
                    tc_q[4 * ki +: 4] <= {1'b0, tc_ld[5 * ki +: 3]};
                    tcy_q[2 * ki +: 2] <= tc_ld[5 * ki + 3 +: 2];
                    tb1_q[4 * ki +: 4] <= tb1_ld[5 * ki +: 4];
                    tb2_q[4 * ki +: 4] <= tb2_ld[5 * ki +: 4];
                end
                nuse_q <= nuse_set;
                gen_q <= 1'b0;
                pre_q <= COMMON_LATENCY[5:0];
                busy_q <= 1'b1;
                cyc_q <= 16'd1;
                issued_q <= 8'd0;
                received_q <= 8'd0;
                ph_q <= 3'd0;
                hb_q <= 1'b0; hd_q <= 1'b0; lazy_q <= 1'b0;
            end else if (busy_q) begin
                cyc_q <= cyc_q + 16'd1;
                if (pre_q != 6'd0) begin
                    pre_q <= pre_q - 6'd1;
                    if (pre_q == 6'd1) gen_q <= 1'b1;
                end
                // the counters step: once on the clock before the issue (the
                // look-ahead's first step), then on every issue clock
                if (pre_q == 6'd1 || (gen_q && slot))
                    for (ki = 0; ki < N; ki = ki + 1) begin
                        ctr_q[ki] <= nxt_q[ki];
                        nxt_q[ki] <= nxt_next[ki];
                    end
                if (gen_q) begin
                    ph_q <= (ph_q == II[2:0] - 3'd1) ? 3'd0 : ph_q + 3'd1;
                    issued_q <= issued_q + nissue;
                    if (last_now) gen_q <= 1'b0;
                end
                received_q <= received_q + nrecv;
                hb_q <= hb; hd_q <= hd; lazy_q <= lz;
                bs_q <= bs; ds_q <= ds; bl_q <= bl; bc_q <= bc; dc_q <= dc;
                bj_q <= bj; dj_q <= dj;
                if (all_in) begin
                    busy_q <= 1'b0;
                    done_o <= 1'b1;
                    cycles_o <= cyc_q + 16'd1;
                    if (lz) begin
                        s_o <= s_prev_i; kind_o <= 2'd0; l_star_o <= 8'd0;
                        cost_o <= 32'd0; j_dl_o <= 32'sd0; candidates_o <= 8'd0;
                    end else if (hb) begin
                        s_o <= bs; kind_o <= 2'd1; l_star_o <= bl;
                        cost_o <= bc; j_dl_o <= bj; candidates_o <= issued_q;
                    end else begin
                        s_o <= ds; kind_o <= 2'd2; l_star_o <= 8'd0;
                        cost_o <= dc; j_dl_o <= dj; candidates_o <= issued_q;
                    end
                end
            end
        end
    end

`ifdef FORMAL
    // Hand-shake properties of the scheduler (scripts/rtl-formal, N = 2),
    // proved for ANY explorer arithmetic: the explorers are cut at their
    // outputs (scripts/rtl-formal, free outputs) constrained only by the
    // explorer's hand-shake contract, assumed here and proved on the real
    // explorer by its own FORMAL block: out_valid_o is in_valid_i exactly
    // F_LAT clocks later, cleared by a reset. Power-up is the all-zero state
    // (no reset assumed); a reset may come at any clock.
    // The monitor below is written for II = 1 (an issue every clock), the
    // configuration the proof runs (the default parameters).
    localparam integer F_LAT = 41;  // mpdcc_explorer's LAT at II = 1 (asserted there)
    localparam integer F_CL = COMMON_LATENCY;
    localparam integer F_AM = ARGMIN_LEVELS;  // a result leaves the tree this much later
    localparam [2:0] F_NU = N[2:0];

    integer f_k;

    // ------------------------------------------------ explorer contract
    // f_fly stage j (1..F_LAT) at [N (j - 1) +: N]: the valid bits issued
    // j clocks ago, i.e. the candidates in flight.
    reg [N*F_LAT-1:0] f_fly = {N * F_LAT{1'b0}};
    always @(posedge clk_i) begin
        if (rst_i) f_fly <= {N * F_LAT{1'b0}};
        else f_fly <= {f_fly[N*(F_LAT-1)-1:0], cv};
    end
    always @(*) assume (rv == f_fly[N*(F_LAT-1) +: N]);
    // The results' valid bits through the arg-min tree: stage j (1..F_AM)
    // at [N (j - 1) +: N]; the scheduler counts them as they leave it.
    reg [N*F_AM-1:0] f_rvd = {N * F_AM{1'b0}};
    always @(posedge clk_i) begin
        if (rst_i) f_rvd <= {N * F_AM{1'b0}};
        else f_rvd <= {f_rvd[N*(F_AM-1)-1:0], rv};
    end

    // ------------------------------------ S(s(k-1)), written independently
    // Level of a position (models::mpdcc::anpc::TABLE): -2, -1, -1, 0, 0, 1,
    // 1, 2; a candidate is admissible in a phase when its level is within
    // one of s(k-1)'s (models::mpdcc::anpc::admissible_phase).
    function automatic signed [3:0] f_level(input [2:0] x);
        case (x)
            3'd0: f_level = -4'sd2;
            3'd1, 3'd2: f_level = -4'sd1;
            3'd3, 3'd4: f_level = 4'sd0;
            3'd5, 3'd6: f_level = 4'sd1;
            default: f_level = 4'sd2;
        endcase
    endfunction
    function automatic f_adm(input [2:0] x, input [2:0] f);
        reg signed [3:0] d;
        begin
            d = f_level(x) - f_level(f);
            f_adm = (d >= -4'sd1) && (d <= 4'sd1);
        end
    endfunction
    function automatic f_in_set(input [8:0] x, input [8:0] f);
        f_in_set = f_adm(x[2:0], f[2:0]) && f_adm(x[5:3], f[5:3]) && f_adm(x[8:6], f[8:6]);
    endfunction
    // smallest / largest admissible position and how many there are
    function automatic [2:0] f_min(input [2:0] f);
        integer x;
        begin
            f_min = 3'd0;
            for (x = 7; x >= 0; x = x - 1) if (f_adm(x[2:0], f)) f_min = x[2:0];
        end
    endfunction
    function automatic [2:0] f_max(input [2:0] f);
        integer x;
        begin
            f_max = 3'd0;
            for (x = 0; x < 8; x = x + 1) if (f_adm(x[2:0], f)) f_max = x[2:0];
        end
    endfunction
    function automatic [2:0] f_cnt(input [2:0] f);  // 3, 5 or 6
        integer x;
        begin
            f_cnt = 3'd0;
            for (x = 0; x < 8; x = x + 1) if (f_adm(x[2:0], f)) f_cnt = f_cnt + 3'd1;
        end
    endfunction
    // x m for a small factor m (shifts and adds: keeps the proof linear)
    function automatic [8:0] f_times(input [8:0] x, input [2:0] m);
        case (m)
            3'd0: f_times = 9'd0;
            3'd1: f_times = x;
            3'd2: f_times = x << 1;
            3'd3: f_times = x + (x << 1);
            3'd4: f_times = x << 2;
            3'd5: f_times = x + (x << 2);
            3'd6: f_times = (x << 1) + (x << 2);
            default: f_times = (x << 3) - x;
        endcase
    endfunction
    // Position of a candidate in the enumeration (a outer, c inner): a
    // bijection from S onto 0 .. |S| - 1.
    function automatic [8:0] f_rank(input [8:0] x, input [8:0] f);
        f_rank = f_times(f_times({6'd0, x[2:0] - f_min(f[2:0])}, f_cnt(f[5:3]))
                         + {6'd0, x[5:3] - f_min(f[5:3])}, f_cnt(f[8:6]))
                 + {6'd0, x[8:6] - f_min(f[8:6])};
    endfunction
    // The same position for a counter {a[3], c, b, a[2:0]} whose a may be
    // past its range (a counter past the set's end: rank >= |S|), and
    // whether its digits are ones the enumeration can reach (b and c in
    // their ranges, a not below its lo).
    function automatic [8:0] f_rank10(input [9:0] x, input [8:0] f);
        f_rank10 = f_times(f_times({5'd0, {x[9], x[2:0]} - {1'b0, f_min(f[2:0])}}, f_cnt(f[5:3]))
                           + {6'd0, x[5:3] - f_min(f[5:3])}, f_cnt(f[8:6]))
                   + {6'd0, x[8:6] - f_min(f[8:6])};
    endfunction
    function automatic f_reach(input [9:0] x, input [8:0] f);
        f_reach = f_adm(x[8:6], f[8:6]) && f_adm(x[5:3], f[5:3])
                  && {x[9], x[2:0]} >= {1'b0, f_min(f[2:0])} && {x[9], x[2:0]} <= 4'd8;
    endfunction
    function automatic [N-1:0] f_ones(input [8:0] n);  // n low bits set
        integer q;
        begin
            for (q = 0; q < N; q = q + 1) f_ones[q] = (q < n);
        end
    endfunction
    function automatic [8:0] f_popc(input [N-1:0] v);
        integer q;
        begin
            f_popc = 9'd0;
            for (q = 0; q < N; q = q + 1) f_popc = f_popc + {8'd0, v[q]};
        end
    endfunction

    // ----------------------------------------------- the decision monitor
    // Latched on an accepted start (a start while busy is ignored, as the
    // design documents): s(k-1), the clamped n_use, |S|. The candidates
    // are issued from clock F_CL + 1 = 21 (the explorers read the common
    // terms as they become final), n_use per clock while at least that many
    // are left, the rest at the last issue clock f_lastclk; their results
    // are back F_LAT clocks later and leave the arg-min tree F_AM = 3 clocks
    // after that, and done_o follows one clock after the last:
    // G = f_lastclk - F_CL issue clocks, so done_o comes at clock
    // T = F_CL + G + F_LAT + F_AM + 1 (models::mpdcc::cycles::pipelined_core_cycles).
    wire f_start = start_i && !busy_q && !rst_i;
    reg        f_busy = 1'b0, f_done = 1'b0;
    reg [8:0]  f_sp = 9'd0;
    reg [2:0]  f_nu = 3'd0;
    reg [8:0]  f_cyc = 9'd0;      // clocks since the accepted start (<= 274)
    reg [8:0]  f_iss = 9'd0;      // candidates issued in this decision
    reg [8:0]  f_rcv = 9'd0;      // results back in this decision
    reg [8:0]  f_lastclk = 9'd0;  // clock of the last issue (0: not yet)
    reg [N-1:0] f_restv = {N{1'b0}};  // valid bits of that clock
    wire [8:0] f_size = f_times(f_times({6'd0, f_cnt(f_sp[2:0])}, f_cnt(f_sp[5:3])), f_cnt(f_sp[8:6]));
    wire [8:0] f_first = F_CL[8:0] + 9'd1;
    wire [8:0] f_left = f_size - f_iss;
    wire       f_gen = f_busy && f_cyc >= f_first && f_lastclk == 9'd0;
    // what the scheduler must issue this clock
    wire [N-1:0] f_cv = !f_gen ? {N{1'b0}} : f_ones((f_left < {6'd0, f_nu}) ? f_left : {6'd0, f_nu});
    always @(posedge clk_i) begin
        f_done <= 1'b0;
        f_iss <= f_iss + f_popc(cv);
        f_rcv <= f_rcv + f_popc(f_rvd[N*(F_AM-1) +: N]);
        if (rst_i) begin
            f_busy <= 1'b0;
            f_cyc <= 9'd0;
            f_iss <= 9'd0;
            f_rcv <= 9'd0;
            f_lastclk <= 9'd0;
        end else if (f_start) begin
            f_busy <= 1'b1;
            f_sp <= s_prev_i;
            f_nu <= (n_use_i < 3'd1) ? 3'd1 : (n_use_i > F_NU) ? F_NU : n_use_i;
            f_cyc <= 9'd1;
            f_iss <= 9'd0;
            f_rcv <= 9'd0;
            f_lastclk <= 9'd0;
        end else if (f_busy) begin
            f_cyc <= f_cyc + 9'd1;
            if (f_gen && f_left <= {6'd0, f_nu}) begin
                f_lastclk <= f_cyc;
                f_restv <= f_cv;
            end
            if (f_lastclk != 9'd0 && f_cyc == f_lastclk + F_LAT[8:0] + F_AM[8:0]) begin
                f_busy <= 1'b0;
                f_done <= 1'b1;
            end
        end
    end
    // valid bits issued at clock e (e < f_cyc) of this decision
    function automatic [N-1:0] f_issued_at(input [8:0] e, input [8:0] first, input [8:0] lastclk,
                                           input [N-1:0] full, input [N-1:0] rest);
        f_issued_at = (e < first || (lastclk != 9'd0 && e > lastclk)) ? {N{1'b0}}
                    : (e == lastclk) ? rest : full;
    endfunction
    wire [N-1:0] f_full = f_ones({6'd0, f_nu});
    // results back before clock f_cyc: those issued before f_cyc - F_LAT
    wire [8:0] f_back_by = f_cyc - F_LAT[8:0] - F_AM[8:0];
    wire [8:0] f_back = (f_cyc <= F_LAT[8:0] + F_AM[8:0] || f_back_by <= f_first) ? 9'd0
                      : (f_lastclk != 9'd0 && f_back_by > f_lastclk) ? f_size
                      : f_times(f_back_by - f_first, f_nu);

    wire [8:0] f_hi = {f_max(f_sp[8:6]), f_max(f_sp[5:3]), f_max(f_sp[2:0])};
    wire [8:0] f_g = f_cyc - F_CL[8:0] - F_LAT[8:0] - F_AM[8:0] - 9'd1;  // issue clocks, at done

    always @(*) begin
        // -- busy_o from the accepted start to done_o; done_o once per
        //    start, at clock T, with cycles_o = T and G = ceil(|S| / n_use)
        //    (G n_use >= |S| > (G - 1) n_use)
        assert (busy_q == f_busy);
        assert (done_o == f_done);
        if (done_o) begin
            assert (cycles_o == {7'd0, f_cyc});
            assert (f_times(f_g, f_nu) >= f_size && f_times(f_g - 9'd1, f_nu) < f_size);
        end
        // -- n_use clamped to 1..N and held for the decision
        if (f_busy) assert (nuse_q == f_nu && nuse_q >= 3'd1 && nuse_q <= F_NU);
        // -- enumeration: the i-th candidate issued in a decision is the
        //    i-th of S (so each candidate of S exactly once, in order),
        //    n_use per clock but the last, explorer 0 first
        assert (cv == f_cv);
        for (f_k = 0; f_k < N; f_k = f_k + 1)
            if (cv[f_k]) assert (f_in_set(cand[f_k], f_sp) && f_rank(cand[f_k], f_sp) == f_iss + f_k[8:0]);
        assert (issued_q == f_iss[7:0] && f_iss <= f_size);
        // -- results: only while busy, each counted once, none lost: what
        //    was issued is back or in flight, nothing in flight when idle
        if (rv != {N{1'b0}}) assert (busy_q);
        assert (received_q == f_rcv[7:0]);
        assert (f_rcv == (f_busy ? f_back : f_iss));
        if (!f_busy) assert (f_fly == {N * F_LAT{1'b0}} && f_rvd == {N * F_AM{1'b0}} && !gen_q && pre_q == 6'd0);
        // -- at done: every candidate issued and back; candidates_o = |S|
        //    (0 for a kept decision, as documented)
        if (done_o) begin
            assert (f_iss == f_size && f_rcv == f_size);
            assert (candidates_o == (kind_o == 2'd0 ? 8'd0 : f_size[7:0]));
            assert (kind_o != 2'd3);
        end
        // -- scheduler state against the monitor (makes the proof inductive)
        if (f_busy) begin
            assert (cyc_q == {7'd0, f_cyc} && f_cyc >= 9'd1);
            assert (pre_q == ((f_cyc < f_first) ? f_first[5:0] - f_cyc[5:0] : 6'd0));
            assert (gen_q == f_gen);
            assert (hi_q == f_hi && aend_q == {1'b0, f_hi[2:0]} + 4'd1);
            // counter k (k < n_use) holds the (issued + k)-th candidate
            // while issuing; its look-ahead the k-th before the issue, then
            // n_use further than the counter but on the last issue clock
            // (whose step is never used)
            for (f_k = 0; f_k < N; f_k = f_k + 1)
                if (f_k < {29'd0, f_nu}) begin
                    if (f_gen)
                        assert (f_reach(ctr_q[f_k], f_sp) && f_rank10(ctr_q[f_k], f_sp) == f_iss + f_k[8:0]);
                    if (f_cyc < f_first)
                        assert (f_reach(nxt_q[f_k], f_sp) && f_rank10(nxt_q[f_k], f_sp) == f_k[8:0]);
                    if (f_gen && f_left > {6'd0, f_nu})
                        assert (f_reach(nxt_q[f_k], f_sp)
                                && f_rank10(nxt_q[f_k], f_sp) == f_iss + f_k[8:0] + {6'd0, f_nu});
                end
            if (f_cyc < f_first) assert (f_iss == 9'd0);
            if (f_gen) assert (f_iss == f_times(f_cyc - f_first, f_nu) && f_iss < f_size);
            if (f_lastclk != 9'd0) begin
                assert (f_lastclk >= f_first && f_cyc > f_lastclk && f_cyc <= f_lastclk + F_LAT[8:0] + F_AM[8:0]);
                assert (f_iss == f_size && f_restv != {N{1'b0}}
                        && f_restv == f_ones(f_size - f_times(f_lastclk - f_first, f_nu)));
                assert (f_times(f_lastclk - F_CL[8:0], f_nu) >= f_size
                        && f_times(f_lastclk - f_first, f_nu) < f_size);
            end
        end
    end
    // A step through the elaboration tables (digit_rom), for any k <= 6.
    function automatic [9:0] f_step(input [9:0] x, input [2:0] fc, input [2:0] fb, input [2:0] k);
        reg [4:0] ec;
        /* verilator lint_off UNUSEDSIGNAL */
        reg [4:0] eb;  // b carries at most 1: bit 4 is 0
        /* verilator lint_on UNUSEDSIGNAL */
        reg [3:0] a;
        begin
            ec = rom_c_at({fc, x[8:6], k});
            eb = rom_b_at({fb, x[5:3], 1'b0, ec[4:3]});
            a = a_plus({x[9], x[2:0]}, eb[3]);
            f_step = {a[3], ec[2:0], eb[2:0], a[2:0]};
        end
    endfunction
    // The decision's tables: entry x of a digit's range is x plus the
    // addend in that range, with the carry times the range's size.
    function automatic f_digit_ok(input [2:0] x, input [2:0] xn, input [1:0] cy, input [2:0] f,
                                  input [2:0] d);
        f_digit_ok = f_adm(xn, f) && f_times({7'd0, cy}, f_cnt(f)) + {6'd0, xn - f_min(f)}
                                     == {6'd0, x - f_min(f)} + {6'd0, d};
    endfunction
    integer f_e;
    always @(*) begin
        if (f_busy)
            for (f_e = 0; f_e < 8; f_e = f_e + 1) begin
                if (f_adm(f_e[2:0], f_sp[8:6]))
                    assert (f_digit_ok(f_e[2:0], tc_q[4 * f_e +: 3], tcy_q[2 * f_e +: 2], f_sp[8:6], f_nu));
                if (f_adm(f_e[2:0], f_sp[5:3])) begin
                    assert (f_digit_ok(f_e[2:0], tb1_q[4 * f_e +: 3], {1'b0, tb1_q[4 * f_e + 3]}, f_sp[5:3], 3'd1));
                    assert (f_digit_ok(f_e[2:0], tb2_q[4 * f_e +: 3], {1'b0, tb2_q[4 * f_e + 3]}, f_sp[5:3], 3'd2));
                end
            end
    end
    // The step for every k up to 6 (the proof's N = 2 steps by 1 or 2
    // only): from any reachable counter of any set, the k-th successor is
    // reachable and k positions further. f_x, f_xk are undriven: free
    // values at every step of the proof.
    /* verilator lint_off UNDRIVEN */
    wire [9:0] f_x;
    wire [2:0] f_xk;
    /* verilator lint_on UNDRIVEN */
    wire [9:0] f_xs = f_step(f_x, f_sp[8:6], f_sp[5:3], f_xk);
    always @(*) begin
        if (f_reach(f_x, f_sp) && f_rank10(f_x, f_sp) < f_size && f_xk <= 3'd6)
            assert (f_reach(f_xs, f_sp) && f_rank10(f_xs, f_sp) == f_rank10(f_x, f_sp) + {6'd0, f_xk});
    end
    // In flight, stage by stage: stage j holds what clock f_cyc - j issued.
    generate
        for (gi = 1; gi <= F_LAT; gi = gi + 1) begin : g_fly
            localparam [8:0] F_J = gi;
            always @(*) begin
                if (f_busy)
                    assert (f_fly[N*(gi-1) +: N] == ((f_cyc <= F_J) ? {N{1'b0}}
                            : f_issued_at(f_cyc - F_J, f_first, f_lastclk, f_full, f_restv)));
            end
        end
    endgenerate
    // Through the arg-min tree, stage by stage: f_rvd stage j holds the
    // results of clock f_cyc - F_LAT - j, and the record counts of tree
    // level j - 1 are their popcounts (records past the N leaves hold
    // nothing). Implied by the assertions above from reset on; stated so
    // that the induction needs one step instead of four (the tree and f_rvd
    // are otherwise free in the induction's first states).
    function automatic [3:0] f_cnt_of(input [N-1:0] v, input integer lo, input integer w);
        integer q;
        begin
            f_cnt_of = 4'd0;
            for (q = 0; q < N; q = q + 1) if (q >= lo && q < lo + w) f_cnt_of = f_cnt_of + {3'd0, v[q]};
        end
    endfunction
    generate
        for (gi = 1; gi <= F_AM; gi = gi + 1) begin : g_rvd
            localparam integer F_JI = F_LAT + gi;
            localparam [8:0] F_J = F_JI[8:0];
            localparam integer K = LEAVES >> gi;
            integer x;
            always @(*) begin
                if (f_busy)
                    assert (f_rvd[N*(gi-1) +: N] == ((f_cyc <= F_J) ? {N{1'b0}}
                            : f_issued_at(f_cyc - F_J, f_first, f_lastclk, f_full, f_restv)));
                for (x = 0; x < K; x = x + 1) begin
                    if (x << gi < N) begin
                        assert (g_lvl[gi-1].r_q[RW*x+F_N +: 4] == f_cnt_of(f_rvd[N*(gi-1) +: N], x << gi, 1 << gi));
                    end else begin
                        assert (g_lvl[gi-1].r_q[RW*x +: RW] == {RW{1'b0}});
                    end
                end
            end
        end
    endgenerate

    // -- reset: the clock after a reset is idle, without done_o, with the
    //    counters cleared (a decision in flight is dropped: no done_o for
    //    it, its results are cleared in the explorers by the same reset).
    //    A start while busy is ignored: the monitor takes no start while
    //    busy, and hi_q, nuse_q, cyc_q and the counters are asserted
    //    equal to it above.
    reg f_rst_q = 1'b0;
    always @(posedge clk_i) f_rst_q <= rst_i;
    always @(*) begin
        if (f_rst_q)
            assert (!busy_o && !done_o && issued_q == 8'd0 && received_q == 8'd0
                    && cycles_o == 16'd0 && candidates_o == 8'd0);
    end
`endif
endmodule

`default_nettype wire
