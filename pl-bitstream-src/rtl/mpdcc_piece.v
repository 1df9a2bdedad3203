// mpdcc_piece: one interpolation piece of an MPDCC search lane
// (models::mpdcc::binsearch::lj_search on one piece of models::mpdcc::mpdcc_fixed's
// lane), pipelined: one piece per clock, fixed latency LATENCY = QMAX + 3.
//
// The error along the piece is a + l d / 2^LS for l = 0..CAP (a, d raw
// Q4.13 words, 19 bits; bnd Q2.13, >= 0). Eq. (24) in integer form
// (Algorithm 2 of paper 001 with the division by L folded into the bound):
//   below  = |a| > bnd                         (l_j = 0 on this piece)
//   x      = |d|, y = (bnd -+ |a|) << LS       (- when a d > 0)
//   capped = x == 0 || CAP x <= y              (inside at the piece's end)
//   q      = floor(y / x)                      (when neither, q < CAP)
// q is found by restoring division, one quotient bit per stage: the stage
// subtracts x 2^m from the running remainder and keeps the difference when
// it does not borrow, which is Algorithm 2's "b + c <= y" on the remainder
// y - b (the same predicate, one adder). QBITS = ceil(log2 CAP) bits; the
// stages after QBITS only delay, so every piece has the same latency.
//
// Stages (n = register loaded at the n-th edge after in_valid_i):
//   1  |a|, |d| (negations), towards = sign(a) == sign(d), a != 0, d != 0
//   2  bnd - |a| and bnd + |a| in parallel, below; CAP x (one adder when
//      CAP is not a power of two)
//   3  y = margin << LS, capped = x == 0 || CAP x <= y
//   4 .. QMAX + 3  quotient bits QBITS-1 .. 0, then delay
// Widths: |a| <= 2^18 (a is 19 bits); when not below, |a| <= bnd < 2^15, so
// margin < 2^16 and y < 2^(16 + LS); x < 2^19, x 2^QBITS < 2^(19 + QBITS):
// W = 28 bits holds both for LS <= 7, QBITS <= 8.
`default_nettype none

module mpdcc_piece #(
    parameter integer LS    = 3,  // log2 of the piece length
    parameter integer CAP   = 8,  // steps searched on this piece (1..2^QBITS)
    parameter integer QBITS = 3,  // quotient bits, 2^QBITS >= CAP
    parameter integer QMAX  = 7   // stages of the longest piece of the lane
) (
    input  wire               clk_i,
    input  wire               rst_i,
    input  wire               in_valid_i,
    input  wire signed [18:0] a_i,
    input  wire signed [18:0] d_i,
    input  wire        [14:0] bnd_i,
    output wire               out_valid_o,
    output wire               below_o,   // |a| > bnd: l_j = 0 on this piece
    output wire               capped_o,  // inside up to CAP (and not below)
    output wire        [7:0]  q_o        // floor(y / x) when neither
);
    localparam integer W = 28;

    // stage 1
    reg              v1_q;
    reg [18:0]       abs_a1_q;
    reg [18:0]       abs_d1_q;
    reg              tow1_q;
    reg [14:0]       bnd1_q;
    wire [18:0] neg_a = -a_i;
    wire [18:0] neg_d = -d_i;
    always @(posedge clk_i) begin
        if (rst_i) begin
            v1_q     <= 1'b0;
            abs_a1_q <= 19'd0;
            abs_d1_q <= 19'd0;
            tow1_q   <= 1'b0;
            bnd1_q   <= 15'd0;
        end else begin
            v1_q     <= in_valid_i;
            abs_a1_q <= a_i[18] ? neg_a : a_i;
            abs_d1_q <= d_i[18] ? neg_d : d_i;
            // a d > 0: both nonzero with equal signs.
            tow1_q   <= (a_i != 19'sd0) && (d_i != 19'sd0) && (a_i[18] == d_i[18]);
            bnd1_q   <= bnd_i;
        end
    end

    // stage 2
    reg              v2_q;
    reg              below2_q;
    reg [W-1:0]      margin2_q;
    reg [W-1:0]      x2_q;
    reg [W-1:0]      capx2_q;
    wire [W-1:0] abs_a1_w = {{(W - 19) {1'b0}}, abs_a1_q};
    wire [W-1:0] bnd1_w   = {{(W - 15) {1'b0}}, bnd1_q};
    wire [W-1:0] diff1    = bnd1_w - abs_a1_w;
    wire [W-1:0] sum1     = bnd1_w + abs_a1_w;
    wire [W-1:0] x1_w     = {{(W - 19) {1'b0}}, abs_d1_q};
    // CAP x by shift and add over CAP's set bits, no multiplier: a shift
    // for a power of two, one adder for the lanes' last pieces (CAP = 2^p +
    // 2^r, e.g. 96 = 64 + 32).
    function automatic [W-1:0] cap_times(input [W-1:0] x);
        integer b;
        begin
            cap_times = {W{1'b0}};
            for (b = 0; b < 8; b = b + 1)
                if (CAP[b]) cap_times = cap_times + (x << b);
        end
    endfunction
    wire [W-1:0] capx1    = cap_times(x1_w);
    always @(posedge clk_i) begin
        if (rst_i) begin
            v2_q      <= 1'b0;
            below2_q  <= 1'b0;
            margin2_q <= {W{1'b0}};
            x2_q      <= {W{1'b0}};
            capx2_q   <= {W{1'b0}};
        end else begin
            v2_q      <= v1_q;
            below2_q  <= diff1[W-1];
            margin2_q <= tow1_q ? diff1 : sum1;
            x2_q      <= x1_w;
            capx2_q   <= capx1;
        end
    end

    // stage 3
    reg              v3_q;
    reg              below3_q;
    reg              capped3_q;
    reg [W-1:0]      rem3_q;
    reg [W-1:0]      x3_q;
    wire [W-1:0] y2 = margin2_q << LS;
    always @(posedge clk_i) begin
        if (rst_i) begin
            v3_q      <= 1'b0;
            below3_q  <= 1'b0;
            capped3_q <= 1'b0;
            rem3_q    <= {W{1'b0}};
            x3_q      <= {W{1'b0}};
        end else begin
            v3_q      <= v2_q;
            below3_q  <= below2_q;
            capped3_q <= !below2_q && (x2_q == {W{1'b0}} || capx2_q <= y2);
            rem3_q    <= y2;
            x3_q      <= x2_q;
        end
    end

    // stages 4 .. QMAX + 3: quotient bits, then delay. Stage s + 1 reads
    // the wires of stage s (index 0 = the stage-3 registers).
    wire [QMAX:0] v_w;
    wire [QMAX:0] below_w;
    wire [QMAX:0] capped_w;
    wire [W-1:0]  rem_w [0:QMAX];
    wire [W-1:0]  x_w   [0:QMAX];
    wire [7:0]    quo_w [0:QMAX];
    assign v_w[0]      = v3_q;
    assign below_w[0]  = below3_q;
    assign capped_w[0] = capped3_q;
    assign rem_w[0]    = rem3_q;
    assign x_w[0]      = x3_q;
    assign quo_w[0]    = 8'd0;
    genvar s;
    generate
        for (s = 0; s < QMAX; s = s + 1) begin : g_stage
            reg         v_q;
            reg         below_q;
            reg         capped_q;
            reg [W-1:0] rem_q;
            reg [W-1:0] x_q;
            reg [7:0]   quo_q;
            wire [W-1:0] rem_d;
            wire [7:0]   quo_d;
            if (s < QBITS) begin : g_bit
                // Quotient bit m = QBITS - 1 - s: subtract x 2^m, keep the
                // difference unless it borrows.
                wire [W:0] t = {1'b0, rem_w[s]} - {1'b0, x_w[s] << (QBITS - 1 - s)};
                assign rem_d = t[W] ? rem_w[s] : t[W-1:0];
                assign quo_d = {quo_w[s][6:0], ~t[W]};
            end else begin : g_delay
                assign rem_d = rem_w[s];
                assign quo_d = quo_w[s];
            end
            always @(posedge clk_i) begin
                if (rst_i) begin
                    v_q      <= 1'b0;
                    below_q  <= 1'b0;
                    capped_q <= 1'b0;
                    rem_q    <= {W{1'b0}};
                    x_q      <= {W{1'b0}};
                    quo_q    <= 8'd0;
                end else begin
                    v_q      <= v_w[s];
                    below_q  <= below_w[s];
                    capped_q <= capped_w[s];
                    rem_q    <= rem_d;
                    x_q      <= x_w[s];
                    quo_q    <= quo_d;
                end
            end
            assign v_w[s+1]      = v_q;
            assign below_w[s+1]  = below_q;
            assign capped_w[s+1] = capped_q;
            assign rem_w[s+1]    = rem_q;
            assign x_w[s+1]      = x_q;
            assign quo_w[s+1]    = quo_q;
        end
    endgenerate

    assign out_valid_o = v_w[QMAX];
    assign below_o     = below_w[QMAX];
    assign capped_o    = capped_w[QMAX];
    assign q_o         = quo_w[QMAX];
endmodule

`default_nettype wire
