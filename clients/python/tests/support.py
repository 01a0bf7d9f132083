"""Helpers of the pyoro tests: a real oro server on a free loopback port,
and a scripted fake server for what a real one cannot be made to do."""

import os
import re
import shutil
import socket
import subprocess
import sys
import threading
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CLIENT_ROOT = os.path.dirname(HERE)                      # clients/python
REPO = os.path.dirname(os.path.dirname(CLIENT_ROOT))
SERVER = os.path.join(REPO, "server", "oro_server.pl")

if CLIENT_ROOT not in sys.path:
    sys.path.insert(0, CLIENT_ROOT)

WAIT = 30.0          # bound of every wait on a condition (seconds)


class Server:
    """``swipl server/oro_server.pl --port=0``, stopped by its PID."""

    def __init__(self, *args):
        swipl = shutil.which("swipl")
        if swipl is None:
            raise unittest.SkipTest("swipl is not installed")
        self.process = subprocess.Popen(
            [swipl, SERVER, "--port=0", "--http=0"] + list(args),
            stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT, text=True)
        self.port = None
        deadline = time.monotonic() + WAIT
        reader = threading.Thread(target=self._read_port, daemon=True)
        reader.start()
        reader.join(max(0.0, deadline - time.monotonic()))
        if self.port is None:
            self.stop()
            raise RuntimeError("the server did not say where it listens")

    def _read_port(self):
        for line in self.process.stdout:
            match = re.match(r"oro listening on (\S+):(\d+)$", line.strip())
            if match:
                self.port = int(match.group(2))
                break
        # keep draining, so that the server never blocks on its output
        self.drain = threading.Thread(target=self.process.stdout.read, daemon=True)
        self.drain.start()

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(WAIT)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(WAIT)
        drain = getattr(self, "drain", None)
        if drain is not None:
            drain.join(WAIT)
        if drain is None or not drain.is_alive():
            self.process.stdout.close()


class FakeServer:
    """A loopback server that answers ``listSimpleMethods`` and ``close``
    and lets the test script the rest: ``respond(request)`` gives the
    reply to each other request (lists of lines), ``requests`` collects
    them all, ``send(text)`` writes to the client."""

    def __init__(self, methods=("add(Set)", "hello()", "find(String, Set)"),
                 respond=None):
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.methods = methods
        self.respond = respond              # request lines -> reply text, or None
        self.requests = []
        self.cond = threading.Condition()
        self.conn = None
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        conn, _ = self.listener.accept()
        self.conn = conn
        stream = conn.makefile("rb")
        request = []
        for raw in stream:
            line = raw.decode().rstrip("\n")
            if line != "#end#":
                request.append(line)
                continue
            if request == ["close"]:
                with self.cond:
                    self.requests.append(request)
                    self.cond.notify_all()
                self.send("Closing now!\n")
                self.conn.shutdown(socket.SHUT_RDWR)
                break
            if request == ["listSimpleMethods"]:
                body = ",".join('"%s"' % m for m in self.methods)
                self.send("ok\n[%s]\n#end#\n" % body)
            elif self.respond is not None:
                reply = self.respond(request)
                if reply is not None:
                    self.send(reply)
            with self.cond:
                self.requests.append(request)
                self.cond.notify_all()
            request = []

    def wait_requests(self, count):
        with self.cond:
            if not self.cond.wait_for(lambda: len(self.requests) >= count, WAIT):
                raise AssertionError("the client sent %d requests, not %d"
                                     % (len(self.requests), count))
            return list(self.requests)

    def send(self, text):
        self.conn.sendall(text.encode())

    def close(self):
        if self.conn is not None:
            try:
                self.conn.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            self.conn.close()
        self.listener.close()


_counter = [0]
_counter_lock = threading.Lock()


def fresh(prefix="x"):
    """A name no other test uses (the server keeps its knowledge)."""
    with _counter_lock:
        _counter[0] += 1
        return "%s%d_%d" % (prefix, os.getpid(), _counter[0])


class RecordingProxy:
    """A loopback TCP proxy to ``port`` that keeps every byte the server
    sends (``from_server``, one bytes object per connection), so that a
    test can tell what the server wrote from what the client made of it."""

    def __init__(self, port):
        self.target = port
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.records = []
        self.pumps = []
        self.thread = threading.Thread(target=self._accept, daemon=True)
        self.thread.start()

    def _accept(self):
        while True:
            try:
                client, _ = self.listener.accept()
            except OSError:
                return
            server = socket.create_connection(("127.0.0.1", self.target), WAIT)
            record = bytearray()
            self.records.append(record)
            for source, sink, keep in ((client, server, None), (server, client, record)):
                pump = threading.Thread(target=self._pump, args=(source, sink, keep),
                                        daemon=True)
                pump.start()
                self.pumps.append(pump)

    @staticmethod
    def _pump(source, sink, keep):
        try:
            while True:
                data = source.recv(65536)
                if not data:
                    break
                if keep is not None:
                    keep.extend(data)
                sink.sendall(data)
        except OSError:
            pass
        finally:
            for s in (sink, source):
                try:
                    s.shutdown(socket.SHUT_RDWR)
                except OSError:
                    pass

    def from_server(self):
        """What the server sent on each connection, once every one ended."""
        for pump in list(self.pumps):
            pump.join(WAIT)
        return [bytes(r) for r in self.records]

    def close(self):
        self.listener.close()
