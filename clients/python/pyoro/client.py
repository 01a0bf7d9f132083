"""The connection to an ORO server: requests, replies and events."""

import atexit
import collections
import inspect
import logging
import os
import queue
import socket
import threading
import weakref
from concurrent.futures import Future, InvalidStateError, TimeoutError as _FutureTimeout

from .wire import IdList, decode_lines, encode_request

__all__ = ["Oro", "OroServerError", "OroConnectionError", "OroTimeout"]

# No handler of its own: until the program configures logging, warnings
# and errors (an exception in a callback) reach stderr through Python's
# last-resort handler rather than vanishing.
logger = logging.getLogger("pyoro")

_FOREVER = object()          # "no timeout given": use the client's default


class OroServerError(Exception):
    """An error: the server's ``error`` reply, or a failure to reach it.

    ``name`` is the exception name the server gave (for example
    ``laas.openrobots.ontology.exceptions.IllegalStatementException``),
    ``message`` its message; ``str()`` gives ``"name: message"``, as the
    original pyoro did.  ``value`` is that text too.
    """

    def __init__(self, name, message=None):
        super().__init__(name, message)
        self.name = name
        self.message = message
        self.value = name if message is None else "%s: %s" % (name, message)

    def __str__(self):
        return self.value


class OroConnectionError(OroServerError):
    """The connection could not be made, or was lost or closed."""

    def __init__(self, message):
        super().__init__(message)


class OroTimeout(OroServerError, TimeoutError):
    """No reply came within the timeout.  The connection stays usable:
    the late reply is read and dropped when it comes."""

    def __init__(self, message):
        super().__init__(message)


# Clients still open when the interpreter exits (after its last
# non-daemon thread) are closed then, after the events already caused
# are delivered (see Oro.close): the reader and dispatcher threads are
# daemons, which still run while atexit handlers do.

_open_clients = weakref.WeakSet()


@atexit.register
def _close_at_exit():
    for client in list(_open_clients):
        try:
            client.close()
        except Exception:                       # exiting: report, go on
            logger.exception("closing %r at exit", client)


def _settle(future, value=None, error=None):
    """Give ``future`` its value or error (once: a second is ignored)."""
    try:
        if error is None:
            future.set_result(value)
        else:
            future.set_exception(error)
    except InvalidStateError:
        pass


class _Subscription:
    __slots__ = ("callback", "with_content", "agent")

    def __init__(self, callback, agent):
        self.callback = callback
        self.agent = agent
        self.with_content = _takes_one_argument(callback)


def _takes_one_argument(callback):
    """Whether ``callback`` can be called with one positional argument.
    A callback that takes none (as the original pyoro called
    FACT_CHECKING callbacks) is called with none."""
    try:
        signature = inspect.signature(callback)
    except (TypeError, ValueError):
        return True
    try:
        signature.bind(None)
        return True
    except TypeError:
        try:
            signature.bind()
            return False
        except TypeError:
            return True


class Oro:
    """A client of an ORO server (oro, or oro-server 0.8.2).

    ``Oro(host, port)`` connects (by default to ``$ORO_HOST`` or
    ``localhost``, port ``$ORO_PORT`` or 6969), asks the server for
    its methods (``listSimpleMethods``) and makes each one a method of
    the object: ``oro.add(["bond rdf:type Human"])``,
    ``oro.lookup("Bond, James Bond")``, ``oro.findForAgent(...)``.
    Each call sends the request and returns the decoded value of the
    reply (bool, int, float, str, list, dict, or None for void methods)
    or raises ``OroServerError`` with the server's exception name and
    message.  Every server method also takes a ``timeout=`` keyword
    (seconds; ``None`` waits for ever; the default is the ``timeout``
    given here).

    One object can be shared by many threads: requests are written in
    one piece each, replies matched to requests in order, and calls of
    different threads are pipelined on the one connection.  A reader
    thread reads replies and events as they come; callbacks run on a
    separate dispatcher thread, one at a time, in the order of the
    events, and may themselves call the server.

    ``close()`` (or leaving a ``with Oro() as oro:`` block) delivers
    the events the client's own changes caused, then closes the
    connection.  A client still open when the program exits is closed
    then in the same way.
    """

    def __init__(self, host=None, port=None, timeout=None,
                 connect_timeout=10.0):
        if host is None:
            host = os.environ.get("ORO_HOST", "localhost")
        if port is None:
            port = int(os.environ.get("ORO_PORT", "6969"))
        self.host = host
        self.port = port
        self.timeout = timeout
        self._write_lock = threading.RLock()    # writes, _pending, _closed
        self._pending = collections.deque()     # Futures, in request order
        self._subscriptions = {}                # event id -> _Subscription
        self._events = queue.SimpleQueue()      # (subscription, content) | None
        self._closing = False
        self._closed = threading.Event()
        self._error = None
        try:
            self._socket = socket.create_connection((host, port), connect_timeout)
        except OSError as e:
            raise OroConnectionError(
                "Unable to connect to the server at %s:%s (%s). Check it is "
                "running and that you provided the right host and port."
                % (host, port, e)) from None
        self._socket.settimeout(None)
        self._socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._reader = threading.Thread(target=self._read_loop,
                                        name="pyoro-reader", daemon=True)
        self._dispatcher = threading.Thread(target=self._dispatch_loop,
                                            name="pyoro-dispatcher", daemon=True)
        self._reader.start()
        self._dispatcher.start()
        try:
            signatures = self.call_server(["listSimpleMethods"],
                                          timeout=connect_timeout)
            if not isinstance(signatures, list):
                raise OroServerError("listSimpleMethods did not answer a list: %r"
                                     % (signatures,))
        except OroServerError:
            self._shut()
            raise
        self.rpc_methods = sorted({str(s).split("(")[0].strip() for s in signatures})
        for name in self.rpc_methods:
            if name and not hasattr(type(self), name):
                setattr(self, name, self._server_method(name))
        _open_clients.add(self)

    def __repr__(self):
        state = "closed" if self._closed.is_set() else "open"
        return "<pyoro.Oro %s:%s %s>" % (self.host, self.port, state)

    # ------------------------------------------------------------ calls

    def _server_method(self, name):
        def method(*args, timeout=_FOREVER):
            return self.call_server([name] + list(args), timeout=timeout)
        method.__name__ = name
        method.__qualname__ = "Oro." + name
        method.__doc__ = "Call the server's %s method." % name
        return method

    def call_server(self, request, timeout=_FOREVER):
        """Send ``request`` (a list: the method name, then its
        arguments) and return the value of the reply."""
        future = self.call_async(request[0], *request[1:])
        return self._wait(future, timeout)

    def call_async(self, method, *args):
        """Send a request without waiting for its reply; return a
        ``concurrent.futures.Future`` of its value.  Many requests can be
        in flight at once (pipelining); their replies come in order."""
        return self._send(method, args)

    def _send(self, method, args, on_reply=None):
        data = encode_request(method, args)
        future = Future()
        future.set_running_or_notify_cancel()   # a request sent cannot be cancelled
        future.on_reply = on_reply
        with self._write_lock:
            if self._closing or self._closed.is_set():
                raise self._error or OroConnectionError("The connection is closed.")
            self._pending.append(future)
            try:
                self._socket.sendall(data)
            except OSError as e:
                error = OroConnectionError("Lost the connection to the server (%s)." % e)
                self._fail(error)
                raise error from None
        return future

    def _wait(self, future, timeout):
        if timeout is _FOREVER:
            timeout = self.timeout
        try:
            return future.result(timeout)
        except _FutureTimeout:
            raise OroTimeout("No reply from the server within %s s." % timeout) from None

    # ----------------------------------------------------------- events

    def subscribe(self, pattern, callback, var=None, type="NEW_INSTANCE",
                  trigger="ON_TRUE", agent="myself"):
        """Register a watcher and call ``callback`` each time it fires.

        ``pattern`` is a statement pattern or a list of them.  By default
        the event is ``NEW_INSTANCE`` ``ON_TRUE`` on the pattern's one
        variable (give ``var`` when it has several); ``type`` and
        ``trigger`` take the other ORO event types and triggers;
        ``agent`` the model watched.  The watcher is registered with
        ``registerEventForAgent``.  Returns the event id.

        ``callback`` gets the event's content, an ``IdList`` (a list of
        the ids the event reports, empty for ``FACT_CHECKING``), as its
        one argument; a callback that takes no argument is called with
        none.  Callbacks run on the dispatcher thread.
        """
        if isinstance(pattern, str):
            pattern = [pattern]
        else:
            pattern = list(pattern)
        if type == "NEW_INSTANCE" and not var:
            variables = {token for statement in pattern
                         for token in statement.split() if token.startswith("?")}
            if len(variables) > 1:
                raise ValueError("The pattern has several variables (%s): say which "
                                 "one the event returns with var=."
                                 % ", ".join(sorted(variables)))
            if variables:
                var = variables.pop()
        args = [agent, type, trigger, var, pattern] if var else \
               [agent, type, trigger, pattern]
        subscription = _Subscription(callback, agent)

        # The reader thread files the callback under the new id as soon
        # as it reads the reply, before it reads any event that follows.
        def on_reply(event_id):
            self._subscriptions[str(event_id)] = subscription

        future = self._send("registerEventForAgent", args, on_reply)
        event_id = self._wait(future, _FOREVER)
        logger.debug("subscribed %s to %r", event_id, pattern)
        return str(event_id)

    def unsubscribe(self, event_id):
        """Remove the watcher ``event_id`` (from ``subscribe``) and its callback."""
        subscription = self._subscriptions.get(event_id)
        agent = subscription.agent if subscription else "myself"
        self.call_server(["clearEvent", agent, event_id])
        self._subscriptions.pop(event_id, None)

    # ------------------------------------------------------ conveniences

    def __getitem__(self, pattern, agent="myself"):
        """``oro["* rdf:type Fork"]``: the ids matching a pattern (``*``
        is the unknown) or a list of patterns; ``oro["a label"]``: the
        ids of the concepts with that label or id."""
        if isinstance(pattern, (list, tuple)):
            return self.findForAgent(agent, "?_var",
                                     [p.replace("*", "?_var") for p in pattern])
        if "*" in pattern:
            return self.findForAgent(agent, "?_var", [pattern.replace("*", "?_var")])
        return [concept[0] for concept in self.lookupForAgent(agent, pattern)]

    def __contains__(self, pattern):
        """``"toto" in oro`` (a concept, by id or label) or
        ``"toto likes icecream" in oro`` (a statement, or a list of them,
        true or inferred)."""
        if not isinstance(pattern, (list, tuple)):
            if self.lookup(pattern):
                return True
            if len(pattern.split()) != 3:
                return False
            pattern = [pattern]
        try:
            return bool(self.check(list(pattern)))
        except OroConnectionError:
            raise
        except OroServerError:
            return False

    def __iadd__(self, statements):
        """``oro += "toto likes icecream"`` (or a list): add to the robot's model."""
        if isinstance(statements, str):
            statements = [statements]
        self.add(list(statements))
        return self

    def __isub__(self, statements):
        """``oro -= "toto likes icecream"`` (or a list): remove from the robot's model."""
        if isinstance(statements, str):
            statements = [statements]
        self.remove(list(statements))
        return self

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    # ------------------------------------------------------------ close

    def close(self, timeout=5.0):
        """Close the connection, once the events caused by this client's
        own requests are delivered.

        Sends ``close``: the server answers it after the events of the
        requests before it, so when the answer is read every such event
        has been read too.  Callbacks already queued run, then the
        reader and dispatcher threads end.  Calls still waiting fail
        with ``OroConnectionError``.  Waits at most ``timeout`` seconds
        for each step; closing twice does nothing.
        """
        with self._write_lock:
            first = not self._closing
            self._closing = True
            if first and not self._closed.is_set():
                try:
                    self._socket.sendall(b"close\n#end#\n")
                except OSError:
                    pass
        _open_clients.discard(self)
        if not first:
            return
        if threading.current_thread() is not self._reader:
            self._reader.join(timeout)
        self._shut()
        if threading.current_thread() is not self._dispatcher:
            self._dispatcher.join(timeout)

    def _shut(self):
        """Stop the reader (unblocking it), fail what waits, stop the dispatcher."""
        try:
            self._socket.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self._fail(OroConnectionError("The connection is closed."))
        self._socket.close()

    def _fail(self, error):
        """Mark the connection dead with ``error`` and fail every waiting
        call.  Under the write lock, so that no request is queued after
        the queue is emptied; the socket is shut down first, so that no
        writer holds that lock for long."""
        with self._write_lock:
            if self._closed.is_set():
                return
            self._error = error
            self._closed.set()
            pending = list(self._pending)
            self._pending.clear()
        for future in pending:
            _settle(future, error=error)
        self._events.put(None)

    # ----------------------------------------------------- reader thread

    def _read_loop(self):
        stream = self._socket.makefile("rb")
        try:
            while True:
                message = self._read_message(stream)
                if message is None:
                    break
                status, lines = message
                if status == "event":
                    self._on_event(lines)
                elif status == "Closing now!":
                    break
                else:
                    self._on_reply(status, lines)
        except OSError as e:
            if not self._closing:
                logger.error("reading from the server: %s", e)
        except Exception:                       # a bug: report it, fail the calls
            logger.exception("reading from the server")
        finally:
            try:
                self._socket.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            self._fail(OroConnectionError(
                "The connection is closed." if self._closing
                else "The server closed the connection."))
            stream.close()

    @staticmethod
    def _read_message(stream):
        """(status, value lines) of the next message, or None at the end."""
        status = None
        lines = []
        while True:
            raw = stream.readline()
            if not raw:
                return None
            line = raw.decode("utf-8", "replace")
            if line.endswith("\n"):
                line = line[:-1]
            if status is None:
                if line == "":
                    continue
                status = line
                if status == "Closing now!":
                    return status, lines
            elif line == "#end#":
                return status, lines
            else:
                lines.append(line)

    def _on_reply(self, status, lines):
        try:
            future = self._pending.popleft()
        except IndexError:
            logger.error("a reply no request waits for: %s %r", status, lines)
            return
        if status == "ok":
            value = decode_lines(lines)
            if future.on_reply is not None:
                future.on_reply(value)
            _settle(future, value)
        elif status == "error":
            name = lines[0] if lines else ""
            message = "\n".join(lines[1:])
            _settle(future, error=OroServerError(name, message))
        else:
            _settle(future, error=OroServerError(
                "Got an unexpected message status from the server: %r" % status))

    def _on_event(self, lines):
        event_id = lines[0] if lines else ""
        subscription = self._subscriptions.get(event_id)
        if subscription is None:
            logger.warning("an event for an unknown watcher %s", event_id)
            return
        content = decode_lines(lines[1:])
        if content is None:
            content = IdList()
        elif isinstance(content, list):
            content = IdList(content)
        self._events.put((subscription, content))

    # ------------------------------------------------- dispatcher thread

    def _dispatch_loop(self):
        while True:
            item = self._events.get()
            if item is None:
                break
            subscription, content = item
            try:
                if subscription.with_content:
                    subscription.callback(content)
                else:
                    subscription.callback()
            except Exception:
                logger.exception("event callback %r", subscription.callback)
