// Read-only simulation models of the xc7 block RAMs RAMB36E1 and RAMB18E1
// for the gate-level checks (scripts/rtl-gatesim): the cell library of
// Yosys (share/xilinx/cells_sim.v) declares these two primitives with
// their ports, parameters and timing only, no behaviour, so a netlist that
// maps a ROM (the sine table of mpdtc_frontend) to block RAM would read
// zeros. Written from the behaviour described in Xilinx UG473 (7 Series
// FPGAs Memory Resources): true dual-port mode, each port reads the word
// its address selects at the clock edge when enabled (SRVAL on RSTRAM),
// optionally through the output register (DO*_REG = 1, REGCE, RSTREG);
// the contents are the INIT_xx (data, bit 0 first) and INITP_xx (parity)
// parameters; a word of READ_WIDTH 36/18/9 is 32/16/8 data bits at
// DO*DO plus 4/2/1 parity bits at DOP*DOP, a narrower one data bits only;
// the word address is ADDR[14:log2(data bits)] (RAMB36E1) or
// ADDR[13:log2(data bits)] (RAMB18E1).
// Only what a ROM needs: a write (any WE bit with the port enabled),
// simple dual-port mode (RAM_MODE "SDP", width 72/36), cascading, ECC and
// inverted pins are rejected at run time ($fatal), so a netlist that uses
// them fails loudly instead of simulating wrongly.
`default_nettype none

// One read port of a ROM of DBITS data and PBITS parity bits.
module xc7_bram_rom_port #(
    parameter integer DBITS = 32768,
    parameter integer PBITS = 4096,
    parameter integer ABITS = 15,   // address bits (bit index of a 1-bit word)
    parameter integer WIDTH = 36,   // READ_WIDTH: 0 (port unused), 1, 2, 4, 9, 18, 36
    parameter integer DO_REG = 0,
    parameter [DBITS-1:0] DATA = 0,
    parameter [PBITS-1:0] PAR = 0,
    parameter [35:0] INIT = 36'h0,
    parameter [35:0] SRVAL = 36'h0
) (
    input  wire             clk,
    input  wire             en,
    input  wire             rst_ram,
    input  wire             rst_reg,
    input  wire             regce,
    input  wire [ABITS-1:0] addr,
    input  wire             we_any,
    output wire [31:0]      dout,
    output wire [3:0]       dpout
);
    // data bits per word and parity bits per word
    localparam integer DW = (WIDTH == 36) ? 32 : (WIDTH == 18) ? 16 : (WIDTH == 9) ? 8 : WIDTH;
    localparam integer PW = (WIDTH == 36) ? 4 : (WIDTH == 18) ? 2 : (WIDTH == 9) ? 1 : 0;
    localparam integer LSB = (DW >= 32) ? 5 : (DW >= 16) ? 4 : (DW >= 8) ? 3 : (DW >= 4) ? 2 : (DW >= 2) ? 1 : 0;
    localparam integer WORDS = (DW == 0) ? 1 : DBITS / DW;
    reg [35:0] lat_q = INIT;  // {parity, data} of the last read
    reg [35:0] reg_q = INIT;  // the output register
    wire [ABITS-1:0] word = addr >> LSB;
    reg [35:0] rd;
    integer i;
    always @(*) begin
        rd = 36'h0;
        for (i = 0; i < 32; i = i + 1)
            if (i < DW && word < WORDS) rd[i] = DATA[word * DW + i];
        for (i = 0; i < 4; i = i + 1)
            if (i < PW && word < WORDS) rd[32 + i] = PAR[word * PW + i];
    end
    always @(posedge clk) begin
        if (en && we_any) $fatal(1, "xc7_bram_rom: a write to a block RAM (only ROMs are modelled)");
        if (en) lat_q <= rst_ram ? SRVAL : rd;
        if (DO_REG != 0 && regce) reg_q <= rst_reg ? SRVAL : lat_q;
    end
    wire [35:0] q = (DO_REG != 0) ? reg_q : lat_q;
    // {parity, data} of a SRVAL/INIT word sit as in the primitive: data in
    // the low DW bits, parity above them
    assign dout = q[31:0];
    assign dpout = q[35:32];
    initial begin
        if (!(WIDTH == 0 || WIDTH == 1 || WIDTH == 2 || WIDTH == 4 || WIDTH == 9 || WIDTH == 18 || WIDTH == 36))
            $fatal(1, "xc7_bram_rom: READ_WIDTH %0d not modelled", WIDTH);
        if (DO_REG != 0 && DO_REG != 1) $fatal(1, "xc7_bram_rom: DO_REG %0d", DO_REG);
    end
endmodule

// RAMB36E1: 32 Kb data + 4 Kb parity, read-only (see above).
module RAMB36E1 #(
    parameter [255:0] INIT_00 = 256'h0, INIT_01 = 256'h0, INIT_02 = 256'h0, INIT_03 = 256'h0,
    parameter [255:0] INIT_04 = 256'h0, INIT_05 = 256'h0, INIT_06 = 256'h0, INIT_07 = 256'h0,
    parameter [255:0] INIT_08 = 256'h0, INIT_09 = 256'h0, INIT_0A = 256'h0, INIT_0B = 256'h0,
    parameter [255:0] INIT_0C = 256'h0, INIT_0D = 256'h0, INIT_0E = 256'h0, INIT_0F = 256'h0,
    parameter [255:0] INIT_10 = 256'h0, INIT_11 = 256'h0, INIT_12 = 256'h0, INIT_13 = 256'h0,
    parameter [255:0] INIT_14 = 256'h0, INIT_15 = 256'h0, INIT_16 = 256'h0, INIT_17 = 256'h0,
    parameter [255:0] INIT_18 = 256'h0, INIT_19 = 256'h0, INIT_1A = 256'h0, INIT_1B = 256'h0,
    parameter [255:0] INIT_1C = 256'h0, INIT_1D = 256'h0, INIT_1E = 256'h0, INIT_1F = 256'h0,
    parameter [255:0] INIT_20 = 256'h0, INIT_21 = 256'h0, INIT_22 = 256'h0, INIT_23 = 256'h0,
    parameter [255:0] INIT_24 = 256'h0, INIT_25 = 256'h0, INIT_26 = 256'h0, INIT_27 = 256'h0,
    parameter [255:0] INIT_28 = 256'h0, INIT_29 = 256'h0, INIT_2A = 256'h0, INIT_2B = 256'h0,
    parameter [255:0] INIT_2C = 256'h0, INIT_2D = 256'h0, INIT_2E = 256'h0, INIT_2F = 256'h0,
    parameter [255:0] INIT_30 = 256'h0, INIT_31 = 256'h0, INIT_32 = 256'h0, INIT_33 = 256'h0,
    parameter [255:0] INIT_34 = 256'h0, INIT_35 = 256'h0, INIT_36 = 256'h0, INIT_37 = 256'h0,
    parameter [255:0] INIT_38 = 256'h0, INIT_39 = 256'h0, INIT_3A = 256'h0, INIT_3B = 256'h0,
    parameter [255:0] INIT_3C = 256'h0, INIT_3D = 256'h0, INIT_3E = 256'h0, INIT_3F = 256'h0,
    parameter [255:0] INIT_40 = 256'h0, INIT_41 = 256'h0, INIT_42 = 256'h0, INIT_43 = 256'h0,
    parameter [255:0] INIT_44 = 256'h0, INIT_45 = 256'h0, INIT_46 = 256'h0, INIT_47 = 256'h0,
    parameter [255:0] INIT_48 = 256'h0, INIT_49 = 256'h0, INIT_4A = 256'h0, INIT_4B = 256'h0,
    parameter [255:0] INIT_4C = 256'h0, INIT_4D = 256'h0, INIT_4E = 256'h0, INIT_4F = 256'h0,
    parameter [255:0] INIT_50 = 256'h0, INIT_51 = 256'h0, INIT_52 = 256'h0, INIT_53 = 256'h0,
    parameter [255:0] INIT_54 = 256'h0, INIT_55 = 256'h0, INIT_56 = 256'h0, INIT_57 = 256'h0,
    parameter [255:0] INIT_58 = 256'h0, INIT_59 = 256'h0, INIT_5A = 256'h0, INIT_5B = 256'h0,
    parameter [255:0] INIT_5C = 256'h0, INIT_5D = 256'h0, INIT_5E = 256'h0, INIT_5F = 256'h0,
    parameter [255:0] INIT_60 = 256'h0, INIT_61 = 256'h0, INIT_62 = 256'h0, INIT_63 = 256'h0,
    parameter [255:0] INIT_64 = 256'h0, INIT_65 = 256'h0, INIT_66 = 256'h0, INIT_67 = 256'h0,
    parameter [255:0] INIT_68 = 256'h0, INIT_69 = 256'h0, INIT_6A = 256'h0, INIT_6B = 256'h0,
    parameter [255:0] INIT_6C = 256'h0, INIT_6D = 256'h0, INIT_6E = 256'h0, INIT_6F = 256'h0,
    parameter [255:0] INIT_70 = 256'h0, INIT_71 = 256'h0, INIT_72 = 256'h0, INIT_73 = 256'h0,
    parameter [255:0] INIT_74 = 256'h0, INIT_75 = 256'h0, INIT_76 = 256'h0, INIT_77 = 256'h0,
    parameter [255:0] INIT_78 = 256'h0, INIT_79 = 256'h0, INIT_7A = 256'h0, INIT_7B = 256'h0,
    parameter [255:0] INIT_7C = 256'h0, INIT_7D = 256'h0, INIT_7E = 256'h0, INIT_7F = 256'h0,
    parameter [255:0] INITP_00 = 256'h0, INITP_01 = 256'h0, INITP_02 = 256'h0, INITP_03 = 256'h0,
    parameter [255:0] INITP_04 = 256'h0, INITP_05 = 256'h0, INITP_06 = 256'h0, INITP_07 = 256'h0,
    parameter [255:0] INITP_08 = 256'h0, INITP_09 = 256'h0, INITP_0A = 256'h0, INITP_0B = 256'h0,
    parameter [255:0] INITP_0C = 256'h0, INITP_0D = 256'h0, INITP_0E = 256'h0, INITP_0F = 256'h0,
    parameter INIT_A = 36'h0,
    parameter INIT_B = 36'h0,
    parameter SRVAL_A = 36'h0,
    parameter SRVAL_B = 36'h0,
    parameter integer DOA_REG = 0,
    parameter integer DOB_REG = 0,
    parameter RAM_MODE = "TDP",
    parameter integer READ_WIDTH_A = 0,
    parameter integer READ_WIDTH_B = 0,
    parameter integer WRITE_WIDTH_A = 0,
    parameter integer WRITE_WIDTH_B = 0,
    parameter WRITE_MODE_A = "WRITE_FIRST",
    parameter WRITE_MODE_B = "WRITE_FIRST",
    parameter RSTREG_PRIORITY_A = "RSTREG",
    parameter RSTREG_PRIORITY_B = "RSTREG",
    parameter RDADDR_COLLISION_HWCONFIG = "DELAYED_WRITE",
    parameter SIM_COLLISION_CHECK = "ALL",
    parameter SIM_DEVICE = "7SERIES",
    parameter INIT_FILE = "NONE",
    parameter EN_ECC_READ = "FALSE",
    parameter EN_ECC_WRITE = "FALSE",
    parameter RAM_EXTENSION_A = "NONE",
    parameter RAM_EXTENSION_B = "NONE",
    parameter [0:0] IS_CLKARDCLK_INVERTED = 1'b0,
    parameter [0:0] IS_CLKBWRCLK_INVERTED = 1'b0,
    parameter [0:0] IS_ENARDEN_INVERTED = 1'b0,
    parameter [0:0] IS_ENBWREN_INVERTED = 1'b0,
    parameter [0:0] IS_RSTRAMARSTRAM_INVERTED = 1'b0,
    parameter [0:0] IS_RSTRAMB_INVERTED = 1'b0,
    parameter [0:0] IS_RSTREGARSTREG_INVERTED = 1'b0,
    parameter [0:0] IS_RSTREGB_INVERTED = 1'b0
) (
    input  wire        CLKARDCLK,
    input  wire        CLKBWRCLK,
    input  wire        ENARDEN,
    input  wire        ENBWREN,
    input  wire        REGCEAREGCE,
    input  wire        REGCEB,
    input  wire        RSTRAMARSTRAM,
    input  wire        RSTRAMB,
    input  wire        RSTREGARSTREG,
    input  wire        RSTREGB,
    input  wire [15:0] ADDRARDADDR,
    input  wire [15:0] ADDRBWRADDR,
    input  wire [31:0] DIADI,
    input  wire [31:0] DIBDI,
    input  wire [3:0]  DIPADIP,
    input  wire [3:0]  DIPBDIP,
    input  wire [3:0]  WEA,
    input  wire [7:0]  WEBWE,
    input  wire        CASCADEINA,
    input  wire        CASCADEINB,
    output wire        CASCADEOUTA,
    output wire        CASCADEOUTB,
    input  wire        INJECTDBITERR,
    input  wire        INJECTSBITERR,
    output wire        DBITERR,
    output wire        SBITERR,
    output wire [7:0]  ECCPARITY,
    output wire [8:0]  RDADDRECC,
    output wire [31:0] DOADO,
    output wire [31:0] DOBDO,
    output wire [3:0]  DOPADOP,
    output wire [3:0]  DOPBDOP
);
    localparam [32767:0] DATA = {INIT_7F, INIT_7E, INIT_7D, INIT_7C, INIT_7B, INIT_7A, INIT_79, INIT_78, INIT_77, INIT_76, INIT_75, INIT_74, INIT_73, INIT_72, INIT_71, INIT_70, INIT_6F, INIT_6E, INIT_6D, INIT_6C, INIT_6B, INIT_6A, INIT_69, INIT_68, INIT_67, INIT_66, INIT_65, INIT_64, INIT_63, INIT_62, INIT_61, INIT_60, INIT_5F, INIT_5E, INIT_5D, INIT_5C, INIT_5B, INIT_5A, INIT_59, INIT_58, INIT_57, INIT_56, INIT_55, INIT_54, INIT_53, INIT_52, INIT_51, INIT_50, INIT_4F, INIT_4E, INIT_4D, INIT_4C, INIT_4B, INIT_4A, INIT_49, INIT_48, INIT_47, INIT_46, INIT_45, INIT_44, INIT_43, INIT_42, INIT_41, INIT_40, INIT_3F, INIT_3E, INIT_3D, INIT_3C, INIT_3B, INIT_3A, INIT_39, INIT_38, INIT_37, INIT_36, INIT_35, INIT_34, INIT_33, INIT_32, INIT_31, INIT_30, INIT_2F, INIT_2E, INIT_2D, INIT_2C, INIT_2B, INIT_2A, INIT_29, INIT_28, INIT_27, INIT_26, INIT_25, INIT_24, INIT_23, INIT_22, INIT_21, INIT_20, INIT_1F, INIT_1E, INIT_1D, INIT_1C, INIT_1B, INIT_1A, INIT_19, INIT_18, INIT_17, INIT_16, INIT_15, INIT_14, INIT_13, INIT_12, INIT_11, INIT_10, INIT_0F, INIT_0E, INIT_0D, INIT_0C, INIT_0B, INIT_0A, INIT_09, INIT_08, INIT_07, INIT_06, INIT_05, INIT_04, INIT_03, INIT_02, INIT_01, INIT_00};
    localparam [4095:0] PAR = {INITP_0F, INITP_0E, INITP_0D, INITP_0C, INITP_0B, INITP_0A, INITP_09, INITP_08, INITP_07, INITP_06, INITP_05, INITP_04, INITP_03, INITP_02, INITP_01, INITP_00};
    wire [31:0] doa, dob;
    wire [3:0] dopa, dopb;
    xc7_bram_rom_port #(
        .DBITS(32768), .PBITS(4096), .ABITS(15), .WIDTH(READ_WIDTH_A), .DO_REG(DOA_REG),
        .DATA(DATA), .PAR(PAR), .INIT(INIT_A[35:0]), .SRVAL(SRVAL_A[35:0])
    ) u_a (
        .clk(CLKARDCLK), .en(ENARDEN), .rst_ram(RSTRAMARSTRAM), .rst_reg(RSTREGARSTREG),
        .regce(REGCEAREGCE), .addr(ADDRARDADDR[14:0]), .we_any(|WEA), .dout(doa), .dpout(dopa)
    );
    xc7_bram_rom_port #(
        .DBITS(32768), .PBITS(4096), .ABITS(15), .WIDTH(READ_WIDTH_B), .DO_REG(DOB_REG),
        .DATA(DATA), .PAR(PAR), .INIT(INIT_B[35:0]), .SRVAL(SRVAL_B[35:0])
    ) u_b (
        .clk(CLKBWRCLK), .en(ENBWREN), .rst_ram(RSTRAMB), .rst_reg(RSTREGB),
        .regce(REGCEB), .addr(ADDRBWRADDR[14:0]), .we_any(|WEBWE), .dout(dob), .dpout(dopb)
    );
    assign DOADO = doa[31:0];
    assign DOBDO = dob[31:0];
    assign DOPADOP = dopa[3:0];
    assign DOPBDOP = dopb[3:0];
    assign CASCADEOUTA = 1'b0;
    assign CASCADEOUTB = 1'b0;
    assign DBITERR = 1'b0;
    assign SBITERR = 1'b0;
    assign ECCPARITY = 8'h0;
    assign RDADDRECC = 9'h0;
    initial begin
        if (RAM_MODE != "TDP") $fatal(1, "RAMB36E1: RAM_MODE %s not modelled (TDP only)", RAM_MODE);
        if (IS_CLKARDCLK_INVERTED || IS_CLKBWRCLK_INVERTED || IS_ENARDEN_INVERTED ||
            IS_ENBWREN_INVERTED || IS_RSTRAMARSTRAM_INVERTED || IS_RSTRAMB_INVERTED ||
            IS_RSTREGARSTREG_INVERTED || IS_RSTREGB_INVERTED)
            $fatal(1, "RAMB36E1: inverted pins not modelled");
        if (RAM_EXTENSION_A != "NONE" || RAM_EXTENSION_B != "NONE" ||
            EN_ECC_READ != "FALSE" || EN_ECC_WRITE != "FALSE")
            $fatal(1, "RAMB36E1: cascading or ECC not modelled");
    end
endmodule

// RAMB18E1: 16 Kb data + 2 Kb parity, read-only (see above).
module RAMB18E1 #(
    parameter [255:0] INIT_00 = 256'h0, INIT_01 = 256'h0, INIT_02 = 256'h0, INIT_03 = 256'h0,
    parameter [255:0] INIT_04 = 256'h0, INIT_05 = 256'h0, INIT_06 = 256'h0, INIT_07 = 256'h0,
    parameter [255:0] INIT_08 = 256'h0, INIT_09 = 256'h0, INIT_0A = 256'h0, INIT_0B = 256'h0,
    parameter [255:0] INIT_0C = 256'h0, INIT_0D = 256'h0, INIT_0E = 256'h0, INIT_0F = 256'h0,
    parameter [255:0] INIT_10 = 256'h0, INIT_11 = 256'h0, INIT_12 = 256'h0, INIT_13 = 256'h0,
    parameter [255:0] INIT_14 = 256'h0, INIT_15 = 256'h0, INIT_16 = 256'h0, INIT_17 = 256'h0,
    parameter [255:0] INIT_18 = 256'h0, INIT_19 = 256'h0, INIT_1A = 256'h0, INIT_1B = 256'h0,
    parameter [255:0] INIT_1C = 256'h0, INIT_1D = 256'h0, INIT_1E = 256'h0, INIT_1F = 256'h0,
    parameter [255:0] INIT_20 = 256'h0, INIT_21 = 256'h0, INIT_22 = 256'h0, INIT_23 = 256'h0,
    parameter [255:0] INIT_24 = 256'h0, INIT_25 = 256'h0, INIT_26 = 256'h0, INIT_27 = 256'h0,
    parameter [255:0] INIT_28 = 256'h0, INIT_29 = 256'h0, INIT_2A = 256'h0, INIT_2B = 256'h0,
    parameter [255:0] INIT_2C = 256'h0, INIT_2D = 256'h0, INIT_2E = 256'h0, INIT_2F = 256'h0,
    parameter [255:0] INIT_30 = 256'h0, INIT_31 = 256'h0, INIT_32 = 256'h0, INIT_33 = 256'h0,
    parameter [255:0] INIT_34 = 256'h0, INIT_35 = 256'h0, INIT_36 = 256'h0, INIT_37 = 256'h0,
    parameter [255:0] INIT_38 = 256'h0, INIT_39 = 256'h0, INIT_3A = 256'h0, INIT_3B = 256'h0,
    parameter [255:0] INIT_3C = 256'h0, INIT_3D = 256'h0, INIT_3E = 256'h0, INIT_3F = 256'h0,
    parameter [255:0] INITP_00 = 256'h0, INITP_01 = 256'h0, INITP_02 = 256'h0, INITP_03 = 256'h0,
    parameter [255:0] INITP_04 = 256'h0, INITP_05 = 256'h0, INITP_06 = 256'h0, INITP_07 = 256'h0,
    parameter INIT_A = 36'h0,
    parameter INIT_B = 36'h0,
    parameter SRVAL_A = 36'h0,
    parameter SRVAL_B = 36'h0,
    parameter integer DOA_REG = 0,
    parameter integer DOB_REG = 0,
    parameter RAM_MODE = "TDP",
    parameter integer READ_WIDTH_A = 0,
    parameter integer READ_WIDTH_B = 0,
    parameter integer WRITE_WIDTH_A = 0,
    parameter integer WRITE_WIDTH_B = 0,
    parameter WRITE_MODE_A = "WRITE_FIRST",
    parameter WRITE_MODE_B = "WRITE_FIRST",
    parameter RSTREG_PRIORITY_A = "RSTREG",
    parameter RSTREG_PRIORITY_B = "RSTREG",
    parameter RDADDR_COLLISION_HWCONFIG = "DELAYED_WRITE",
    parameter SIM_COLLISION_CHECK = "ALL",
    parameter SIM_DEVICE = "7SERIES",
    parameter INIT_FILE = "NONE",
    parameter [0:0] IS_CLKARDCLK_INVERTED = 1'b0,
    parameter [0:0] IS_CLKBWRCLK_INVERTED = 1'b0,
    parameter [0:0] IS_ENARDEN_INVERTED = 1'b0,
    parameter [0:0] IS_ENBWREN_INVERTED = 1'b0,
    parameter [0:0] IS_RSTRAMARSTRAM_INVERTED = 1'b0,
    parameter [0:0] IS_RSTRAMB_INVERTED = 1'b0,
    parameter [0:0] IS_RSTREGARSTREG_INVERTED = 1'b0,
    parameter [0:0] IS_RSTREGB_INVERTED = 1'b0
) (
    input  wire        CLKARDCLK,
    input  wire        CLKBWRCLK,
    input  wire        ENARDEN,
    input  wire        ENBWREN,
    input  wire        REGCEAREGCE,
    input  wire        REGCEB,
    input  wire        RSTRAMARSTRAM,
    input  wire        RSTRAMB,
    input  wire        RSTREGARSTREG,
    input  wire        RSTREGB,
    input  wire [13:0] ADDRARDADDR,
    input  wire [13:0] ADDRBWRADDR,
    input  wire [15:0] DIADI,
    input  wire [15:0] DIBDI,
    input  wire [1:0]  DIPADIP,
    input  wire [1:0]  DIPBDIP,
    input  wire [1:0]  WEA,
    input  wire [3:0]  WEBWE,
    output wire [15:0] DOADO,
    output wire [15:0] DOBDO,
    output wire [1:0]  DOPADOP,
    output wire [1:0]  DOPBDOP
);
    localparam [16383:0] DATA = {INIT_3F, INIT_3E, INIT_3D, INIT_3C, INIT_3B, INIT_3A, INIT_39, INIT_38, INIT_37, INIT_36, INIT_35, INIT_34, INIT_33, INIT_32, INIT_31, INIT_30, INIT_2F, INIT_2E, INIT_2D, INIT_2C, INIT_2B, INIT_2A, INIT_29, INIT_28, INIT_27, INIT_26, INIT_25, INIT_24, INIT_23, INIT_22, INIT_21, INIT_20, INIT_1F, INIT_1E, INIT_1D, INIT_1C, INIT_1B, INIT_1A, INIT_19, INIT_18, INIT_17, INIT_16, INIT_15, INIT_14, INIT_13, INIT_12, INIT_11, INIT_10, INIT_0F, INIT_0E, INIT_0D, INIT_0C, INIT_0B, INIT_0A, INIT_09, INIT_08, INIT_07, INIT_06, INIT_05, INIT_04, INIT_03, INIT_02, INIT_01, INIT_00};
    localparam [2047:0] PAR = {INITP_07, INITP_06, INITP_05, INITP_04, INITP_03, INITP_02, INITP_01, INITP_00};
    wire [31:0] doa, dob;
    wire [3:0] dopa, dopb;
    xc7_bram_rom_port #(
        .DBITS(16384), .PBITS(2048), .ABITS(14), .WIDTH(READ_WIDTH_A), .DO_REG(DOA_REG),
        .DATA(DATA), .PAR(PAR), .INIT(INIT_A[35:0]), .SRVAL(SRVAL_A[35:0])
    ) u_a (
        .clk(CLKARDCLK), .en(ENARDEN), .rst_ram(RSTRAMARSTRAM), .rst_reg(RSTREGARSTREG),
        .regce(REGCEAREGCE), .addr(ADDRARDADDR[13:0]), .we_any(|WEA), .dout(doa), .dpout(dopa)
    );
    xc7_bram_rom_port #(
        .DBITS(16384), .PBITS(2048), .ABITS(14), .WIDTH(READ_WIDTH_B), .DO_REG(DOB_REG),
        .DATA(DATA), .PAR(PAR), .INIT(INIT_B[35:0]), .SRVAL(SRVAL_B[35:0])
    ) u_b (
        .clk(CLKBWRCLK), .en(ENBWREN), .rst_ram(RSTRAMB), .rst_reg(RSTREGB),
        .regce(REGCEB), .addr(ADDRBWRADDR[13:0]), .we_any(|WEBWE), .dout(dob), .dpout(dopb)
    );
    assign DOADO = doa[15:0];
    assign DOBDO = dob[15:0];
    assign DOPADOP = dopa[1:0];
    assign DOPBDOP = dopb[1:0];
    initial begin
        if (RAM_MODE != "TDP") $fatal(1, "RAMB18E1: RAM_MODE %s not modelled (TDP only)", RAM_MODE);
        if (IS_CLKARDCLK_INVERTED || IS_CLKBWRCLK_INVERTED || IS_ENARDEN_INVERTED ||
            IS_ENBWREN_INVERTED || IS_RSTRAMARSTRAM_INVERTED || IS_RSTRAMB_INVERTED ||
            IS_RSTREGARSTREG_INVERTED || IS_RSTREGB_INVERTED)
            $fatal(1, "RAMB18E1: inverted pins not modelled");
    end
endmodule
