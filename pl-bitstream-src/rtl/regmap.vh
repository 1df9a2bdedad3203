// Generated from firmware/drive/src/regmap.rs by `cargo run -p rtl-sim --bin
// regmap-gen`; do not edit (a test fails when this file is stale).
// Included inside module bodies. RM_<REG>_ADDR: byte address in the
// 15-bit AXI window (page << 12 | offset); _W: implemented bits;
// _RESET; _MIN/_MAX: clamp or reject bounds; _<FIELD>_LSB/_W: fields.
localparam integer RM_AXI_ADDR_W = 15;
localparam [31:0] RM_MODE_OFF = 32'd0;
localparam [31:0] RM_MODE_FOC_PWM = 32'd1;
localparam [31:0] RM_MODE_MPDTC = 32'd2;

// Block 0 TOP: Identification, mode, status, heartbeat.
localparam [2:0] RM_BLK_TOP = 3'd0;
localparam [14:0] RM_ID_ADDR = 15'h0000;
localparam integer RM_ID_W = 32;
localparam [31:0] RM_ID_RESET = 32'h50534452;
localparam [14:0] RM_VERSION_ADDR = 15'h0004;
localparam integer RM_VERSION_W = 32;
localparam [31:0] RM_VERSION_RESET = 32'h00010000;
localparam integer RM_VERSION_MINOR_LSB = 0;
localparam integer RM_VERSION_MINOR_W = 16;
localparam integer RM_VERSION_MAJOR_LSB = 16;
localparam integer RM_VERSION_MAJOR_W = 16;
localparam [14:0] RM_CTRL_ADDR = 15'h0008;
localparam integer RM_CTRL_W = 2;
localparam [31:0] RM_CTRL_RESET = 32'h00000000;
localparam [31:0] RM_CTRL_MAX = 32'h00000002;
localparam integer RM_CTRL_MODE_LSB = 0;
localparam integer RM_CTRL_MODE_W = 2;
localparam [14:0] RM_STATUS_ADDR = 15'h000c;
localparam integer RM_STATUS_W = 4;
localparam [31:0] RM_STATUS_RESET = 32'h00000000;
localparam integer RM_STATUS_MODE_LSB = 0;
localparam integer RM_STATUS_MODE_W = 2;
localparam integer RM_STATUS_GATES_ACTIVE_LSB = 2;
localparam integer RM_STATUS_GATES_ACTIVE_W = 1;
localparam integer RM_STATUS_FAULT_LSB = 3;
localparam integer RM_STATUS_FAULT_W = 1;
localparam [14:0] RM_ERR_ADDR = 15'h0010;
localparam integer RM_ERR_W = 2;
localparam [31:0] RM_ERR_RESET = 32'h00000000;
localparam integer RM_ERR_BAD_VALUE_LSB = 0;
localparam integer RM_ERR_BAD_VALUE_W = 1;
localparam integer RM_ERR_BAD_ADDR_LSB = 1;
localparam integer RM_ERR_BAD_ADDR_W = 1;
localparam [14:0] RM_HEARTBEAT_ADDR = 15'h0014;
localparam integer RM_HEARTBEAT_W = 32;
localparam [31:0] RM_HEARTBEAT_RESET = 32'h00000000;
localparam [14:0] RM_SCRATCH_ADDR = 15'h0018;
localparam integer RM_SCRATCH_W = 32;
localparam [31:0] RM_SCRATCH_RESET = 32'h00000000;

// Block 1 MPDTC: Reserved for mpdtc_core (not implemented yet): every access is SLVERR.
localparam [2:0] RM_BLK_MPDTC = 3'd1;

// Block 2 MPDCC: Reserved for the MPDCC core (not implemented yet): every access is SLVERR.
localparam [2:0] RM_BLK_MPDCC = 3'd2;

// Block 3 PWM: Gate enable, dead time, centre-aligned PWM, switching state.
localparam [2:0] RM_BLK_PWM = 3'd3;
localparam [14:0] RM_GATE_CTRL_ADDR = 15'h3000;
localparam integer RM_GATE_CTRL_W = 1;
localparam [31:0] RM_GATE_CTRL_RESET = 32'h00000000;
localparam integer RM_GATE_CTRL_GATE_EN_LSB = 0;
localparam integer RM_GATE_CTRL_GATE_EN_W = 1;
localparam [14:0] RM_DEAD_TIME_ADDR = 15'h3004;
localparam integer RM_DEAD_TIME_W = 10;
localparam [31:0] RM_DEAD_TIME_RESET = 32'h00000032;
localparam [31:0] RM_DEAD_TIME_MIN = 32'h00000000;
localparam [31:0] RM_DEAD_TIME_MAX = 32'h000003ff;
localparam [14:0] RM_PWM_PERIOD_ADDR = 15'h3008;
localparam integer RM_PWM_PERIOD_W = 16;
localparam [31:0] RM_PWM_PERIOD_RESET = 32'h000009c4;
localparam [31:0] RM_PWM_PERIOD_MIN = 32'h00000002;
localparam [31:0] RM_PWM_PERIOD_MAX = 32'h0000ffff;
localparam [14:0] RM_DUTY_A_ADDR = 15'h300c;
localparam integer RM_DUTY_A_W = 16;
localparam [31:0] RM_DUTY_A_RESET = 32'h000004e2;
localparam [14:0] RM_DUTY_B_ADDR = 15'h3010;
localparam integer RM_DUTY_B_W = 16;
localparam [31:0] RM_DUTY_B_RESET = 32'h000004e2;
localparam [14:0] RM_DUTY_C_ADDR = 15'h3014;
localparam integer RM_DUTY_C_W = 16;
localparam [31:0] RM_DUTY_C_RESET = 32'h000004e2;
localparam [14:0] RM_SW_STATE_ADDR = 15'h3018;
localparam integer RM_SW_STATE_W = 3;
localparam [31:0] RM_SW_STATE_RESET = 32'h00000000;
localparam [14:0] RM_GATE_STATUS_ADDR = 15'h301c;
localparam integer RM_GATE_STATUS_W = 9;
localparam [31:0] RM_GATE_STATUS_RESET = 32'h00000000;
localparam integer RM_GATE_STATUS_HI_LSB = 0;
localparam integer RM_GATE_STATUS_HI_W = 3;
localparam integer RM_GATE_STATUS_LO_LSB = 3;
localparam integer RM_GATE_STATUS_LO_W = 3;
localparam integer RM_GATE_STATUS_STATE_LSB = 6;
localparam integer RM_GATE_STATUS_STATE_W = 3;
localparam [14:0] RM_PWM_COUNT_ADDR = 15'h3020;
localparam integer RM_PWM_COUNT_W = 17;
localparam [31:0] RM_PWM_COUNT_RESET = 32'h00000000;
localparam integer RM_PWM_COUNT_COUNT_LSB = 0;
localparam integer RM_PWM_COUNT_COUNT_W = 16;
localparam integer RM_PWM_COUNT_DOWN_LSB = 16;
localparam integer RM_PWM_COUNT_DOWN_W = 1;

// Block 4 ADC: ADC front end: 3 phase currents, sampled every ADC_PERIOD, averaged by 4.
localparam [2:0] RM_BLK_ADC = 3'd4;
localparam [14:0] RM_ADC_CTRL_ADDR = 15'h4000;
localparam integer RM_ADC_CTRL_W = 1;
localparam [31:0] RM_ADC_CTRL_RESET = 32'h00000001;
localparam integer RM_ADC_CTRL_ENABLE_LSB = 0;
localparam integer RM_ADC_CTRL_ENABLE_W = 1;
localparam [14:0] RM_ADC_PERIOD_ADDR = 15'h4004;
localparam integer RM_ADC_PERIOD_W = 16;
localparam [31:0] RM_ADC_PERIOD_RESET = 32'h00000187;
localparam [31:0] RM_ADC_PERIOD_MIN = 32'h00000010;
localparam [31:0] RM_ADC_PERIOD_MAX = 32'h0000ffff;
localparam [14:0] RM_ADC_IA_ADDR = 15'h4008;
localparam integer RM_ADC_IA_W = 16;
localparam [31:0] RM_ADC_IA_RESET = 32'h00000000;
localparam [14:0] RM_ADC_IB_ADDR = 15'h400c;
localparam integer RM_ADC_IB_W = 16;
localparam [31:0] RM_ADC_IB_RESET = 32'h00000000;
localparam [14:0] RM_ADC_IC_ADDR = 15'h4010;
localparam integer RM_ADC_IC_W = 16;
localparam [31:0] RM_ADC_IC_RESET = 32'h00000000;
localparam [14:0] RM_ADC_COUNT_ADDR = 15'h4014;
localparam integer RM_ADC_COUNT_W = 32;
localparam [31:0] RM_ADC_COUNT_RESET = 32'h00000000;

// Block 5 ENC: Incremental encoder (A/B quadrature + index).
localparam [2:0] RM_BLK_ENC = 3'd5;
localparam [14:0] RM_ENC_CPR_ADDR = 15'h5000;
localparam integer RM_ENC_CPR_W = 16;
localparam [31:0] RM_ENC_CPR_RESET = 32'h00001000;
localparam [31:0] RM_ENC_CPR_MIN = 32'h00000004;
localparam [31:0] RM_ENC_CPR_MAX = 32'h0000ffff;
localparam [14:0] RM_ENC_POS_ADDR = 15'h5004;
localparam integer RM_ENC_POS_W = 16;
localparam [31:0] RM_ENC_POS_RESET = 32'h00000000;
localparam [14:0] RM_ENC_SPEED_ADDR = 15'h5008;
localparam integer RM_ENC_SPEED_W = 16;
localparam [31:0] RM_ENC_SPEED_RESET = 32'h00000000;
localparam [14:0] RM_ENC_WINDOW_ADDR = 15'h500c;
localparam integer RM_ENC_WINDOW_W = 24;
localparam [31:0] RM_ENC_WINDOW_RESET = 32'h000186a0;
localparam [31:0] RM_ENC_WINDOW_MIN = 32'h00000064;
localparam [31:0] RM_ENC_WINDOW_MAX = 32'h00ffffff;
localparam [14:0] RM_ENC_INDEX_ADDR = 15'h5010;
localparam integer RM_ENC_INDEX_W = 16;
localparam [31:0] RM_ENC_INDEX_RESET = 32'h00000000;

// Block 6 FAULT: Over-current, external and watchdog faults, latched.
localparam [2:0] RM_BLK_FAULT = 3'd6;
localparam [14:0] RM_FAULT_STATUS_ADDR = 15'h6000;
localparam integer RM_FAULT_STATUS_W = 3;
localparam [31:0] RM_FAULT_STATUS_RESET = 32'h00000000;
localparam integer RM_FAULT_STATUS_OVERCURRENT_LSB = 0;
localparam integer RM_FAULT_STATUS_OVERCURRENT_W = 1;
localparam integer RM_FAULT_STATUS_EXTERNAL_LSB = 1;
localparam integer RM_FAULT_STATUS_EXTERNAL_W = 1;
localparam integer RM_FAULT_STATUS_WATCHDOG_LSB = 2;
localparam integer RM_FAULT_STATUS_WATCHDOG_W = 1;
localparam [14:0] RM_FAULT_RAW_ADDR = 15'h6004;
localparam integer RM_FAULT_RAW_W = 3;
localparam [31:0] RM_FAULT_RAW_RESET = 32'h00000000;
localparam [14:0] RM_OC_LIMIT_ADDR = 15'h6008;
localparam integer RM_OC_LIMIT_W = 11;
localparam [31:0] RM_OC_LIMIT_RESET = 32'h00000708;
localparam [31:0] RM_OC_LIMIT_MIN = 32'h00000000;
localparam [31:0] RM_OC_LIMIT_MAX = 32'h000007ff;
localparam [14:0] RM_WDG_TIMEOUT_ADDR = 15'h600c;
localparam integer RM_WDG_TIMEOUT_W = 32;
localparam [31:0] RM_WDG_TIMEOUT_RESET = 32'h00989680;
localparam [31:0] RM_WDG_TIMEOUT_MIN = 32'h000003e8;
localparam [31:0] RM_WDG_TIMEOUT_MAX = 32'hffffffff;

// Block 7 CAPTURE: Reserved for the capture buffer (not implemented yet): every access is SLVERR.
localparam [2:0] RM_BLK_CAPTURE = 3'd7;
