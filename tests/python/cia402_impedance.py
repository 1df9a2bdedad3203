"""A python-canopen master commands the drive's vendor impedance mode
(0x6060 = -1): stiffness 2 N m/rev and damping 0.05 N m s/rev about the
present position (0x2101, 0x607A, 0x60FF), on the FOC, then prints
RUNNING and the position every 0.5 s until killed; the test that runs it
loads the simulated motor and checks the deflection on the console.

usage: cia402_impedance.py PORT EDS
"""
import sys
import time

import canopen

NODE_ID = 1


def main() -> int:
    port = int(sys.argv[1])
    net = canopen.Network()
    net.connect(
        interface="socketcand", host="127.0.0.1", port=port, channel="can0", tcp_tune=True
    )
    node = net.add_node(NODE_ID, sys.argv[2])
    node.sdo.RESPONSE_TIMEOUT = 3.0
    node.sdo[0x2100].raw = 0
    node.sdo[0x6060].raw = -1
    node.sdo[0x2101][1].raw = 2.0
    node.sdo[0x2101][2].raw = 0.05
    node.sdo[0x2101][3].raw = 0.0
    node.sdo[0x607A].raw = node.sdo[0x6064].raw
    node.sdo[0x60FF].raw = 0
    node.nmt.state = "OPERATIONAL"
    for cw in (0x06, 0x07, 0x0F):
        node.sdo[0x6040].raw = cw
    sw = node.sdo[0x6041].raw
    if sw & 0x6F != 0x27 or node.sdo[0x6061].raw != -1:
        print(f"FAIL: statusword 0x{sw:04X}", flush=True)
        return 1
    print("RUNNING", flush=True)
    while True:
        time.sleep(0.5)
        print(f"position {node.sdo[0x6064].raw}", flush=True)


if __name__ == "__main__":
    sys.exit(main())
