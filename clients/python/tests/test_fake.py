"""What a real server cannot be made to do: late replies, lost connections."""

import threading
import unittest

import support
from support import WAIT
from pyoro import Oro, OroConnectionError, OroServerError, OroTimeout


class FakeServerTest(unittest.TestCase):

    def setUp(self):
        self.fake = support.FakeServer()
        self.addCleanup(self.fake.close)
        self.oro = Oro("127.0.0.1", self.fake.port)
        self.addCleanup(self.oro.close, 1.0)

    def test_timeout_keeps_replies_in_step(self):
        with self.assertRaises(OroTimeout):
            self.oro.hello(timeout=0.05)            # the fake does not answer yet
        self.assertTrue(issubclass(OroTimeout, TimeoutError))
        self.assertTrue(issubclass(OroTimeout, OroServerError))
        future = self.oro.call_async("hello")
        self.fake.wait_requests(3)
        self.fake.send('ok\n"late"\n#end#\nok\n"second"\n#end#\n')
        self.assertEqual(future.result(WAIT), "second")

    def test_request_lines(self):
        self.oro.call_async("add", ["a b c", "d e \"f\""])
        requests = self.fake.wait_requests(2)
        self.assertEqual(requests[1], ["add", '["a b c","d e \\"f\\""]'])

    def test_error_reply_and_unknown_status(self):
        first = self.oro.call_async("hello")
        second = self.oro.call_async("hello")
        self.fake.wait_requests(3)
        self.fake.send("error\nSomeException\nline one\nline two\n#end#\n"
                       "weird\n#end#\n")
        with self.assertRaises(OroServerError) as caught:
            first.result(WAIT)
        self.assertEqual(caught.exception.name, "SomeException")
        self.assertEqual(caught.exception.message, "line one\nline two")
        with self.assertRaises(OroServerError):
            second.result(WAIT)

    def test_lost_connection_fails_waiting_calls(self):
        results = []

        def call():
            try:
                self.oro.hello()
            except OroConnectionError as e:
                results.append(e)

        thread = threading.Thread(target=call)
        thread.start()
        self.fake.wait_requests(2)
        self.fake.close()
        thread.join(WAIT)
        self.assertEqual(len(results), 1)
        with self.assertRaises(OroConnectionError):
            self.oro.hello()

    def test_event_for_an_unknown_watcher_is_dropped(self):
        future = self.oro.call_async("hello")
        self.fake.wait_requests(2)
        with self.assertLogs("pyoro", "WARNING"):
            self.fake.send("event\nnot-a-watcher\n[\"x\"]\n#end#\nok\n\"hi\"\n#end#\n")
            self.assertEqual(future.result(WAIT), "hi")


if __name__ == "__main__":
    unittest.main()
