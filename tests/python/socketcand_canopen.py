"""The firmware's socketcand server seen by unmodified python-can
(`socketcand` interface) and canopen from PyPI: SDO uploads of the device
type and identity, NMT start and the heartbeat that follows.

usage: socketcand_canopen.py PORT   (the host port forwarded to the drive)
Prints one line per check; exits non-zero on the first mismatch.
"""
import sys

import canopen

# CiA 402 servo drive: profile 0x0192, additional information 0x0002.
DEVICE_TYPE = 0x0002_0192
NODE_ID = 1


def main() -> int:
    port = int(sys.argv[1])
    net = canopen.Network()
    net.connect(interface="socketcand", host="127.0.0.1", port=port, channel="can0")
    try:
        node = canopen.RemoteNode(NODE_ID, None)
        net.add_node(node)
        node.sdo.RESPONSE_TIMEOUT = 2.0
        raw = node.sdo.upload(0x1000, 0)
        print(f"0x1000:00 = {raw.hex()}")
        if raw != DEVICE_TYPE.to_bytes(4, "little"):
            print(f"FAIL: device type {raw.hex()}, expected {DEVICE_TYPE:08x} little-endian")
            return 1
        count = node.sdo.upload(0x1018, 0)
        print(f"0x1018:00 = {count.hex()}")
        if count != b"\x04":
            print("FAIL: 0x1018:00 is not 4")
            return 1
        # NMT start; the next heartbeats say operational. The 100 ms heartbeat
        # takes 0.33 s of wall time under QEMU, whose A9 timers run at 0.3x
        # of the board's rate.
        node.nmt.state = "OPERATIONAL"
        state = None
        for _ in range(3):
            state = node.nmt.wait_for_heartbeat(timeout=5.0)
            if state == "OPERATIONAL":
                break
        print(f"heartbeat state = {state}")
        if state != "OPERATIONAL":
            print("FAIL: no operational heartbeat")
            return 1
        print("OK")
        return 0
    finally:
        net.disconnect()


if __name__ == "__main__":
    sys.exit(main())
