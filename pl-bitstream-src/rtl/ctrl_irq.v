// ctrl_irq: the control interrupt to the PS (IRQ_F2P[0], GIC SPI 61).
// Sticky flags (register IRQ_STATUS, write 1 to clear; a condition in the
// same cycle as its clear wins): BOUNDARY at every control-period boundary
// (boundary_i, one-cycle strobe, set when the sample the control step
// needs is ready), FAULT when a fault is newly latched (rising fault_i),
// MISSED when a boundary finds BOUNDARY still set (the previous step did
// not acknowledge it). irq_o = |(flags[1:0] & en_i), registered: a level,
// high until the handler clears what it serves. age_o counts the cycles
// since the last boundary (BOUNDARY_AGE: the step's start latency when read
// at its start), saturating at 16 bits.
`default_nettype none

module ctrl_irq (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        boundary_i,
    input  wire        fault_i,
    input  wire [ 1:0] en_i,
    input  wire [ 2:0] clr_i,
    output wire [ 2:0] status_o,
    output wire        irq_o,
    output wire [15:0] age_o
);
    reg [ 2:0] status_q;
    reg        fault_q;
    reg        irq_q;
    reg [15:0] age_q;

    wire [2:0] kept = status_q & ~clr_i;
    wire [2:0] status_d = kept | {boundary_i && kept[0], fault_i && !fault_q, boundary_i};

    always @(posedge clk_i) begin
        if (rst_i) begin
            status_q <= 3'd0;
            fault_q  <= 1'b0;
            irq_q    <= 1'b0;
            age_q    <= 16'd0;
        end else begin
            status_q <= status_d;
            fault_q  <= fault_i;
            irq_q    <= |(status_d[1:0] & en_i);
            if (boundary_i) age_q <= 16'd0;
            else if (age_q != 16'hFFFF) age_q <= age_q + 16'd1;
        end
    end

    assign status_o = status_q;
    assign irq_o    = irq_q;
    assign age_o    = age_q;

`ifdef FORMAL
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;
    // en_i as sampled with the flags (the line's registered inputs).
    reg [1:0] en_q_f = 2'd0;
    always @(posedge clk_i) en_q_f <= en_i;
    always @(*) begin
        if (!f_past_valid) assume (rst_i);
        // The line is exactly the enabled flags, one cycle late.
        if (f_past_valid && !rst_i) assert (irq_o == |(status_q[1:0] & en_q_f));
    end
    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            // Every boundary sets BOUNDARY and restarts the age.
            if ($past(boundary_i)) assert (status_q[0] && age_q == 16'd0);
            // A boundary on an unacknowledged one is a missed step.
            if ($past(boundary_i && status_q[0] && !clr_i[0])) assert (status_q[2]);
            // A newly latched fault sets FAULT.
            if ($past(fault_i && !fault_q)) assert (status_q[1]);
            // Flags stay until cleared.
            if ($past(status_q[0] && !clr_i[0])) assert (status_q[0]);
            if ($past(status_q[1] && !clr_i[1])) assert (status_q[1]);
            if ($past(status_q[2] && !clr_i[2])) assert (status_q[2]);
            // Flags only set by their condition.
            if (status_q[0] && !$past(status_q[0])) assert ($past(boundary_i));
            if (status_q[1] && !$past(status_q[1])) assert ($past(fault_i && !fault_q));
            if (status_q[2] && !$past(status_q[2])) assert ($past(boundary_i));
            // Without a boundary the age grows by one, up to its top.
            if (!$past(boundary_i))
                assert (age_q == ($past(age_q) == 16'hFFFF ? 16'hFFFF : $past(age_q) + 16'd1));
        end
    end
`endif
endmodule

`default_nettype wire
