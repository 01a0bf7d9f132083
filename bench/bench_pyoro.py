"""How long after its `ok` the callback of an event runs, with pyoro.

    python3 bench/bench_pyoro.py [--adds=200] [--rounds=3]

Starts a server on a free loopback port, subscribes a NEW_INSTANCE
watcher with clients/python's pyoro, then makes N adds one after the
other, each firing the watcher once.  For each add it takes the time
the reader thread read the `ok` (the reply future's completion) and the
time the callback starts on the dispatcher thread, and prints the
distribution of the difference: for the client's own adds, and for
adds made by a second client (the event then crosses connections).
"""

import argparse
import os
import statistics
import sys
import threading
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "clients", "python", "tests"))

import support                                   # noqa: E402  (adds pyoro to the path)
from pyoro import Oro                           # noqa: E402


def measure(watcher, writer, adds, tag):
    """Delays (s) from each add's `ok` on ``writer`` to its callback on ``watcher``."""
    target = support.fresh(tag)
    ok_at, callback_at = {}, {}
    all_done = threading.Event()

    def callback(content):
        callback_at[content[0]] = time.perf_counter()
        if len(callback_at) == adds:
            all_done.set()

    watcher.subscribe(["?a isAt %s" % target], callback)
    for i in range(adds):
        thing = "t%d_%s" % (i, target)
        future = writer.call_async("add", ["%s isAt %s" % (thing, target)])
        future.add_done_callback(lambda f, t=thing: ok_at.__setitem__(t, time.perf_counter()))
        future.result(support.WAIT)
    if not all_done.wait(support.WAIT):
        raise SystemExit("only %d callbacks of %d" % (len(callback_at), adds))
    return [callback_at[t] - ok_at[t] for t in ok_at]


def row(name, delays):
    ms = sorted(d * 1000 for d in delays)
    p = lambda q: ms[min(len(ms) - 1, int(q * len(ms)))]
    within = sum(1 for d in ms if d <= 10.0)
    return "| %-22s | %5d | %6.3f | %6.3f | %6.3f | %6.3f | %7.3f | %5d |" % (
        name, len(ms), ms[0], statistics.median(ms), p(0.95), p(0.99), ms[-1], within)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--adds", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=3)
    options = parser.parse_args()
    server = support.Server()
    try:
        own, other = [], []
        with Oro("127.0.0.1", server.port) as oro, Oro("127.0.0.1", server.port) as second:
            measure(oro, oro, 20, "warm")
            for _ in range(options.rounds):
                own += measure(oro, oro, options.adds, "own")
                other += measure(oro, second, options.adds, "other")
        print("Delay from an add's `ok` (read by the reader thread) to the start of "
              "its callback, ms")
        print("| %-22s | %5s | %6s | %6s | %6s | %6s | %7s | %5s |" % (
            "events of", "n", "min", "median", "p95", "p99", "max", "<=10ms"))
        print("|%s|" % "|".join("-" * w for w in (24, 7, 8, 8, 8, 8, 9, 7)))
        print(row("the client's own adds", own))
        print(row("another client's adds", other))
    finally:
        server.stop()


if __name__ == "__main__":
    main()
