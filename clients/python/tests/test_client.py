"""pyoro against a real oro server on a free loopback port."""

import socket
import threading
import unittest

import support
from support import WAIT, fresh
from pyoro import IdList, Oro, OroConnectionError, OroServerError, quote

server = None


def setUpModule():
    global server
    server = support.Server()


def tearDownModule():
    if server is not None:
        server.stop()


class Collector:
    """A callback that records what it gets; ``wait(n)`` for n calls."""

    def __init__(self):
        self.items = []
        self.cond = threading.Condition()

    def __call__(self, content):
        with self.cond:
            self.items.append(content)
            self.cond.notify_all()

    def wait(self, count):
        with self.cond:
            self.cond.wait_for(lambda: len(self.items) >= count, WAIT)
            return list(self.items)


class ClientTest(unittest.TestCase):

    def setUp(self):
        self.oro = Oro("127.0.0.1", server.port, timeout=WAIT)

    def tearDown(self):
        self.oro.close()

    def test_methods_come_from_the_server(self):
        self.assertIn("findForAgent", self.oro.rpc_methods)
        self.assertEqual(self.oro.hello(), "oro-server 0.8.2")
        self.assertTrue(callable(self.oro.getResourceDetails))

    def test_typed_values(self):
        bond = fresh("bond")
        self.assertIsNone(self.oro.add(["%s rdf:type Human" % bond]))
        self.assertIs(self.oro.check(["%s rdf:type Human" % bond]), True)
        self.assertIs(self.oro.check(["%s rdf:type Robot" % bond]), False)
        self.assertIn("Human", self.oro.find("?a", ["%s rdf:type ?a" % bond]))
        self.assertEqual(self.oro.lookup(bond), [[bond, "INSTANCE"]])
        details = self.oro.getResourceDetails(bond)
        self.assertIsInstance(details, dict)
        self.assertEqual(details["id"], bond)
        self.assertIsInstance(self.oro.stats(), dict)

    def test_server_errors(self):
        with self.assertRaises(OroServerError) as caught:
            self.oro.add(["only two"])
        error = caught.exception
        self.assertEqual(error.name,
                         "laas.openrobots.ontology.exceptions.IllegalStatementException")
        self.assertIn("only two", error.message)
        self.assertEqual(str(error), error.name + ": " + error.message)
        with self.assertRaises(OroServerError) as caught:
            self.oro.call_server(["noSuchMethod"])
        self.assertEqual(caught.exception.name, "NotImplementedException")
        self.assertEqual(self.oro.hello(), "oro-server 0.8.2")   # still in step

    def test_pythonic_forms(self):
        fork, human = fresh("fork"), fresh("alfred")
        self.oro += "%s rdf:type Fork" % fork
        self.oro += ["%s rdf:type Human" % human, '%s rdfs:label "A que %s"' % (human, human)]
        self.assertIn(fork, self.oro["* rdf:type Fork"])
        self.assertEqual(self.oro[["* rdf:type Human", "* rdfs:label \"A que %s\"" % human]],
                         [human])
        self.assertEqual(self.oro["A que %s" % human], [human])
        self.assertTrue(fork in self.oro)
        self.assertTrue("%s rdf:type Fork" % fork in self.oro)
        self.assertFalse(fresh("nobody") in self.oro)
        self.assertFalse("%s likes judo" % human in self.oro)
        self.oro -= "%s rdf:type Fork" % fork
        self.assertNotIn(fork, self.oro["* rdf:type Fork"])

    def test_labels_read_back(self):
        texts = ['say "hi"', "back\\slash", "comma, and ]bracket[", "it's",
                 "tab\there", "smile \U0001F600", "{brace}: x"]
        for text in texts:
            thing = fresh("label")
            literal = '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
            self.oro.add(["%s rdf:type Human" % thing, "%s rdfs:label %s" % (thing, literal)])
            self.assertEqual(self.oro.getLabel(thing), text)
            self.assertEqual(self.oro.lookup(quote(text)), [[thing, "INSTANCE"]])

    def test_event_of_own_add_fires_without_another_request(self):
        got = Collector()
        target = fresh("bond")
        event_id = self.oro.subscribe(["?a kills %s" % target], got)
        self.assertRegex(event_id, r"^[0-9a-f-]{36}$")
        self.oro += "hrp2 kills %s" % target
        self.assertEqual(got.wait(1), [["hrp2"]])
        self.assertIsInstance(got.items[0], IdList)

    def test_event_types_and_agents(self):
        got, quiet = Collector(), Collector()
        thing = fresh("chicken")
        self.oro.subscribe("%s has teeth" % thing, got, type="FACT_CHECKING")
        called = threading.Event()
        self.oro.subscribe("%s has claws" % thing, called.set, type="FACT_CHECKING")
        agent = fresh("gerard")
        self.oro.add(["%s rdf:type Human" % agent])          # makes its model
        self.oro.subscribe(["?x likes %s" % thing], quiet, agent=agent)
        self.oro.add(["%s has teeth" % thing, "%s has claws" % thing])
        self.assertEqual(got.wait(1), [[]])
        self.assertTrue(called.wait(WAIT))
        self.oro.addForAgent(agent, ["bob likes %s" % thing])
        self.assertEqual(quiet.wait(1), [["bob"]])
        with self.assertRaises(ValueError):
            self.oro.subscribe(["?a likes ?b"], got)
        with self.assertRaises(OroServerError):
            self.oro.subscribe(["?a likes x"], got, type="NO_SUCH_TYPE")

    def test_unsubscribe(self):
        got = Collector()
        target = fresh("t")
        event_id = self.oro.subscribe(["?a sees %s" % target], got)
        self.oro.unsubscribe(event_id)
        self.oro += "a1 sees %s" % target
        self.assertEqual(self.oro.hello(), "oro-server 0.8.2")
        self.assertEqual(got.items, [])

    def test_callback_may_call_the_client(self):
        answers = Collector()
        target = fresh("cup")

        def callback(content):
            answers(self.oro.find("?c", ["%s isOn ?c" % content[0]]))

        self.oro.subscribe(["?x isOn %s" % target], callback)
        self.oro += "mug isOn %s" % target
        self.assertEqual(answers.wait(1), [[target]])

    def test_a_failing_callback_is_logged_and_the_next_runs(self):
        got = Collector()
        target = fresh("vase")
        self.oro.subscribe(["?a breaks %s" % target], lambda content: 1 / 0)
        self.oro.subscribe(["?a drops %s" % target], got)
        with self.assertLogs("pyoro", "ERROR") as logs:
            self.oro += "cat breaks %s" % target
            self.oro += "cat drops %s" % target
            self.assertEqual(got.wait(1), [["cat"]])
        self.assertIn("ZeroDivisionError", "\n".join(logs.output))

    def test_events_of_another_client(self):
        got = Collector()
        target = fresh("room")
        self.oro.subscribe(["?o isIn %s" % target], got)
        with Oro("127.0.0.1", server.port, timeout=WAIT) as other:
            other += "ball isIn %s" % target
        self.assertEqual(got.wait(1), [["ball"]])

    def test_eight_threads_share_one_client(self):
        names = [fresh("obj") for _ in range(8)]
        self.oro.add(["%s rdf:type Robot" % n for n in names])
        wrong, done = [], []

        def work(index):
            name = names[index]
            for i in range(50):
                if i % 2:
                    answer = self.oro.lookup(name)
                    ok = answer == [[name, "INSTANCE"]]
                else:
                    answer = self.oro.check(["%s rdf:type Robot" % name])
                    ok = answer is True
                if not ok:
                    wrong.append((name, answer))
                done.append(1)

        threads = [threading.Thread(target=work, args=(i,)) for i in range(8)]
        for t in threads:
            t.start()
        for t in threads:
            t.join(WAIT * 4)
        self.assertEqual(wrong, [])
        self.assertEqual(len(done), 400)

    def test_pipelined_calls(self):
        names = [fresh("p") for _ in range(50)]
        self.oro.add(["%s rdf:type Robot" % n for n in names])
        futures = [self.oro.call_async("lookup", n) for n in names]
        self.assertEqual([f.result(WAIT) for f in futures],
                         [[[n, "INSTANCE"]] for n in names])

    def test_two_hundred_rapid_adds_give_two_hundred_callbacks(self):
        got = Collector()
        target = fresh("kitchen")
        self.oro.subscribe(["?a isAt %s" % target], got)
        for i in range(200):
            self.oro += "thing%d_%s isAt %s" % (i, target, target)
        items = got.wait(200)
        self.assertEqual(len(items), 200)
        self.assertEqual(sorted(i[0] for i in items),
                         sorted("thing%d_%s" % (i, target) for i in range(200)))


class CloseTest(unittest.TestCase):

    def test_context_manager_and_close(self):
        with Oro("127.0.0.1", server.port) as oro:
            self.assertEqual(oro.hello(), "oro-server 0.8.2")
        with self.assertRaises(OroConnectionError):
            oro.hello()
        oro.close()                                 # twice: nothing
        for thread in (oro._reader, oro._dispatcher):
            self.assertFalse(thread.is_alive())

    def test_close_from_a_callback(self):
        oro = Oro("127.0.0.1", server.port, timeout=WAIT)
        closed = threading.Event()
        target = fresh("door")

        def callback(content):
            oro.close()
            closed.set()

        oro.subscribe(["?a opens %s" % target], callback)
        oro += "robot opens %s" % target
        self.assertTrue(closed.wait(WAIT))
        oro._dispatcher.join(WAIT)
        self.assertFalse(oro._dispatcher.is_alive())

    def test_unreachable_server(self):
        probe = socket.socket()
        probe.bind(("127.0.0.1", 0))                # bound, not listening
        port = probe.getsockname()[1]
        self.addCleanup(probe.close)
        with self.assertRaises(OroConnectionError):
            Oro("127.0.0.1", port)


if __name__ == "__main__":
    unittest.main()
