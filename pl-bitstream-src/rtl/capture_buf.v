// capture_buf: triggered capture of six channels into a BRAM ring, with
// pre-trigger (the CAPTURE page, docs/register-map.md).
//
//   sample_i     averaged-ADC strobe (adc_avg_valid: the MPDTC control
//                period boundary); a sample is taken every decim_i + 1
//                strobes while ARMED or TRIGGERED
//   ch_*_i       the channels of a sample: i_d, i_q, torque, torque
//                reference (16-bit two's complement, written by the PS each
//                control period), the selectable channel (16 bits), the
//                switching state at the gate driver (3 bits), and the PS's
//                multi-turn position (32-bit counts), velocity (Q16.16
//                rev/s) and following error (Q12.4 counts), formats in the
//                register table (CAP_IN_POS, CAP_IN_VEL, CAP_IN_FERR); only
//                stored and read back, never computed on here
//   arm_i        one-cycle strobe: empty the ring, latch pre_i, ARMED
//   trig_i       one-cycle strobe: manual trigger at the next sample
//   source_i     0 manual only, 1 reference step (|tref - previous tref|
//                >= step_i), 2 threshold crossing of the trigger channel
//                thr_now_i (selected by the caller: CAP_THR_CH) over
//                thr_level_i (thr_edge_i: 0 rising, 1 falling), 3 fault_i
//   thr_ge_i, thr_le_i  thr_now_i >= thr_level_i, thr_now_i <= thr_level_i
//                (signed; computed by the caller with them, before its
//                input registers: no comparison chain on this path)
//   rd_index_i   record index (0 = oldest sample); rd_data_o shows that
//                sample one clock later
// A record: after the trigger sample, DEPTH - pre - 1 more samples are
// taken, then DONE; the ring then holds the last min(taken, DEPTH) samples,
// the trigger sample at trig_index_o = count_o - (DEPTH - pre) (fewer than
// pre samples before it when the trigger came early). Memory word
// (W = 163 bits): {ferr, vel[31:0], pos[31:0], sw[2:0], sel, tref, torque,
// i_q, i_d}, i_d in bits 15..0, pos in 114..83, vel 146..115, ferr 162..147.
`default_nettype none

module capture_buf #(
    // Ring of 2^AW samples. pl_top sets it from the register map's
    // CAPTURE_DEPTH; the default is the small ring the formal proof uses.
    parameter integer AW = 2
) (
    input  wire          clk_i,
    input  wire          rst_i,
    input  wire          arm_i,
    input  wire          trig_i,
    input  wire [   1:0] source_i,
    input  wire [  15:0] pre_i,
    input  wire [   7:0] decim_i,
    input  wire [  15:0] step_i,
    input  wire [  15:0] thr_now_i,
    input  wire          thr_ge_i,
    input  wire          thr_le_i,
    input  wire [  15:0] thr_level_i,
    input  wire          thr_edge_i,
    input  wire          sample_i,
    input  wire          fault_i,
    input  wire [  15:0] ch_id_i,
    input  wire [  15:0] ch_iq_i,
    input  wire [  15:0] ch_torque_i,
    input  wire [  15:0] ch_tref_i,
    input  wire [  15:0] ch_sel_i,
    input  wire [   2:0] ch_sw_i,
    input  wire [  31:0] ch_pos_i,
    input  wire [  31:0] ch_vel_i,
    input  wire [  15:0] ch_ferr_i,
    input  wire [  15:0] rd_index_i,
    output wire [   1:0] state_o,
    output wire [  AW:0] count_o,
    output wire [  AW:0] trig_index_o,
    output reg  [ 162:0] rd_data_o
);
    localparam integer DEPTH = 1 << AW;
    localparam [1:0] IDLE = 2'd0, ARMED = 2'd1, TRIG = 2'd2, DONE = 2'd3;
    localparam [AW:0] DEPTH_W = DEPTH[AW:0];
    localparam [AW:0] ONE = 1;

    reg [162:0] mem_q[0:DEPTH-1];
    reg [1:0] state_q;
    reg [AW-1:0] wr_ptr_q;
    reg [AW:0] count_q;
    reg [AW:0] post_q;  // samples still to take after the trigger
    reg [AW-1:0] pre_q;
    reg [7:0] decim_q;
    reg trig_pend_q;
    reg prev_valid_q;
    reg [15:0] tref_prev_q;
    reg [15:0] thr_prev_q;
    reg signed [17:0] step_hi_q;
    reg signed [17:0] step_lo_q;

    integer i;
    initial for (i = 0; i < DEPTH; i = i + 1) mem_q[i] = 163'd0;

    // pre_i is clamped to CAPTURE_DEPTH - 1 by the register file; the
    // clamp here keeps a smaller ring consistent.
    wire [AW-1:0] pre_eff = (pre_i >= {{(15 - AW) {1'b0}}, DEPTH_W}) ? {AW{1'b1}} : pre_i[AW-1:0];
    wire running = (state_q == ARMED) || (state_q == TRIG);
    wire take = running && sample_i && (decim_q >= decim_i);

    // Trigger conditions, on the values of this sample.
    // Reference step |tref - tref_prev| >= step, as tref >= tref_prev + step
    // or tref <= tref_prev - step against the two bounds kept in registers
    // (step_hi_q, step_lo_q, 18-bit signed: exact), so the comparison is one
    // carry chain within the clock (docs/rtl.md, delay model). The bounds
    // follow tref_prev_q at its own edge and CAP_STEP one clock after its
    // write: the step in force is step_i of the cycle before.
    wire signed [17:0] tref_s = {{2{ch_tref_i[15]}}, ch_tref_i};
    wire step_hit = prev_valid_q && (tref_s >= step_hi_q || tref_s <= step_lo_q);
    wire signed [15:0] thr_prev = thr_prev_q;
    wire signed [15:0] thr_lvl = thr_level_i;
    wire rise = (thr_prev < thr_lvl) && thr_ge_i;
    wire fall = (thr_prev > thr_lvl) && thr_le_i;
    wire thr_hit = prev_valid_q && (thr_edge_i ? fall : rise);
    wire trigger = trig_pend_q || (source_i == 2'd1 && step_hit) ||
        (source_i == 2'd2 && thr_hit) || (source_i == 2'd3 && fault_i);
    // Samples from the trigger on, the trigger sample included.
    wire [AW:0] post_len = DEPTH_W - {1'b0, pre_q};

    wire [AW-1:0] start = wr_ptr_q - count_q[AW-1:0];
    wire [AW-1:0] rd_ptr = start + rd_index_i[AW-1:0];

    always @(posedge clk_i) begin
        if (rst_i) begin
            rd_data_o <= 163'd0;
        end else begin
            rd_data_o <= mem_q[rd_ptr];
        end
        if (take && !arm_i) begin
            mem_q[wr_ptr_q] <= {
                ch_ferr_i, ch_vel_i, ch_pos_i, ch_sw_i, ch_sel_i, ch_tref_i, ch_torque_i, ch_iq_i, ch_id_i
            };
        end
    end

    always @(posedge clk_i) begin
        if (rst_i) begin
            state_q      <= IDLE;
            wr_ptr_q     <= {AW{1'b0}};
            count_q      <= {(AW + 1) {1'b0}};
            post_q       <= {(AW + 1) {1'b0}};
            pre_q        <= {AW{1'b0}};
            decim_q      <= 8'd0;
            trig_pend_q  <= 1'b0;
            prev_valid_q <= 1'b0;
            tref_prev_q  <= 16'd0;
            thr_prev_q   <= 16'd0;
        end else if (arm_i) begin
            state_q      <= ARMED;
            wr_ptr_q     <= {AW{1'b0}};
            count_q      <= {(AW + 1) {1'b0}};
            post_q       <= {(AW + 1) {1'b0}};
            pre_q        <= pre_eff;
            decim_q      <= 8'd0;
            trig_pend_q  <= 1'b0;
            prev_valid_q <= 1'b0;
            tref_prev_q  <= 16'd0;
            thr_prev_q   <= 16'd0;
        end else begin
            if (trig_i && state_q == ARMED) trig_pend_q <= 1'b1;
            if (running && sample_i) decim_q <= take ? 8'd0 : decim_q + 8'd1;
            if (take) begin
                wr_ptr_q     <= wr_ptr_q + 1'b1;
                count_q      <= (count_q == DEPTH_W) ? DEPTH_W : count_q + 1'b1;
                prev_valid_q <= 1'b1;
                tref_prev_q  <= ch_tref_i;
                thr_prev_q   <= thr_now_i;
                if (state_q == ARMED) begin
                    if (trigger) begin
                        trig_pend_q <= 1'b0;
                        post_q      <= post_len - 1'b1;
                        state_q     <= (post_len == ONE) ? DONE : TRIG;
                    end
                end else begin
                    post_q <= post_q - 1'b1;
                    if (post_q == ONE) state_q <= DONE;
                end
            end
        end
    end

    // tref_prev_q after this edge, and the bounds around it.
    wire [15:0] tref_prev_d = arm_i ? 16'd0 : take ? ch_tref_i : tref_prev_q;
    wire signed [17:0] tref_prev_s = {{2{tref_prev_d[15]}}, tref_prev_d};
    always @(posedge clk_i) begin
        if (rst_i) begin
            step_hi_q <= 18'sd0;
            step_lo_q <= 18'sd0;
        end else begin
            step_hi_q <= tref_prev_s + $signed({2'b00, step_i});
            step_lo_q <= tref_prev_s - $signed({2'b00, step_i});
        end
    end

    assign state_o = state_q;
    assign count_o = count_q;
    assign trig_index_o = (state_q == DONE) ? count_q - post_len : {(AW + 1) {1'b0}};

`ifdef FORMAL
    // Pointer logic of the ring. Reset in the first cycle.
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;
    always @(*) begin
        if (!f_past_valid) assume (rst_i);
    end
    // The step bounds are tref_prev_q +- the step of the cycle before.
    reg [15:0] f_step_q = 16'd0;
    always @(posedge clk_i) f_step_q <= rst_i ? 16'd0 : step_i;
    always @(*) begin
        if (f_past_valid) begin
            assert (step_hi_q == $signed({{2{tref_prev_q[15]}}, tref_prev_q}) + $signed({2'b00, f_step_q}));
            assert (step_lo_q == $signed({{2{tref_prev_q[15]}}, tref_prev_q}) - $signed({2'b00, f_step_q}));
        end
    end
    always @(*) begin
        if (f_past_valid) begin
            // The record never holds more than the ring.
            assert (count_q <= DEPTH_W);
            // Until the ring wraps, the write pointer is the sample count,
            // so record index 0 is slot 0.
            if (count_q < DEPTH_W) assert (wr_ptr_q == count_q[AW-1:0]);
            if (state_q == IDLE) assert (count_q == 0 && wr_ptr_q == 0 && post_q == 0);
            if (state_q == ARMED) assert (post_q == 0);
            // After the trigger: at least one sample to go, never more
            // than the post-trigger length, and the samples taken since
            // the trigger are in the record.
            if (state_q == TRIG) begin
                assert (post_q >= 1 && post_q < post_len);
                assert ({1'b0, count_q} + {1'b0, post_q} >= {1'b0, post_len});
            end
            // A complete record holds the whole post-trigger part, so the
            // trigger index is at most the pre-trigger length.
            if (state_q == DONE) begin
                assert (count_q >= post_len);
                assert (trig_index_o <= {1'b0, pre_q});
            end
        end
    end
    // A sample stores every channel where the word layout above says
    // (the read-back registers CAP_DATA0..5 slice that layout).
    reg f_took_q = 1'b0;
    reg [AW-1:0] f_slot_q;
    reg [162:0] f_word_q;
    always @(posedge clk_i) begin
        f_took_q <= take && !arm_i;
        f_slot_q <= wr_ptr_q;
        f_word_q[15:0] <= ch_id_i;
        f_word_q[31:16] <= ch_iq_i;
        f_word_q[47:32] <= ch_torque_i;
        f_word_q[63:48] <= ch_tref_i;
        f_word_q[79:64] <= ch_sel_i;
        f_word_q[82:80] <= ch_sw_i;
        f_word_q[114:83] <= ch_pos_i;
        f_word_q[146:115] <= ch_vel_i;
        f_word_q[162:147] <= ch_ferr_i;
    end
    always @(*) begin
        if (f_past_valid && f_took_q) begin
            assert (mem_q[f_slot_q][162:147] == f_word_q[162:147]);
            assert (mem_q[f_slot_q][146:115] == f_word_q[146:115]);
            assert (mem_q[f_slot_q][114:83] == f_word_q[114:83]);
            assert (mem_q[f_slot_q][82:0] == f_word_q[82:0]);
        end
    end
    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            if ($past(arm_i)) assert (state_q == ARMED && count_q == 0 && wr_ptr_q == 0);
            // Each sample advances the write pointer by one and the count
            // by one until the ring is full.
            if ($past(take && !arm_i)) begin
                assert (wr_ptr_q == $past(wr_ptr_q) + 1'b1);
                assert (count_q == ($past(count_q) == DEPTH_W ? DEPTH_W : $past(count_q) + 1'b1));
            end
            // No sample, no change of the pointers.
            if ($past(!take && !arm_i)) assert (wr_ptr_q == $past(wr_ptr_q) && count_q == $past(count_q));
            // A complete record stays until the next arm.
            if ($past(state_q == DONE && !arm_i)) assert (state_q == DONE);
            // The trigger is only taken while armed.
            if ($past(state_q == ARMED && !arm_i) && state_q != ARMED) assert ($past(take && trigger));
        end
    end
`endif
endmodule

`default_nettype wire
