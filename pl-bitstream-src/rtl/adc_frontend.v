// adc_frontend: ADC front end for the three phase currents.
//
// Modelled ADC interface (documented in docs/rtl.md): a simultaneous-
// sampling, 3-channel converter with a parallel, PL-synchronous bus.
//   adc_cnv_o    one-cycle convert-start pulse, every period_i cycles while
//                en_i = 1 (sample rate f_clk / period_i; reset 391 cycles =
//                255.75 kHz, the paper's 256 kHz within 0.1 %)
//   adc_drdy_i   one-cycle strobe from the converter when a result is ready
//                (its conversion time must be shorter than period_i)
//   adc_data_i   {ia, ib, ic}, 12-bit two's complement each, ia in [35:24],
//                valid with adc_drdy_i
// Outputs
//   sample_*     the raw sample, registered one cycle after adc_drdy_i,
//                with the one-cycle strobe sample_valid_o (to the fault
//                block: over-current is judged on every raw sample)
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
            tmr_q   <= 16'd0;
            cnv_q   <= 1'b0;
            sv_q    <= 1'b0;
            n_q     <= 2'd0;
            av_q    <= 1'b0;
            acc_a_q <= 14'd0;
            acc_b_q <= 14'd0;
            acc_c_q <= 14'd0;
            avg_a_q <= 12'd0;
            avg_b_q <= 12'd0;
            avg_c_q <= 12'd0;
            count_q <= 32'd0;
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
            sv_q <= adc_drdy_i;
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
        if (adc_drdy_i) begin
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
endmodule

`default_nettype wire
