# Runs one of the Vivado/xsct flow scripts under plain tclsh, with every
# Vivado and xsct command it uses replaced by a stand-in (scripts/board-check).
#
#   tclsh stub-run.tcl FACTS SCRIPT ARGS...
#
# A typo in a command name, an unbalanced brace, an unset variable or a
# path that does not exist fails here as it would in Vivado. The stand-ins
# record what the script builds in FACTS, one fact per line, for boardgen
# to compare with the RTL and the register map:
#   port NAME DIR WIDTH        a block-design port as Vivado names it in HDL
#   address OFFSET RANGE       the PL's address window
#   ps7 KEY VALUE              a PS7 parameter
#   top NAME                   the synthesis top
#   output PATH                a file the script writes
# STUB_SLACK (environment, default 1.0) is the slack get_timing_paths reports.
if {[llength $argv] < 2} {
    puts stderr "usage: tclsh stub-run.tcl FACTS SCRIPT ARGS..."
    exit 2
}
set stub_facts_file [lindex $argv 0]
set stub_script [lindex $argv 1]
set stub_facts {}
set stub_props [dict create]
set stub_intf [dict create]
set stub_slack [expr {[info exists ::env(STUB_SLACK)] ? $::env(STUB_SLACK) : 1.0}]

proc fact {args} { lappend ::stub_facts [join $args " "] }

proc need_file {cmd path} {
    if {![file exists $path]} {
        error "$cmd: $path does not exist"
    }
}

# Options of a stand-in call: returns the dict of -opt value pairs (flags
# listed in `flags` take no value) and the remaining positional arguments.
proc opts {cmd argl flags known} {
    set o [dict create]
    set pos {}
    for {set i 0} {$i < [llength $argl]} {incr i} {
        set a [lindex $argl $i]
        if {[string index $a 0] eq "-" && ![string is double -strict $a]} {
            if {$a in $flags} {
                dict set o $a 1
            } elseif {$a in $known} {
                incr i
                if {$i >= [llength $argl]} { error "$cmd: $a needs a value" }
                dict set o $a [lindex $argl $i]
            } else {
                error "$cmd: unknown option $a"
            }
        } else {
            lappend pos $a
        }
    }
    return [list $o $pos]
}

# --- Vivado -------------------------------------------------------------
proc set_param {name value} {}
proc create_project {args} {
    lassign [opts create_project $args {-in_memory -force} {-part}] o pos
    if {![dict exists $o -part]} { error "create_project: no -part" }
    fact part [dict get $o -part]
}
proc current_project {} { return proj }
proc create_bd_design {args} {
    lassign [opts create_bd_design $args {} {-dir}] o pos
    if {[llength $pos] != 1} { error "create_bd_design: one name expected" }
    # Vivado refuses a design directory that exists (a second run).
    if {[dict exists $o -dir]} {
        set d [file join [dict get $o -dir] [lindex $pos 0]]
        if {[file exists $d]} { error "create_bd_design: $d exists" }
        file mkdir $d
    }
}
proc create_bd_cell {args} {
    lassign [opts create_bd_cell $args {} {-type -vlnv}] o pos
    if {![string match "xilinx.com:ip:*:*" [dict get $o -vlnv]]} { error "create_bd_cell: bad vlnv" }
    return "cell:[lindex $pos 0]"
}
proc create_bd_intf_port {args} {
    lassign [opts create_bd_intf_port $args {} {-mode -vlnv}] o pos
    set name [lindex $pos 0]
    dict set ::stub_intf $name [dict get $o -vlnv]
    return "intf:$name"
}
proc create_bd_port {args} {
    lassign [opts create_bd_port $args {} {-dir -type -from -to}] o pos
    set name [lindex $pos 0]
    set dir [dict get $o -dir]
    set width 1
    if {[dict exists $o -from]} { set width [expr {[dict get $o -from] - [dict get $o -to] + 1}] }
    fact port $name [dict get {I input O output IO inout} $dir] $width
    return "port:$name"
}
proc set_property {args} {
    if {[lindex $args 0] eq "-dict"} {
        set kv [lindex $args 1]
        set obj [lindex $args 2]
    } else {
        set kv [lrange $args 0 1]
        set obj [lindex $args 2]
    }
    if {[llength $kv] % 2} { error "set_property: odd key/value list" }
    foreach {k v} $kv {
        dict set ::stub_props $obj $k $v
        if {$obj eq "cell:ps7"} { fact ps7 $k $v }
        if {[string match "port:*" $obj]} { fact portprop [string range $obj 5 end] $k $v }
    }
}
proc get_bd_intf_pins {p} { return "pin:$p" }
proc get_bd_pins {p} { return "pin:$p" }
proc get_bd_intf_ports {p} {
    if {![dict exists $::stub_intf $p]} { error "get_bd_intf_ports: no port $p" }
    return "intf:$p"
}
proc get_bd_ports {p} { return "port:$p" }
proc connect_bd_intf_net {a b} {}
proc connect_bd_net {args} {
    if {[llength $args] < 2} { error "connect_bd_net: needs two ends" }
    fact net {*}$args
}
proc get_bd_addr_spaces {p} { return "space:$p" }
proc get_bd_addr_segs {p} { return "seg:$p" }
proc assign_bd_address {args} {
    lassign [opts assign_bd_address $args {-force} {-offset -range -target_address_space}] o pos
    fact address [dict get $o -offset] [dict get $o -range]
}
proc validate_bd_design {} {}
proc save_bd_design {} {}
proc get_files {p} { return "file:$p" }
proc generate_target {what f} {}
proc read_verilog {files} {
    foreach f $files { need_file read_verilog $f }
}
proc read_xdc {f} { need_file read_xdc $f }
proc synth_design {args} {
    lassign [opts synth_design $args {} {-top -part -include_dirs}] o pos
    foreach d [dict get $o -include_dirs] { need_file synth_design $d }
    fact top [dict get $o -top]
}
proc opt_design {} {}
proc place_design {} {}
proc phys_opt_design {} {}
proc route_design {} {}
proc write_checkpoint {args} { fact output [lindex $args end] }
proc report_timing_summary {args} { fact output [lindex $args end] }
proc report_utilization {args} { fact output [lindex $args end] }
proc get_timing_paths {args} {
    lassign [opts get_timing_paths $args {-setup -hold} {-max_paths -nworst}] o pos
    return path
}
proc get_property {name obj} {
    if {$name eq "SLACK"} { return $::stub_slack }
    error "get_property: $name not stubbed"
}
proc write_bitstream {args} { fact output [lindex $args end] }
proc write_hw_platform {args} {
    lassign [opts write_hw_platform $args {-fixed -include_bit -force} {-file}] o pos
    fact output [dict get $o -file]
}

# --- xsct ---------------------------------------------------------------
namespace eval hsi {
    proc open_hw_design {xsa} { ::need_file open_hw_design $xsa; return hw }
    proc create_sw_design {args} {
        lassign [::opts create_sw_design $args {} {-proc -os -app}] o pos
        if {[llength $pos] != 1} { error "create_sw_design: one name expected" }
        return sw
    }
    proc get_os {} { return os }
    proc generate_app {args} {
        lassign [::opts generate_app $args {-compile} {-hw -os -proc -app -sw -dir}] o pos
        if {![dict exists $o -dir]} { error "generate_app: -dir missing" }
        ::fact output [file join [dict get $o -dir] executable.elf]
        # What the real command leaves behind.
        close [open [file join [dict get $o -dir] executable.elf] w]
    }
    proc close_hw_design {hw} {}
}
namespace eval common {
    proc set_property {name value obj} { ::fact bsp $obj $name $value }
}
proc connect {args} {}
proc targets {args} {}
proc rst {args} {}
proc fpga {args} {
    lassign [opts fpga $args {} {-file}] o pos
    need_file fpga [dict get $o -file]
}
proc dow {elf} { need_file dow $elf }
proc con {} {}

# --- run ----------------------------------------------------------------
proc write_facts {} {
    # Interface ports, expanded as Vivado names their HDL signals.
    dict for {name vlnv} $::stub_intf {
        set props [expr {[dict exists $::stub_props "intf:$name"] ? [dict get $::stub_props "intf:$name"] : {}}]
        switch -glob -- $vlnv {
            *:ddrx_rtl:* {
                foreach {s w} {addr 15 ba 3 cas_n 1 ck_n 1 ck_p 1 cke 1 cs_n 1 dm 4 dq 32 dqs_n 4 dqs_p 4 odt 1 ras_n 1 reset_n 1 we_n 1} {
                    fact port ${name}_$s inout $w
                }
            }
            *:fixedio_rtl:* {
                foreach {s w} {ddr_vrn 1 ddr_vrp 1 mio 54 ps_clk 1 ps_porb 1 ps_srstb 1} {
                    fact port ${name}_$s inout $w
                }
            }
            *:aximm_rtl:* {
                if {[dict get $props CONFIG.PROTOCOL] ne "AXI4LITE"} { error "$name: only AXI4-Lite is expanded" }
                set aw [dict get $props CONFIG.ADDR_WIDTH]
                set dw [dict get $props CONFIG.DATA_WIDTH]
                foreach {s d w} [list araddr output $aw arprot output 3 arready input 1 arvalid output 1 \
                        awaddr output $aw awprot output 3 awready input 1 awvalid output 1 \
                        bready output 1 bresp input 2 bvalid input 1 rdata input $dw rready output 1 \
                        rresp input 2 rvalid input 1 wdata output $dw wready input 1 \
                        wstrb output [expr {$dw / 8}] wvalid output 1] {
                    fact port ${name}_$s $d $w
                }
            }
            default { error "$name: interface $vlnv not known to the stand-ins" }
        }
    }
    dict for {obj props} $::stub_props {
        if {[string match "port:*" $obj] && [dict exists $props CONFIG.FREQ_HZ]} {
            fact clock [string range $obj 5 end] [dict get $props CONFIG.FREQ_HZ]
        }
    }
    set f [open $::stub_facts_file w]
    puts $f [join $::stub_facts "\n"]
    close $f
}

rename exit stub_real_exit
proc exit {{code 0}} {
    write_facts
    stub_real_exit $code
}
set argv [lrange $argv 2 end]
set argc [llength $argv]
set argv0 $stub_script
source $stub_script
exit 0
