# Vivado non-project flow of the drive's bitstream (called by scripts/bitstream).
#
#   vivado -mode batch -source bitstream.tcl -tclargs ROOT BOARD OUT JOBS
#
# ROOT the repository, BOARD a board file name (boards/BOARD-ps7.tcl and
# boards/BOARD.xdc, both generated from boards/BOARD.toml), OUT the output
# directory, JOBS the number of parallel jobs. Writes OUT/board_top.bit,
# OUT/board_top.xsa (hardware description with the bitstream, for the
# FSBL), OUT/timing.rpt, OUT/utilization.rpt and OUT/post_route.dcp. Exits 1
# on negative setup or hold slack, before writing the bitstream.
#
# Block design ps_bd (instantiated by pl-bitstream-src/board/board_top.v):
#   ps7       PS7 configured from the board file: DDR, UART0 (defmt log) and
#             UART1 (console), SD0, QSPI, FCLK0, GP0 master, IRQ_F2P,
#             32 EMIO GPIO (GPIO 54..85, bank 2)
#   axi_conv  AXI protocol converter, GP0 (AXI3) -> M_AXI_PL (AXI4-Lite),
#             mapped at pl_base (0x43C0_0000) with pl_range (32 KiB)
#   rst_fclk0 proc_sys_reset: aresetn synchronous to FCLK0
# External ports: DDR, FIXED_IO, M_AXI_PL, fclk0, aresetn, irq_f2p,
# emio_gpio_i (board_top drives the signature the firmware reads in the
# GPIO controller's DATA_RO_2 before any GP0 access).

if {[llength $argv] != 4} {
    puts stderr "usage: vivado -mode batch -source bitstream.tcl -tclargs ROOT BOARD OUT JOBS"
    exit 2
}
lassign $argv root board out jobs
set ps7_file [file join $root boards "${board}-ps7.tcl"]
if {![file exists $ps7_file]} {
    puts stderr "bitstream.tcl: no board `$board` ($ps7_file missing)"
    exit 2
}
# board_name, board_part, fclk0_hz, pl_base, pl_range, emio_gpio_width,
# ps7_config
source $ps7_file
file mkdir $out
set_param general.maxThreads $jobs

create_project -in_memory -part $board_part
set_property target_language Verilog [current_project]

# --- block design -------------------------------------------------------
# A second run into the same directory: Vivado refuses an existing design.
file delete -force [file join $out bd]
create_bd_design -dir [file join $out bd] ps_bd

set ps7 [create_bd_cell -type ip -vlnv xilinx.com:ip:processing_system7:5.5 ps7]
set_property -dict $ps7_config $ps7
create_bd_intf_port -mode Master -vlnv xilinx.com:interface:ddrx_rtl:1.0 DDR
create_bd_intf_port -mode Master -vlnv xilinx.com:display_processing_system7:fixedio_rtl:1.0 FIXED_IO
connect_bd_intf_net [get_bd_intf_pins ps7/DDR] [get_bd_intf_ports DDR]
connect_bd_intf_net [get_bd_intf_pins ps7/FIXED_IO] [get_bd_intf_ports FIXED_IO]

set conv [create_bd_cell -type ip -vlnv xilinx.com:ip:axi_protocol_converter:2.1 axi_conv]
set_property CONFIG.MI_PROTOCOL AXI4LITE $conv
set m_axi [create_bd_intf_port -mode Master -vlnv xilinx.com:interface:aximm_rtl:1.0 M_AXI_PL]
set_property -dict [list CONFIG.PROTOCOL AXI4LITE CONFIG.ADDR_WIDTH 32 CONFIG.DATA_WIDTH 32 \
    CONFIG.FREQ_HZ $fclk0_hz] $m_axi
connect_bd_intf_net [get_bd_intf_pins ps7/M_AXI_GP0] [get_bd_intf_pins axi_conv/S_AXI]
connect_bd_intf_net [get_bd_intf_pins axi_conv/M_AXI] $m_axi

set rst [create_bd_cell -type ip -vlnv xilinx.com:ip:proc_sys_reset:5.0 rst_fclk0]
set fclk0 [create_bd_port -dir O -type clk fclk0]
set_property -dict [list CONFIG.FREQ_HZ $fclk0_hz CONFIG.ASSOCIATED_BUSIF M_AXI_PL \
    CONFIG.ASSOCIATED_RESET aresetn] $fclk0
create_bd_port -dir O -type rst aresetn
set irq [create_bd_port -dir I -type intr irq_f2p]
set_property CONFIG.SENSITIVITY LEVEL_HIGH $irq

connect_bd_net [get_bd_pins ps7/FCLK_CLK0] [get_bd_pins ps7/M_AXI_GP0_ACLK] \
    [get_bd_pins axi_conv/aclk] [get_bd_pins rst_fclk0/slowest_sync_clk] [get_bd_ports fclk0]
connect_bd_net [get_bd_pins ps7/FCLK_RESET0_N] [get_bd_pins rst_fclk0/ext_reset_in]
connect_bd_net [get_bd_pins rst_fclk0/peripheral_aresetn] [get_bd_pins axi_conv/aresetn] \
    [get_bd_ports aresetn]
connect_bd_net [get_bd_ports irq_f2p] [get_bd_pins ps7/IRQ_F2P]
# EMIO GPIO inputs only: the signature is read, never driven by the PS, so
# GPIO_O and GPIO_T stay unconnected (outputs left open).
create_bd_port -dir I -from [expr {$emio_gpio_width - 1}] -to 0 emio_gpio_i
connect_bd_net [get_bd_ports emio_gpio_i] [get_bd_pins ps7/GPIO_I]

assign_bd_address -offset $pl_base -range $pl_range \
    -target_address_space [get_bd_addr_spaces ps7/Data] [get_bd_addr_segs M_AXI_PL/Reg] -force
validate_bd_design
save_bd_design
set bd_file [get_files ps_bd.bd]
# Synthesise the block design with the top level (no out-of-context runs:
# non-project mode has no run manager).
set_property synth_checkpoint_mode None $bd_file
generate_target all $bd_file

# --- RTL, constraints, implementation -------------------------------------
set rtl_dir [file join $root pl-bitstream-src rtl]
read_verilog [lsort [glob [file join $rtl_dir *.v]]]
read_verilog [file join $root pl-bitstream-src board board_top.v]
read_xdc [file join $root boards "${board}.xdc"]

synth_design -top board_top -part $board_part -include_dirs [list $rtl_dir]
opt_design
place_design
phys_opt_design
route_design
write_checkpoint -force [file join $out post_route.dcp]
report_timing_summary -file [file join $out timing.rpt]
report_utilization -file [file join $out utilization.rpt]

set wns [get_property SLACK [get_timing_paths -max_paths 1 -nworst 1 -setup]]
set whs [get_property SLACK [get_timing_paths -max_paths 1 -nworst 1 -hold]]
puts "bitstream.tcl: worst setup slack $wns ns, worst hold slack $whs ns"
if {$wns eq "" || $whs eq "" || $wns < 0 || $whs < 0} {
    puts stderr "bitstream.tcl: timing not met (setup $wns ns, hold $whs ns), see [file join $out timing.rpt]"
    exit 1
}

write_bitstream -force [file join $out board_top.bit]
write_hw_platform -fixed -include_bit -force -file [file join $out board_top.xsa]
puts "bitstream.tcl: wrote [file join $out board_top.bit] and board_top.xsa ($board_name)"
