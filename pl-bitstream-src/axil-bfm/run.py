"""Builds pl_top under Icarus Verilog and runs test_axil.py with cocotb.
Usage: run.py <build dir>; $REGMAP_JSON names the register table's JSON."""
import os
import sys
from pathlib import Path

from cocotb.runner import get_runner

here = Path(__file__).resolve().parent
rtl = here.parent / "rtl"
build = Path(sys.argv[1]).resolve()
runner = get_runner("icarus")
runner.build(
    verilog_sources=sorted(rtl.glob("*.v")) + [here / "axil_bfm_top.v"],
    includes=[rtl],
    hdl_toplevel="axil_bfm_top",
    build_dir=build,
    build_args=["-g2012"],
    always=True,
    timescale=("1ns", "1ps"),
)
runner.test(
    hdl_toplevel="axil_bfm_top",
    test_module="test_axil",
    test_dir=here,
    build_dir=build,
    results_xml=str(build / "results.xml"),
    extra_env={"REGMAP_JSON": os.environ["REGMAP_JSON"]},
)
