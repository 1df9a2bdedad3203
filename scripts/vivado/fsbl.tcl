# FSBL from the hardware description (called by scripts/bitstream --fsbl).
#
#   xsct fsbl.tcl XSA OUT
#
# Generates Xilinx's zynq_fsbl application for ps7_cortexa9_0 from XSA (its
# ps7_init sets the clocks, DDR and MIO of the board file) and compiles it;
# the result is OUT/executable.elf. The standalone BSP would pick the first
# UART of the hardware (UART0, the firmware's defmt log on Pmod JE) for the
# FSBL's messages: stdin/stdout are set to UART1, the console on the USB-UART.
if {[llength $argv] != 2} {
    puts stderr "usage: xsct fsbl.tcl XSA OUT"
    exit 2
}
lassign $argv xsa out
if {![file exists $xsa]} {
    puts stderr "fsbl.tcl: $xsa missing (run scripts/bitstream first)"
    exit 2
}
file mkdir $out
set hw [hsi::open_hw_design $xsa]
hsi::create_sw_design fsbl -proc ps7_cortexa9_0 -os standalone -app zynq_fsbl
common::set_property CONFIG.stdin ps7_uart_1 [hsi::get_os]
common::set_property CONFIG.stdout ps7_uart_1 [hsi::get_os]
hsi::generate_app -dir $out -compile
hsi::close_hw_design $hw
if {![file exists [file join $out executable.elf]]} {
    puts stderr "fsbl.tcl: no [file join $out executable.elf] after the build"
    exit 1
}
puts "fsbl.tcl: wrote [file join $out executable.elf]"
