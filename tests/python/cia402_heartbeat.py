"""A python-canopen master that watches the drive with heartbeats and is
then killed: it sets the drive's heartbeat consumer (0x1016:1, its own
node-ID 0x7F, 300 ms), sends its own heartbeat every 50 ms (python-can's
periodic task), enables the drive in CSV at 2 rev/s and prints RUNNING;
then it waits to be killed. The test that runs it checks the drive's
reaction on the console.

usage: cia402_heartbeat.py PORT EDS
"""
import sys
import time

import canopen

NODE_ID = 1
MASTER_ID = 0x7F


def main() -> int:
    port = int(sys.argv[1])
    net = canopen.Network()
    net.connect(
        interface="socketcand", host="127.0.0.1", port=port, channel="can0", tcp_tune=True
    )
    node = net.add_node(NODE_ID, sys.argv[2])
    node.sdo.RESPONSE_TIMEOUT = 3.0
    # Our heartbeat: 0x700 + 0x7F, state operational (0x05), every 50 ms.
    net.send_periodic(0x700 + MASTER_ID, b"\x05", 0.05)
    time.sleep(0.2)
    node.sdo[0x1016][1].raw = (MASTER_ID << 16) | 300
    node.sdo[0x2100].raw = 0
    node.sdo[0x6060].raw = 9
    node.nmt.state = "OPERATIONAL"
    for cw in (0x06, 0x07, 0x0F):
        node.sdo[0x6040].raw = cw
    node.sdo[0x60FF].raw = 8192
    sw = node.sdo[0x6041].raw
    if sw & 0x6F != 0x27:
        print(f"FAIL: statusword 0x{sw:04X}", flush=True)
        return 1
    # The consumer watches from the first heartbeat after 0x1016 is set
    # (CiA 301): let several arrive before anyone kills us.
    time.sleep(0.5)
    print("RUNNING", flush=True)
    while True:
        time.sleep(1.0)


if __name__ == "__main__":
    sys.exit(main())
