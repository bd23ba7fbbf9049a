#!/usr/bin/env python3
"""Idle keep-alive connections, slow clients and oversized bodies must not hold up other
clients.

(c) open ten times the worker count of idle keep-alive connections, then GET /healthz
    must answer within 100 ms;
(d) clients that send a request a byte a second, and clients that announce or send an
    oversized body, while a normal client's POST /evaluate answers within 100 ms each.

    tests/load/slow_clients.py [service-binary]
"""
import json
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BINARY = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build/test/service/bezier-service")
THREADS = 4
BODY = json.dumps({"points": [[0, 0], [1, 2], [3, 3], [4, 0]], "t": 0.5}).encode()


def start_service():
    proc = subprocess.Popen([BINARY, "--port", "0", "--threads", str(THREADS), "--log-level", "warn"],
                            stdout=subprocess.PIPE, text=True)
    line = proc.stdout.readline()
    port = int(line.rsplit(":", 1)[1])
    threading.Thread(target=proc.stdout.read, daemon=True).start()  # keep the pipe drained
    return proc, port


def request(port, method, path, body=b""):
    """One request on a fresh connection; returns (status, seconds)."""
    start = time.monotonic()
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        head = f"{method} {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n"
        if body:
            head += f"Content-Type: application/json\r\nContent-Length: {len(body)}\r\n"
        s.sendall(head.encode() + b"\r\n" + body)
        data = b""
        while chunk := s.recv(65536):
            data += chunk
    return int(data.split(b" ", 2)[1]), time.monotonic() - start


def check(name, status, seconds, expected=200, limit=0.1):
    ok = status == expected and seconds < limit
    print(f"{'ok  ' if ok else 'FAIL'} {name}: status {status}, {seconds * 1000:.1f} ms")
    return ok


def main():
    proc, port = start_service()
    ok = True
    stop = threading.Event()
    try:
        # (c) idle keep-alive connections, ten per worker thread.
        idle = []
        for _ in range(10 * THREADS):
            s = socket.create_connection(("127.0.0.1", port))
            s.sendall(b"GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n")
            s.recv(4096)  # answered; the connection stays open and idle
            idle.append(s)
        status, seconds = request(port, "GET", "/healthz")
        ok &= check(f"GET /healthz with {len(idle)} idle keep-alive connections open", status, seconds)

        # (d) slow clients: a byte a second, each holding a connection mid-request.

        def slow_client():
            data = b"POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n" \
                   b"Content-Length: %d\r\n\r\n" % len(BODY) + BODY
            try:
                with socket.create_connection(("127.0.0.1", port)) as s:
                    for byte in data:
                        if stop.is_set():
                            return
                        s.sendall(bytes([byte]))
                        time.sleep(1)
            except OSError:
                pass  # the service may time the slow client out: that is the point

        slow = [threading.Thread(target=slow_client, daemon=True) for _ in range(4 * THREADS)]
        for t in slow:
            t.start()

        # Oversized bodies: announced (Content-Length over the limit) and sent for real.
        status, seconds = request(port, "POST", "/evaluate", b"{\"pad\":\"" + b"x" * (2 << 20) + b"\"}")
        ok &= check("oversized body (2 MiB) is refused", status, seconds, expected=413, limit=1.0)
        # The service answers 413 as soon as it reads a Content-Length over the limit; at
        # worst such a connection is released by the read timeout (5 s by default), and
        # it never holds up the other connections.
        start = time.monotonic()
        with socket.create_connection(("127.0.0.1", port), timeout=10) as s:
            s.sendall(b"POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
                      b"Content-Length: 1000000000\r\n\r\n{")
            s.recv(4096)  # an answer, or the connection closed
        ok &= check("announced 1 GB body, never sent: connection released by the read timeout",
                    200, time.monotonic() - start, limit=6.5)

        time.sleep(2)  # the slow clients are mid-request now
        worst = 0.0
        for _ in range(20):
            status, seconds = request(port, "POST", "/evaluate", BODY)
            ok &= status == 200
            worst = max(worst, seconds)
        ok &= check(f"20 POST /evaluate with {len(slow)} byte-a-second clients connected (slowest)", 200, worst)
        stop.set()
        for s in idle:
            s.close()
    finally:
        stop.set()
        proc.terminate()
        proc.wait(timeout=10)
    print("OK" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
