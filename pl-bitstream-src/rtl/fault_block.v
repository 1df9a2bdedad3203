// fault_block: over-current, external and watchdog faults, latched.
//
//   sample_valid_i, ia/ib/ic_i  raw ADC samples (signed 12-bit counts, one
//                    strobe per conversion, from adc_frontend)
//   oc_limit_i       unsigned counts: over-current when |sample| > limit on
//                    any phase of a valid sample (-2048 has magnitude 2048,
//                    so it always trips)
//   ext_fault_i      external fault, active high, already synchronised
//   heartbeat_i      one-cycle strobe on every HEARTBEAT write
//   wdg_timeout_i    cycles without a heartbeat before the watchdog trips
//   clr_i            W1C strobes of FAULT_STATUS (bit order as status_o)
//   status_o         latched faults {watchdog, external, overcurrent}
//   raw_o            live conditions: over-current of the latest sample,
//                    external input, watchdog expired
//   trip_o           combinational: a fault is latched or is being raised
//                    this cycle. Wired to the gate driver's fault input, it
//                    turns every gate off at the next clock edge.
// A latched bit clears on a written 1 only if its condition is not present
// in the same cycle (set wins). The watchdog counter saturates, so it stays
// expired until a heartbeat.
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
    input  wire [ 2:0] clr_i,
    output wire [ 2:0] status_o,
    output wire [ 2:0] raw_o,
    output wire        trip_o
);
    reg  [ 2:0] status_q;
    reg         oc_last_q;
    reg  [31:0] wdg_cnt_q;

    // |x| of a signed 12-bit value as 12-bit unsigned (|-2048| = 2048).
    function automatic [11:0] mag(input [11:0] x);
        mag = x[11] ? (~x + 12'd1) : x;
    endfunction

    wire [11:0] lim = {1'b0, oc_limit_i};
    wire oc_sample = (mag(ia_i) > lim) || (mag(ib_i) > lim) || (mag(ic_i) > lim);
    wire oc_now = sample_valid_i && oc_sample;
    wire wdg_now = (wdg_cnt_q >= wdg_timeout_i);
    wire [2:0] cond = {wdg_now, ext_fault_i, oc_now};

    always @(posedge clk_i) begin
        if (rst_i) begin
            status_q  <= 3'b000;
            oc_last_q <= 1'b0;
            wdg_cnt_q <= 32'd0;
        end else begin
            status_q <= (status_q & ~clr_i) | cond;
            if (sample_valid_i) oc_last_q <= oc_sample;
            if (heartbeat_i) wdg_cnt_q <= 32'd0;
            else if (wdg_cnt_q != 32'hFFFF_FFFF) wdg_cnt_q <= wdg_cnt_q + 32'd1;
        end
    end

    assign status_o = status_q;
    assign raw_o    = {wdg_now, ext_fault_i, oc_last_q};
    assign trip_o   = (|status_q) || (|cond);

`ifdef FORMAL
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;
    always @(*) begin
        if (!f_past_valid) assume (rst_i);
        // Specification of the three sources, then: a live condition trips
        // at once.
        if (sample_valid_i && (mag(ia_i) > lim || mag(ib_i) > lim || mag(ic_i) > lim))
            assert (trip_o);
        if (ext_fault_i) assert (trip_o);
        if (wdg_cnt_q >= wdg_timeout_i) assert (trip_o);
        if (|cond) assert (trip_o);
        if (|status_q) assert (trip_o);
    end
    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            // Every condition latches its bit.
            if ($past(oc_now)) assert (status_q[0]);
            if ($past(ext_fault_i)) assert (status_q[1]);
            if ($past(wdg_now)) assert (status_q[2]);
            // A latched bit stays until a clear strobe for it.
            if ($past(status_q[0] && !clr_i[0])) assert (status_q[0]);
            if ($past(status_q[1] && !clr_i[1])) assert (status_q[1]);
            if ($past(status_q[2] && !clr_i[2])) assert (status_q[2]);
            // Bits only set from a condition.
            if (status_q[0] && !$past(status_q[0])) assert ($past(oc_now));
            if (status_q[1] && !$past(status_q[1])) assert ($past(ext_fault_i));
            if (status_q[2] && !$past(status_q[2])) assert ($past(wdg_now));
            // Without a heartbeat the watchdog counter only grows.
            if (!$past(heartbeat_i)) assert (wdg_cnt_q >= $past(wdg_cnt_q));
        end
    end
`endif
endmodule

`default_nettype wire
