// adc_frontend: ADC front end for the three phase currents.
//
// Converter interface (asynchronous: no clock leaves the PL for the
// converter; timing in docs/rtl.md, "ADC interface"): a simultaneous-
// sampling, 3-channel converter with a parallel output bus.
//   adc_cnv_o    one-cycle (10 ns) convert-start pulse, every period_i cycles
//                while en_i = 1 (sample rate f_clk / period_i; reset 391
//                cycles = 255.75 kHz, the paper's 256 kHz within 0.1 %)
//   adc_drdy_i   data ready, asynchronous to clk_i: a rising edge per result,
//                high >= 15 ns and low >= 15 ns (one clock period plus
//                margin, so the synchroniser sees every level). It passes a
//                two-flop synchroniser (sync2) and an edge detector: one
//                sample per rising edge, however long the level lasts
//   adc_data_i   {ia, ib, ic}, 12-bit two's complement each, ia in [35:24],
//                not synchronised: valid at the pins from the rising edge of
//                adc_drdy_i (setup >= 0 ns) until >= 50 ns after it; it is
//                captured at the edge after the synchronised rise (2 to 3
//                clock periods after the pin's edge, 4 with a metastable first
//                flop), so it has settled for >= 10 ns through a data path of
//                at most 10 ns (the board's set_max_delay)
// Latency: the sample register loads 3 clock edges after the first edge
// that sees adc_drdy_i high (sync2: 2, edge detection and capture: 1).
// A level held high through reset is not a new result (the synchroniser and
// the edge register reset to 1). A missing converter card reads as drdy = 0
// (pull-downs on the board): no samples, ADC_COUNT stops, the firmware's
// ADC-stuck check trips.
// Outputs
//   sample_*     the raw sample, with the one-cycle strobe sample_valid_o
//                (to the fault block: over-current is judged on every raw
//                sample)
//   avg_*        floor((s0 + .. + s(n-1)) / n) of n = 2^avg_log2_i
//                consecutive samples (n = 1, 2 or 4: arithmetic shift of the
//                14-bit sum), sign-extended to 16 bits, updated with the
//                strobe avg_valid_o at f_s / n. A smaller n takes effect at
//                once (a sum already past it ends with the next sample)
//   avg_count_o  number of averages since reset (wraps)
`default_nettype none

module adc_frontend (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire        en_i,
    input  wire [15:0] period_i,
    input  wire [ 1:0] avg_log2_i,       // 0, 1, 2 (the register rejects 3)
    output wire        adc_cnv_o,
    input  wire        adc_drdy_i,
    input  wire [35:0] adc_data_i,
    output wire        sample_valid_o,
    output wire [11:0] sample_ia_o,
    output wire [11:0] sample_ib_o,
    output wire [11:0] sample_ic_o,
    output wire        avg_valid_o,
    output wire [15:0] avg_ia_o,
    output wire [15:0] avg_ib_o,
    output wire [15:0] avg_ic_o,
    output wire [31:0] avg_count_o
);
    reg [15:0] tmr_q;
    reg        cnv_q;
    reg        sv_q;
    reg [11:0] s_a_q, s_b_q, s_c_q;
    reg [13:0] acc_a_q, acc_b_q, acc_c_q;
    reg [ 1:0] n_q;
    reg        av_q;
    reg [11:0] avg_a_q, avg_b_q, avg_c_q;
    reg [31:0] count_q;
    reg        drdy_prev_q;
    wire       drdy_s;

    sync2 #(
        .RESET_VAL(1'b1)
    ) u_drdy_sync (
        .clk_i(clk_i),
        .rst_i(rst_i),
        .d_i  (adc_drdy_i),
        .q_o  (drdy_s)
    );
    // Rising edge of the synchronised data-ready: one result.
    wire drdy_rise = drdy_s && !drdy_prev_q;

    // Index of the last sample of an average: n - 1.
    wire [ 1:0] last = (avg_log2_i == 2'd0) ? 2'd0 : (avg_log2_i == 2'd1) ? 2'd1 : 2'd3;
    // 14-bit sums including the current sample (sign-extended).
    wire [13:0] sum_a = acc_a_q + {{2{s_a_q[11]}}, s_a_q};
    wire [13:0] sum_b = acc_b_q + {{2{s_b_q[11]}}, s_b_q};
    wire [13:0] sum_c = acc_c_q + {{2{s_c_q[11]}}, s_c_q};

    // floor(sum / n): the 12 bits above the shift (the rest is the sign).
    function automatic [11:0] avg_of(input [13:0] sum);
        case (avg_log2_i)
            2'd0: avg_of = sum[11:0];
            2'd1: avg_of = sum[12:1];
            default: avg_of = sum[13:2];
        endcase
    endfunction

    always @(posedge clk_i) begin
        if (rst_i) begin
            tmr_q       <= 16'd0;
            cnv_q       <= 1'b0;
            sv_q        <= 1'b0;
            drdy_prev_q <= 1'b1;
            n_q         <= 2'd0;
            av_q        <= 1'b0;
            acc_a_q     <= 14'd0;
            acc_b_q     <= 14'd0;
            acc_c_q     <= 14'd0;
            avg_a_q     <= 12'd0;
            avg_b_q     <= 12'd0;
            avg_c_q     <= 12'd0;
            count_q     <= 32'd0;
        end else begin
            // Sample-rate timer.
            cnv_q <= 1'b0;
            if (!en_i) begin
                tmr_q <= 16'd0;
            end else if (tmr_q == 16'd0) begin
                tmr_q <= period_i - 16'd1;
                cnv_q <= 1'b1;
            end else begin
                tmr_q <= tmr_q - 16'd1;
            end
            // Capture.
            drdy_prev_q <= drdy_s;
            sv_q        <= drdy_rise;
            // Average of n = 2^avg_log2_i.
            av_q <= 1'b0;
            if (sv_q) begin
                if (n_q >= last) begin
                    avg_a_q <= avg_of(sum_a);
                    avg_b_q <= avg_of(sum_b);
                    avg_c_q <= avg_of(sum_c);
                    acc_a_q <= 14'd0;
                    acc_b_q <= 14'd0;
                    acc_c_q <= 14'd0;
                    av_q    <= 1'b1;
                    count_q <= count_q + 32'd1;
                    n_q     <= 2'd0;
                end else begin
                    acc_a_q <= sum_a;
                    acc_b_q <= sum_b;
                    acc_c_q <= sum_c;
                    n_q     <= n_q + 2'd1;
                end
            end
        end
    end

    // Sample payload: no reset (datapath).
    always @(posedge clk_i) begin
        if (drdy_rise) begin
            s_a_q <= adc_data_i[35:24];
            s_b_q <= adc_data_i[23:12];
            s_c_q <= adc_data_i[11:0];
        end
    end

    assign adc_cnv_o      = cnv_q;
    assign sample_valid_o = sv_q;
    assign sample_ia_o    = s_a_q;
    assign sample_ib_o    = s_b_q;
    assign sample_ic_o    = s_c_q;
    assign avg_valid_o    = av_q;
    assign avg_ia_o       = {{4{avg_a_q[11]}}, avg_a_q};
    assign avg_ib_o       = {{4{avg_b_q[11]}}, avg_b_q};
    assign avg_ic_o       = {{4{avg_c_q[11]}}, avg_c_q};
    assign avg_count_o    = count_q;
`ifdef FORMAL
    // History of the pins and of reset at the last four clock edges ([0]:
    // the latest), and the data pins at the last edge.
    reg        f_past_valid = 1'b0;
    reg [ 3:0] f_pin_q = 4'd0;
    reg [ 3:0] f_rst_q = 4'd0;
    reg [35:0] f_data_q = 36'd0;
    reg        f_sv_q = 1'b0;
    always @(posedge clk_i) begin
        f_past_valid <= 1'b1;
        f_pin_q      <= {f_pin_q[2:0], adc_drdy_i};
        f_rst_q      <= {f_rst_q[2:0], rst_i};
        f_data_q     <= adc_data_i;
        f_sv_q       <= sv_q;
    end
    always @(*) begin
        if (!f_past_valid) assume (rst_i);
        if (f_past_valid) begin
            // Exactly one sample per rising edge of the data-ready pin, however
            // long it stays high, three edges after the first edge that sees
            // it high (two synchroniser flops, then the capture).
            if (f_rst_q == 4'd0) assert (sv_q == (f_pin_q[2] && !f_pin_q[3]));
            if (f_rst_q[0]) assert (!sv_q);
            // The sample is the data at the pins at the capture edge.
            if (sv_q) assert ({s_a_q, s_b_q, s_c_q} == f_data_q);
            // An average ends only with a sample.
            if (av_q) assert (f_sv_q);
        end
    end
`endif
endmodule

`default_nettype wire
