"""The text of the ORO socket protocol: requests out, values in.

A request is the method name, one line per parameter, then ``#end#``.
A reply is a status line (``ok``, ``error`` or ``event``), value lines,
then ``#end#``.  This module turns Python values into parameter lines
and value lines back into Python values; it does no input or output.

Value lines are JSON-like literals: ``"text"``, ``true``, ``3.5``,
``["a","b"]``, ``{"k":"v"}``.  They are read by a small literal parser
(never ``eval``) that accepts both JSON and Python spellings (``true``
and ``True``, ``null`` and ``None``, double or single quotes) and
Python's string escapes, so that it reads the server's replies whether
they escape strings the JSON way or strictly the Python way.  A line
that is no such literal (an event id, a bare word) is returned as the
text of the line, as the original pyoro did.
"""

import re

__all__ = ["IdList", "decode_lines", "decode_value", "encode_request", "quote"]


class IdList(list):
    """The content of an event: the list of the ids it reports.

    It is a plain list (index it, iterate over it, compare it with a
    list), and it also concatenates with a string, as the ids joined by
    ``", "``, so that ``"Killed by " + content`` reads ``Killed by hrp2``.
    """

    __slots__ = ()

    def _text(self):
        return ", ".join(str(item) for item in self)

    def __add__(self, other):
        if isinstance(other, str):
            return self._text() + other
        return list.__add__(self, other)

    def __radd__(self, other):
        if isinstance(other, str):
            return other + self._text()
        return NotImplemented


# --------------------------------------------------------------- requests

_LINE_BREAKS = str.maketrans({"\n": "\\n", "\r": "\\r"})


def quote(text):
    """``text`` quoted and escaped so that the server reads it back exactly.

    Use it for an argument that must arrive as written (a string
    argument is otherwise sent as it is, and the server removes one pair
    of outer quotes and reads backslash escapes in it), and for every
    element of a set or a map, which is how lists and dicts are sent.

    The server reads each element with Java's unescaping (``\\\\``,
    ``\\"``, ``\\'``, ``\\n``, ``\\r``, ``\\t``, ``\\b``, ``\\f``,
    ``\\uXXXX``).  The apostrophe is escaped too: the server's tokeniser
    tracks single and double quotes separately, so a bare ``'`` inside a
    double-quoted element would hide the commas that follow it.
    """
    return '"' + text.translate(_ELEMENT_ESCAPES) + '"'


_ELEMENT_ESCAPES = {code: "\\u%04x" % code for code in list(range(32)) + [127]}
_ELEMENT_ESCAPES.update({ord("\\"): "\\\\", ord('"'): '\\"', ord("'"): "\\'",
                         ord("\n"): "\\n", ord("\r"): "\\r", ord("\t"): "\\t"})


def _element(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)
    return quote(str(value))


def encode_param(value):
    """The parameter line for one argument of a call.

    Strings are sent as they are (the server trims them and removes one
    pair of outer quotes), except that line breaks are written ``\\n``
    and ``\\r`` so that they cannot end the line.  Lists, tuples and
    sets become ``["a","b"]`` and dicts ``{"k":"v"}``, every element
    quoted and escaped; booleans ``true``/``false``; numbers as Python
    writes them; ``None`` ``null``.
    """
    if isinstance(value, str):
        return value.translate(_LINE_BREAKS)
    if isinstance(value, bool):
        return "true" if value else "false"
    if value is None:
        return "null"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, dict):
        return "{" + ",".join(_element(k) + ":" + _element(v)
                              for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple, set, frozenset)):
        return "[" + ",".join(_element(v) for v in value) + "]"
    return str(value).translate(_LINE_BREAKS)


def encode_request(method, args):
    """The bytes of one request: ``method``, one line per argument, ``#end#``."""
    lines = [method]
    lines.extend(encode_param(a) for a in args)
    lines.append("#end#")
    return ("\n".join(lines) + "\n").encode("utf-8")


# ----------------------------------------------------------------- values

class _NotALiteral(Exception):
    pass


_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)\Z")
_WORDS = {"true": True, "True": True, "false": False, "False": False,
          "null": None, "None": None,
          "Infinity": float("inf"), "-Infinity": float("-inf"),
          "NaN": float("nan")}
_SIMPLE_ESCAPES = {"\\": "\\", "'": "'", '"': '"', "a": "\a", "b": "\b",
                   "f": "\f", "n": "\n", "r": "\r", "t": "\t", "v": "\v",
                   "/": "/"}
_TOKEN_END = set(",:]}) \t")


class _Parser:
    __slots__ = ("text", "pos")

    def __init__(self, text):
        self.text = text
        self.pos = 0

    def fail(self):
        raise _NotALiteral()

    def skip_blanks(self):
        text, pos = self.text, self.pos
        while pos < len(text) and text[pos] in " \t\r\n":
            pos += 1
        self.pos = pos

    def peek(self):
        self.skip_blanks()
        return self.text[self.pos] if self.pos < len(self.text) else ""

    def value(self):
        char = self.peek()
        if char in ('"', "'"):
            return self.string(char)
        if char == "[":
            return self.sequence("]")
        if char == "{":
            return self.mapping()
        if char == "(":
            return tuple(self.sequence(")"))
        return self.word()

    def sequence(self, close):
        self.pos += 1
        items = []
        if self.peek() == close:
            self.pos += 1
            return items
        while True:
            items.append(self.value())
            char = self.peek()
            self.pos += 1
            if char == close:
                return items
            if char != ",":
                self.fail()
            if self.peek() == close:            # a trailing comma
                self.pos += 1
                return items

    def mapping(self):
        self.pos += 1
        items = {}
        if self.peek() == "}":
            self.pos += 1
            return items
        while True:
            key = self.value()
            if self.peek() != ":":
                self.fail()
            self.pos += 1
            try:
                items[key] = self.value()
            except TypeError:                   # an unhashable key
                self.fail()
            char = self.peek()
            self.pos += 1
            if char == "}":
                return items
            if char != ",":
                self.fail()

    def word(self):
        text, start = self.text, self.pos
        pos = start
        while pos < len(text) and text[pos] not in _TOKEN_END:
            pos += 1
        token = text[start:pos]
        self.pos = pos
        if token in _WORDS:
            return _WORDS[token]
        if _NUMBER.match(token):
            if any(c in token for c in ".eE"):
                return float(token)
            return int(token)
        self.fail()

    def string(self, quote):
        text = self.text
        pos = self.pos + 1
        out = []
        while True:
            end = pos
            while end < len(text) and text[end] != quote and text[end] != "\\":
                end += 1
            out.append(text[pos:end])
            if end >= len(text):
                self.fail()                     # no closing quote
            if text[end] == quote:
                self.pos = end + 1
                return _join_surrogates("".join(out))
            pos = self.escape(end + 1, out)

    def escape(self, pos, out):
        """Read the escape after a backslash at ``pos - 1``; return the next position."""
        text = self.text
        if pos >= len(text):
            self.fail()
        char = text[pos]
        if char in _SIMPLE_ESCAPES:
            out.append(_SIMPLE_ESCAPES[char])
            return pos + 1
        for letter, width in (("x", 2), ("u", 4), ("U", 8)):
            if char == letter:
                digits = text[pos + 1:pos + 1 + width]
                if len(digits) != width or not all(d in "0123456789abcdefABCDEF"
                                                   for d in digits):
                    self.fail()
                code = int(digits, 16)
                if code > 0x10FFFF:
                    self.fail()
                out.append(chr(code))
                return pos + 1 + width
        if char in "01234567":
            end = pos
            while end < len(text) and end < pos + 3 and text[end] in "01234567":
                end += 1
            out.append(chr(int(text[pos:end], 8)))
            return end
        out.append("\\" + char)                 # unknown: kept, as Python does
        return pos + 1


_SURROGATE_PAIR = re.compile("[\ud800-\udbff][\udc00-\udfff]")


def _join_surrogates(text):
    """Join JSON-style ``\\ud83d\\ude00`` pairs into the one character they stand for."""
    if not any("\ud800" <= c <= "\udfff" for c in text):
        return text
    return _SURROGATE_PAIR.sub(
        lambda m: chr(0x10000 + ((ord(m.group()[0]) - 0xD800) << 10)
                      + (ord(m.group()[1]) - 0xDC00)),
        text)


def decode_value(line):
    """The Python value of one value line: bool, int, float, str, list,
    dict or None; a line that is no literal is returned as it is."""
    parser = _Parser(line)
    try:
        value = parser.value()
        parser.skip_blanks()
        if parser.pos != len(line):
            parser.fail()
    except (_NotALiteral, ValueError, RecursionError):
        return line
    return value


def decode_lines(lines):
    """The value of an ``ok`` reply from its value lines: ``None`` when
    it has none (a void method), else the value of its one line.  A
    string the server wrote over several lines (``help``) is read
    whole."""
    values = [line for line in lines if line != ""]
    if not values:
        return None
    if len(values) > 1:
        whole = "\n".join(lines)
        value = decode_value(whole)
        if value is not whole:
            return value
    return decode_value(values[0])
