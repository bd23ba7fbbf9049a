#!/usr/bin/env python3
"""CPU time the service spends on one request, read from /proc of its process.

Starts BINARY (with the service flags given after --), sends the JSON body of FILE (or stdin) to
PATH REPEAT times, one after the other, and prints, for each request, its status and the
service's utime + stime spent on it (fields 14 and 15 of /proc/<pid>/stat, in clock
ticks, so the resolution is 1/CLK_TCK s); then the median and the largest. What the
figures in docs/WORK_CAPS.md were measured with:

    python3 tools/request_cpu.py build/service/bezier-service /intersections body.json --repeat 5
    python3 tools/request_cpu.py build/service/bezier-service /batch batch.json -- --threads 1
"""
import argparse
import http.client
import os
import socket
import statistics
import subprocess
import sys
import time


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as f:
        stat = f.read()
    fields = stat[stat.rfind(")") + 2:].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("binary")
    parser.add_argument("path")
    parser.add_argument("body", nargs="?", default="-", help="file with the JSON body, - for stdin")
    parser.add_argument("--repeat", type=int, default=3)
    argv = sys.argv[1:]
    flags = argv[argv.index("--") + 1:] if "--" in argv else []
    args = parser.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    body = sys.stdin.buffer.read() if args.body == "-" else open(args.body, "rb").read()
    port = free_port()
    service = subprocess.Popen([args.binary, "--port", str(port), *flags],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        for _ in range(100):
            try:
                socket.create_connection(("127.0.0.1", port), timeout=1).close()
                break
            except OSError:
                time.sleep(0.05)
        spent = []
        for _ in range(args.repeat):
            before = cpu_seconds(service.pid)
            connection = http.client.HTTPConnection("127.0.0.1", port, timeout=600)
            connection.request("POST", args.path, body, {"Content-Type": "application/json"})
            answer = connection.getresponse()
            answer.read()
            connection.close()
            spent.append(cpu_seconds(service.pid) - before)
            print(f"status {answer.status}  cpu {spent[-1]:.3f} s")
        print(f"median {statistics.median(spent):.3f} s  largest {max(spent):.3f} s")
    finally:
        service.terminate()
        service.wait()


if __name__ == "__main__":
    main()
