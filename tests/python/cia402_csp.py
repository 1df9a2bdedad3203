"""An unmodified python-canopen master drives the firmware as a CiA 402
servo over socketcand (python-can's `socketcand` interface):

1. imports the drive's EDS (docs/canopen/drive.eds) and reads every object
   in it over SDO, checking each value's length against the EDS's data type;
2. maps RPDO1 (controlword, target position) and TPDO1 (statusword,
   position actual value), both synchronous, with python-canopen's PDO
   API, then NMT start;
3. mode 8 (cyclic synchronous position), controlword 6, 7, 15: Operation
   enabled;
4. SYNCS cycles: a target position in RPDO1, then a SYNC; each SYNC must
   be answered by exactly one TPDO1; the target ramps by STEP counts per
   SYNC, then holds;
5. the position after the stream is within one count of the last target;
6. refusals while enabled, each with CiA 301's abort code;
7. homing method 37: the position becomes 0, statusword bits 12 and 10.

usage: cia402_csp.py PORT EDS [SYNCS]
Prints one line per check and the measured figures; exits non-zero on the
first failure.
"""
import struct
import sys
import threading
import time

import canopen
from canopen.objectdictionary import ODArray, ODRecord, ODVariable
from canopen.objectdictionary import datatypes as dt

NODE_ID = 1
# Target ramp: counts per SYNC while ramping, and how many SYNCs ramp.
STEP = 2
RAMP = 1000
SIZES = {
    dt.BOOLEAN: 1,
    dt.INTEGER8: 1,
    dt.UNSIGNED8: 1,
    dt.INTEGER16: 2,
    dt.UNSIGNED16: 2,
    dt.INTEGER32: 4,
    dt.UNSIGNED32: 4,
    dt.REAL32: 4,
}
# CiA 301: "no data available", the answer for 0x1003's empty history.
NO_DATA = 0x0800_0024


def fail(msg: str) -> int:
    print(f"FAIL: {msg}")
    return 1


def variables(od):
    for obj in od.values():
        if isinstance(obj, ODVariable):
            yield obj
        elif isinstance(obj, (ODRecord, ODArray)):
            for sub in obj.values():
                yield sub


def read_every_object(node) -> int:
    read = no_data = 0
    for var in variables(node.object_dictionary):
        if not var.readable:
            continue
        try:
            raw = node.sdo.upload(var.index, var.subindex)
        except canopen.SdoAbortedError as e:
            if e.code == NO_DATA and var.index == 0x1003:
                no_data += 1
                continue
            print(f"FAIL: 0x{var.index:04X}:{var.subindex} aborted 0x{e.code:08X}")
            return -1
        size = SIZES.get(var.data_type)
        if size is not None and len(raw) != size:
            print(f"FAIL: 0x{var.index:04X}:{var.subindex} {len(raw)} bytes, EDS type 0x{var.data_type:04X}")
            return -1
        if var.data_type == dt.VISIBLE_STRING and not raw:
            print(f"FAIL: 0x{var.index:04X} empty string")
            return -1
        read += 1
    print(f"EDS objects read: {read}, with the type's length; 0x1003 entries without data: {no_data}")
    return read


def main() -> int:
    port = int(sys.argv[1])
    eds = sys.argv[2]
    syncs = int(sys.argv[3]) if len(sys.argv) > 3 else 2000
    net = canopen.Network()
    # tcp_tune: python-can's own low-latency option (TCP_NODELAY, quick
    # ACKs); without it each SYNC waits for the client's delayed ACK of the
    # RPDO before it (about 45 ms).
    net.connect(
        interface="socketcand", host="127.0.0.1", port=port, channel="can0", tcp_tune=True
    )
    try:
        node = canopen.RemoteNode(NODE_ID, eds)
        net.add_node(node)
        # Generous: QEMU with the co-simulated RTL on a loaded host answers
        # late, never wrongly.
        node.sdo.RESPONSE_TIMEOUT = 10.0

        if read_every_object(node) < 100:
            return fail("too few EDS objects read")

        node.nmt.state = "PRE-OPERATIONAL"
        node.tpdo.read()
        node.rpdo.read()
        node.rpdo[1].clear()
        node.rpdo[1].add_variable(0x6040)
        node.rpdo[1].add_variable(0x607A)
        node.rpdo[1].trans_type = 1
        node.rpdo[1].enabled = True
        node.tpdo[1].clear()
        node.tpdo[1].add_variable(0x6041)
        node.tpdo[1].add_variable(0x6064)
        node.tpdo[1].trans_type = 1
        node.tpdo[1].enabled = True
        for n in (2, 3, 4):
            node.tpdo[n].enabled = False
            node.rpdo[n].enabled = False
        node.rpdo.save()
        node.tpdo.save()
        print("PDOs mapped: RPDO1 0x6040+0x607A, TPDO1 0x6041+0x6064, synchronous")

        # The loop under CSP: the FOC (0x2100 = 0) for a short first
        # enable; mode 8.
        node.sdo[0x2100].raw = 0
        node.sdo[0x6060].raw = 8
        node.nmt.state = "OPERATIONAL"
        start = node.sdo[0x6064].raw
        for cw in (0x06, 0x07, 0x0F):
            node.sdo[0x6040].raw = cw
        sw = node.sdo[0x6041].raw
        print(f"statusword after enable = 0x{sw:04X}")
        if sw & 0x6F != 0x27:
            return fail("not Operation enabled")
        if node.sdo[0x6061].raw != 8:
            return fail("0x6061 is not 8")

        received = []
        lock = threading.Condition()

        def on_tpdo(msg):
            with lock:
                received.append((msg["Statusword"].raw, msg["Position actual value"].raw))
                lock.notify_all()

        node.tpdo[1].add_callback(on_tpdo)
        missing = extra = 0
        target = start
        t0 = time.monotonic()
        worst = 0.0
        for k in range(syncs):
            target = start + STEP * min(k, RAMP, syncs // 2)
            node.rpdo[1]["Controlword"].raw = 0x0F
            node.rpdo[1]["Target position"].raw = target
            node.rpdo[1].transmit()
            before = len(received)
            t = time.monotonic()
            net.sync.transmit()
            with lock:
                ok = lock.wait_for(lambda: len(received) > before, timeout=10.0)
            worst = max(worst, time.monotonic() - t)
            if not ok:
                missing += 1
                if missing > 3:
                    return fail(f"SYNC {k}: no TPDO")
        # Late duplicates would arrive now.
        time.sleep(0.5)
        extra = len(received) - (syncs - missing)
        elapsed = time.monotonic() - t0
        print(
            f"SYNCs {syncs}, TPDOs {len(received)}, missing {missing}, extra {extra}, "
            f"{syncs / elapsed:.0f} SYNC/s, worst SYNC-to-TPDO {worst * 1e3:.1f} ms wall"
        )
        if missing or extra:
            return fail("not exactly one TPDO per SYNC")
        bad = [sw for sw, _ in received if sw & 0x6F != 0x27]
        if bad:
            return fail(f"{len(bad)} TPDOs without Operation enabled, first 0x{bad[0]:04X}")
        # Hold the last target; the position settles on it.
        end = time.monotonic() + 30.0
        pos = None
        while time.monotonic() < end:
            pos = node.sdo[0x6064].raw
            if abs(pos - target) <= 1:
                break
            time.sleep(0.2)
        fe = node.sdo[0x60F4].raw
        print(f"target {target}, position {pos}, following error {fe} counts")
        if pos is None or abs(pos - target) > 1:
            return fail("the position did not reach the last target")
        # Refusals while enabled, each with CiA 301's abort code.
        for what, call, want in (
            ("read-only 0x6041", lambda: node.sdo.download(0x6041, 0, b"\x00\x00"), 0x0601_0002),
            ("unknown 0x2FFF", lambda: node.sdo.upload(0x2FFF, 0), 0x0602_0000),
            ("sub-index 0x1018:9", lambda: node.sdo.upload(0x1018, 9), 0x0609_0011),
            ("too long 0x6071", lambda: node.sdo.download(0x6071, 0, b"\x01\x02\x03\x04"), 0x0607_0012),
            ("0x6072 = 1001", lambda: node.sdo.download(0x6072, 0, (1001).to_bytes(2, "little")), 0x0609_0031),
            ("0x2000 (motor_r_s) with the gates on", lambda: node.sdo.download(0x2000, 0, struct.pack("<f", 0.5)), 0x0800_0022),
        ):
            try:
                call()
            except canopen.SdoAbortedError as e:
                if e.code != want:
                    return fail(f"{what}: abort 0x{e.code:08X}, expected 0x{want:08X}")
                print(f"refused: {what}: 0x{e.code:08X}")
                continue
            return fail(f"{what}: accepted")
        # Homing, method 37: the present position becomes 0, statusword
        # bit 12 (homing attained) and bit 10 (target reached).
        node.sdo[0x6098].raw = 37
        node.sdo[0x6060].raw = 6
        end = time.monotonic() + 30.0
        while time.monotonic() < end:
            sw = node.sdo[0x6041].raw
            if sw & 0x1400 == 0x1400:
                break
            time.sleep(0.1)
        # The position loop holds the new 0 (a count of transient first).
        while time.monotonic() < end:
            home = node.sdo[0x6064].raw
            if abs(home) <= 1:
                break
            time.sleep(0.1)
        print(f"homing: statusword 0x{sw:04X}, position {home}")
        if sw & 0x1400 != 0x1400 or abs(home) > 1:
            return fail("homing method 37 did not end at 0")
        node.sdo[0x6040].raw = 0x00
        print("OK")
        return 0
    finally:
        net.disconnect()


if __name__ == "__main__":
    sys.exit(main())
