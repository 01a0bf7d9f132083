"""The ORO wiki's pyoro example, run unchanged as a script."""

import os
import socket
import subprocess
import sys
import unittest

import support
from support import WAIT, CLIENT_ROOT

EXAMPLE = os.path.join(CLIENT_ROOT, "examples", "james_bond.py")


def own_events_before_close(port, rounds=10):
    """Whether the server wrote, in each of ``rounds`` tries, the event an
    ``add`` caused before its answer to the ``close`` that followed (as
    ORO-SPEC section 1.4 asks)."""
    for i in range(rounds):
        with socket.create_connection(("127.0.0.1", port), WAIT) as s:
            stream = s.makefile("rb")

            def request(*lines):
                s.sendall(("\n".join(lines) + "\n#end#\n").encode())
                while stream.readline() not in (b"#end#\n", b""):
                    pass

            name = support.fresh("spectre")
            request("registerEventForAgent", "myself", "NEW_INSTANCE", "ON_TRUE",
                    "?a", "[?a kills %s]" % name)
            request("add", "[hrp2 kills %s]" % name)
            s.sendall(b"close\n#end#\n")
            if b"\nevent\n" not in b"\n" + stream.read():
                return False
    return True


class ExampleTest(unittest.TestCase):

    def test_wiki_example_runs_unchanged(self):
        server = support.Server()
        self.addCleanup(server.stop)
        env = dict(os.environ, ORO_PORT=str(server.port), PYTHONPATH=CLIENT_ROOT)
        run = subprocess.run([sys.executable, EXAMPLE], env=env, cwd=CLIENT_ROOT,
                             capture_output=True, text=True, timeout=WAIT)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(run.stderr, "")
        lines = run.stdout.splitlines()
        self.assertEqual(lines[0], "['bond', 'INSTANCE']")
        if lines[1:] == [] and not own_events_before_close(server.port):
            self.skipTest("this server answers a request before writing the events "
                          "the previous one caused (ORO-SPEC 1.4): the example's "
                          "event was lost by the server, not by pyoro")
        self.assertEqual(lines[1:], ["God save the queen! hrp2 killed Bond!"])


if __name__ == "__main__":
    unittest.main()
