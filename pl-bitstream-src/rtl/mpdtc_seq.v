// mpdtc_seq: the control sequence of paper 000, section 3 (Figure 6), as an
// explicit state machine around mpdtc_core: IDLE, INITIAL (rotor alignment),
// SAMPLE, MPDTC, PWM. Used in pl_top in mode MPDTC with MPDTC_CTRL.MANUAL = 0.
//
// run_i = mode MPDTC && GATE_EN && MANUAL = 0 && STATE_CLR = 0 && no latched
// fault && no trip condition (pl_top). run_i low in cycle t: state IDLE at
// the edge ending t, and drive_o (the gate-driver enable) is low already in
// cycle t (combinational), so the gates are off at the edge ending t.
//
// States (encoding = MPDTC_SEQ_STATUS.STATE) and what each waits for:
//   0 IDLE     gates off (drive_o = 0). Waits for run_i. With auto_i = 0,
//              MPDTC_START writes pass straight to the core here (PS-paced
//              use); with auto_i = 1 nothing starts the core in IDLE.
//   1 INITIAL  rotor alignment. Requests align_vec_i (reset 100: phase a
//              upper, b and c lower = voltage vector on the a axis = d axis
//              at angle 0) while chop_q < min(align_on_i, align_period_i / 2)
//              and the zero vector 000 otherwise; chop_q counts 0 ..
//              align_period_i - 1 and wraps, starting at 0 on entry. So the
//              vector is on for min(ON, floor(P / 2)) of every P cycles: at
//              most half of the time, never full time. Holds the core's state
//              at zero (core_clr_o). Waits ALIGN_TIME cycles (INITIAL lasts
//              exactly max(ALIGN_TIME, 1) cycles; it also waits until the
//              core is idle, so the clear takes effect), then latches the
//              encoder position in align_pos_o (MPDTC_ALIGN_POS: the PS
//              subtracts it, theta_e = (ENC_POS - ALIGN_POS) pp 2 pi / CPR;
//              the encoder counter itself is not touched) and goes to SAMPLE
//              with the applied state 000 (the core's cleared S[k]).
//   2 SAMPLE   applies S[k]. Waits for (a) the averaged ADC sample of this
//              control period (sample_i = adc_avg_valid, the control-period
//              boundary, 2^ADC_AVG_LOG2 ADC periods) and (b) start_i, the core's
//              inputs of this period are ready:
//              - auto_i = 1 (MPDTC_CTRL.AUTO, the autonomous loop): start_i
//                is the out_valid of mpdtc_frontend, which pl_top starts with
//                every averaged sample (encoder angle, speed, sin/cos,
//                Clarke/Park in the PL), MPDTC_FE_LATENCY_CYCLES = 9 cycles
//                after the boundary; no PS access in the period.
//              - auto_i = 0 (PS-fed debug path): start_i is the MPDTC_START
//                write after the PS read ADC_IA..IC and ENC_POS and wrote the
//                dq currents and cos/sin (MPDTC_IN_*).
//              With both and the core ready it starts the core (core_start_o,
//              one cycle) and goes to MPDTC. A start before the sample is
//              ignored; a second boundary in SAMPLE (the inputs were late)
//              counts an overrun and S[k] stays.
//   3 MPDTC    waits for the core's out_valid (39 cycles), latches S[k+1]
//              (pending), goes to PWM. A boundary here counts an overrun.
//   4 PWM      waits for the next boundary (sample_i): then S[k+1] becomes
//              the applied state (at the gate driver's input 1 cycle after
//              the strobe, at the gates 1 cycle later / after the dead time),
//              the period counter increments and the state is SAMPLE with
//              that boundary's sample already taken.
// This is the timeline of models::pmsm::sim (measurement at t_k, decision
// applied during [t_k+1, t_k+2), 000 before the first decision).
// start_i in INITIAL, MPDTC and PWM is ignored. In the autonomous loop a
// period takes 9 (front end) + 1 + 39 (core) cycles from the boundary to
// S[k+1] pending, so control periods down to 100 cycles (1 us) leave margin.
`default_nettype none

module mpdtc_seq (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        run_i,            // may drive: see header
    input  wire        sample_i,         // averaged ADC sample strobe (boundary)
    input  wire        auto_i,           // MPDTC_CTRL.AUTO: start_i = front end
    input  wire        start_i,          // inputs ready: MPDTC_START write or front end
    input  wire        core_ready_i,
    input  wire        core_valid_i,
    input  wire [ 2:0] core_s_i,         // S[k+1], valid with core_valid_i
    input  wire [ 2:0] align_vec_i,      // bits SaSbSc
    input  wire [15:0] align_period_i,   // chopper period, cycles (>= 2)
    input  wire [15:0] align_on_i,       // vector cycles per chopper period
    input  wire [31:0] align_time_i,     // INITIAL duration, cycles
    input  wire [15:0] enc_pos_i,
    output wire        core_start_o,     // in_valid of mpdtc_core
    output wire        core_clr_o,       // st_load of mpdtc_core (zero state)
    output wire        drive_o,          // gate-driver enable from the sequence
    output wire [ 2:0] s_o,              // requested switching state
    output wire [ 2:0] state_o,
    output wire        sampled_o,
    output wire        aligned_o,
    output wire [ 7:0] overruns_o,
    output wire [15:0] periods_o,
    output wire [15:0] align_pos_o
);
    localparam [2:0] IDLE = 3'd0;
    localparam [2:0] INITIAL = 3'd1;
    localparam [2:0] SAMPLE = 3'd2;
    localparam [2:0] MPDTC = 3'd3;
    localparam [2:0] PWM = 3'd4;

    reg [ 2:0] state_q;
    reg [31:0] tmr_q;
    reg [15:0] chop_q;
    reg        sampled_q;
    reg        aligned_q;
    reg [ 2:0] s_pend_q;
    reg [ 2:0] s_apply_q;
    reg [ 7:0] overruns_q;
    reg [15:0] periods_q;
    reg [15:0] align_pos_q;

    // Alignment chopper: vector on for min(ON, floor(P / 2)) cycles of P.
    wire [15:0] half = {1'b0, align_period_i[15:1]};
    wire        align_on = (state_q == INITIAL) && (chop_q < align_on_i) && (chop_q < half);
    wire        chop_wrap = chop_q + 16'd1 >= align_period_i;
    wire        align_done = (tmr_q + 32'd1 >= align_time_i) && core_ready_i;
    wire        go = (state_q == SAMPLE) && sampled_q && start_i && core_ready_i;

    always @(posedge clk_i) begin
        if (rst_i) begin
            state_q     <= IDLE;
            tmr_q       <= 32'd0;
            chop_q      <= 16'd0;
            sampled_q   <= 1'b0;
            aligned_q   <= 1'b0;
            s_pend_q    <= 3'd0;
            s_apply_q   <= 3'd0;
            overruns_q  <= 8'd0;
            periods_q   <= 16'd0;
            align_pos_q <= 16'd0;
        end else if (!run_i) begin
            state_q   <= IDLE;
            sampled_q <= 1'b0;
        end else begin
            case (state_q)
                IDLE: begin
                    state_q   <= INITIAL;
                    tmr_q     <= 32'd0;
                    chop_q    <= 16'd0;
                    aligned_q <= 1'b0;
                end
                INITIAL: begin
                    tmr_q  <= tmr_q + 32'd1;
                    chop_q <= chop_wrap ? 16'd0 : chop_q + 16'd1;
                    if (align_done) begin
                        state_q     <= SAMPLE;
                        aligned_q   <= 1'b1;
                        align_pos_q <= enc_pos_i;
                        s_apply_q   <= 3'd0;
                        sampled_q   <= 1'b0;
                    end
                end
                SAMPLE: begin
                    if (sample_i) begin
                        sampled_q <= 1'b1;
                        if (sampled_q) overruns_q <= overruns_q + 8'd1;
                    end
                    if (go) begin
                        state_q   <= MPDTC;
                        sampled_q <= 1'b0;
                    end
                end
                MPDTC: begin
                    if (sample_i) overruns_q <= overruns_q + 8'd1;
                    if (core_valid_i) begin
                        state_q  <= PWM;
                        s_pend_q <= core_s_i;
                    end
                end
                PWM: begin
                    if (sample_i) begin
                        state_q   <= SAMPLE;
                        s_apply_q <= s_pend_q;
                        sampled_q <= 1'b1;
                        periods_q <= periods_q + 16'd1;
                    end
                end
                default: state_q <= IDLE;
            endcase
        end
    end

    assign core_start_o = (state_q == IDLE) ? (start_i && !auto_i) : go;
    assign core_clr_o   = state_q == INITIAL;
    assign drive_o      = run_i && (state_q != IDLE);
    assign s_o          = (state_q == INITIAL) ? (align_on ? align_vec_i : 3'd0) : s_apply_q;
    assign state_o      = state_q;
    assign sampled_o    = sampled_q;
    assign aligned_o    = aligned_q;
    assign overruns_o   = overruns_q;
    assign periods_o    = periods_q;
    assign align_pos_o  = align_pos_q;

`ifdef FORMAL
    // All-zero power-up state = reset state (IDLE), so no reset assumption.
    reg f_past_valid = 1'b0;
    always @(posedge clk_i) f_past_valid <= 1'b1;

    // Length of the current run of cycles with the alignment vector
    // requested, up to and including the previous cycle (independent monitor).
    reg [15:0] f_run_q = 16'd0;
    always @(posedge clk_i) begin
        if (align_on) f_run_q <= f_run_q + 16'd1;
        else f_run_q <= 16'd0;
    end

    always @(*) begin
        // Only the five states are ever reached.
        assert (state_q <= PWM);
        // No gates without run_i, none in IDLE.
        if (!run_i || state_q == IDLE) assert (!drive_o);
        // Alignment: the vector only in the first half of the chopper period
        // (so at least ceil(P / 2) zero-vector cycles in every period) ...
        if (align_on) assert (chop_q < half);
        // ... and no vector pulse longer than 32767 cycles whatever the
        // registers do (a run only grows while chop_q counts up).
        if (state_q == INITIAL) assert (f_run_q <= chop_q);
        assert (f_run_q <= 16'd32767);
        // Outside INITIAL, the requested state is the applied S.
        if (state_q != INITIAL) assert (s_o == s_apply_q);
        // The core is started by the sequence only from SAMPLE with the
        // period's sample and a ready core.
        if (state_q != IDLE && core_start_o) assert (state_q == SAMPLE && sampled_q && core_ready_i);
        // In the autonomous loop nothing starts the core in IDLE.
        if (auto_i && state_q == IDLE) assert (!core_start_o);
        // The core's state is cleared only during the alignment.
        assert (core_clr_o == (state_q == INITIAL));
    end

    always @(posedge clk_i) begin
        if (f_past_valid && !$past(rst_i)) begin
            // Mode change, GATE_EN = 0 or a fault (run_i low): IDLE next clock.
            if ($past(!run_i)) assert (state_q == IDLE);
            // Legal transitions only: IDLE -> INITIAL -> SAMPLE -> MPDTC ->
            // PWM -> SAMPLE, any -> IDLE.
            if (state_q != $past(state_q) && state_q != IDLE) begin
                assert (($past(state_q) == IDLE && state_q == INITIAL)
                     || ($past(state_q) == INITIAL && state_q == SAMPLE)
                     || ($past(state_q) == SAMPLE && state_q == MPDTC)
                     || ($past(state_q) == MPDTC && state_q == PWM)
                     || ($past(state_q) == PWM && state_q == SAMPLE));
            end
            // INITIAL ends only after ALIGN_TIME cycles (timer) ...
            if ($past(state_q) == INITIAL && state_q == SAMPLE)
                assert ($past(tmr_q) + 32'd1 >= $past(align_time_i));
            // ... and MPDTC only on the core's result.
            if ($past(state_q) == MPDTC && state_q == PWM) assert ($past(core_valid_i));
            // S[k+1] is applied only at the control-period boundary.
            if ($past(state_q) != IDLE && $past(state_q) != INITIAL && s_apply_q != $past(s_apply_q))
                assert ($past(state_q) == PWM && $past(sample_i));
        end
    end
`endif
endmodule

`default_nettype wire
