"""A pykb-compatible client for oro's KB-API dialect.

Code written for pykb (the Python client of minimalkb and knowledge_core)
runs against oro with the import unchanged::

    import kb

    with kb.KB() as kb:
        kb += ["ari rdf:type Robot"]
        kb["* rdf:type Robot"]            # [{"var1": "ari"}]
        "ari" in kb                       # True
        kb.subscribe(["?r isIn ?p"], callback)

The server's methods (``hello``, ``find``, ``revise``, ``sparql``, ...
and oro's extras ``check_consistency``, ``explain``, ``similarities``...)
become methods of ``KB`` when it connects, as pykb builds them from the
server's ``methods`` list.  Standard library only; Python >= 3.9.

oro serves the KB-API on port 6971 by default (6969 is the ORO
protocol), which is ``KB()``'s default port here.
"""

import json
import logging
import queue
import random
import shlex
import socket
import string
import threading

__all__ = ["KB", "KbError", "DEFAULT_PORT"]

DEFAULT_PORT = 6971
MSG_SEPARATOR = "#end#"

kblogger = logging.getLogger("kb")
kblogger.addHandler(logging.NullHandler())


class KbError(Exception):
    """An error reported by the server, or a broken connection."""

    def __init__(self, value):
        super().__init__(value)
        self.value = value

    def __str__(self):
        return repr(self.value)


class _Connection:
    """The socket, a reader thread splitting messages on ``#end#``, and
    the replies waiting for the caller."""

    def __init__(self, host, port, sock, on_event):
        self._sock = sock or socket.create_connection((host, port))
        self._send_lock = threading.Lock()
        self._call_lock = threading.Lock()
        self._replies = queue.Queue()
        self._on_event = on_event
        self.connected = True
        self._reader = threading.Thread(target=self._read, daemon=True,
                                        name="kb-reader")
        self._reader.start()

    def _read(self):
        buffer = b""
        sep = MSG_SEPARATOR.encode("ascii")
        try:
            while True:
                data = self._sock.recv(65536)
                if not data:
                    break
                buffer += data
                while sep in buffer:
                    raw, buffer = buffer.split(sep, 1)
                    if buffer.startswith(b"\n"):
                        buffer = buffer[1:]
                    self._dispatch(raw.decode("utf-8"))
        except OSError:
            pass
        finally:
            self.connected = False
            self._replies.put(None)

    def _dispatch(self, raw):
        parts = raw.strip("\n").split("\n")
        status = parts[0].strip()
        if status == "event":
            self._on_event(parts[1], json.loads(parts[2]))
        elif status == "ok":
            value = json.loads(parts[1]) if len(parts) > 1 and parts[1] else None
            self._replies.put(("ok", value))
        elif status == "error":
            name = parts[1] if len(parts) > 1 else "kberror"
            msg = parts[2] if len(parts) > 2 else "[no error msg]"
            self._replies.put(("error", "%s: %s" % (name, msg)))
        else:
            self._replies.put(("error", "unexpected message: %r" % raw))

    def call(self, method, *args, **kwargs):
        lines = [method] + [json.dumps(a) for a in args]
        if kwargs:
            lines.append(json.dumps({"kwargs": kwargs}))
        lines.append(MSG_SEPARATOR)
        data = ("\n".join(lines) + "\n").encode("utf-8")
        with self._call_lock:
            if not self.connected:
                raise KbError("not connected to the knowledge base")
            with self._send_lock:
                self._sock.sendall(data)
            if method == "close":
                return None
            reply = self._replies.get()
        if reply is None:
            raise KbError("the knowledge base closed the connection")
        status, value = reply
        if status == "error":
            raise KbError(value)
        return value

    def close(self, timeout=5):
        if self.connected:
            try:
                self.call("close")
            except (OSError, KbError):
                pass
            self._reader.join(timeout)
        try:
            self._sock.close()
        except OSError:
            pass


class KB:
    """A connection to a knowledge base speaking the KB-API.

    ``KB(host, port)`` connects and adds a method for each method the
    server lists.  Events arrive in a thread of their own: those of a
    subscription with a callback are passed to it, the others are put in
    ``KB.events`` as ``(event_id, value)`` for polling.
    """

    def __init__(self, host="localhost", port=DEFAULT_PORT, embedded=False,
                 defaultontology=None, sock=None):
        if embedded:
            raise KbError("oro has no embedded mode: start the server")
        if not host or not port:
            raise KbError("No host and/or port specified to connect to the "
                          "knowledge base.")
        self.events = queue.Queue()
        self._incoming = queue.Queue()
        self._callbacks = {}
        self._subscribing = threading.Lock()
        self._client = None
        self._executor = None
        try:
            self._client = _Connection(host, port, sock, self._event)
        except OSError as e:
            raise KbError("Could not connect to the knowledge base at %s:%s: %s"
                          % (host, port, e))
        methods = self._client.call("methods")
        if not methods:
            raise KbError("Could not connect to the knowledge base. "
                          "Is it started?")
        for m in methods:
            self._add_method(m.split("(")[0])
        self._running = True
        self._executor = threading.Thread(target=self._run_callbacks,
                                          daemon=True, name="kb-events")
        self._executor.start()

    # ---- server methods ------------------------------------------------

    def _add_method(self, name):
        def method(*args, **kwargs):
            kblogger.debug("Sending <%s(%s, %s)> request to server.",
                           name, args, kwargs)
            return self._client.call(name, *args, **kwargs)

        method.__doc__ = ("This method is a proxy for the knowledge "
                          "server's %s method." % name)
        if name == "subscribe":
            method.__name__ = "server_subscribe"
        elif name == "close":
            method.__name__ = "server_close"
        else:
            method.__name__ = name
        setattr(self, method.__name__, method)

    # ---- with statement ------------------------------------------------

    def __enter__(self):
        return self

    def __exit__(self, exc_type, exc_val, exc_tb):
        self.close()

    def __del__(self):
        try:
            self.close()
        except Exception:
            pass

    def close(self):
        """Close the connection; events received before are handled."""
        if self._executor is not None:
            self._running = False
            self._incoming.put(None)
            if self._executor is not threading.current_thread():
                self._executor.join(5)
            self._executor = None
        if self._client is not None:
            self._client.close()
            self._client = None

    # ---- events --------------------------------------------------------

    def _event(self, event_id, value):
        kblogger.debug("Event received: %s (%s)", event_id, value)
        self._incoming.put((event_id, value))

    def _run_callbacks(self):
        while True:
            item = self._incoming.get()
            if item is None:
                return
            event_id, value = item
            with self._subscribing:
                callbacks = list(self._callbacks.get(event_id, []))
            if not callbacks:
                self.events.put((event_id, value))
            for cb in callbacks:
                try:
                    cb(value)
                except Exception:
                    kblogger.exception("Event callback %s failed", cb)

    def subscribe(self, pattern, callback=None, one_shot=False, models=None,
                  var=None, type=None, trigger=None):
        """Subscribe to the new solutions of ``pattern`` (a statement or a
        list of them, sharing their variables).

        Each event carries the new bindings of every named variable, as a
        list of ``{variable: value}`` dicts (knowledge_core's form); with
        ``var`` (and optionally ``type``, ``trigger``), minimalkb's form:
        the list of the new values of that variable.  ``one_shot`` events
        fire once.  With a ``callback`` it is called with the event's
        value in a thread of its own; otherwise events go to
        ``KB.events`` as ``(event_id, value)``.  Returns the event id.
        """
        if isinstance(pattern, str):
            pattern = [pattern]
        with self._subscribing:
            if var is not None or type is not None or trigger is not None:
                if var and not var.startswith("?"):
                    var = "?" + var
                if trigger is None:
                    trigger = "ON_TRUE_ONE_SHOT" if one_shot else "ON_TRUE"
                event_id = self.server_subscribe(type or "NEW_INSTANCE",
                                                 trigger, var, pattern, models)
            else:
                event_id = self.server_subscribe(pattern, one_shot, models)
            if callback:
                self._callbacks.setdefault(event_id, []).append(callback)
        kblogger.debug("New event successfully registered with ID %s",
                       event_id)
        return event_id

    # ---- pythonic queries ----------------------------------------------

    def __getitem__(self, args):
        """``kb["* rdf:type Robot"]``, ``kb["?a desires ?b", "?b rdf:type
        Jump"]``, ``kb["s p o", ["model1"]]``: the rows of bindings (a
        list of dicts; ``*`` stands for an anonymous variable, named
        ``var1``, ``var2``... when there is no named one).  A pattern
        without variables gives ``[pattern]`` if it holds, else ``[]``.  A
        text that is not a statement is looked up: the matching ids.
        """
        models = None
        if isinstance(args, tuple):
            args = list(args)
            if len(args) > 1 and isinstance(args[-1], list):
                models = args.pop()
        else:
            args = [args]
        if len(args) == 1 and isinstance(args[0], list):
            args = args[0]
        if len(args) == 1:
            toks = _tokens(args[0])
            if len(toks) != 3:
                return [c[0] for c in self.lookup(args[0], models)]
        patterns = [" ".join(_replace_stars(_tokens(p))) for p in args]
        return self.find(patterns, None, models)

    def __contains__(self, pattern):
        """``"alfred" in kb`` (a known id or label) or ``"alfred likes *"
        in kb`` (a statement or pattern that holds)."""
        toks = _tokens(pattern)
        if len(toks) == 3:
            return bool(self.exist([" ".join(_replace_stars(toks))]))
        return bool(self.lookup(pattern))

    def __iadd__(self, stmts):
        """``kb += ["a b c"]``: update the robot's model."""
        if not isinstance(stmts, list):
            stmts = [stmts]
        self.update(stmts)
        return self

    def __isub__(self, stmts):
        """``kb -= ["a b c"]``: retract from the robot's model."""
        if not isinstance(stmts, list):
            stmts = [stmts]
        self.retract(stmts)
        return self


def _tokens(text):
    try:
        return shlex.split(text, posix=False)
    except ValueError:
        return text.split()


def _replace_stars(tokens):
    return ["?__" + "".join(random.sample(string.ascii_letters, 8))
            if tok == "*" else tok for tok in tokens]
