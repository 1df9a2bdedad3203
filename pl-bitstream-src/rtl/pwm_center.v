// pwm_center: centre-aligned (symmetric) PWM comparators for 3 legs.
//
// An up-down counter runs 0, 1, .., P-1, P-1, .., 1, 0, 0, 1, .. (every
// value twice per period, so one PWM period is exactly 2 P clock cycles,
// f_pwm = f_clk / (2 P), P = PWM_PERIOD >= 2, 16 bits). Leg x's upper
// switch is requested (s_o[x] = 1) while count < duty_x: on-time = 2 duty_x
// cycles per period, i.e. duty_x / P; duty_x >= P gives 100 %, 0 gives 0 %.
// Period and duties are loaded from the registers at the start of each
// period (the bottom, when the counter leaves 0 upwards), so a period never
// mixes old and new values. s_o is combinational from registers; the gate
// driver registers it. Bit order: s_o[2] = leg a (state index 4 Sa+2 Sb+Sc).
`default_nettype none

module pwm_center (
    input  wire        clk_i,
    input  wire        rst_i,
    input  wire [15:0] period_i,
    input  wire [15:0] duty_a_i,
    input  wire [15:0] duty_b_i,
    input  wire [15:0] duty_c_i,
    output wire [ 2:0] s_o,
    output wire [15:0] count_o,
    output wire        down_o
);
    reg [15:0] cnt_q;
    reg        down_q;
    reg [15:0] period_q;
    reg [15:0] duty_a_q;
    reg [15:0] duty_b_q;
    reg [15:0] duty_c_q;

    // Start of a period: the last cycle of the down ramp (count 0).
    wire bottom = down_q && (cnt_q == 16'd0);
    wire top = !down_q && (cnt_q + 16'd1 >= period_q);

    always @(posedge clk_i) begin
        if (rst_i) begin
            cnt_q    <= 16'd0;
            down_q   <= 1'b1;  // so that the registers load at once
            period_q <= 16'd2;
            duty_a_q <= 16'd0;
            duty_b_q <= 16'd0;
            duty_c_q <= 16'd0;
        end else if (bottom) begin
            down_q   <= 1'b0;
            period_q <= period_i;
            duty_a_q <= duty_a_i;
            duty_b_q <= duty_b_i;
            duty_c_q <= duty_c_i;
        end else if (top) begin
            down_q <= 1'b1;
        end else if (down_q) begin
            cnt_q <= cnt_q - 16'd1;
        end else begin
            cnt_q <= cnt_q + 16'd1;
        end
    end

    assign s_o     = {cnt_q < duty_a_q, cnt_q < duty_b_q, cnt_q < duty_c_q};
    assign count_o = cnt_q;
    assign down_o  = down_q;
endmodule

`default_nettype wire
