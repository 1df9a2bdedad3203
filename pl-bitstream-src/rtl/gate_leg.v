// gate_leg: gate signals of one inverter leg, with dead time and interlock.
//
// Ports
//   clk_i      rising-edge clock (100 MHz on the Zynq PL)
//   rst_i      synchronous reset, active high: both gates off, dead-time
//              counter cleared (a fresh dead time runs after reset)
//   en_i       1 = follow s_i; 0 = both gates off (safe state)
//   fault_i    1 = both gates off at the next clock edge (overrides en_i)
//   s_i        desired switch state, 1 = upper switch on, 0 = lower switch on
//   dt_i       dead time in clock cycles, DT_W bits, unsigned: 0..2^DT_W-1.
//              0 is treated as 1: a gate never turns on in the cycle right
//              after the other one turned off. With DT_W = 10 and 100 MHz
//              the range is 10 ns .. 10.23 us. dt_i is sampled every cycle;
//              firmware writes it only with the gates disabled.
//   hi_o, lo_o upper / lower gate, 1 = on. Registered outputs.
//
// Behaviour (the Rust model simpl::gates::GateLeg is the same, bit for bit
// on the outputs)
//   While both gates are off, off_cnt_q counts the consecutive cycles, up to
//   and including the current one, in which both gates are off; it
//   saturates at 2^DT_W-1 (>= every dead time). A gate may turn on at the
//   next edge only if the other gate is off and off_cnt_q >= max(dt_i, 1).
//   A gate that is on turns off at the next edge when s_i asks for the other
//   switch, en_i is 0, fault_i is 1 or rst_i is 1.
//   The counter restarts from the registered gates (1 after a cycle with a
//   gate on), not from hi_d/lo_d: those come last in the state selection of
//   pl_top, and as the synchronous reset of the ten counter flip-flops they
//   made the PL's longest path (8.3 ns estimated). While a gate is on the
//   count is not read (a gate that is on stays on or turns off, and the
//   other one needs this one off first); while both are off it equals the
//   count restarted by hi_d/lo_d (the Rust model's, and f_off_q of the
//   formal properties below).
`default_nettype none

module gate_leg #(
    parameter integer DT_W = 10
) (
    input  wire            clk_i,
    input  wire            rst_i,
    input  wire            en_i,
    input  wire            fault_i,
    input  wire            s_i,
    input  wire [DT_W-1:0] dt_i,
    output wire            hi_o,
    output wire            lo_o
);
    localparam [DT_W-1:0] CNT_MAX = {DT_W{1'b1}};
    localparam [DT_W-1:0] DT_MIN = {{(DT_W - 1) {1'b0}}, 1'b1};

    reg            hi_q;
    reg            lo_q;
    reg [DT_W-1:0] off_cnt_q;
    reg            hi_d;
    reg            lo_d;
    reg [DT_W-1:0] off_cnt_d;

    // Dead time with 0 read as 1.
    wire [DT_W-1:0] dt_eff = (dt_i == {DT_W{1'b0}}) ? DT_MIN : dt_i;
    // Both gates have been off for at least the dead time.
    wire dead_done = (off_cnt_q >= dt_eff);

    always @(*) begin
        hi_d = 1'b0;
        lo_d = 1'b0;
        if (rst_i || fault_i || !en_i) begin
            hi_d = 1'b0;
            lo_d = 1'b0;
        end else if (s_i) begin
            hi_d = hi_q | (!lo_q && dead_done);
        end else begin
            lo_d = lo_q | (!hi_q && dead_done);
        end
        if (rst_i) begin
            off_cnt_d = {DT_W{1'b0}};
        end else if (hi_q || lo_q) begin
            off_cnt_d = DT_MIN;
        end else if (off_cnt_q != CNT_MAX) begin
            off_cnt_d = off_cnt_q + 1'b1;
        end else begin
            off_cnt_d = off_cnt_q;
        end
    end

    always @(posedge clk_i) begin
        hi_q      <= hi_d;
        lo_q      <= lo_d;
        off_cnt_q <= off_cnt_d;
    end

    assign hi_o = hi_q;
    assign lo_o = lo_q;

`ifdef FORMAL
    // The proof starts from the all-zero state (sat -set-init-zero), which
    // is the reset state of this module.
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;

    // Independent monitor: consecutive cycles (including the current one)
    // with both outputs off, saturating like the design's counter.
    reg [DT_W-1:0] f_off_q = {DT_W{1'b0}};
    always @(posedge clk_i) begin
        if (rst_i || hi_d || lo_d) f_off_q <= {DT_W{1'b0}};
        else if (f_off_q != CNT_MAX) f_off_q <= f_off_q + 1'b1;
    end

    always @(*) begin
        // P1 interlock: the two gates of the leg are never on together.
        assert (!(hi_q && lo_q));
        // Induction strengthening: with both gates off the design counter
        // equals the monitor; a gate that is on has a zero monitor count.
        if (!hi_q && !lo_q) assert (off_cnt_q == f_off_q);
        if (hi_q || lo_q) assert (f_off_q == {DT_W{1'b0}});
    end

    always @(posedge clk_i) begin
        if (f_past_valid) begin
            // P2 dead time: a gate turns on only if both gates were off for
            // max(dt, 1) cycles just before (dt as seen at the decision).
            if (hi_q && !$past(hi_q)) begin
                assert (!$past(lo_q));
                assert ($past(f_off_q) >= (($past(dt_i) == 0) ? 1 : $past(dt_i)));
            end
            if (lo_q && !$past(lo_q)) begin
                assert (!$past(hi_q));
                assert ($past(f_off_q) >= (($past(dt_i) == 0) ? 1 : $past(dt_i)));
            end
            // P3 fault / disable / reset: every gate off in the next clock.
            if ($past(fault_i) || !$past(en_i) || $past(rst_i)) begin
                assert (!hi_q && !lo_q);
            end
        end
    end
`endif
endmodule

`default_nettype wire
