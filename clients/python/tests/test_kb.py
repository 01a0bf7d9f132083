"""Tests of the pykb-compatible ``kb`` module against a real oro server.

The scenarios are those of knowledge_core's socket test suite, written
from its public API description, with pykb's idioms (``+=``, ``-=``,
``[]``, ``in``, ``subscribe``, ``with``).  One server is started for the
module on free loopback ports (``--port=0``: the ORO port and the
KB-API port are picked by the system) and stopped by its PID.  Waits
are bounded: an event is waited for (10 s at most); the absence of an
event is checked after a round trip and a short wait.

Run from the repository root:

    PYTHONPATH=clients/python python3 -m unittest discover -s clients/python/tests
"""

import os
import queue
import re
import subprocess
import threading
import time
import unittest

import kb

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
SERVER = os.path.join(ROOT, "server", "oro_server.pl")
TIME_BASE = 20          # ms: a lifespan of 1 "second" lasts 20 ms

_server = None
_port = None


def setUpModule():
    global _server, _port
    _server = subprocess.Popen(
        ["swipl", SERVER, "--port=0", "--no-commonsense",
         "--time-base=%d" % TIME_BASE],
        cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
        text=True)
    found = queue.Queue()

    def read_ports():
        for line in _server.stdout:
            m = re.match(r"oro serving the KB-API on .*:(\d+)", line)
            if m:
                found.put(int(m.group(1)))
                break
        for _ in _server.stdout:        # keep the pipe drained
            pass

    threading.Thread(target=read_ports, daemon=True).start()
    try:
        _port = found.get(timeout=120)
    except queue.Empty:
        tearDownModule()
        raise RuntimeError("the oro server did not start")


def tearDownModule():
    if _server is not None:
        _server.terminate()
        try:
            _server.wait(timeout=15)
        except subprocess.TimeoutExpired:
            _server.kill()
            _server.wait(timeout=15)


def wait_for(condition, timeout=10):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.01)
    return condition()


class TestKB(unittest.TestCase):

    def setUp(self):
        self.kb = kb.KB(port=_port)
        self.kb.clear()

    def tearDown(self):
        self.kb.close()

    def no_event(self):
        self.kb.hello()            # a round trip: the change is done
        time.sleep(0.2)
        with self.assertRaises(queue.Empty):
            self.kb.events.get_nowait()

    def next_event(self):
        return self.kb.events.get(timeout=10)

    def test_basics(self):
        self.assertIn("oro", self.kb.hello())
        with self.assertRaises(kb.KbError):
            self.kb.add()
        with self.assertRaises(kb.KbError):
            self.kb.add("toto")
        with self.assertRaises(kb.KbError):
            self.kb.add(["toto"])
        with self.assertRaises(kb.KbError):
            self.kb += ["toto"]
        with self.assertRaises(kb.KbError):
            self.kb += ["toto titi"]
        with self.assertRaises(kb.KbError):
            self.kb += ["toto titi tutu tata"]

    def test_modifications(self):
        self.kb.add(["johnny rdf:type Human", 'johnny rdfs:label "A que Johnny"'])
        self.kb += ["alfred rdf:type Human", "alfred likes icecream"]
        self.assertIn({"var1": "alfred", "var2": "likes", "var3": "icecream"},
                      self.kb["* * *"])
        self.kb.remove(["alfred rdf:type Human", "alfred likes icecream"])
        self.kb -= ["johnny rdf:type Human"]
        self.assertNotIn({"var1": "alfred", "var2": "likes", "var3": "icecream"},
                         self.kb["* * *"])
        self.kb.revise(["toto likes tata"], {"method": "add"})
        self.kb.revise(["toto likes tata"], policy={"method": "add"})
        self.assertTrue(self.kb["toto likes tata"])

    def test_models(self):
        self.kb.add(["s p o", "s2 p2 o2"], ["model1", "model2"])
        self.assertTrue(self.kb["s p o", ["model1"]])
        self.assertTrue(self.kb["s2 p2 o2", ["model2"]])
        self.assertFalse(self.kb["s p o"])
        self.kb.add(["nono isNice true"], ["model1"])
        self.assertTrue(self.kb.about("nono", ["model1"]))
        self.assertFalse(self.kb.about("nono", ["model2"]))

    def test_existence(self):
        self.assertFalse("alfred" in self.kb)
        self.assertFalse("alfred likes icecream" in self.kb)
        self.kb += ["alfred rdf:type Human", "alfred likes icecream"]
        self.assertTrue("alfred" in self.kb)
        self.assertFalse("tartempion" in self.kb)
        self.assertFalse("alfred likes" in self.kb)
        self.assertTrue("alfred likes icecream" in self.kb)
        self.assertTrue("alfred likes *" in self.kb)
        self.assertTrue("alfred likes ?smthg" in self.kb)
        self.assertTrue("* likes *" in self.kb)
        self.assertFalse("* dislikes *" in self.kb)
        self.assertFalse("alfred likes mygrandmother" in self.kb)
        self.kb -= ["alfred rdf:type Human", "alfred likes icecream"]
        self.assertFalse("alfred likes icecream" in self.kb)
        self.assertFalse("alfred" in self.kb)

    def test_lookup_and_literals(self):
        self.assertEqual(self.kb.lookup("alfred"), [])
        self.kb += ["alfred rdf:type Robot", "alfred likes icecream"]
        self.assertEqual(self.kb.lookup("Robot"), [["Robot", "class"]])
        self.assertEqual(self.kb.lookup("likes"), [["likes", "object_property"]])
        self.kb += ['gerard rdfs:label "likes"', "gerard age 18"]
        self.assertEqual(self.kb.lookup('"likes"'), [['"likes"', "literal"]])
        self.assertEqual(self.kb.lookup("age"), [["age", "datatype_property"]])
        self.assertEqual(self.kb["gerard age ?a"], [{"a": 18}])

    def test_complex_queries(self):
        self.assertEqual(self.kb["?agent rdf:type Robot", "?agent desires ?obj"], [])
        self.kb += ["nono rdf:type Human", "alfred rdf:type Robot",
                    "nono desires jump", "alfred desires oil",
                    "nono loves icecream", "jump rdf:type Action"]
        self.assertEqual(self.kb["?agent desires jump", "?agent loves icecream"],
                         [{"agent": "nono"}])
        self.assertEqual(self.kb["?agent desires *", "?agent loves icecream"],
                         [{"agent": "nono"}])
        self.assertEqual(self.kb["?agent rdf:type Robot", "?agent desires ?obj"],
                         [{"agent": "alfred", "obj": "oil"}])
        self.assertCountEqual(self.kb["?agent desires ?obj"],
                              [{"agent": "alfred", "obj": "oil"},
                               {"agent": "nono", "obj": "jump"}])

    def test_update(self):
        self.kb += ["nono isNice true", "isNice rdf:type owl:FunctionalProperty"]
        self.assertEqual(self.kb["* isNice true"], [{"var1": "nono"}])
        self.kb += ["nono isNice false"]
        self.assertFalse(self.kb["* isNice true"])
        self.assertEqual(self.kb["* isNice false"], [{"var1": "nono"}])

    def test_events(self):
        got = queue.Queue()
        evtid = self.kb.subscribe(["?o isIn room"], got.put)
        self.kb += ["alfred isIn garage"]
        self.kb += ["alfred isIn room"]
        self.assertEqual(got.get(timeout=10), [{"o": "alfred"}])
        self.kb += ["alfred leaves room"]
        evtid2 = self.kb.subscribe(["?o isIn garage"], got.put)
        self.assertNotEqual(evtid, evtid2)
        self.kb += ["batman isIn garage"]
        self.assertEqual(got.get(timeout=10), [{"o": "batman"}])
        self.assertTrue(got.empty())

    def test_events_multiclients(self):
        got = queue.Queue()
        with kb.KB(port=_port) as kb2:
            self.kb.subscribe(["?o isIn room"], got.put)
            kb2 += ["alfred isIn garage"]
            kb2 += ["alfred isIn room"]
            self.assertEqual(got.get(timeout=10), [{"o": "alfred"}])

    def test_polled_events(self):
        evtid = self.kb.subscribe(["?o isIn room"])
        self.kb += ["alfred isIn garage"]
        self.no_event()
        self.kb += ["alfred isIn room"]
        self.assertEqual(self.next_event(), (evtid, [{"o": "alfred"}]))
        self.kb += ["alfred leaves room"]
        self.no_event()

    def test_complex_and_one_shot_events(self):
        evtid = self.kb.subscribe(["?a desires ?act", "?act rdf:type Action"],
                                  one_shot=True)
        self.kb += ["alfred desires ragnagna"]
        self.kb += ["ragnagna rdf:type Zorro"]
        self.no_event()
        self.kb += ["Zorro rdfs:subClassOf Action"]
        self.assertEqual(self.next_event(),
                         (evtid, [{"a": "alfred", "act": "ragnagna"}]))
        self.kb += ["bob desires ragnagna"]
        self.no_event()

    def test_minimalkb_events(self):
        evtid = self.kb.subscribe(["?a desires ?act", "?act rdf:type Action"],
                                  var="a")
        self.kb += ["alfred desires ragnagna", "ragnagna rdf:type Action"]
        self.assertEqual(self.next_event(), (evtid, ["alfred"]))

    def test_taxonomy_walking(self):
        self.assertFalse(self.kb.classesof("john"))
        self.kb += ["john rdf:type Human"]
        self.assertEqual(self.kb.classesof("john", True), ["Human"])
        self.kb += ["Human rdfs:subClassOf Animal"]
        self.assertTrue({"Human", "Animal"} <= set(self.kb.classesof("john")))
        self.assertTrue("john rdf:type Animal" in self.kb)
        self.kb -= ["john rdf:type Human"]
        self.assertNotIn("Animal", self.kb.classesof("john"))

    def test_lifespan(self):
        self.kb.add(["john rdf:type Human"], [], 1)       # 1 unit: 20 ms here
        self.kb.add(["jim rdf:type Human"], lifespan=0)  # for ever
        self.assertTrue(wait_for(lambda: "john rdf:type Human" not in self.kb))
        self.assertTrue("jim rdf:type Human" in self.kb)

    def test_oro_extras(self):
        self.kb += ["Animal owl:disjointWith Plant", "cow rdf:type Animal"]
        self.assertFalse(self.kb.safe_add(["cow rdf:type Plant"]))
        self.assertTrue(self.kb.check_consistency())
        self.assertFalse("cow rdf:type Plant" in self.kb)
        self.kb += ["Monkey rdfs:subClassOf Animal", "gorilla rdf:type Monkey"]
        [why] = self.kb.explain(["gorilla rdf:type Animal"])
        self.assertEqual(why["axioms"], ["Monkey rdfs:subClassOf Animal"])

    def test_sparql(self):
        self.kb += ["myself age 40"]
        res = self.kb.sparql("SELECT ?age WHERE { :myself :age ?age . }")
        self.assertEqual(res["head"]["vars"], ["age"])
        self.assertEqual(res["results"]["bindings"][0]["age"]["value"], "40")


if __name__ == "__main__":
    unittest.main()
