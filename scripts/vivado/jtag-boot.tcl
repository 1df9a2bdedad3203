# Boot over JTAG without an SD card (called by scripts/flash jtag).
#
#   xsct jtag-boot.tcl PS7_INIT BIT ELF
#
# PS7_INIT is ps7_init.tcl from the hardware description (scripts/flash
# extracts it from the XSA). Resets the system, configures the PL with BIT,
# initialises the PS (clocks, DDR, MIO: what the FSBL does on an SD boot),
# enables the PS-PL level shifters, loads ELF into DDR and starts it on CPU 0.
if {[llength $argv] != 3} {
    puts stderr "usage: xsct jtag-boot.tcl PS7_INIT BIT ELF"
    exit 2
}
lassign $argv ps7_init bit elf
foreach f [list $ps7_init $bit $elf] {
    if {![file exists $f]} {
        puts stderr "jtag-boot.tcl: $f missing"
        exit 2
    }
}
connect
targets -set -nocase -filter {name =~ "APU*"}
rst -system
after 1000
targets -set -nocase -filter {name =~ "xc7z*"}
fpga -file $bit
targets -set -nocase -filter {name =~ "APU*"}
source $ps7_init
ps7_init
ps7_post_config
targets -set -nocase -filter {name =~ "*A9*#0"}
dow $elf
con
puts "jtag-boot.tcl: $elf running on CPU 0"
