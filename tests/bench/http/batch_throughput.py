#!/usr/bin/env python3
"""Wall time of N /classify requests sent one after another on one keep-alive connection,
against one POST /batch of the same N items, on a freshly started bezier-service.

The cubics are the shared benchmark stream's (BENCHMARKS.md, "Benchmark input": mulberry32 seeded with 1; the
single cubics follow the 20000 intersection pairs). The client is a raw socket that sends
prepared bytes and reads each answer by its Content-Length, so its own cost per request
is a few microseconds and the keep-alive figure is the service's and the loopback's. Each
round times both (in alternating order) and checks that every batch item is byte for byte
the answer of the same request sent alone; the medians and their ratio are printed, and
the fastest rounds' ratio. On a shared machine wall times swing with the other work on
the CPUs, so the service's own CPU time for each (the sum over its threads of
/proc/PID/task/*/schedstat, nanoseconds on a CPU) is printed too.

    tests/bench/http/batch_throughput.py [service-binary] [--items N] [--rounds R]
"""
import argparse
import json
import os
import re
import socket
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_BINARY = os.path.join(HERE, "..", "..", "..", "build", "test", "service", "bezier-service")


def mulberry32_draws(seed):
    """The benchmark input's generator (BENCHMARKS.md): each draw in [0, 1)."""
    a = seed & 0xFFFFFFFF
    mask = 0xFFFFFFFF
    while True:
        a = (a + 0x6D2B79F5) & mask
        t = ((a ^ (a >> 15)) * (a | 1)) & mask
        t = ((t + (((t ^ (t >> 7)) * (t | 61)) & mask)) & mask) ^ t
        yield ((t ^ (t >> 14)) & mask) / 4294967296.0


def benchmark_cubics(count):
    draws = mulberry32_draws(1)
    for _ in range(20000 * 16):  # the intersection pairs come first
        next(draws)
    cubics = []
    for _ in range(count):
        cubics.append([[next(draws), next(draws)] for _ in range(4)])
    return cubics


def start_service(binary):
    process = subprocess.Popen([binary, "--port", "0", "--log-level", "warn"], stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    for line in process.stdout:
        match = re.search(r"listening on http://([0-9.]+):([0-9]+)", line)
        if match:
            return process, match.group(1), int(match.group(2))
    raise RuntimeError("the service did not start")


def service_cpu_ns(pid):
    """Nanoseconds the process's threads have run on a CPU (first field of schedstat)."""
    total = 0
    for task in os.listdir(f"/proc/{pid}/task"):
        try:
            with open(f"/proc/{pid}/task/{task}/schedstat") as f:
                total += int(f.read().split()[0])
        except FileNotFoundError:
            pass
    return total


def request_bytes(path, body):
    data = body.encode()
    head = (f"POST {path} HTTP/1.1\r\nHost: bench\r\nContent-Type: application/json\r\n"
            f"Content-Length: {len(data)}\r\n\r\n")
    return head.encode() + data


class Connection:
    def __init__(self, host, port):
        self.sock = socket.create_connection((host, port))
        self.sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self.buffer = b""

    def exchange(self, raw):
        """Sends one request, returns (status, body bytes)."""
        self.sock.sendall(raw)
        while b"\r\n\r\n" not in self.buffer:
            self.buffer += self.sock.recv(1 << 20)
        head, _, rest = self.buffer.partition(b"\r\n\r\n")
        length = int(re.search(rb"\r\nContent-Length: (\d+)", head).group(1))
        while len(rest) < length:
            rest += self.sock.recv(1 << 20)
        self.buffer = rest[length:]
        return int(head[9:12]), rest[:length]

    def close(self):
        self.sock.close()


def time_one_by_one(host, port, requests):
    connection = Connection(host, port)
    start = time.perf_counter()
    answers = [connection.exchange(raw) for raw in requests]
    elapsed = time.perf_counter() - start
    connection.close()
    return elapsed, answers


def time_batch(host, port, batch):
    connection = Connection(host, port)
    start = time.perf_counter()
    answer = connection.exchange(batch)
    elapsed = time.perf_counter() - start
    connection.close()
    return elapsed, answer


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary", nargs="?", default=DEFAULT_BINARY)
    parser.add_argument("--items", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=9)
    args = parser.parse_args()

    bodies = [json.dumps({"points": c}, separators=(",", ":")) for c in benchmark_cubics(args.items)]
    singles = [request_bytes("/classify", b) for b in bodies]
    batch = request_bytes("/batch", '{"requests":[' + ",".join(
        '{"path":"/classify","body":' + b + "}" for b in bodies) + "]}")

    process, host, port = start_service(args.binary)
    try:
        # Warm-up, and the byte-for-byte check of the batch against the answers alone.
        _, alone = time_one_by_one(host, port, singles)
        _, (status, batch_answer) = time_batch(host, port, batch)
        expected = b'{"responses":[' + b",".join(
            b'{"body":' + body + b',"status":' + str(s).encode() + b"}" for s, body in alone) + b"]}"
        if status != 200 or batch_answer != expected:
            sys.exit("the batch's answer is not the answers of its items sent alone")

        one_by_one, batched = [], []
        cpu = {0: [], 1: []}
        for r in range(args.rounds):
            order = [0, 1] if r % 2 == 0 else [1, 0]
            for which in order:
                before = service_cpu_ns(process.pid)
                if which == 0:
                    one_by_one.append(time_one_by_one(host, port, singles)[0])
                else:
                    batched.append(time_batch(host, port, batch)[0])
                cpu[which].append(service_cpu_ns(process.pid) - before)
    finally:
        process.terminate()
        process.wait()

    keep_alive = statistics.median(one_by_one)
    single_batch = statistics.median(batched)
    print(f"{args.items} /classify requests on one keep-alive connection: median {keep_alive * 1e3:.2f} ms "
          f"({keep_alive / args.items * 1e6:.1f} us each; rounds {min(one_by_one) * 1e3:.2f}-{max(one_by_one) * 1e3:.2f} ms)")
    print(f"one /batch of the same {args.items} items ({len(batch)} bytes in, {len(batch_answer)} out): "
          f"median {single_batch * 1e3:.2f} ms (rounds {min(batched) * 1e3:.2f}-{max(batched) * 1e3:.2f} ms)")
    print(f"batch / keep-alive wall time: 1/{keep_alive / single_batch:.1f} (medians), "
          f"1/{min(one_by_one) / min(batched):.1f} (fastest rounds)")
    cpu_keep_alive = statistics.median(cpu[0]) * 1e-6
    cpu_batch = statistics.median(cpu[1]) * 1e-6
    print(f"service CPU time, median: {cpu_keep_alive:.2f} ms for the {args.items} requests, "
          f"{cpu_batch:.2f} ms for the batch: 1/{cpu_keep_alive / cpu_batch:.1f}")


if __name__ == "__main__":
    main()
