// fault_block: over-current, external, watchdog, encoder-loss and
// ADC-stuck faults, latched.
//
//   sample_valid_i, ia/ib/ic_i  raw ADC samples (signed 12-bit counts, one
//                    strobe per conversion, from adc_frontend)
//   oc_limit_i       unsigned counts: over-current when |sample| > limit on
//                    any phase of a valid sample (-2048 has magnitude 2048,
//                    so it always trips)
//   ext_fault_i      external fault, active high, already synchronised
//   heartbeat_i      one-cycle strobe on every HEARTBEAT write
//   wdg_timeout_i    cycles without a heartbeat before the watchdog trips
//   run_i            the drive runs (GATE_EN = 1): encoder loss and ADC
//                    stuck are judged only then
//   enc_illegal_i    an illegal quadrature step this cycle (A and B changed
//                    in one clock; encoder_qei ignores it)
//   adc_en_i         ADC_CTRL.ENABLE
//   adc_period_i     ADC_PERIOD, cycles between raw samples
//   clr_i            W1C strobes of FAULT_STATUS (bit order as status_o)
//   status_o         latched faults {adc stuck, encoder loss, watchdog,
//                    external, overcurrent}
//   raw_o            live conditions: over-current of the latest sample,
//                    external input, watchdog expired, illegal step now,
//                    raw sample overdue now
//   trip_o           combinational: a fault is latched or is being raised
//                    this cycle. Wired to the gate driver's fault input, it
//                    turns every gate off at the next clock edge.
// Over-current is judged one clock after its sample: the comparison of the
// three magnitudes is registered (oc_hit_q) before it reaches trip_o, so the
// path from the ADC's sample register to the gate legs stays within one
// clock at 100 MHz (docs/rtl.md, delay model); the gates go off at the
// second edge after the sample strobe. The watchdog's comparison is
// registered too: it trips one clock after its counter reaches
// WDG_TIMEOUT (and a heartbeat ends the expired condition one clock after
// it clears the counter).
// A latched bit clears on a written 1 only if its condition is not present
// in the same cycle (set wins). The watchdog counter saturates, so it stays
// expired until a heartbeat.
// ADC result timer: adc_age_q counts the cycles since the last raw sample
// strobe; while running, ADC_STUCK trips when it reaches adc_period_i +
// ADC_MARGIN (ADC_PERIOD + 16 cycles: the synchroniser's +-1 cycle and a
// converter's conversion-time jitter; regmap::ADC_STUCK_MARGIN_CYCLES). A
// raw sample (not the average) is judged, so the trip comes one sample
// period after the converter stops, whatever the averaging. The timer
// restarts (0) at every sample, in every cycle GATE_EN = 0 and at every
// change of ADC_CTRL.ENABLE: the firmware's restart (ENABLE 0 then 1) gives
// the timer a fresh sample period for the first conversion, and a disable
// alone trips one sample period plus the margin after it. A shorter
// ADC_PERIOD takes effect in the timer one clock after its write (the
// comparison is a register, adc_early_q) but in the converter's pace
// only at its next conversion: a new period is written with ENABLE = 0 and
// then ENABLE = 1 (the firmware's Adc::set_period), else a shorter one
// trips with the gates on (a false trip: the safe side).
`default_nettype none

module fault_block (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        sample_valid_i,
    input  wire [11:0] ia_i,
    input  wire [11:0] ib_i,
    input  wire [11:0] ic_i,
    input  wire [10:0] oc_limit_i,
    input  wire        ext_fault_i,
    input  wire        heartbeat_i,
    input  wire [31:0] wdg_timeout_i,
    input  wire        run_i,
    input  wire        enc_illegal_i,
    input  wire        adc_en_i,
    input  wire [15:0] adc_period_i,
    input  wire [ 4:0] clr_i,
    output wire [ 4:0] status_o,
    output wire [ 4:0] raw_o,
    output wire        trip_o
);
    localparam [16:0] ADC_MARGIN = 17'd16;
    reg  [ 4:0] status_q;
    reg         oc_last_q;
    reg         oc_hit_q;
    reg  [31:0] wdg_cnt_q;
    reg  [16:0] adc_age_q;
    reg         adc_en_q;
    // The watchdog comparison, registered (out of the trip path): the
    // watchdog trips one clock after the counter reaches WDG_TIMEOUT.
    reg         wdg_exp_q;

    // |x| of a signed 12-bit value as 12-bit unsigned (|-2048| = 2048).
    function automatic [11:0] mag(input [11:0] x);
        mag = x[11] ? (~x + 12'd1) : x;
    endfunction

    wire [11:0] lim = {1'b0, oc_limit_i};
    wire oc_sample = (mag(ia_i) > lim) || (mag(ib_i) > lim) || (mag(ic_i) > lim);
    wire oc_now = oc_hit_q;
    wire wdg_now = wdg_exp_q;
    wire enc_now = run_i && enc_illegal_i;
    wire adc_restart = !run_i || sample_valid_i || (adc_en_i != adc_en_q);
    wire [16:0] adc_limit_d = {1'b0, adc_period_i} + ADC_MARGIN;
    wire [16:0] adc_age_d = adc_restart ? 17'd0
                          : (adc_age_q != 17'h1FFFF) ? adc_age_q + 17'd1 : adc_age_q;
    // The timer against ADC_PERIOD + ADC_MARGIN of the clock before (a new
    // ADC_PERIOD counts one clock later), decided a clock ahead from the
    // timer's next value (the same comparison, exactly), so that the trip
    // path starts at a flip-flop: with the sum and the comparison's carry
    // chains in it, the trip reached the gate legs in 8.2 ns (estimated,
    // pl_top). Stored as "early" (0 = late), so the all-zero power-up
    // state and the reset state (age 0, level 0: late) read right.
    reg         adc_early_q;
    wire adc_late = !adc_early_q;
    wire adc_now = run_i && adc_late;
    wire [4:0] cond = {adc_now, enc_now, wdg_now, ext_fault_i, oc_now};

    always @(posedge clk_i) begin
        if (rst_i) begin
            status_q  <= 5'b00000;
            oc_last_q <= 1'b0;
            oc_hit_q  <= 1'b0;
            wdg_cnt_q <= 32'd0;
            adc_age_q <= 17'd0;
            adc_en_q  <= 1'b1;
            adc_early_q <= 1'b0;
            wdg_exp_q <= 1'b0;
        end else begin
            adc_early_q <= adc_age_d < adc_limit_d;
            status_q <= (status_q & ~clr_i) | cond;
            if (sample_valid_i) oc_last_q <= oc_sample;
            oc_hit_q <= sample_valid_i && oc_sample;
            if (heartbeat_i) wdg_cnt_q <= 32'd0;
            else if (wdg_cnt_q != 32'hFFFF_FFFF) wdg_cnt_q <= wdg_cnt_q + 32'd1;
            wdg_exp_q <= wdg_cnt_q >= wdg_timeout_i;
            adc_en_q <= adc_en_i;
            adc_age_q <= adc_age_d;
        end
    end

    assign status_o = status_q;
    assign raw_o    = {adc_now, enc_now, wdg_now, ext_fault_i, oc_last_q};
    assign trip_o   = (|status_q) || (|cond);

`ifdef FORMAL
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;
    // Specification of the ADC result timer: cycles since the last raw
    // sample, change of ADC_CTRL.ENABLE or cycle with the drive stopped
    // (saturating), counted from the inputs alone.
    reg [16:0] f_quiet_q = 17'd0;
    reg        f_en_q = 1'b1;
    always @(posedge clk_i) begin
        f_en_q <= rst_i ? 1'b1 : adc_en_i;
        if (rst_i || !run_i || sample_valid_i || adc_en_i != f_en_q) f_quiet_q <= 17'd0;
        else if (f_quiet_q != 17'h1FFFF) f_quiet_q <= f_quiet_q + 17'd1;
    end
    // the watchdog's condition one clock late
    reg         f_wdg_q = 1'b0;
    always @(posedge clk_i) f_wdg_q <= !rst_i && wdg_cnt_q >= wdg_timeout_i;
    // the trip level: ADC_PERIOD of the cycle before + 16
    reg  [16:0] f_limit_q = 17'd0;
    always @(posedge clk_i) f_limit_q <= rst_i ? 17'd0 : {1'b0, adc_period_i} + 17'd16;
    always @(*) begin
        if (!f_past_valid) assume (rst_i);
        if (f_past_valid) begin
            assert (f_en_q == adc_en_q);
            assert (f_quiet_q == adc_age_q);
        end
        assert (adc_late == (adc_age_q >= f_limit_q));
        // A raw sample overdue by the margin while running trips at once;
        // an illegal quadrature step while running too.
        if (run_i && f_quiet_q >= f_limit_q) assert (trip_o);
        if (run_i && enc_illegal_i) assert (trip_o);
        // Specification of the three sources, then: a live condition trips
        // at once (over-current one clock after its sample, below).
        if (ext_fault_i) assert (trip_o);
        if (f_past_valid) assert (wdg_exp_q == f_wdg_q);
        if (f_wdg_q) assert (trip_o);
        if (|cond) assert (trip_o);
        if (|status_q) assert (trip_o);
    end
    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            // An over-current sample trips one clock later.
            if ($past(sample_valid_i && (mag(ia_i) > lim || mag(ib_i) > lim || mag(ic_i) > lim)))
                assert (trip_o);
            // Every condition latches its bit.
            if ($past(oc_now)) assert (status_q[0]);
            if ($past(ext_fault_i)) assert (status_q[1]);
            if ($past(wdg_now)) assert (status_q[2]);
            if ($past(enc_now)) assert (status_q[3]);
            if ($past(adc_now)) assert (status_q[4]);
            // A latched bit stays until a clear strobe for it.
            if ($past(status_q[0] && !clr_i[0])) assert (status_q[0]);
            if ($past(status_q[1] && !clr_i[1])) assert (status_q[1]);
            if ($past(status_q[2] && !clr_i[2])) assert (status_q[2]);
            if ($past(status_q[3] && !clr_i[3])) assert (status_q[3]);
            if ($past(status_q[4] && !clr_i[4])) assert (status_q[4]);
            // Bits only set from a condition.
            if (status_q[0] && !$past(status_q[0])) assert ($past(oc_now));
            if (status_q[1] && !$past(status_q[1])) assert ($past(ext_fault_i));
            if (status_q[2] && !$past(status_q[2])) assert ($past(wdg_now));
            // No ADC_STUCK before its time, no ENCODER_LOSS without an
            // illegal step, both only while running.
            if (status_q[3] && !$past(status_q[3])) assert ($past(run_i && enc_illegal_i));
            if (status_q[4] && !$past(status_q[4])) assert ($past(run_i && f_quiet_q >= f_limit_q));
            // Without a heartbeat the watchdog counter only grows.
            if (!$past(heartbeat_i)) assert (wdg_cnt_q >= $past(wdg_cnt_q));
        end
    end
`endif
endmodule

`default_nettype wire
