# Generated from boards/zedboard.toml by `cargo run -p boardgen -- gen`; do not edit.
# Avnet ZedBoard (rev C/D), xc7z020clg484-1; top level board_top.
# FCLK0 (clk_fpga_0, 100 MHz) is created by the PS7's own constraints.

# Pins: port, package pin, IO standard; the comment names the board's connector pin.
set_property -dict {PACKAGE_PIN Y11 IOSTANDARD LVCMOS33} [get_ports {gate_hi_o[2]}] ;# JA1: phase a, upper switch (1 = on)
set_property -dict {PACKAGE_PIN AA11 IOSTANDARD LVCMOS33} [get_ports {gate_lo_o[2]}] ;# JA2: phase a, lower switch
set_property -dict {PACKAGE_PIN Y10 IOSTANDARD LVCMOS33} [get_ports {gate_hi_o[1]}] ;# JA3: phase b, upper switch
set_property -dict {PACKAGE_PIN AA9 IOSTANDARD LVCMOS33} [get_ports {gate_lo_o[1]}] ;# JA4: phase b, lower switch
set_property -dict {PACKAGE_PIN AB11 IOSTANDARD LVCMOS33} [get_ports {gate_hi_o[0]}] ;# JA7: phase c, upper switch
set_property -dict {PACKAGE_PIN AB10 IOSTANDARD LVCMOS33} [get_ports {gate_lo_o[0]}] ;# JA8: phase c, lower switch
set_property -dict {PACKAGE_PIN AB9 IOSTANDARD LVCMOS33} [get_ports {gate_en_o}] ;# JA9: gate-driver enable (1 = drivers may switch: GATE_EN set, no trip); wire to the drivers' enable with a pull-down
set_property -dict {PACKAGE_PIN W12 IOSTANDARD LVCMOS33} [get_ports {enc_a_i}] ;# JB1: encoder A (3.3 V logic)
set_property -dict {PACKAGE_PIN W11 IOSTANDARD LVCMOS33} [get_ports {enc_b_i}] ;# JB2: encoder B
set_property -dict {PACKAGE_PIN V10 IOSTANDARD LVCMOS33} [get_ports {enc_z_i}] ;# JB3: encoder index Z
set_property -dict {PACKAGE_PIN W8 IOSTANDARD LVCMOS33} [get_ports {fault_ext_ni}] ;# JB4: external fault, active low (gate driver FAULT/desat, e-stop); pulled up
set_property -dict {PACKAGE_PIN M19 IOSTANDARD LVCMOS25} [get_ports {adc_cnv_o}] ;# FMC-LA00_CC_P: ADC convert start
set_property -dict {PACKAGE_PIN M20 IOSTANDARD LVCMOS25} [get_ports {adc_drdy_i}] ;# FMC-LA00_CC_N: ADC data ready (asynchronous; pulled down: no card reads as no data)
set_property -dict {PACKAGE_PIN N19 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[35]}] ;# FMC-LA01_CC_P: ia bit 11 (MSB)
set_property -dict {PACKAGE_PIN N20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[34]}] ;# FMC-LA01_CC_N: ia bit 10
set_property -dict {PACKAGE_PIN P17 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[33]}] ;# FMC-LA02_P: ia bit 9
set_property -dict {PACKAGE_PIN P18 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[32]}] ;# FMC-LA02_N: ia bit 8
set_property -dict {PACKAGE_PIN N22 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[31]}] ;# FMC-LA03_P: ia bit 7
set_property -dict {PACKAGE_PIN P22 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[30]}] ;# FMC-LA03_N: ia bit 6
set_property -dict {PACKAGE_PIN M21 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[29]}] ;# FMC-LA04_P: ia bit 5
set_property -dict {PACKAGE_PIN M22 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[28]}] ;# FMC-LA04_N: ia bit 4
set_property -dict {PACKAGE_PIN J18 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[27]}] ;# FMC-LA05_P: ia bit 3
set_property -dict {PACKAGE_PIN K18 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[26]}] ;# FMC-LA05_N: ia bit 2
set_property -dict {PACKAGE_PIN L21 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[25]}] ;# FMC-LA06_P: ia bit 1
set_property -dict {PACKAGE_PIN L22 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[24]}] ;# FMC-LA06_N: ia bit 0 (LSB)
set_property -dict {PACKAGE_PIN T16 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[23]}] ;# FMC-LA07_P: ib bit 11 (MSB)
set_property -dict {PACKAGE_PIN T17 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[22]}] ;# FMC-LA07_N: ib bit 10
set_property -dict {PACKAGE_PIN J21 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[21]}] ;# FMC-LA08_P: ib bit 9
set_property -dict {PACKAGE_PIN J22 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[20]}] ;# FMC-LA08_N: ib bit 8
set_property -dict {PACKAGE_PIN R20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[19]}] ;# FMC-LA09_P: ib bit 7
set_property -dict {PACKAGE_PIN R21 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[18]}] ;# FMC-LA09_N: ib bit 6
set_property -dict {PACKAGE_PIN R19 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[17]}] ;# FMC-LA10_P: ib bit 5
set_property -dict {PACKAGE_PIN T19 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[16]}] ;# FMC-LA10_N: ib bit 4
set_property -dict {PACKAGE_PIN N17 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[15]}] ;# FMC-LA11_P: ib bit 3
set_property -dict {PACKAGE_PIN N18 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[14]}] ;# FMC-LA11_N: ib bit 2
set_property -dict {PACKAGE_PIN P20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[13]}] ;# FMC-LA12_P: ib bit 1
set_property -dict {PACKAGE_PIN P21 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[12]}] ;# FMC-LA12_N: ib bit 0 (LSB)
set_property -dict {PACKAGE_PIN L17 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[11]}] ;# FMC-LA13_P: ic bit 11 (MSB)
set_property -dict {PACKAGE_PIN M17 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[10]}] ;# FMC-LA13_N: ic bit 10
set_property -dict {PACKAGE_PIN K19 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[9]}] ;# FMC-LA14_P: ic bit 9
set_property -dict {PACKAGE_PIN K20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[8]}] ;# FMC-LA14_N: ic bit 8
set_property -dict {PACKAGE_PIN J16 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[7]}] ;# FMC-LA15_P: ic bit 7
set_property -dict {PACKAGE_PIN J17 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[6]}] ;# FMC-LA15_N: ic bit 6
set_property -dict {PACKAGE_PIN J20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[5]}] ;# FMC-LA16_P: ic bit 5
set_property -dict {PACKAGE_PIN K21 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[4]}] ;# FMC-LA16_N: ic bit 4
set_property -dict {PACKAGE_PIN B19 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[3]}] ;# FMC-LA17_CC_P: ic bit 3
set_property -dict {PACKAGE_PIN B20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[2]}] ;# FMC-LA17_CC_N: ic bit 2
set_property -dict {PACKAGE_PIN D20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[1]}] ;# FMC-LA18_CC_P: ic bit 1
set_property -dict {PACKAGE_PIN C20 IOSTANDARD LVCMOS25} [get_ports {adc_data_i[0]}] ;# FMC-LA18_CC_N: ic bit 0 (LSB)
set_property -dict {PACKAGE_PIN T22 IOSTANDARD LVCMOS33} [get_ports {led_o[0]}] ;# LD0: PL clock alive: blinks at 1 Hz
set_property -dict {PACKAGE_PIN T21 IOSTANDARD LVCMOS33} [get_ports {led_o[1]}] ;# LD1: PL out of reset (FCLK_RESET0_N released by the FSBL)
set_property -dict {PACKAGE_PIN U22 IOSTANDARD LVCMOS33} [get_ports {led_o[2]}] ;# LD2: gates switching: any gate on in the last ~84 ms
set_property -dict {PACKAGE_PIN U21 IOSTANDARD LVCMOS33} [get_ports {led_o[3]}] ;# LD3: external fault input asserted (low)
set_property PULLUP true [get_ports {fault_ext_ni}]
set_property PULLDOWN true [get_ports {adc_drdy_i}]
set_property PULLDOWN true [get_ports {adc_data_i[35]}]
set_property PULLDOWN true [get_ports {adc_data_i[34]}]
set_property PULLDOWN true [get_ports {adc_data_i[33]}]
set_property PULLDOWN true [get_ports {adc_data_i[32]}]
set_property PULLDOWN true [get_ports {adc_data_i[31]}]
set_property PULLDOWN true [get_ports {adc_data_i[30]}]
set_property PULLDOWN true [get_ports {adc_data_i[29]}]
set_property PULLDOWN true [get_ports {adc_data_i[28]}]
set_property PULLDOWN true [get_ports {adc_data_i[27]}]
set_property PULLDOWN true [get_ports {adc_data_i[26]}]
set_property PULLDOWN true [get_ports {adc_data_i[25]}]
set_property PULLDOWN true [get_ports {adc_data_i[24]}]
set_property PULLDOWN true [get_ports {adc_data_i[23]}]
set_property PULLDOWN true [get_ports {adc_data_i[22]}]
set_property PULLDOWN true [get_ports {adc_data_i[21]}]
set_property PULLDOWN true [get_ports {adc_data_i[20]}]
set_property PULLDOWN true [get_ports {adc_data_i[19]}]
set_property PULLDOWN true [get_ports {adc_data_i[18]}]
set_property PULLDOWN true [get_ports {adc_data_i[17]}]
set_property PULLDOWN true [get_ports {adc_data_i[16]}]
set_property PULLDOWN true [get_ports {adc_data_i[15]}]
set_property PULLDOWN true [get_ports {adc_data_i[14]}]
set_property PULLDOWN true [get_ports {adc_data_i[13]}]
set_property PULLDOWN true [get_ports {adc_data_i[12]}]
set_property PULLDOWN true [get_ports {adc_data_i[11]}]
set_property PULLDOWN true [get_ports {adc_data_i[10]}]
set_property PULLDOWN true [get_ports {adc_data_i[9]}]
set_property PULLDOWN true [get_ports {adc_data_i[8]}]
set_property PULLDOWN true [get_ports {adc_data_i[7]}]
set_property PULLDOWN true [get_ports {adc_data_i[6]}]
set_property PULLDOWN true [get_ports {adc_data_i[5]}]
set_property PULLDOWN true [get_ports {adc_data_i[4]}]
set_property PULLDOWN true [get_ports {adc_data_i[3]}]
set_property PULLDOWN true [get_ports {adc_data_i[2]}]
set_property PULLDOWN true [get_ports {adc_data_i[1]}]
set_property PULLDOWN true [get_ports {adc_data_i[0]}]

# Timing.
# Asynchronous inputs: each passes a two-flop synchroniser (sync2).
set_false_path -from [get_ports {enc_a_i enc_b_i enc_z_i fault_ext_ni}]
# Outputs leave PL registers; their ns-scale skew is small against the dead
# time (DEAD_TIME, 500 ns from reset) and the ADC period (3.9 us).
set_false_path -to [get_ports {gate_hi_o[*] gate_lo_o[*] gate_en_o adc_cnv_o led_o[*]}]
# The strobe of the captured inputs (the ADC's data-ready) is asynchronous too
# (sync2; the converter sees no PL clock), but its pin-to-flop delay decides
# when the data is captured: 2 to 3 periods plus this delay after the pin's
# edge, inside the converter's data-valid window (timing.strobe_max_delay_ns).
set_max_delay -datapath_only -from [get_ports {adc_drdy_i}] 5.0
# Inputs captured at the clock edge after the synchronised data-ready rose
# (adc_frontend: 2 to 3 periods after the pin's edge). Their pin-to-register
# delay only has to be shorter than that (timing.strobed_max_delay_ns).
set_max_delay -datapath_only -from [get_ports {adc_data_i[*]}] 10.0
