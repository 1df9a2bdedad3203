// encoder_qei: incremental encoder interface (A/B quadrature + index Z).
//
// Inputs a_i, b_i, z_i must already be synchronised (sync2 in pl_top).
// Quadrature decoding, 4 counts per line: the phase (a, b) = 00, 10, 11, 01
// is 0, 1, 2, 3; a step of +1 (A leads B) counts up, -1 counts down, a jump
// of 2 (both inputs changed in one clock: the encoder is too fast or noisy)
// is ignored by the count and flagged on illegal_o (one cycle: the fault
// block's ENCODER_LOSS). The position wraps in 0..cpr_i-1 (mechanical counts per
// revolution). A rising edge of z_i sets the position to 0 (it wins over a
// simultaneous count) and counts in index_cnt_o.
// Speed: the counts moved during each window of window_i clock cycles,
// saturated to signed 16 bits (speed_o, updated at the end of each window).
// The first clock after reset only samples the inputs (no count, no index).
// Sampled position: pos_sample_o takes pos_o of the cycle sample_i is high
// (the control-period boundary), so the control step reads the position of
// its sample's instant however late after the boundary its read comes.
// The electrical angle is pos * pole pairs * 2 pi / cpr (firmware / core).
`default_nettype none

module encoder_qei (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        a_i,
    input  wire        b_i,
    input  wire        z_i,
    input  wire [15:0] cpr_i,
    input  wire [23:0] window_i,
    input  wire        sample_i,
    output wire [15:0] pos_o,
    output wire [15:0] speed_o,
    output wire [15:0] index_cnt_o,
    output wire [15:0] pos_sample_o,
    output wire        illegal_o
);
    localparam signed [15:0] SMAX = 16'sh7FFF;
    localparam signed [15:0] SMIN = -16'sh7FFF - 16'sh0001;

    reg  [ 1:0] ph_q;
    reg         primed_q;  // ph_q holds a real sample (not the reset value)
    reg         z_q;
    reg  [15:0] pos_q;
    reg  [15:0] index_q;
    reg  [23:0] win_q;
    reg  signed [15:0] acc_q;
    reg  signed [15:0] speed_q;
    reg  [15:0] pos_sample_q;

    wire [1:0] ph = {b_i, a_i ^ b_i};
    wire [1:0] step = ph - ph_q;
    wire up = primed_q && (step == 2'd1);
    wire down = primed_q && (step == 2'd3);
    wire illegal = primed_q && (step == 2'd2);
    wire index = z_i && !z_q;

    // Saturating accumulate of this cycle's step.
    wire signed [15:0] acc_next = (up && acc_q != SMAX) ? acc_q + 16'sd1
        : (down && acc_q != SMIN) ? acc_q - 16'sd1 : acc_q;

    always @(posedge clk_i) begin
        if (rst_i) begin
            ph_q     <= 2'd0;
            primed_q <= 1'b0;
            z_q      <= 1'b1;  // no index edge right out of reset
            pos_q   <= 16'd0;
            index_q <= 16'd0;
            win_q   <= 24'd0;
            acc_q   <= 16'sd0;
            speed_q <= 16'sd0;
            pos_sample_q <= 16'd0;
        end else begin
            if (sample_i) pos_sample_q <= pos_q;
            ph_q     <= ph;
            primed_q <= 1'b1;
            z_q      <= z_i;
            if (index) begin
                pos_q   <= 16'd0;
                index_q <= index_q + 16'd1;
            end else if (up) begin
                pos_q <= (pos_q >= cpr_i - 16'd1) ? 16'd0 : pos_q + 16'd1;
            end else if (down) begin
                pos_q <= (pos_q == 16'd0) ? cpr_i - 16'd1 : pos_q - 16'd1;
            end
            if (win_q + 24'd1 >= window_i) begin
                win_q   <= 24'd0;
                speed_q <= acc_next;
                acc_q   <= 16'sd0;
            end else begin
                win_q <= win_q + 24'd1;
                acc_q <= acc_next;
            end
        end
    end

    assign pos_o       = pos_q;
    assign speed_o     = speed_q;
    assign index_cnt_o = index_q;
    assign pos_sample_o = pos_sample_q;

`ifdef FORMAL
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;
    always @(*) if (!f_past_valid) assume (rst_i);
    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            // The sample is the position of the strobe's cycle, and holds
            // between strobes.
            if ($past(sample_i)) assert (pos_sample_q == $past(pos_q));
            if (!$past(sample_i)) assert (pos_sample_q == $past(pos_sample_q));
        end
    end
`endif
    assign illegal_o   = illegal;
endmodule

`default_nettype wire
