#!/usr/bin/env python3
"""Raw capture of one network link for the end-to-end tests: every frame seen on IFACE is
appended to OUT until SIGTERM or SECONDS pass. The test then looks for clear text in OUT.

    capture_link.py IFACE OUT SECONDS

Needs root (an AF_PACKET socket). Prints "capturing" once the socket is bound, so the caller
can wait for that line before it starts the traffic."""
import signal
import socket
import sys
import time

ETH_P_ALL = 0x0003


def main():
    iface, out_file, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3])
    sock = socket.socket(socket.AF_PACKET, socket.SOCK_RAW, socket.htons(ETH_P_ALL))
    sock.bind((iface, 0))
    sock.settimeout(0.2)
    stop = []
    signal.signal(signal.SIGTERM, lambda *_: stop.append(True))
    frames = 0
    deadline = time.monotonic() + seconds
    print("capturing", flush=True)
    with open(out_file, "wb") as out:
        while not stop and time.monotonic() < deadline:
            try:
                frame = sock.recv(65536)
            except socket.timeout:
                continue
            out.write(frame)
            frames += 1
    print(f"captured {frames} frames", flush=True)


if __name__ == "__main__":
    main()
